"""Where the crowd starts to pay: a crowd of N patrolling actors run as one
(:class:`~playground.controller.crowd.Crowd`) against the same crowd with each controller
running its own step, timed in interleaved blocks in one process (issue 27).

    python benchmarks/crowd_crossover.py                   # N = 2, 4, 8, 16, 32, 64, 200
    python benchmarks/crowd_crossover.py --actors 8 12 16 --repeats 15

The ratio (batch step / scalar step, the median of adjacent blocks' ratios, with the lowest and
highest) passes below 1 where the batch path is the cheaper: ``CROWD_MIN_ACTORS``
(playground/controller/crowd/members.py) is set from it.
"""

from __future__ import annotations

import argparse

from playground.bench.blocks import interleave
from playground.bench.crowd import crowd_world
from playground.controller.crowd import Crowd


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, nargs="*", default=[2, 4, 8, 16, 32, 64, 200])
    parser.add_argument("--repeats", type=int, default=11)
    args = parser.parse_args()
    print("| actors | scalar µs | batch µs | batch / scalar (blocks) |")
    print("|---|---|---|---|")
    for n in args.actors:
        batch, scalar = crowd_world(n), crowd_world(n)
        Crowd.of(batch).set_min_actors(0)
        Crowd.of(scalar).set_min_actors(10**9)
        for _ in range(10):
            batch.step()
            scalar.step()
        t = interleave(batch.step, scalar.step, repeats=args.repeats)
        lo, hi = t.spread
        print(
            f"| {n} | {1e6 * t.b_median:.0f} | {1e6 * t.a_median:.0f} | "
            f"{t.ratio:.2f}× ({lo:.2f}–{hi:.2f}) |"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
