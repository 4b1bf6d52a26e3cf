"""What a crowd of patrolling enemies costs a step, against the engine's own step (issue 27).

The crowds of :mod:`playground.bench.crowd` (N enemies, the default ``Controller`` on a
``Patrol``, 2 m apart on one static floor): the world's ``World.step`` and ``space.step`` of a
copy of the same space, timed in interleaved blocks in one process
(:func:`playground.bench.blocks.interleave`). The ratio is the median of the ratios of adjacent
blocks, so it holds on a loaded machine; the level step is that ratio × the engine's median.
``playground bench overhead`` measures the same rows (its "Crowds" table).

    python benchmarks/crowd_step.py                  # 1, 10, 50, 100, 200 actors
    python benchmarks/crowd_step.py --actors 200 --repeats 15 --json

Columns: path (scalar: a hook per controller; batch: one crowd), level step (µs), engine step
(µs), × engine (the median ratio, and the lowest and highest ratio of the blocks), per actor
(µs), × real time (dt / level step, dt = 1/120 s).
"""

from __future__ import annotations

import argparse
import dataclasses
import json

from playground.bench.crowd import CROWD_SIZES, crowd_row
from playground.bench.performance_tables import crowds_markdown


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, nargs="*", default=list(CROWD_SIZES))
    parser.add_argument("--repeats", type=int, default=11)
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    args = parser.parse_args()
    rows = [crowd_row(n, args.repeats) for n in args.actors]
    if args.json:
        print(json.dumps([dataclasses.asdict(r) for r in rows], indent=2))
        return 0
    print(crowds_markdown(rows))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
