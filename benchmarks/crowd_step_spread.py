"""A crowd's single steps: their spread in time, and how many members ran their own step.

The crowds of :mod:`playground.bench.crowd` (N patrolling enemies, settled), stepped K times;
each step is timed alone in CPU time of this thread (``time.thread_time_ns``), and the members
that ran their own scalar step that step are counted (a member that runs its own step has its
state absorbed back into the crowd's arrays: ``Members._absorb`` is counted, wrapped). The
benchmark's figures (``crowd_step.py``) are medians of blocks; this shows the tail they leave
out and whether it comes from members leaving the batch path.

    python benchmarks/crowd_step_spread.py                  # 100 actors, 1200 steps
    python benchmarks/crowd_step_spread.py --actors 200 --steps 2400

Prints, by the number of members that ran their own step: how many steps, and their mean,
median, 90th and 99th percentile µs; then the same over all steps.
"""

from __future__ import annotations

import argparse
import gc
import statistics
import time
from collections import defaultdict
from typing import Any

from playground.bench.crowd import crowd_world
from playground.controller.crowd.members import Members


def _line(label: str, us: list[float]) -> str:
    us = sorted(us)
    k = len(us)
    return (
        f"{label:>10s} {k:6d} steps  mean {statistics.fmean(us):7.1f}  median "
        f"{us[k // 2]:7.1f}  p90 {us[int(k * 0.9)]:7.1f}  p99 {us[int(k * 0.99)]:7.1f} µs"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, default=100)
    parser.add_argument("--steps", type=int, default=1200)
    args = parser.parse_args()
    world = crowd_world(args.actors)
    absorbed = [0]
    absorb = Members._absorb

    def counted(self: Any, i: int) -> None:
        absorbed[0] += 1
        absorb(self, i)

    Members._absorb = counted  # type: ignore[method-assign]
    by_count: dict[int, list[float]] = defaultdict(list)
    gc.collect()
    for _ in range(args.steps):
        absorbed[0] = 0
        t0 = time.thread_time_ns()
        world.step()
        by_count[absorbed[0]].append((time.thread_time_ns() - t0) / 1e3)
    Members._absorb = absorb  # type: ignore[method-assign]
    print(f"{args.actors} actors, {args.steps} steps; by members that ran their own step:")
    for count in sorted(by_count):
        print(_line(str(count), by_count[count]))
    print(_line("all", [t for ts in by_count.values() for t in ts]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
