"""Where a crowd's step goes, stage by stage (issue 27): the stages around its control.

The crowds of :mod:`playground.bench.crowd` (N enemies, the default ``Controller`` on a
``Patrol``), stepped with ``WorldConfig(timing=True)``; each stage's time of every step is kept
and the median over the steps is quoted (a median, so a burst of load on a shared machine moves
it little). PHYSICS is split in two: the engine's own ``space.step`` (timed around the call) and
the rest of the stage, the ledger's flush and the tracked bodies' reads, which is Python and numpy
overhead. The last column adds up what is not the controller's and not the engine's: INPUTS +
PHYSICS − engine + FORCES + FILTER.

    python benchmarks/crowd_stages.py                      # 100 and 200 actors, 600 steps
    python benchmarks/crowd_stages.py --actors 200 --steps 2000

Columns (µs a step, medians): INPUTS, CONTROL, PHYSICS − engine, engine, FORCES, FILTER, around
(the sum named above), around per actor.
"""

from __future__ import annotations

import argparse
import dataclasses
import statistics
import time
from collections.abc import Callable

from playground.bench.crowd import crowd_world
from playground.world.schedule import Stage

STAGES = (Stage.INPUTS, Stage.CONTROL, Stage.PHYSICS, Stage.FORCES, Stage.FILTER)
"""The stages a crowd's step runs (no gravity field, mover, event or observer)."""


def stage_medians(n: int, steps: int) -> dict[str, float]:
    """Median µs a step of each stage of a crowd of ``n``, and of the engine's ``space.step``."""
    world = crowd_world(n)
    world.config = dataclasses.replace(world.config, timing=True)
    space = world.space
    step: Callable[[float], None] = space.step
    engine: list[float] = []

    def timed_step(h: float) -> None:
        t0 = time.perf_counter()
        step(h)
        engine.append(time.perf_counter() - t0)

    # An attribute of the instance: the physics stage calls space.step through it.
    space.step = timed_step  # type: ignore[method-assign]
    laps: dict[Stage, list[float]] = {s: [] for s in STAGES}
    for _ in range(steps):
        world.step()
        for s in STAGES:
            laps[s].append(world.timings[s].last)
    med = {s.name: 1e6 * statistics.median(laps[s]) for s in STAGES}
    med["engine"] = 1e6 * statistics.median(engine)
    med["PHYSICS-engine"] = 1e6 * statistics.median(
        p - e for p, e in zip(laps[Stage.PHYSICS], engine, strict=True)
    )
    med["around"] = med["INPUTS"] + med["PHYSICS-engine"] + med["FORCES"] + med["FILTER"]
    return med


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--actors", type=int, nargs="*", default=[100, 200])
    parser.add_argument("--steps", type=int, default=600)
    args = parser.parse_args()
    cols = ("INPUTS", "CONTROL", "PHYSICS-engine", "engine", "FORCES", "FILTER", "around")
    print("| actors | " + " | ".join(cols) + " | around / actor |")
    print("|---" * (len(cols) + 2) + "|")
    for n in args.actors:
        med = stage_medians(n, args.steps)
        cells = " | ".join(f"{med[c]:.1f}" for c in cols)
        print(f"| {n} | {cells} | {med['around'] / n:.3f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
