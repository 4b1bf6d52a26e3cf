"""What a crowd of patrolling enemies costs a step, against the engine's own step (issue 27).

N enemies (the default :class:`~playground.controller.controller.Controller` on a
:class:`~playground.intents.Patrol`, periods spread so they do not walk in step) stand
:data:`SPACING` apart on one static floor. The world's ``World.step`` and ``space.step`` of a
copy of the same space are timed in interleaved blocks in one process
(:func:`playground.bench.blocks.interleave`): the ratio is the median of the ratios of adjacent
blocks, so it holds on a loaded machine; the times are quoted as that ratio × the engine's median.

>>> row = crowd_row(2, repeats=1)
>>> row.actors, row.ratio > 1.0
(2, True)
"""

from __future__ import annotations

import pymunk

from playground.bench.blocks import interleave
from playground.bench.measurement import CrowdRow
from playground.controller.controller import Controller
from playground.intents import Patrol
from playground.world.world import World

__all__ = ["CROWD_SIZES", "SETTLE", "SPACING", "crowd_row", "crowd_world", "path_of"]

CROWD_SIZES = (1, 10, 50, 100, 200)
"""Actors in the crowds measured by default (issue 27's table)."""
SPACING = 2.0
"""m between enemies at the start."""
SETTLE = 240
"""Steps run before timing (2 s): the hover springs settle on the floor and every patrol has
turned once (periods 2 + 0.01·i s, the 200th's first turn at 1.995 s), so the timed steps are
a crowd's steady state: some members turning and leaning into their step, not only walking
away from where they stood."""


def crowd_world(n: int) -> World:
    """A world of ``n`` patrolling enemies on one static floor, settled for :data:`SETTLE`
    steps."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0 + SPACING * n, 0.0))
    for i in range(n):
        Controller(
            world,
            f"enemy{i}",
            position=(SPACING * i, 0.95),
            source=Patrol(speed=0.5, period=2.0 + 0.01 * i),
        )
    for _ in range(SETTLE):
        world.step()
    return world


def path_of(world: World) -> str:
    """Which path runs the world's controllers: ``"batch"`` if a crowd does, else
    ``"scalar"``."""
    from playground.controller.crowd import Crowd

    return "batch" if Crowd.of(world).active else "scalar"


def crowd_row(n: int, repeats: int = 11) -> CrowdRow:
    """Time a crowd of ``n`` actors against its engine (see the module docstring)."""
    world = crowd_world(n)
    bare: pymunk.Space = world.space.copy()
    dt = world.config.dt
    t = interleave(world.step, lambda: bare.step(dt), repeats=repeats)
    engine = 1e6 * t.b_median
    level = t.ratio * engine
    lo, hi = t.spread
    return CrowdRow(
        actors=n,
        level_us=level,
        engine_us=engine,
        ratio=t.ratio,
        ratio_lo=lo,
        ratio_hi=hi,
        per_actor_us=level / n,
        realtime=1e6 * dt / level,
        path=path_of(world),
    )
