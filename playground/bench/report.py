"""Tables and figures of the benchmarks: Markdown, CSV, JSON and matplotlib figures.

The accuracy report summarises the sweep one knob at a time, computes where each knob stops
paying (:class:`Findings`), marks the Pareto front of error against cost, and renders
docs/accuracy.md. matplotlib is imported only when a figure is drawn.

>>> r = Result("rest", 0.01, 1, 10, "reverse", "none", 0.0, 0.0, 0.0, 5.0, 4.0, 1.25)
>>> to_csv([r]).splitlines()[1]
'rest,0.01,1,10,reverse,none,0.0,0.0,0.0,5.0,4.0,1.25'
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import math
import statistics
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path

from playground.bench.accuracy import DTS, FILTERS, ITERATIONS, SUBSTEPS, Result
from playground.bench.guide import Run, advice, guide_figure, guide_markdown
from playground.bench.overhead import (
    NO_EFFECT_BUDGET,
    OverheadRow,
    overhead_figure,
    overhead_markdown,
)
from playground.bench.scenes import SCENES, Knobs

__all__ = [
    "Findings",
    "accuracy_doc",
    "accuracy_figure",
    "accuracy_markdown",
    "findings",
    "pareto",
    "to_csv",
    "to_json",
]

ONE_PERCENT = 0.01
"""The error a reader calls "accurate": 1 % of the scene's force scale."""

STOPS_PAYING = 0.1
"""A knob stops paying once more of it lowers the error by less than 10 % (relative)."""

BASE = Knobs()


def to_csv(rows: Iterable[object]) -> str:
    """Rows of dataclasses as CSV text, a header first."""
    rows = list(rows)
    if not rows:
        return ""
    out = io.StringIO()
    names = [f.name for f in fields(rows[0])]  # type: ignore[arg-type]
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(names)
    for r in rows:
        writer.writerow([getattr(r, n) for n in names])
    return out.getvalue()


def to_json(rows: Iterable[object]) -> str:
    """Rows of dataclasses as a JSON list of objects (NaN written as null)."""

    def clean(v: object) -> object:
        return None if isinstance(v, float) and not math.isfinite(v) else v

    data = [{k: clean(v) for k, v in asdict(r).items()} for r in rows]  # type: ignore[call-overload]
    return json.dumps(data, indent=1, ensure_ascii=False)


def _knobs(r: Result) -> Knobs:
    return Knobs(dt=r.dt, substeps=r.substeps, iterations=r.iterations)


def _pick(
    rows: Sequence[Result], knobs: Knobs, estimator: str = "reverse", filt: str = "none"
) -> dict[str, Result]:
    """The rows at ``knobs`` for one estimator and filter, by scene."""
    return {
        r.scene: r
        for r in rows
        if _knobs(r) == knobs and r.estimator == estimator and r.filter == filt
    }


def _pct(v: float) -> str:
    if not math.isfinite(v):
        return "–"
    p = 100.0 * v
    if p == 0.0:
        return "0"
    return f"{p:.2g} %" if p < 10 else f"{p:.0f} %"


def _dt_label(dt: float) -> str:
    return f"1/{round(1.0 / dt)}"


