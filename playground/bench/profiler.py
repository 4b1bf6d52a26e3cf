"""Where a level's time goes: its stages (``World.timings``) and its top functions (cProfile).

``playground run LEVEL --profile`` prints both. The stage table comes from the run itself, with
stage timing on; the functions from a second run of the same level under ``cProfile``, which slows
every Python call, so its times are for ranking, not for quoting.

>>> from playground.world import World, WorldConfig
>>> world = World(WorldConfig(timing=True))
>>> _ = world.add_box("b", mass=1.0, size=(1.0, 1.0), position=(0.0, 5.0))
>>> world.track("b")
>>> world.run(0.1)
>>> print(stage_table(world).splitlines()[0])
stage       calls   total ms   mean µs   share
"""

from __future__ import annotations

import cProfile
import pstats
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "TOP_FUNCTIONS",
    "FunctionCost",
    "StageCost",
    "function_table",
    "stage_costs",
    "stage_table",
    "top_functions",
]

TOP_FUNCTIONS = 15
"""Functions listed by ``--profile``."""


@dataclass(frozen=True, slots=True)
class StageCost:
    """One stage over a run.

    Attributes:
        stage: its name.  calls: the steps it ran in.  total_s: its time over the run, s.
        mean_us: per call, µs.  share: of the time of all stages (0 … 1).
    """

    stage: str
    calls: int
    total_s: float
    mean_us: float
    share: float


@dataclass(frozen=True, slots=True)
class FunctionCost:
    """One function under cProfile: where it is, calls, own seconds and cumulative seconds."""

    function: str
    calls: int
    own_s: float
    cumulative_s: float


def stage_costs(world: World) -> list[StageCost]:
    """Every stage that ran, in step order (the world must have run with ``timing`` on)."""
    ran = [(s, world.timings[s]) for s in Stage if world.timings[s].calls]
    whole = sum(t.total for _, t in ran)
    return [
        StageCost(s.name.lower(), t.calls, t.total, 1e6 * t.mean, t.total / whole if whole else 0.0)
        for s, t in ran
    ]


def stage_table(world: World) -> str:
    """The stage costs as a fixed-width text table."""
    lines = [f"{'stage':<10}{'calls':>7}{'total ms':>11}{'mean µs':>10}{'share':>8}"]
    for c in stage_costs(world):
        lines.append(
            f"{c.stage:<10}{c.calls:>7}{1e3 * c.total_s:>11.1f}{c.mean_us:>10.1f}{c.share:>8.0%}"
        )
    return "\n".join(lines)


def top_functions(run: Callable[[], object], count: int = TOP_FUNCTIONS) -> list[FunctionCost]:
    """Run ``run`` under cProfile: the ``count`` functions with the most own time."""
    profile = cProfile.Profile()
    profile.enable()
    try:
        run()
    finally:
        profile.disable()
    rows = []
    # pstats keeps (file, line, name) -> (primitive calls, calls, own s, cumulative s, callers)
    entries = pstats.Stats(profile).stats  # type: ignore[attr-defined]
    for (file, line, name), (_, calls, own, cumulative, _) in entries.items():
        where = f"{_short(file)}:{line}({name})" if line else name
        rows.append(FunctionCost(where, calls, own, cumulative))
    rows.sort(key=lambda r: r.own_s, reverse=True)
    return rows[:count]


def _short(file: str) -> str:
    """A source path from its package folder on (``playground/vec.py``, ``pymunk/space.py``)."""
    parts = Path(file).parts
    for i in range(len(parts) - 1, -1, -1):
        if parts[i] in ("playground", "pymunk", "numpy"):
            return "/".join(parts[i:])
    return file


def function_table(rows: list[FunctionCost]) -> str:
    """The function costs as a fixed-width text table (own time first: where the time is)."""
    lines = [f"{'own ms':>9}{'cum ms':>9}{'calls':>9}  function"]
    for r in rows:
        lines.append(f"{1e3 * r.own_s:>9.1f}{1e3 * r.cumulative_s:>9.1f}{r.calls:>9}  {r.function}")
    return "\n".join(lines)
