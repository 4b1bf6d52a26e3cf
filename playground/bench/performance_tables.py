"""The tables of one performance run (:class:`~playground.bench.measurement.Measurement`) in
Markdown: every shipped level against its engine, the pile, where the scalar implementation
of the tracked bodies stops paying, and crowds of actors; ``playground bench overhead`` prints
them.
"""

from __future__ import annotations

from collections.abc import Sequence

from playground.bench.markdown import table
from playground.bench.measurement import STAGES, CrowdRow, LevelRow, Measurement, PileRow
from playground.forces.scalar import SCALAR_MAX_BODIES

__all__ = [
    "crossover_markdown",
    "crowds_markdown",
    "levels_markdown",
    "piles_markdown",
    "summary_markdown",
]


def levels_markdown(levels: Sequence[LevelRow]) -> str:
    """One row per level: step, engine, ratio, real-time factor and the stages."""
    names = [s.name.lower() for s in STAGES]
    used = [s for s in names if any(s in r.stages for r in levels)]
    rows = [
        [
            r.level,
            str(r.players),
            "scalar" if r.scalar else "vector",
            f"{r.level_us:.0f}",
            f"{r.engine_us:.1f}",
            f"{r.ratio:.0f}× ({r.ratio_lo:.0f}–{r.ratio_hi:.0f})",
            f"{r.realtime:.0f}×",
            *(f"{r.stages[s]:.1f}" if s in r.stages else "" for s in used),
        ]
        for r in levels
    ]
    header = ["level", "players", "path", "step µs", "engine µs", "× engine (blocks)",
              "× real time", *(f"{s} µs" for s in used)]  # fmt: skip
    return table(header, rows)


def piles_markdown(piles: Sequence[PileRow]) -> str:
    """One row per pile measurement."""
    rows = [
        [
            r.kind,
            str(r.bodies),
            f"{r.us:.0f}",
            f"{r.base_us:.0f}",
            f"{r.ratio:.3f}× ({r.ratio_lo:.3f}–{r.ratio_hi:.3f})",
            f"{r.overhead:.3f}×",
        ]
        for r in piles
    ]
    return table(["measure", "N", "µs", "compared with, µs", "ratio (blocks)", "overhead"], rows)


def crossover_markdown(piles: Sequence[PileRow]) -> str:
    """Where the scalar implementation stops paying: the measured ratios and the crossover they
    give."""
    rows = sorted((r for r in piles if r.kind == "scalar/vector"), key=lambda r: r.bodies)
    if not rows:
        return ""
    below = [r.bodies for r in rows if r.ratio < 1.0]
    above = [r.bodies for r in rows if r.ratio >= 1.0]
    cross = (
        f"the scalar implementation is cheaper up to {max(below)} tracked bodies"
        + (f" and dearer from {min(above)}" if above else "")
        if below
        else "the scalar implementation is never cheaper"
    )
    return (
        "## Scalar or batch: where the scalar implementation stops paying\n\n"
        "With few tracked bodies the solver and the filter run in plain floats, reading each "
        "body's attributes (`playground/forces/scalar/`); with many, on numpy arrays filled by "
        "`pymunk.batch`. "
        "Both give the same readings (tests/test_solver_oracle.py compares them step by step on "
        "random scenes). Measured here on the pile with every box tracked and perceived, scalar "
        f"step / batch step: {cross}. The world switches at "
        f"`SCALAR_MAX_BODIES` = {SCALAR_MAX_BODIES} tracked bodies.\n\n"
        + table(
            ["tracked bodies", "scalar µs", "vectorised µs", "scalar / vectorised (blocks)"],
            [
                [
                    str(r.bodies),
                    f"{r.us:.0f}",
                    f"{r.base_us:.0f}",
                    f"{r.ratio:.2f}× ({r.ratio_lo:.2f}–{r.ratio_hi:.2f})",
                ]
                for r in rows
            ],
        )
        + "\n"
    )


def crowds_markdown(crowds: Sequence[CrowdRow]) -> str:
    """A crowd per row: level step, engine step, × engine, per actor, × real time (empty
    without crowds)."""
    if not crowds:
        return ""
    rows = [
        [
            str(r.actors),
            r.path,
            f"{r.level_us:.0f} µs",
            f"{r.engine_us:.1f} µs",
            f"{r.ratio:.0f}× ({r.ratio_lo:.0f}–{r.ratio_hi:.0f})",
            f"{r.per_actor_us:.1f} µs",
            f"{r.realtime:.1f}×",
        ]
        for r in sorted(crowds, key=lambda r: r.actors)
    ]
    header = ["actors", "path", "level step", "engine step", "× engine (blocks)", "per actor",
              "× real time"]  # fmt: skip
    return (
        "## Crowds: many actors on one floor\n\n"
        "N patrolling enemies (the default controller on a patrol, 2 m apart on one static "
        "floor, `playground/bench/crowd.py`): the world's step against `space.step` of a copy "
        "of its space; per actor is the level step over N. Issue 27's goals for it are with the "
        "other goals, in `tools/goals.py`.\n\n" + table(header, rows) + "\n"
    )


def summary_markdown(m: Measurement) -> str:
    """The levels, pile, crossover and crowd tables under headings."""
    piles = [r for r in m.piles if r.kind != "scalar/vector"]
    cross = crossover_markdown(m.piles)
    crowds = crowds_markdown(m.crowds)
    return (
        f"## Every shipped level\n\n{levels_markdown(m.levels)}\n\n"
        f"## The pile\n\n{piles_markdown(piles)}\n"
        + (f"\n{cross}" if cross else "")
        + (f"\n{crowds}" if crowds else "")
    )
