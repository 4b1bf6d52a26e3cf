"""The settings guide's section of docs/accuracy.md and its figure: the fronts of each measure
against the cost (settings that no other beats on both), the worst case over every scenario, the
"if you want X, set Y" rows, the tables of settings and of the hover's error against dt.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from playground.bench.markdown import table
from playground.bench.plots import pyplot, save
from tools.guide import BLOCK, HOVER_DTS, HOVER_FREQUENCIES
from tools.guide_settings import COMBOS, KNOBS, THRESHOLDS, Run, value_text
from tools.scenarios import DROP, RUN_SPEED, SCENARIOS

__all__ = [
    "COST_TIE",
    "WANTS",
    "advice",
    "front",
    "guide_figure",
    "guide_markdown",
    "misses",
    "worst_case",
]


COST_TIE = 0.1
"""Relative: costs closer than this count as equal (the paired ratios' run-to-run noise on a shared
machine), so the front is not decided by timing noise between settings that cost the same."""


def front(points: Sequence[tuple[float, float]], tie: float = COST_TIE) -> list[int]:
    """Indices of the (cost, measure) points that no other point dominates, by rising cost.

    ``j`` dominates ``i`` when it is no worse on the measure and costs no more than ``i`` (within
    the relative ``tie``), and is strictly better on one of them.

    >>> front([(1.0, 5.0), (2.0, 3.0), (3.0, 4.0), (4.0, 1.0)], tie=0.0)
    [0, 1, 3]
    >>> front([(1.0, 5.0), (1.05, 3.0)], tie=0.1)    # 5 % dearer counts as the same cost
    [1]
    """

    def dominates(j: int, i: int) -> bool:
        (cj, mj), (ci, mi) = points[j], points[i]
        cheap = cj <= ci * (1.0 + tie)
        return cheap and mj <= mi and (mj < mi or cj < ci / (1.0 + tie))

    n = range(len(points))
    keep = [i for i in n if not any(dominates(j, i) for j in n if j != i)]
    return sorted(keep, key=lambda i: (points[i][0], points[i][1]))


def _by_setting(runs: Sequence[Run]) -> dict[str, dict[str, Run]]:
    """Setting label → scenario → its run."""
    out: dict[str, dict[str, Run]] = {}
    for r in runs:
        out.setdefault(r.label, {})[r.scenario] = r
    return out


def worst_case(runs: Sequence[Run]) -> list[tuple[str, float, float]]:
    """Per setting: (label, mean share of a 60 Hz frame over the scenarios, worst measure over
    its threshold across every measure of every scenario)."""
    out = []
    for label, per in _by_setting(runs).items():
        if len(per) < len(SCENARIOS):
            continue
        worst = max(r.measures[m] / THRESHOLDS[m][0] for r in per.values() for m in r.measures)
        share = statistics.fmean(r.frame_share for r in per.values())
        out.append((label, share, worst))
    return out


WANTS = {
    "drift": "the player to stay put on an accelerating platform (drift under {t} {u})",
    "shake": "a camera that does not shake where nothing turns (perceived up under {t} {u} RMS)",
    "ring up": "a steady camera in a spinning room (perceived up within {t} {u})",
    "room up": "the camera to follow a turning room (within {t} {u})",
    "landing tilt": "running landings that stay upright (tilt under {t} {u})",
    "penetration": "feet that never sink into the floor (under {t} {u})",
}
"""What a player wants, per measure of :data:`THRESHOLDS` (``t`` and ``u``: its threshold)."""


def _breaks(runs: Sequence[Run], label: str) -> list[str]:
    """The measures over their thresholds in any scenario at setting ``label``: "shake 15.9 °/s"."""
    return [
        f"{m} {r.measures[m]:.3g} {THRESHOLDS[m][1]}"
        for r in runs
        if r.label == label
        for m in r.measures
        if math.isfinite(r.measures[m]) and r.measures[m] >= THRESHOLDS[m][0]
    ]


def _but(runs: Sequence[Run], label: str, measure: str) -> str:
    """ ", but shake 15.9 °/s" when setting ``label`` breaks another measure, else ""."""
    others = [b for b in _breaks(runs, label) if not b.startswith(f"{measure} ")]
    return f"; but {', '.join(others)}" if others else ""


def advice(runs: Sequence[Run]) -> list[tuple[str, str]]:
    """The "if you want X, set Y" rows: for each measure, the cheapest tried setting (one knob or
    a combination) that keeps it under its threshold, or the best one if none does, and what that
    setting breaks elsewhere, read off the runs."""
    rows = []
    for measure, text in WANTS.items():
        limit, unit = THRESHOLDS[measure]
        cands = [r for r in runs if measure in r.measures and math.isfinite(r.measures[measure])]
        if not cands:
            continue
        base = next((r for r in cands if r.knob == "defaults"), None)
        ok = [r for r in cands if r.measures[measure] < limit]
        if base is not None and base.measures[measure] < limit:
            y = f"the defaults ({base.measures[measure]:.3g} {unit})"
        elif ok:
            best = min(ok, key=lambda r: r.frame_share)
            missed = f"the defaults miss ({base.measures[measure]:.3g} {unit}): " if base else ""
            y = (
                f"{missed}{best.label} ({best.measures[measure]:.3g} {unit}, "
                f"{100 * best.frame_share:.1f} % of a 60 Hz frame"
                + _but(runs, best.label, measure)
                + ")"
            )
        else:
            best = min(cands, key=lambda r: r.measures[measure])
            y = (
                f"no setting tried gets there; the best is {best.label} "
                f"({best.measures[measure]:.3g} {unit}"
                + (f", defaults {base.measures[measure]:.3g}" if base is not None else "")
                + _but(runs, best.label, measure)
                + ")"
            )
        rows.append((text.format(t=f"{limit:g}", u=unit), y))
    return rows


def misses(runs: Sequence[Run]) -> list[str]:
    """Where the defaults miss a threshold: one sentence each, with what to change (the
    cheapest setting tried that meets it) and what that change costs on the other measures."""
    out = []
    for r in runs:
        if r.knob != "defaults":
            continue
        for m, v in r.measures.items():
            limit, unit = THRESHOLDS[m]
            if not math.isfinite(v) or v < limit:
                continue
            ok = [c for c in runs if m in c.measures and c.measures[m] < limit]
            if ok:
                best = min(ok, key=lambda c: c.frame_share)
                fix = f"{best.label} gets it to {best.measures[m]:.3g} {unit}" + (
                    f", at the price of {', '.join(others)}"
                    if (others := [b for b in _breaks(runs, best.label) if not b.startswith(m)])
                    else ", and breaks nothing else tried"
                )
            else:
                fix = "no setting tried gets there"
            out.append(f"- **{r.scenario}, {m}**: {v:.3g} {unit} against {limit:g} {unit}; {fix}.")
    return out


def guide_markdown(
    runs: Sequence[Run], hover: dict[tuple[float, float], float], seconds: float
) -> str:
    """The settings guide's section of docs/accuracy.md (after its "if you want" table)."""
    measures = [m for m in THRESHOLDS if any(m in r.measures for r in runs)]
    per = _by_setting(runs)
    header = ["setting", *(f"{m} ({THRESHOLDS[m][1]})" for m in measures)]
    header += ["µs/step median [p10–p90]", "% of a 60 Hz frame"]
    body = []
    for label, scen in per.items():
        row = [label]
        for m in measures:
            vals = [r.measures[m] for r in scen.values() if m in r.measures]
            row.append(f"{vals[0]:.3g}" if vals else "–")
        costs = list(scen.values())
        med = statistics.median(r.cost_us for r in costs)
        lo = statistics.median(r.cost_lo for r in costs)
        hi = statistics.median(r.cost_hi for r in costs)
        share = statistics.median(r.frame_share for r in costs)
        row += [f"{med:.0f} [{lo:.0f}–{hi:.0f}]", f"{100 * share:.1f}"]
        body.append(row)
    fronts = []
    for name, (_, _, ms) in SCENARIOS.items():
        rs = [r for r in runs if r.scenario == name]
        for m in ms:
            idx = front([(r.frame_share, r.measures[m]) for r in rs])
            items = ", ".join(
                f"{rs[i].label} ({rs[i].measures[m]:.3g} {THRESHOLDS[m][1]}, "
                f"{100 * rs[i].frame_share:.1f} %)"
                for i in idx
            )
            fronts.append(f"- **{name}, {m}**: {items}")
    wc = worst_case(runs)
    idx = front([(s, w) for _, s, w in wc])
    worst_items = ", ".join(
        f"{wc[i][0]} (worst {wc[i][2]:.2g}× its threshold, {100 * wc[i][1]:.1f} %)" for i in idx
    )
    knob_lines = "\n".join(
        f"| `{k.name}` | {k.what} | {', '.join(map(value_text, k.values))} | {k.unit or '–'} |"
        for k in KNOBS
    )
    hover_rows = []
    for f in HOVER_FREQUENCIES:
        cells = []
        for dt in HOVER_DTS:
            e = hover[(f, dt)]
            cells.append("refused (beyond the limit)" if math.isinf(e) else f"{100 * e:.2g} %")
        hover_rows.append(f"| {f:g} Hz | " + " | ".join(cells) + " |")
    hover_head = "| f \\ dt | " + " | ".join(f"1/{round(1 / dt)} s" for dt in HOVER_DTS) + " |"
    thresholds = ", ".join(f"{m} {t:g} {u}" for m, (t, u) in THRESHOLDS.items())
    combo_text = "; ".join(f"`{c.name}`" for c in COMBOS)
    miss_lines = misses(runs)
    return f"""## The settings guide (`python -m tools guide`)

Four game-felt scenarios, each a shipped level run with the real controller (module
`tools.guide`): **platform** (moving_platform: drift relative to the platform, cm,
and *shake*, the RMS rate at which the perceived up turns once settled, °/s: nothing turns there,
so all of it is the filter's jitter, which the lag measures below cannot see),
**ring** (spinning_ring: RMS angle between the perceived up and the exact one once settled, °),
**room** (rotating_room: largest angle between perceived gravity and the field while it turns, °),
**landing** (rest, the player dropped {DROP:g} m with {RUN_SPEED:g} m/s sideways: largest tilt
after touchdown, °, and deepest overlap with the ground, mm). Fifteen knobs, each moved one at a
time from the defaults, and {len(COMBOS)} combinations of knobs that trade one measure for another
({len(runs)} runs, {seconds:.0f} s on this machine):

| knob | what | values tried (default first) | unit |
|---|---|---|---|
{knob_lines}

Combinations: {combo_text}.

### Where the defaults miss

{chr(10).join(miss_lines) if miss_lines else "Nowhere: the defaults meet every threshold."}

Cost: all the runs of a scenario advance in lockstep, {BLOCK:g} s of simulated time at a time,
each block timed, so a busy spell of the machine hits every setting alike; the table gives the
median µs per step over those blocks with the 10th and 90th percentiles, each block paired with
the defaults' block of the same round (the spread is what is left of the machine's noise), and
the share of a 60 Hz frame the physics takes (µs per step ×
steps per frame / 16.7 ms). Thresholds (what a player notices): {thresholds}.

![each scenario's measure against its cost, fronts marked; the worst case](img/guide.png)

{table(header, body)}

### Fronts

For each measure, the settings no other beats on both the measure and the cost (cheapest first;
costs within {100 * COST_TIE:.0f} % count as equal, the timing noise on this shared machine):

{chr(10).join(fronts)}

**Worst case** (each setting's largest measure over its threshold, across every scenario, against
its mean frame share): {worst_items}.

### Hover frequency against dt

RMS height error over 1 s of the critically damped hover released 5 mm low, against the
continuous oscillator, as a share of the drop. The error is first order in dt and grows with f:
keep 2πf·dt small (≈ 0.26 at the default 5 Hz, 1/120 s); the controller refuses a frequency at or
beyond its stability limit.

{hover_head}
|---|{"---|" * len(HOVER_DTS)}
{chr(10).join(hover_rows)}
"""


