"""What the core's force solver, 1€ filter and per-body gravity cost, against bare pymunk.

A settled pile of N dynamic bodies (boxes and circles) rests in a walled pit. In one run, and on
the very same space, blocks of bare ``space.step(dt)`` alternate with blocks of ``World.step()``
with every dynamic body tracked and perceived (reverse-integration solver + 1€ filter), so a busy
machine slows both alike. The per-step medians give the overhead ratio
``(world − bare) / bare`` (goals: ≤ 0.10 at N ≥ 1000, ≤ 3 at N = 10) and the total ratio.
Then two piles of 1000, one under uniform ``space.gravity`` and one under a per-body field
(radial, centre far away, or zones), are stepped in alternating blocks (goal ≤ 1.10×).

Usage::

    python benchmarks/bench_core.py                      # the default run (~2 minutes)
    python benchmarks/bench_core.py --sizes 10 100 --repeats 3 --block 50
"""

from __future__ import annotations

import argparse
import math
import platform
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pymunk

from playground import (
    GravityField,
    Perception,
    Radial,
    Stage,
    Uniform,
    World,
    WorldConfig,
    Zone,
    Zones,
)
from playground.filters import FilterChain, Median3, OneEuroFilter

SETTLE_SECONDS = 2.0
"""Simulated time a pile gets to come to rest before it is measured, s."""

BODY_SIZE = 0.5
"""Box side and circle diameter, m."""


def build_pile(
    n: int,
    gravity: GravityField | None = None,
    *,
    timing: bool = False,
    perception: Perception | None = None,
) -> World:
    """A pit ``~√n`` bodies wide with n boxes and circles dropped in a grid, then settled."""
    config = WorldConfig(timing=timing, perception=perception or Perception())
    world = World(config, gravity=gravity if gravity is not None else Uniform())
    cols = max(2, math.ceil(math.sqrt(n)))
    width = cols * BODY_SIZE * 1.1
    world.add_static_segment((-0.1, 0.0), (width + 0.1, 0.0), radius=0.1)
    world.add_static_segment((-0.1, 0.0), (-0.1, 1e3), radius=0.1)
    world.add_static_segment((width + 0.1, 0.0), (width + 0.1, 1e3), radius=0.1)
    for i in range(n):
        row, col = divmod(i, cols)
        x = (col + 0.5) * BODY_SIZE * 1.1
        y = (row + 0.5) * BODY_SIZE * 1.05 + 0.1
        name = f"b{i}"
        if i % 2:
            world.add_box(name, mass=1.0, size=(BODY_SIZE, BODY_SIZE), position=(x, y))
        else:
            r = BODY_SIZE / 2
            body = pymunk.Body(1.0, pymunk.moment_for_circle(1.0, 0.0, r))
            body.position = (x, y)
            shape = pymunk.Circle(body, r)
            shape.friction = 0.8
            world.add(name, body, shape)
    world.run(SETTLE_SECONDS)
    return world


def per_step(fn: Callable[[], None], steps: int) -> float:
    """Seconds per call of ``fn`` over a block of ``steps`` calls."""
    t0 = time.perf_counter()
    for _ in range(steps):
        fn()
    return (time.perf_counter() - t0) / steps


@dataclass(frozen=True)
class Overhead:
    n: int
    bare: float
    world: float
    bare_min: float
    world_min: float

    @property
    def overhead(self) -> float:
        return (self.world - self.bare) / self.bare

    @property
    def total(self) -> float:
        return self.world / self.bare

    @property
    def overhead_min(self) -> float:
        """The overhead from the fastest blocks: least disturbed by other processes."""
        return (self.world_min - self.bare_min) / self.bare_min


def measure_overhead(
    n: int, repeats: int, block: int, perception: Perception
) -> tuple[Overhead, dict[Stage, float]]:
    """Medians of bare and tracked+perceived steps on one settled pile, in alternating blocks;
    and the per-stage mean times of a separate timed block (s)."""
    world = build_pile(n, perception=perception)
    world.track(*world.names)
    dt = world.config.dt
    space = world.space

    def bare() -> None:
        space.step(dt)

    per_step(world.step, block)  # warm up: first readings, filter state, buffers
    bares, worlds = [], []
    for _ in range(repeats):
        bares.append(per_step(bare, block))
        worlds.append(per_step(world.step, block))
    timed = build_pile(
        n, timing=True, perception=perception
    )  # a timed twin: timing costs ~1 µs a stage
    timed.track(*timed.names)
    per_step(timed.step, block)
    for t in timed.timings.values():
        t.total, t.calls = 0.0, 0
    per_step(timed.step, block)
    stages = {s: t.mean for s, t in timed.timings.items() if t.calls}
    row = Overhead(n, statistics.median(bares), statistics.median(worlds), min(bares), min(worlds))
    return row, stages


