"""The generated accuracy page, docs/accuracy.md, and the files beside it: the "if you want"
table, the settings guide, where each knob stops paying (:mod:`tools.findings`), the
fronts, the definitions and the tables (:mod:`playground.bench.accuracy_tables`), the figure
(:mod:`playground.bench.accuracy_figure`), and the section on what each effect costs; the sweep's
rows as CSV and JSON (:mod:`playground.bench.export`). ``python -m tools docs`` writes them all.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

from playground.bench.accuracy import FILTERS, Result
from playground.bench.accuracy_figure import accuracy_figure
from playground.bench.accuracy_tables import accuracy_markdown
from playground.bench.export import to_csv, to_json
from playground.bench.markdown import dt_label, pct
from playground.bench.overhead import (
    NO_EFFECT_BUDGET,
    OverheadRow,
    overhead_figure,
    overhead_markdown,
)
from playground.bench.sweep_rows import (
    BASE,
    BOOKKEEPING_ERROR,
    Config,
    bookkeeping,
    pick,
    scene_fronts,
)
from tools.findings import Findings, findings
from tools.guide_report import advice, guide_figure, guide_markdown
from tools.guide_settings import Run

__all__ = ["COMMAND", "accuracy_doc", "overhead_doc", "write_docs"]

COMMAND = "python -m tools docs"
"""The one command that regenerates docs/accuracy.md, its CSV and JSON files and figures."""


def _dt_text(dt: float) -> str:
    return "none of the swept steps" if not math.isfinite(dt) else f"{dt_label(dt)} s"


def _estimator_text(rows: Sequence[Result], f: Findings) -> str:
    rev, con = pick(rows, BASE), pick(rows, BASE, "contact")
    shared = [sc for sc in con if sc in rev and rev[sc].error > 0]
    worst = max((abs(con[sc].error - rev[sc].error) for sc in shared), default=math.nan)
    return (
        f"Reverse integration and the arbiter-impulse sum agree on the contact scenes of this "
        f"sweep (largest difference in relative error {worst:.1g}). They agree because the world "
        f"drops an arbiter as soon as its contact ends: with pymunk's default persistence, a "
        f"contact made again from a cached arbiter reports an impulse that was never applied, and "
        f"the contact split marks such steps unknown rather than trust it. The arbiter sum cannot "
        f"see a joint, so it is not run on the grip. Finite differences of positions are centred "
        f"on their middle sample, the start of the step, so this page compares them with the "
        f"exact force there (the mean of the mid-step answers on either side), as chapter 7 "
        f"does: compared at the reverse reading's mid-step instead, half a step away, a turning "
        f"force would show that time offset as an error. So compared, their error is a median "
        f"{f.fd_over_reverse:.1f}× reverse integration's on the scenes where either errs, for "
        f"the same cost and without engine access{_fd_worse(rows)}."
    )


FD_WORSE = 1.5
"""Finite differences' error over reverse integration's above which the page names the scene."""

ROUND_OFF = 1e-9
"""A relative error below this is round-off (the rest scene's 1e-16), not worth naming."""


def _fd_worse(rows: Sequence[Result]) -> str:
    """ ", worse on the hover (1.5 % against 0.74 %)" for the scenes where finite differences err
    more than :data:`FD_WORSE` times reverse integration (or "" if none)."""
    rev, fd = pick(rows, BASE), pick(rows, BASE, "finite-difference")
    worse = [
        f"the {sc} ({pct(fd[sc].error)} against {pct(rev[sc].error)})"
        for sc in fd
        if sc in rev and fd[sc].error > max(FD_WORSE * rev[sc].error, ROUND_OFF) and sc != "landing"
    ]
    return f"; they are worse on {', '.join(worse)}" if worse else ""


def _filter_text(rows: Sequence[Result]) -> str:
    none = pick(rows, BASE)
    if "stack" not in none or "hover" not in none:
        return ""
    options = [(name, pick(rows, BASE, "reverse", name)) for name in FILTERS if name != "none"]
    options = [(n, p) for n, p in options if "stack" in p and "hover" in p]
    if not options:
        return ""
    calm_name, calm = min(options, key=lambda o: o[1]["stack"].jitter)
    quick_name, quick = min(options, key=lambda o: o[1]["hover"].error)
    return (
        f"Where the raw reading is noisy (the stack) the steadiest, {calm_name}, takes the jitter "
        f"from {pct(none['stack'].jitter)} to {pct(calm['stack'].jitter)}, but lags a ramp by "
        f"{1000 * calm['stack'].lag:.0f} ms and lifts the hover's error from "
        f"{pct(none['hover'].error)} to {pct(calm['hover'].error)}. The quickest, {quick_name} "
        f"({1000 * quick['hover'].lag:.0f} ms), keeps the hover at "
        f"{pct(quick['hover'].error)} and the stack's jitter at {pct(quick['stack'].jitter)}. "
        f"On static scenes reverse integration has no jitter to remove: a filter pays only where "
        f"something downstream needs a steady signal (perceived gravity), never for accuracy."
    )


def _row_label(r: Result) -> str:
    return f"dt {dt_label(r.dt)}×{r.substeps}, {r.iterations} it, {r.estimator}, {r.filter}"


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
            f"{_row_label(r)} ({pct(r.error)}, {r.cost_us / r.dt / 1000:.0f} ms/s)" for r in rs[:6]
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
    stack = ", ".join(f"{i}: {pct(e)}" for i, e in f.stack_errors)
    hover = ", ".join(f"{dt_label(dt)}: {pct(e)}" for dt, e in f.hover_errors)
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
    front_lines = "\n".join(f"| {c.label} | {pct(c.error)} | {c.cost_ms:.0f} |" for c in front)
    return f"""# What accuracy costs

Generated by `{COMMAND}` ({len(rows)} rows, {seconds:.0f} s on this machine, plus the settings
guide); the full table is [accuracy.csv](accuracy.csv) and [accuracy.json](accuracy.json). Rerun
it to refresh every number on this page and the figures.

## If you want X, set Y

Read off the runs below (one knob moved at a time from the defaults, and a few together; costs on
this machine; where the fix for one measure breaks another, the row says so):

| if you want | set |
|---|---|
{want_table}

{guide}
## Force readings against exact answers

![error against cost, Pareto front; error against dt and iterations](img/accuracy.png)

**Bookkeeping scenes**: {", ".join(books) or "none"}. Each reads a constant force back almost
exactly at any setting (median error under {pct(BOOKKEEPING_ERROR)}), so they check the
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
- **Substeps.** At dt = 1/30 s with 4 substeps the hover error is {pct(f.substep_hover[0])}
  for {f.substep_cost[0]:.0f} ms of computing per simulated second; a plain dt = 1/120 s gives
  {pct(f.substep_hover[1])} for {f.substep_cost[1]:.0f} ms. {substep_verdict}
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
    runs, its hover table and its wall time (:mod:`tools.guide`), if it was run.
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
