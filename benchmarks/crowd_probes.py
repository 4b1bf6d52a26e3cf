"""What a crowd's ground probes cost: all of them in one call of ``Sweeps.nearest``, by the
compiled helper and by its fallback (the Python callback, one call a query), issue 27.

The crowd of :mod:`playground.bench.crowd` (N patrolling enemies 2 m apart on one static floor),
run 50 steps; then each member's probe (a circle of its probe radius swept its probe length
down from its body) is cast through one :class:`~playground._engine.sweep.Sweeps` of them, the
two paths timed in interleaved blocks in one process (:func:`playground.bench.blocks.interleave`)
and checked to answer alike.

    python benchmarks/crowd_probes.py                   # 200 actors
    python benchmarks/crowd_probes.py --actors 100 200 --repeats 21

Columns: actors, compiled (µs for all N probes, the median block), callback (the same),
callback / compiled (the median ratio of adjacent blocks, lowest–highest), per query (µs).
"""

from __future__ import annotations

import argparse
from unittest import mock

import numpy as np

from playground._engine import sweep
from playground.bench.blocks import interleave
from playground.bench.crowd import crowd_world
from playground.controller.crowd import Crowd

WARM_STEPS = 50
"""Steps the crowd runs before the probes are timed (its members on their patrols)."""


def row(actors: int, repeats: int) -> str:
    """One table row: the N probes of a crowd of ``actors``, both paths."""
    if sweep.QUERIES_BY != "compiled":
        raise SystemExit(f"the compiled helper is not built (QUERIES_BY = {sweep.QUERIES_BY!r})")
    world = crowd_world(actors)
    for _ in range(WARM_STEPS):
        world.step()
    crowd = Crowd.of(world)
    probes = sweep.Sweeps([c.senses.sweep for c in crowd.members])
    rows = np.arange(len(crowd.members))
    x, y = np.array([tuple(c.body.position) for c in crowd.members]).T
    length = np.array([c.config.probe_length for c in crowd.members])  # m
    radius = np.array([c.config.probe_radius for c in crowd.members])  # m
    args = (rows, x, y, x, y - length, radius)

    def compiled() -> sweep.Hits:
        return probes.nearest(*args)

    def callback() -> sweep.Hits:
        with mock.patch.object(sweep, "_segment_queries", None):
            return probes.nearest(*args)

    a, b = compiled(), callback()
    assert (
        a.shape.tolist() == b.shape.tolist()
        and a.point_normal.tobytes() == b.point_normal.tobytes()
    )
    t = interleave(callback, compiled, repeats=repeats)
    fast = float(np.median(t.b)) * 1e6
    slow = float(np.median(t.a)) * 1e6
    lo, hi = t.spread
    return (
        f"| {actors} | {fast:.0f} µs | {slow:.0f} µs | {t.ratio:.1f}× ({lo:.1f}–{hi:.1f}) "
        f"| {fast / actors:.2f} µs |"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, nargs="*", default=[200])
    parser.add_argument("--repeats", type=int, default=11)
    args = parser.parse_args()
    print("| actors | compiled | callback | callback / compiled | per query (compiled) |")
    print("|---|---|---|---|---|")
    for n in args.actors:
        print(row(n, args.repeats))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