def _table(header: Sequence[str], body: Sequence[Sequence[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in body]
    return "\n".join(lines)


def _knob_table(rows: Sequence[Result], columns: Sequence[tuple[str, Knobs]]) -> str | None:
    picks = [(label, _pick(rows, k)) for label, k in columns]
    picks = [(label, p) for label, p in picks if p]
    if len(picks) < 2:
        return None
    body = []
    books = set(bookkeeping(rows))
    for scene in SCENES:
        label = f"{scene} (bookkeeping)" if scene in books else scene
        body.append([label, *(_pct(p[scene].error) if scene in p else "–" for _, p in picks)])
    body.append(
        [
            "cost, µs/step",
            *(f"{statistics.median(r.cost_us for r in p.values()):.0f}" for _, p in picks),
        ]
    )
    body.append(
        [
            "× bare pymunk",
            *(f"{statistics.median(r.ratio for r in p.values()):.0f}" for _, p in picks),
        ]
    )
    return _table(["scene", *(label for label, _ in picks)], body)


def _estimator_table(rows: Sequence[Result]) -> str | None:
    by = {e: _pick(rows, BASE, e) for e in ("reverse", "contact", "finite-difference")}
    by = {e: p for e, p in by.items() if p}
    if len(by) < 2:
        return None
    body = [[s, *(_pct(p[s].error) if s in p else "–" for p in by.values())] for s in SCENES]
    body.append(
        [
            "cost, µs/step",
            *(f"{statistics.median(r.cost_us for r in p.values()):.0f}" for p in by.values()),
        ]
    )
    return _table(["scene", *by], body)


def _filter_table(rows: Sequence[Result]) -> str | None:
    body = []
    for name in FILTERS:
        p = _pick(rows, BASE, "reverse", name)
        if not p:
            continue
        errors = [r.error for r in p.values()]
        any_row = next(iter(p.values()))
        filter_us = any_row.cost_us - _pick(rows, BASE)[any_row.scene].cost_us
        body.append(
            [
                name,
                _pct(statistics.median(errors)),
                _pct(p["hover"].error) if "hover" in p else "–",
                _pct(p["stack"].jitter) if "stack" in p else "–",
                _pct(p["ring"].jitter) if "ring" in p else "–",
                f"{1000 * any_row.lag:.0f}",
                f"{filter_us:.0f}",
            ]
        )
    if not body:
        return None
    header = [
        "filter",
        "median error",
        "hover error",
        "stack jitter",
        "ring jitter",
        "ramp lag, ms",
        "filter µs/step",
    ]
    return _table(header, body)


def accuracy_markdown(rows: Sequence[Result]) -> str:
    """The sweep summarised one knob at a time (reverse integration, no filter, unless noted)."""
    parts = []
    sections = [
        (
            "Error against dt (1 substep, 10 iterations)",
            _knob_table(rows, [(_dt_label(dt), Knobs(dt=dt)) for dt in DTS]),
        ),
        (
            "Error against solver iterations (dt = 1/120 s)",
            _knob_table(rows, [(str(i), Knobs(iterations=i)) for i in ITERATIONS]),
        ),
        (
            "Substeps at dt = 1/30 s, against dt = 1/120 s",
            _knob_table(
                rows,
                [
                    ("1/30 × 1", Knobs(dt=1 / 30)),
                    *((f"1/30 × {n}", Knobs(dt=1 / 30, substeps=n)) for n in SUBSTEPS),
                    ("1/120 × 1", BASE),
                ],
            ),
        ),
        ("Force estimators (dt = 1/120 s, 10 iterations, no filter)", _estimator_table(rows)),
        ("Filters (dt = 1/120 s, 10 iterations, reverse integration)", _filter_table(rows)),
    ]
    for title, table in sections:
        if table is not None:
            parts.append(f"### {title}\n\n{table}\n")
    return "\n".join(parts)


@dataclass(frozen=True, slots=True)
class Findings:
    """Where each knob stops paying, read off the sweep (NaN or 0 where not measured).

    Attributes:
        stack_iterations: iterations past which the stack's error falls by less than 10 %.
        stack_iterations_1pct: fewest iterations with the stack's error under 1 %.
        stack_errors: (iterations, error) of the stack at each swept iteration count.
        hover_dt: largest dt (s) with the hover oscillation's error under 1 %.
        hover_errors: (dt in s, error) of the hover at each swept dt.
        dt_1pct: per scene, the largest dt (s) with error under 1 % (NaN: none).
        substep_hover: hover error at dt 1/30 with 4 substeps, and at dt 1/120 with 1.
        substep_cost: cost of the same two, ms of computing per simulated second.
        fd_over_reverse: median over scenes of finite-difference error / reverse error.
        reverse_us, bare_us: median cost per step at the base knobs, µs.
        plateau: per scene, the iteration count past which its error falls by less than 10 %.
        hover_dt_interpolated: dt (s) where the hover error crosses 1 %, interpolated on the
            log-log line between the swept steps that bracket it.
        stack_iterations_01pct: fewest iterations with the stack's error under 0.1 %.
    """

    stack_iterations: int
    stack_iterations_1pct: int
    stack_errors: tuple[tuple[int, float], ...]
    hover_dt: float
    hover_errors: tuple[tuple[float, float], ...]
    dt_1pct: dict[str, float]
    substep_hover: tuple[float, float]
    substep_cost: tuple[float, float]
    fd_over_reverse: float
    reverse_us: float
    bare_us: float
    plateau: dict[str, int] = field(default_factory=dict)
    hover_dt_interpolated: float = math.nan
    stack_iterations_01pct: int = 0


ROUND_OFF = 1e-6
"""Relative errors below this are round-off: a knob that only moves them has stopped paying."""


def _stops_paying(values: Sequence[float]) -> int:
    """Index of the first value within :data:`STOPS_PAYING` of the best at or after it (or
    below :data:`ROUND_OFF`).

    >>> _stops_paying([0.3, 0.1, 0.095, 0.094]), _stops_paying([1e-3, 1e-9, 1e-15])
    (1, 1)
    """
    for i, v in enumerate(values):
        if v <= min(values[i:]) * (1.0 + STOPS_PAYING) or v < ROUND_OFF:
            return i
    return len(values) - 1


def findings(rows: Sequence[Result]) -> Findings:
    """Read the thresholds of :class:`Findings` off the sweep's rows."""
    its = [(i, _pick(rows, Knobs(iterations=i)).get("stack")) for i in ITERATIONS]
    its_ok = [(i, r.error) for i, r in its if r is not None]
    stack_iterations = its_ok[_stops_paying([e for _, e in its_ok])][0] if its_ok else 0
    stack_1pct = next((i for i, e in its_ok if e < ONE_PERCENT), 0)
    dts = sorted((dt for dt in DTS if _pick(rows, Knobs(dt=dt))), reverse=True)
    dt_1pct = {}
    for scene in SCENES:
        errors = [(dt, _pick(rows, Knobs(dt=dt)).get(scene)) for dt in dts]
        swept = [(dt, r.error) for dt, r in errors if r is not None]
        if not swept:
            continue
        # The largest dt from which every smaller dt is also under 1 %.
        good = math.nan
        for dt, error in reversed(swept):
            if error >= ONE_PERCENT:
                break
            good = dt
        dt_1pct[scene] = good
    hover = [
        (dt, r.error) for dt in dts if (r := _pick(rows, Knobs(dt=dt)).get("hover")) is not None
    ]
    sub = _pick(rows, Knobs(dt=1 / 30, substeps=4)).get("hover")
    base = _pick(rows, BASE)
    fd = _pick(rows, BASE, "finite-difference")
    ratios = [
        fd[s].error / base[s].error
        for s in fd
        if s in base and base[s].error > 0 and s != "landing"
    ]
    plateau = {}
    for scene in SCENES:
        swept = [
            (i, r.error) for i in ITERATIONS if (r := _pick(rows, Knobs(iterations=i)).get(scene))
        ]
        if swept:
            plateau[scene] = int(swept[_stops_paying([e for _, e in swept])][0])
    crossing = math.nan
    for (dt0, e0), (dt1, e1) in itertools.pairwise(hover):
        if e0 >= ONE_PERCENT > e1 and e0 > 0 and e1 > 0:
            t = math.log(e0 / ONE_PERCENT) / math.log(e0 / e1)
            crossing = math.exp(math.log(dt0) + t * (math.log(dt1) - math.log(dt0)))
    return Findings(
        plateau=plateau,
        hover_dt_interpolated=crossing,
        stack_iterations_01pct=next((i for i, e in its_ok if e < ONE_PERCENT / 10), 0),
        stack_iterations=stack_iterations,
        stack_iterations_1pct=stack_1pct,
        stack_errors=tuple(its_ok),
        hover_dt=dt_1pct.get("hover", math.nan),
        hover_errors=tuple(hover),
        dt_1pct=dt_1pct,
        substep_hover=(
            sub.error if sub else math.nan,
            base["hover"].error if "hover" in base else math.nan,
        ),
        substep_cost=(
            sub.cost_us / sub.dt / 1000.0 if sub else math.nan,
            base["hover"].cost_us / base["hover"].dt / 1000.0 if "hover" in base else math.nan,
        ),
        fd_over_reverse=statistics.median(ratios) if ratios else math.nan,
        reverse_us=statistics.median(r.cost_us for r in base.values()) if base else math.nan,
        bare_us=statistics.median(r.bare_us for r in base.values()) if base else math.nan,
    )


@dataclass(frozen=True, slots=True)
class Config:
    """One configuration across scenes: its mean error and its mean cost in ms of computing per
    simulated second (µs per step / dt: a smaller dt takes more steps), for the front."""

    label: str
    estimator: str
    error: float
    cost_ms: float


BOOKKEEPING_ERROR = ONE_PERCENT / 10
"""A scene whose median unfiltered reverse-integration error over the swept settings is below this
(a tenth of what a reader calls accurate) reads a constant force back almost exactly at any
setting: it checks the bookkeeping, and cannot rank settings."""


def bookkeeping(rows: Sequence[Result]) -> list[str]:
    """Scenes whose reading is a bookkeeping identity (see :data:`BOOKKEEPING_ERROR`).

    >>> r = Result("rest", 0.01, 1, 10, "reverse", "none", 1e-12, 0.0, 0.0, 5.0, 4.0, 1.25)
    >>> bookkeeping([r])
    ['rest']
    """
    out = []
    for scene in SCENES:
        errs = [
            r.error
            for r in rows
            if r.scene == scene and r.estimator == "reverse" and r.filter == "none"
        ]
        if errs and statistics.median(errs) < BOOKKEEPING_ERROR:
            out.append(scene)
    return out


def configurations(rows: Sequence[Result]) -> list[Config]:
    """Mean error and mean cost of each (knobs, estimator, filter) over the scenes it ran,
    bookkeeping scenes left out (they are ~0 for every setting and would only dilute the mean)."""
    groups: dict[tuple[Knobs, str, str], list[Result]] = {}
    skip = set(bookkeeping(rows))
    for r in rows:
        if r.scene in skip:
            continue
        groups.setdefault((_knobs(r), r.estimator, r.filter), []).append(r)
    out = []
    for (k, est, filt), rs in groups.items():
        label = f"dt {_dt_label(k.dt)}×{k.substeps}, {k.iterations} it, {est}, {filt}"
        out.append(
            Config(
                label,
                est,
                statistics.fmean(r.error for r in rs),
                statistics.fmean(r.cost_us / r.dt / 1000.0 for r in rs),
            )
        )
    return out


def pareto(points: Sequence[tuple[float, float]]) -> list[int]:
    """Indices of the (cost, error) points no other point beats on both, by rising cost.

    >>> pareto([(1.0, 5.0), (2.0, 3.0), (3.0, 4.0), (4.0, 1.0)])
    [0, 1, 3]
    """
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def accuracy_figure(rows: Sequence[Result], path: Path) -> list[Config]:
    """Draw error against cost with the Pareto front marked (and, beside it, error against dt
    and iterations) into ``path`` (PNG). Returns the configurations on the front.

    Needs matplotlib (``pip install 'pymunk-playground[bench]'``).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    configs = configurations(rows)
    front = pareto([(c.cost_ms, c.error) for c in configs])
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    ax = axes[0]
    colours = {"reverse": "tab:blue", "contact": "tab:orange", "finite-difference": "tab:green"}
    for est, colour in colours.items():
        pts = [c for c in configs if c.estimator == est]
        ax.scatter(
            [c.cost_ms for c in pts], [c.error for c in pts], s=12, alpha=0.6, c=colour, label=est
        )
    ax.plot(
        [configs[i].cost_ms for i in front],
        [configs[i].error for i in front],
        "k-o",
        ms=4,
        lw=1.5,
        label="Pareto front",
    )
    ax.set(
        xscale="log",
        yscale="log",
        xlabel="cost, ms of computing per simulated second",
        ylabel="mean relative error over the force scenes",
        title="Accuracy against cost",
    )
    ax.legend(fontsize=8)
    for ax, label, knob_list, values in (
        (axes[1], "dt, s", [Knobs(dt=dt) for dt in DTS], DTS),
        (axes[2], "solver iterations", [Knobs(iterations=i) for i in ITERATIONS], ITERATIONS),
    ):
        for scene in SCENES:
            xs, ys = [], []
            for v, k in zip(values, knob_list, strict=True):
                r = _pick(rows, k).get(scene)
                if r is not None and r.error > 0:
                    xs.append(v)
                    ys.append(r.error)
            if xs:
                ax.plot(xs, ys, "-o", ms=3, label=scene)
        ax.axhline(ONE_PERCENT, color="grey", ls="--", lw=0.8)
        ax.set(
            xscale="log",
            yscale="log",
            xlabel=label,
            ylabel="relative error (reverse, no filter)",
            title=f"Error against {label.split(',')[0]}",
        )
        # Label the swept values themselves (1/30 … 1/480 s; 1 … 40): log ticks collide here.
        ax.set_xticks(list(values), [f"1/{round(1 / v)}" if v < 1 else f"{v:g}" for v in values])
        ax.minorticks_off()
        ax.legend(fontsize=7)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [configs[i] for i in front]


COMMAND = "playground bench docs"
"""The one command that regenerates docs/accuracy.md, its CSV and JSON files and figures."""


def _dt_text(dt: float) -> str:
    return "none of the swept steps" if not math.isfinite(dt) else f"{_dt_label(dt)} s"


def _estimator_text(rows: Sequence[Result], f: Findings) -> str:
    rev, con = _pick(rows, BASE), _pick(rows, BASE, "contact")
    shared = [sc for sc in con if sc in rev and rev[sc].error > 0]
    worst = max((abs(con[sc].error - rev[sc].error) for sc in shared), default=math.nan)
    return (
        f"Reverse integration and the arbiter-impulse sum agree on the contact scenes of this "
        f"sweep (largest difference in relative error {worst:.1g}). They agree because the world "
        f"drops an arbiter as soon as its contact ends: with pymunk's default persistence, a "
        f"contact made again from a cached arbiter reports an impulse that was never applied, and "
        f"the contact split marks such steps unknown rather than trust it. The arbiter sum cannot "
        f"see a joint, so it is not run on the grip. Finite differences of positions are a median "
        f"{f.fd_over_reverse:.1f}× less accurate than reverse integration on the scenes where "
        f"either errs, for the same cost: not because they measure worse, but because they are "
        f"centred on their middle sample, the start of the step, half a step before the mid-step "
        f"this page compares with (chapter 7 shows that against their own mid-point they are as "
        f"accurate)."
    )


def _filter_text(rows: Sequence[Result]) -> str:
    none = _pick(rows, BASE)
    if "stack" not in none or "hover" not in none:
        return ""
    options = [(name, _pick(rows, BASE, "reverse", name)) for name in FILTERS if name != "none"]
    options = [(n, p) for n, p in options if "stack" in p and "hover" in p]
    if not options:
        return ""
    calm_name, calm = min(options, key=lambda o: o[1]["stack"].jitter)
    quick_name, quick = min(options, key=lambda o: o[1]["hover"].error)
    return (
        f"Where the raw reading is noisy (the stack) the steadiest, {calm_name}, takes the jitter "
        f"from {_pct(none['stack'].jitter)} to {_pct(calm['stack'].jitter)}, but lags a ramp by "
        f"{1000 * calm['stack'].lag:.0f} ms and lifts the hover's error from "
        f"{_pct(none['hover'].error)} to {_pct(calm['hover'].error)}. The quickest, {quick_name} "
        f"({1000 * quick['hover'].lag:.0f} ms), keeps the hover at "
        f"{_pct(quick['hover'].error)} and the stack's jitter at {_pct(quick['stack'].jitter)}. "
        f"On static scenes reverse integration has no jitter to remove: a filter pays only where "
        f"something downstream needs a steady signal (perceived gravity), never for accuracy."
    )


def scene_fronts(rows: Sequence[Result]) -> dict[str, list[Result]]:
    """Per scene that is not bookkeeping: its rows no other row of the scene beats on both error
    and cost per simulated second, cheapest first."""
    out = {}
    skip = set(bookkeeping(rows))
    for scene in SCENES:
        rs = [r for r in rows if r.scene == scene]
        if scene in skip or not rs:
            continue
        idx = pareto([(r.cost_us / r.dt / 1000.0, r.error) for r in rs])
        out[scene] = [rs[i] for i in idx]
    return out


def _row_label(r: Result) -> str:
    return f"dt {_dt_label(r.dt)}×{r.substeps}, {r.iterations} it, {r.estimator}, {r.filter}"


def accuracy_doc(
    rows: Sequence[Result],
    front: Sequence[Config],
    seconds: float,
    guide: str = "",
    advice: Sequence[tuple[str, str]] = (),
) -> str:
    """docs/accuracy.md: the "if you want" table, the settings guide (when given), definitions,
    where each knob stops paying, the tables, the figure."""
    f = findings(rows)
    books = bookkeeping(rows)
    fronts = "\n".join(
        f"- **{sc}**: "
        + ", ".join(
            f"{_row_label(r)} ({_pct(r.error)}, {r.cost_us / r.dt / 1000:.0f} ms/s)" for r in rs[:6]
        )
        + (f" … ({len(rs)} in all)" if len(rs) > 6 else "")
        for sc, rs in scene_fronts(rows).items()
    )
    want = [
        *advice,
        (
            "a heavy stack read within 1 % (four 200 kg crates on the player)",
            f"iterations ≥ {f.stack_iterations_1pct} ({f.stack_iterations_01pct} for 0.1 %)",
        ),
        (
            "the hover's support force within 1 % of the exact oscillator",
            f"dt ≤ {_dt_text(f.hover_dt)}"
            + (
                " (substeps do worse at the same inner step: the controller acts once per step)"
                if f.substep_hover[0] > f.substep_hover[1]
                else ""
            ),
        ),
    ]
    want_table = "\n".join(f"| {x} | {y} |" for x, y in want)
    per_scene = ", ".join(f"{s} {_dt_text(dt)}" for s, dt in f.dt_1pct.items())
    stack = ", ".join(f"{i}: {_pct(e)}" for i, e in f.stack_errors)
    hover = ", ".join(f"{_dt_label(dt)}: {_pct(e)}" for dt, e in f.hover_errors)
    stack_plateau = (
        f"it still falls at {f.stack_errors[-1][0]} iterations (no plateau in the sweep)"
        if f.stack_errors and f.stack_iterations == f.stack_errors[-1][0]
        else f"past {f.stack_iterations} iterations another step lowers it by less than 10 %"
    )
    plateaus = ", ".join(f"{sc} {n}" for sc, n in f.plateau.items() if sc != "stack")
    if f.substep_hover[0] > f.substep_hover[1]:
        substep_verdict = (
            "Substeps refine the contacts, but the controller (and every hook) still acts once "
            "per frame, so at the same inner step a smaller dt is the more accurate of the two."
        )
    else:
        substep_verdict = "At the same inner step, substeps are as accurate as a smaller dt."
    estimators = _estimator_text(rows, f)
    filters = _filter_text(rows)
    front_lines = "\n".join(f"| {c.label} | {_pct(c.error)} | {c.cost_ms:.0f} |" for c in front)
    return f"""# What accuracy costs

Generated by `{COMMAND}` ({len(rows)} rows, {seconds:.0f} s on this machine, plus the settings
guide); the full table is [accuracy.csv](accuracy.csv) and [accuracy.json](accuracy.json). Rerun
it to refresh every number on this page and the figures.

## If you want X, set Y

Read off the runs below (one knob moved at a time from the defaults; costs on this machine):

| if you want | set |
|---|---|
{want_table}

{guide}
## Force readings against exact answers

![error against cost, Pareto front; error against dt and iterations](img/accuracy.png)

**Bookkeeping scenes**: {", ".join(books) or "none"}. Each reads a constant force back almost
exactly at any setting (median error under {_pct(BOOKKEEPING_ERROR)}), so they check the
bookkeeping but cannot rank settings: they stay in the tables, marked "(bookkeeping)", and out of
every front and mean below.

### Per-scene fronts (cheapest first; error, ms of computing per simulated second)

{fronts}

## Where each knob stops paying

- **Solver iterations.** The stack (four 200 kg crates on a 70 kg player, dt = 1/120 s) is the
  scene that needs them: its ground-contact error by iterations is {stack}. It is under 1 % from
  **{f.stack_iterations_1pct} iterations** and under 0.1 % from **{f.stack_iterations_01pct}**;
  {stack_plateau}. The other scenes stop paying much earlier (iterations past which the error
  falls by less than 10 %): {plateaus}.
- **dt.** The hover spring's (2 Hz, ζ = 0.3) support-force error by dt is {hover}: first order,
  it halves with dt. It is under 1 % for **dt ≤ {_dt_text(f.hover_dt)}** of the swept steps
  (the 1 % crossing, interpolated: dt ≈ {_dt_text(f.hover_dt_interpolated)}). Per scene, the
  largest swept dt with error under 1 % (and every smaller one too): {per_scene}.
- **Substeps.** At dt = 1/30 s with 4 substeps the hover error is {_pct(f.substep_hover[0])}
  for {f.substep_cost[0]:.0f} ms of computing per simulated second; a plain dt = 1/120 s gives
  {_pct(f.substep_hover[1])} for {f.substep_cost[1]:.0f} ms. {substep_verdict}
- **Force estimator.** {estimators}
- **Filters** trade jitter for lag (table below). {filters}
- **Cost.** At the base knobs the world with one tracked body costs a median
  {f.reverse_us:.0f} µs per step against {f.bare_us:.1f} µs for bare pymunk stepping a copy of
  the same space: with a body or two, the price of a reading is the solver's fixed numpy cost per
  step, not the bodies (see the overhead section for how it grows). Costs were measured with
  other work running on the machine; the ratio to bare pymunk, timed in interleaved blocks, is
  the number to compare across runs.

## Definitions

- **error**: RMS over the measured window of |F̂ − F*| / scale, with F̂ the (filtered) support force
  reading and F* the exact one (scale: the scene's force, e.g. m·g at rest, k·x₀ for the hover).
  A reading is the mean force over a step, so every scene takes F* at the middle of the step
  (chapter 7: against the end of the step a force turning at ω shows an error of ω·dt/2).
  For the landing: |Σ F̂·dt − m·g·T| / (m·√(2gh)), the impulse error over the window T.
- **jitter** (Casiez et al. 2012): standard deviation of the residual F̂ − F* over the window,
  / scale; on a static scene, the spread of the filtered signal at rest.
- **lag** (same paper): the delay with which the filter follows a ramp of 9.81 m/s² per second
  of specific force, read after one second of ramp: (x − x̂)/slope, s.
- **cost**: µs per step of `world.step()` plus taking the reading, median over blocks of 50
  steps, plus the filter's µs per call; **× bare pymunk**: divided by a copy of the same space
  stepped by `space.step` alone, timed in blocks interleaved with the world's in the same process.

The sweep is one knob at a time around dt = 1/120 s, 1 substep, 10 iterations; each point is
simulated once and every filter runs over its recorded signal. Points run on any
`concurrent.futures.Executor` (processes by default), so a Dask cluster runs a large sweep
unchanged: `sweep(plan(), executor=distributed.Client(...).get_executor())`.

## Pareto front (mean over the scenes that are not bookkeeping)

| configuration | mean error | ms per simulated s |
|---|---|---|
{front_lines}

## Tables

{accuracy_markdown(rows)}"""


def overhead_doc(
    rows: Sequence[OverheadRow], seconds: float, fixed: tuple[float, float] = (math.nan, math.nan)
) -> str:
    """The overhead section of docs/accuracy.md: the no-effect check and each effect's cost."""
    none = sorted((r for r in rows if r.effect == "none"), key=lambda r: r.bodies)
    within = [r.bodies for r in none if r.ratio <= NO_EFFECT_BUDGET]
    ratios = ", ".join(f"{r.bodies}: ×{r.ratio:.2f} (best ×{r.best_ratio:.2f})" for r in none)
    above = [r.bodies for r in none if r.ratio > NO_EFFECT_BUDGET]
    verdict = (
        f"within {NO_EFFECT_BUDGET}× at {', '.join(map(str, within)) or 'no size'} bodies, "
        f"above it at {', '.join(map(str, above)) or 'no size'}"
    )
    return f"""
## What each effect costs (`playground.bench overhead`)

A pile of 1 kg boxes resting on a floor, in a `World` with one effect switched on and in a bare
`pymunk.Space` with the same bodies in the same order, stepped in interleaved blocks in the same
process ({seconds:.0f} s on this machine; rows in [accuracy_overhead.csv](accuracy_overhead.csv)).

**No effect against bare pymunk** (median of paired-block ratios, and fastest world block /
fastest bare block, by bodies): {ratios} — {verdict}.

Why: with nothing but a floor, a world step costs {fixed[0]:.1f} µs against {fixed[1]:.1f} µs
for `space.step`, a fixed {fixed[0] - fixed[1]:.1f} µs of Python per step whatever the body count.
`World.step` keeps a plan of the stages the scene needs, rebuilt only when the scene changes (a
hook, an event, a mover, a tracked body, a gravity rule, a force in the ledger); a scene that
calls for no effect runs `space.step` and advances time, nothing else. With uniform gravity and
nothing tracked it adds nothing per body, so the ratio can only fall as pymunk's own cost grows.
The rows are medians of interleaved blocks on a shared machine: read ratios within ±10 % as noise.

![marginal cost of each effect against bodies; the no-effect ratio](img/accuracy_overhead.png)

{overhead_markdown(rows)}"""


def write_docs(
    rows: Sequence[Result],
    over: Sequence[OverheadRow],
    out: Path,
    *,
    seconds: tuple[float, float],
    fixed: tuple[float, float] = (math.nan, math.nan),
    guide: tuple[Sequence[Run], dict[tuple[float, float], float], float] | None = None,
) -> list[Path]:
    """Write accuracy.md with its CSV and JSON files and figures under ``out`` (img/ beside).

    ``seconds``: wall time of the sweep and of the overhead profile, quoted in the page;
    ``fixed``: :func:`~playground.bench.overhead.fixed_cost`; ``guide``: the settings guide's
    runs, its hover table and its wall time (:mod:`playground.bench.guide`), if it was run.
    """
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name, data in (("accuracy", rows), ("accuracy_overhead", over)):
        (out / f"{name}.csv").write_text(to_csv(data), encoding="utf-8")
        (out / f"{name}.json").write_text(to_json(data), encoding="utf-8")
        written += [out / f"{name}.csv", out / f"{name}.json"]
    front = accuracy_figure(rows, out / "img" / "accuracy.png")
    overhead_figure(over, out / "img" / "accuracy_overhead.png")
    written += [out / "img" / "accuracy.png", out / "img" / "accuracy_overhead.png"]
    section, wants = "", []
    if guide is not None:
        runs, hover, guide_seconds = guide
        guide_figure(runs, out / "img" / "guide.png")
        (out / "accuracy_guide.json").write_text(to_json(runs), encoding="utf-8")
        written += [out / "img" / "guide.png", out / "accuracy_guide.json"]
        section = guide_markdown(runs, hover, guide_seconds)
        wants = advice(runs)
    text = accuracy_doc(rows, front, seconds[0], section, wants) + overhead_doc(
        over, seconds[1], fixed
    )
    (out / "accuracy.md").write_text(text, encoding="utf-8")
    written.append(out / "accuracy.md")
    return written
