"""What a performance run records: a row per shipped level, per pile measurement and per crowd,
and the machine they were measured on; as plain JSON-ready values (:meth:`Measurement.to_dict`,
NaN written as null). :mod:`playground.bench.performance` measures them.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from playground.world.schedule import Stage

__all__ = ["STAGES", "CrowdRow", "LevelRow", "Measurement", "PileRow"]

STAGES = (Stage.INPUTS, Stage.EVENTS, Stage.GRAVITY, Stage.MOVERS, Stage.CONTROL, Stage.PHYSICS,
          Stage.FORCES, Stage.FILTER, Stage.OBSERVE)  # fmt: skip
"""The stages a level row times, in the order of a step."""


@dataclass(frozen=True, slots=True)
class LevelRow:
    """One shipped level.

    Attributes:
        level: its name.  dt: its step, s.  players: controllers it runs.
        level_us: ``World.step``, µs (ratio × engine_us).  engine_us: its space's bare steps, µs.
        ratio: level / engine, median of paired blocks.  ratio_lo, ratio_hi: their spread.
        realtime: dt / level step: simulated seconds per wall second.
        stages: median µs of each stage over the steps it ran in, by lower-case stage name.
        scalar: its tracked bodies are served by the scalar implementation (plain floats), not
            numpy.
    """

    level: str
    dt: float
    players: int
    level_us: float
    engine_us: float
    ratio: float
    ratio_lo: float
    ratio_hi: float
    realtime: float
    stages: dict[str, float]
    scalar: bool


@dataclass(frozen=True, slots=True)
class PileRow:
    """One measurement on the pile.

    Attributes:
        kind: ``solver+1€`` (every box tracked and perceived against bare steps of the same
            space), ``split off`` and ``split on`` (the same with the default perception and the
            contact split off or on), ``field`` (a per-body radial field against uniform
            gravity), ``no effect``
            (a world against a bare space holding the same pile) or ``scalar/vector`` (the
            scalar implementation against the batch one, every box tracked and perceived).
        bodies: boxes.  us: the measured side, µs per step.  base_us: what it is compared with.
        ratio: us / base_us, median of paired blocks.  ratio_lo, ratio_hi: their spread.
        overhead: ratio − 1.
    """

    kind: str
    bodies: int
    us: float
    base_us: float
    ratio: float
    ratio_lo: float
    ratio_hi: float
    overhead: float


@dataclass(frozen=True, slots=True)
class CrowdRow:
    """One crowd.

    Attributes:
        actors: patrolling enemies.  level_us: ``World.step``, µs (ratio × engine_us).
        engine_us: ``space.step`` of a copy of its space, µs.
        ratio: level / engine, median of paired blocks.  ratio_lo, ratio_hi: their spread.
        per_actor_us: level_us / actors.  realtime: dt / level step.
        path: which path ran the controllers (``"scalar"``: each its own hook; ``"batch"``:
            as one crowd).
    """

    actors: int
    level_us: float
    engine_us: float
    ratio: float
    ratio_lo: float
    ratio_hi: float
    per_actor_us: float
    realtime: float
    path: str


@dataclass(frozen=True, slots=True)
class Measurement:
    """One run of :func:`~playground.bench.performance.measure`: the machine and the rows."""

    machine: dict[str, str]
    command: str
    repeats: int
    levels: tuple[LevelRow, ...]
    piles: tuple[PileRow, ...]
    crowds: tuple[CrowdRow, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON-ready values (NaN as None)."""
        out: dict[str, Any] = _clean(asdict(self))
        return out


def _clean(v: Any) -> Any:
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, dict):
        return {k: _clean(x) for k, x in v.items()}
    if isinstance(v, list | tuple):
        return [_clean(x) for x in v]
    return v