def measure_filter(n: int, repeats: int, block: int) -> float:
    """Seconds per call of the perception filter alone (median-of-3 + 1€, the default
    :class:`Perception`) on n rows of 2-vectors: the part of the FILTER stage in filters.py."""
    cfg = Perception()
    chain = FilterChain(Median3(), OneEuroFilter(cfg.min_cutoff, cfg.beta, cfg.d_cutoff))
    rng = np.random.default_rng(0)
    samples = rng.normal(0.0, 0.1, size=(block, n, 2)) + np.array([0.0, -9.81])
    chain.filter(samples[0], 1.0 / 120.0)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for x in samples:
            chain.filter(x, 1.0 / 120.0)
        times.append((time.perf_counter() - t0) / block)
    return statistics.median(times)


def measure_fields(n: int, repeats: int, block: int) -> list[tuple[str, float, float, float]]:
    """(field, uniform s/step, field s/step, ratio of the fastest blocks): medians of untracked
    piles stepped in alternating blocks."""
    far = 1e6
    # A planet so large that its field over the pile is uniform to ~1e-5: same pile, same physics.
    radial = Radial(center=(0.0, -far), surface_gravity=9.81, radius=far, softening=0.0)
    zones = Zones(Uniform(), (Zone((-1e3, 1e3, 1e3, 2e3), Uniform((0.0, 9.81))),))
    out = []
    for label, field in (("radial (far centre)", radial), ("zones", zones)):
        uniform_world = build_pile(n)
        field_world = build_pile(n, gravity=field)
        per_step(uniform_world.step, block)
        per_step(field_world.step, block)
        u, f = [], []
        for _ in range(repeats):
            u.append(per_step(uniform_world.step, block))
            f.append(per_step(field_world.step, block))
        out.append((label, statistics.median(u), statistics.median(f), min(f) / min(u)))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[10, 100, 1000, 3000])
    parser.add_argument("--repeats", type=int, default=7, help="blocks per variant (median)")
    parser.add_argument("--block", type=int, default=60, help="steps per block")
    parser.add_argument("--field-bodies", type=int, default=1000)
    args = parser.parse_args()

    print(f"python {platform.python_version()}, pymunk {pymunk.version}, numpy {np.__version__}")
    print(f"repeats {args.repeats} × block {args.block} steps, dt = 1/120 s\n")
    variants = (
        ("1€", Perception(spike_filter=False)),
        ("median-3 + 1€ (default)", Perception()),
    )
    print(
        "| N | filter | bare space.step (µs) | World.step tracked+perceived (µs) "
        "| overhead / bare | total ratio | overhead, fastest blocks | FORCES (µs) "
        "| FILTER (µs) |"
    )
    print("|---:|---|---:|---:|---:|---:|---:|---:|---:|")
    for n in args.sizes:
        for label, perception in variants:
            row, stages = measure_overhead(n, args.repeats, args.block, perception)
            forces = stages.get(Stage.FORCES, math.nan) * 1e6
            filt = stages.get(Stage.FILTER, math.nan) * 1e6
            print(
                f"| {n} | {label} | {row.bare * 1e6:.0f} | {row.world * 1e6:.0f} "
                f"| {row.overhead:.3f}× | {row.total:.3f}× | {row.overhead_min:.3f}× "
                f"| {forces:.0f} | {filt:.0f} |",
                flush=True,
            )
        chain = measure_filter(n, args.repeats, args.block) * 1e6
        print(f"|  | filters.py chain alone | | | | | | | {chain:.0f} |", flush=True)
    print(f"\nPer-body gravity fields at N = {args.field_bodies} (untracked):\n")
    print(
        "| field | uniform space.gravity (µs) | per-body field (µs) | ratio "
        "| ratio, fastest blocks |"
    )
    print("|---|---:|---:|---:|---:|")
    for label, u, f, fastest in measure_fields(args.field_bodies, args.repeats, args.block):
        print(
            f"| {label} | {u * 1e6:.0f} | {f * 1e6:.0f} | {f / u:.3f}× | {fastest:.3f}× |",
            flush=True,
        )


if __name__ == "__main__":
    main()
