"""What a crowd of patrolling enemies costs a step, against the engine's own step (issue 27).

N enemies (the default ``Controller`` on a ``Patrol``, periods spread so they do not walk in
step) stand 2 m apart on one static floor. The world's ``World.step`` and ``space.step`` of a
copy of the same space are timed in interleaved blocks in one process
(:func:`playground.bench.blocks.interleave`): the ratio is the median of the ratios of adjacent
blocks, so it holds on a loaded machine; the times are medians of the blocks.

    python benchmarks/crowd_step.py                  # 1, 10, 50, 100, 200 actors
    python benchmarks/crowd_step.py --actors 200 --repeats 15 --json

Columns: level step (µs), engine step (µs), × engine (the median ratio), per actor (µs),
× real time (dt / level step, dt = 1/120 s).
"""

from __future__ import annotations

import argparse
import json

import pymunk

from playground.bench.blocks import interleave
from playground.controller.controller import Controller
from playground.intents import Patrol
from playground.world.world import World

SPACING = 2.0
"""m between enemies: farther than their arms and probes reach, so each patrols alone."""
SETTLE = 60
"""Steps run before timing: the hover springs settle on the floor."""


def crowd(n: int) -> World:
    """A world of ``n`` patrolling enemies on one static floor."""
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


def row(n: int, repeats: int) -> dict[str, float]:
    """One row of the table for ``n`` actors."""
    world = crowd(n)
    bare: pymunk.Space = world.space.copy()
    dt = world.config.dt
    t = interleave(world.step, lambda: bare.step(dt), repeats=repeats)
    level, engine = 1e6 * t.a_median, 1e6 * t.b_median
    return {
        "actors": n,
        "level_us": level,
        "engine_us": engine,
        "x_engine": t.ratio,
        "per_actor_us": level / n,
        "x_real_time": 1e6 * dt / level,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, nargs="*", default=[1, 10, 50, 100, 200])
    parser.add_argument("--repeats", type=int, default=11)
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    args = parser.parse_args()
    rows = [row(n, args.repeats) for n in args.actors]
    if args.json:
        print(json.dumps(rows, indent=2))
        return 0
    print("| actors | level step | engine step | × engine | per actor | × real time |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(
            f"| {r['actors']} | {r['level_us']:.0f} µs | {r['engine_us']:.1f} µs | "
            f"{r['x_engine']:.0f}× | {r['per_actor_us']:.1f} µs | {r['x_real_time']:.1f}× |"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