def guide_figure(runs: Sequence[Run], path: Path) -> None:
    """Each scenario's measures against the frame share, fronts marked; and the worst case."""
    plt = pyplot()
    panels = [(n, m) for n, (_, _, ms) in SCENARIOS.items() for m in ms]
    fig, axes = plt.subplots(2, 4, figsize=(19, 8.5))
    flat = list(axes.flat)
    for ax, (name, m) in zip(flat, panels, strict=False):
        rs = [r for r in runs if r.scenario == name]
        if not rs:
            ax.axis("off")  # this scenario was not run
            continue
        x = [100 * r.frame_share for r in rs]
        y = [r.measures[m] for r in rs]
        lo = [100 * r.frame_share * r.cost_lo / r.cost_us for r in rs]
        hi = [100 * r.frame_share * r.cost_hi / r.cost_us for r in rs]
        ax.errorbar(
            x, y, xerr=np.maximum(0.0, [np.subtract(x, lo), np.subtract(hi, x)]), fmt="o",
            ms=4, alpha=0.5,
            elinewidth=0.6, label="settings (cost p10–p90)",
        )  # fmt: skip
        idx = front(list(zip(x, y, strict=True)))
        ax.plot([x[i] for i in idx], [y[i] for i in idx], "k-o", ms=5, label="front")
        ax.set_ylim(bottom=0.0)
        for i in idx:
            ax.annotate(rs[i].label, (x[i], y[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7)  # fmt: skip
        ax.axhline(THRESHOLDS[m][0], color="C3", ls="--", lw=1, label="what a player notices")
        ax.set(xscale="log", xlabel="% of a 60 Hz frame", ylabel=f"{m} ({THRESHOLDS[m][1]})",
               title=f"{name}: {m}")  # fmt: skip
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    ax = flat[len(panels)]
    wc = worst_case(runs)
    if wc:
        x = [100 * s for _, s, _ in wc]
        y = [w for _, _, w in wc]
        ax.plot(x, y, "o", ms=4, alpha=0.5)
        idx = front(list(zip(x, y, strict=True)))
        ax.plot([x[i] for i in idx], [y[i] for i in idx], "k-o", ms=5)
        for i in idx:
            ax.annotate(wc[i][0], (x[i], y[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7)  # fmt: skip
        ax.axhline(1.0, color="C3", ls="--", lw=1)
        ax.set(xscale="log", xlabel="mean % of a 60 Hz frame", ylabel="worst measure / threshold",
               title="worst case over every scenario")  # fmt: skip
        ax.grid(True, alpha=0.3)
    else:
        ax.axis("off")  # not every scenario was run: no worst case
    for ax in flat[len(panels) + 1 :]:
        ax.axis("off")
    save(fig, path, dpi=100)
