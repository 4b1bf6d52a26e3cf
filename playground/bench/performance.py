"""What a step costs against the engine: every shipped level and the pile.

Every figure is a ratio of interleaved blocks in one process (:mod:`playground.bench.blocks`), so
it holds on a loaded machine where absolute microseconds move by 2×:

- **levels**: a shipped level's ``World.step`` against ``space.step`` of the same scene (a copy of
  its space taken before each bare block, so both run the same bodies and contacts), the real-time
  factor at the level's dt, and the mean µs of each stage (``World.timings``);
- **piles**: every box of a settled pile tracked and perceived (solver + 1€) against bare
  ``space.step`` of the same space; the same with the default perception and the contact split
  off, then on; a per-body gravity field against uniform gravity; a world with no effect
  against a bare space holding the same pile;
- **crowds**: N patrolling enemies on one floor against ``space.step`` of a copy of the same space
  (:mod:`playground.bench.crowd`).

:func:`measure` runs them all; :func:`from_dict` reads a run back from its JSON.

>>> m = measure(
...     levels=("rest",), sizes=(10,), field_bodies=10, crossover=(1,), split_sizes=(10,),
...     crowds=(2,), repeats=1,
... )
>>> [r.level for r in m.levels], sorted({r.kind for r in m.piles}), [r.actors for r in m.crowds]
(['rest'], ['field', 'no effect', 'scalar/vector', 'solver+1€', 'split off', 'split on'], [2])
"""

from __future__ import annotations

import math
import os
import platform
import statistics
from collections.abc import Callable, Sequence
from dataclasses import replace
from datetime import UTC, datetime
from typing import Any

import numpy as np
import pymunk

from playground.bench.blocks import Blocks, interleave
from playground.bench.crowd import CROWD_SIZES, crowd_row
from playground.bench.measurement import STAGES, CrowdRow, LevelRow, Measurement, PileRow
from playground.bench.pile import floor_length, pile_names, pile_space, pile_world
from playground.gravity import Perception, Radial
from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "STAGE_STEPS",
    "crossover_row",
    "field_row",
    "from_dict",
    "level_row",
    "machine",
    "measure",
    "no_effect_row",
    "solver_row",
    "split_row",
]

PILE_SIZES = (10, 100, 1000, 3000)
"""Pile sizes measured by default (the performance goals quote 10, 1000 and 3000)."""

SPLIT_SIZES = (10, 100, 1000)
"""Pile sizes at which the contact split is timed off and on (issue 27 quotes 10 and 1000)."""

CROSSOVER_SIZES = (1, 2, 4, 8, 12, 16, 20, 24, 28, 32, 48)
"""Tracked bodies at which the scalar implementation is timed against the batch one."""

FIELD_BODIES = 1000
"""Boxes in the pile on which a per-body gravity field is timed against uniform gravity."""

REPEATS = 21
"""Interleaved blocks per measurement (the figure is their median pair ratio)."""

SETTLE_STEPS = 30
"""Steps a pile or a level runs before it is timed (first readings, filter state, buffers)."""

STAGE_STEPS = 200
"""Steps timed stage by stage after the blocks (``World.timings``; timing adds two
``perf_counter`` calls a stage: docs/performance.md, row stage_timer)."""


def _stage_medians(world: World, steps: int) -> dict[str, float]:
    """Median µs of each stage over the ``steps`` steps (timing on) in which it ran.

    Medians of single steps, not means: on a loaded machine a step the scheduler interrupts
    counts once, not in proportion to how long another process held the core.
    """
    world.config = replace(world.config, timing=True)
    samples: dict[Stage, list[float]] = {s: [] for s in STAGES}
    for _ in range(steps):
        calls = [world.timings[s].calls for s in STAGES]
        world.step()
        for s, before in zip(STAGES, calls, strict=True):
            if world.timings[s].calls != before:
                samples[s].append(world.timings[s].last)
    world.config = replace(world.config, timing=False)
    return {s.name.lower(): 1e6 * statistics.median(v) for s, v in samples.items() if v}


def level_row(name: str, repeats: int = REPEATS) -> LevelRow:
    """Time the shipped level ``name`` against its engine (see the module docstring)."""
    from playground.level.files import find
    from playground.level.loading import load
    from playground.scene import build

    scene = build(load(find(name)))
    world = scene.world
    for _ in range(SETTLE_STEPS):
        world.step()
    copy: list[pymunk.Space] = [world.space.copy()]
    engine = _engine_step_of(copy, world.config)

    def fresh_copy() -> None:
        # The bare side steps a copy of the level's space as it is now: the same bodies, shapes,
        # joints and contacts, without the controllers that would keep it where the level is.
        copy[0] = world.space.copy()

    t = interleave(world.step, engine, repeats=repeats, prepare_b=fresh_copy)
    stages = _stage_medians(world, STAGE_STEPS)
    engine_us = 1e6 * t.b_median
    level_us = t.ratio * engine_us
    lo, hi = t.spread
    return LevelRow(
        level=name,
        dt=world.config.dt,
        players=len(scene.controllers),
        level_us=level_us,
        engine_us=engine_us,
        ratio=t.ratio,
        ratio_lo=lo,
        ratio_hi=hi,
        realtime=world.config.dt / (level_us * 1e-6),
        stages=stages,
        scalar=world.tracked_kind == "scalar",
    )


def _engine_step_of(holder: list[pymunk.Space], config: WorldConfig) -> Callable[[], None]:
    h = config.dt / config.substeps
    n = config.substeps

    def step() -> None:
        space = holder[0]
        for _ in range(n):
            space.step(h)

    return step


# -- piles -----------------------------------------------------------------------------------


def _settle(*steps: Callable[[], object]) -> None:
    for _ in range(SETTLE_STEPS):
        for step in steps:
            step()


def _pile_row(kind: str, n: int, t: Blocks) -> PileRow:
    lo, hi = t.spread
    base = 1e6 * t.b_median
    return PileRow(kind, n, t.ratio * base, base, t.ratio, lo, hi, t.ratio - 1.0)


def solver_row(n: int, repeats: int = REPEATS) -> PileRow:
    """Every box tracked and perceived (1€ alone, the goals' configuration) against bare steps
    of the same space."""
    world = pile_world(n, WorldConfig(perception=Perception(spike_filter=False)))
    world.track(*pile_names(n))
    space, dt = world.space, world.config.dt
    _settle(world.step)
    return _pile_row(
        "solver+1€", n, interleave(world.step, lambda: space.step(dt), repeats=repeats)
    )


def split_row(n: int, split: bool, repeats: int = REPEATS) -> PileRow:
    """Every box tracked and perceived (the default perception: median-of-3 and 1€) with the
    contact split off or on, against bare steps of the same space."""
    world = pile_world(n, WorldConfig(contact_split=split))
    world.track(*pile_names(n))
    space, dt = world.space, world.config.dt
    _settle(world.step)
    kind = "split on" if split else "split off"
    return _pile_row(kind, n, interleave(world.step, lambda: space.step(dt), repeats=repeats))


def crossover_row(n: int, repeats: int = REPEATS) -> PileRow:
    """The scalar implementation against the batch one, every box tracked and perceived (the default
    perception): where the ratio passes 1 is where the world should switch."""
    worlds = []
    for most in (n, 0):
        world = pile_world(n, WorldConfig())
        world.scalar_max_bodies = most
        world.track(*pile_names(n))
        worlds.append(world)
    _settle(worlds[0].step, worlds[1].step)
    return _pile_row(
        "scalar/vector", n, interleave(worlds[0].step, worlds[1].step, repeats=repeats)
    )


def field_row(n: int, repeats: int = REPEATS) -> PileRow:
    """A per-body radial field against uniform ``space.gravity``, on two untracked piles. The
    planet is so large that its surface is flat under the pile (tilt < 0.2° at its ends): the
    same physics."""
    middle = floor_length(n) / 2.0
    far = 1e5
    radial = Radial(center=(middle, -far), surface_gravity=9.81, radius=far, softening=0.0)
    field = pile_world(n, WorldConfig(), gravity=radial)
    uniform = pile_world(n, WorldConfig())
    _settle(field.step, uniform.step)
    return _pile_row("field", n, interleave(field.step, uniform.step, repeats=repeats))


def no_effect_row(n: int, repeats: int = REPEATS) -> PileRow:
    """A world that uses no effect against a bare space holding the same pile."""
    config = WorldConfig()
    world = pile_world(n, config)
    bare = pile_space(n, config)
    _settle(world.step, lambda: bare.step(config.dt))
    return _pile_row(
        "no effect", n, interleave(world.step, lambda: bare.step(config.dt), repeats=repeats)
    )


def machine() -> dict[str, str]:
    """What the numbers were measured on: CPU, cores, load, versions."""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = os.getloadavg() if hasattr(os, "getloadavg") else (math.nan,) * 3
    return {
        "cpu": model,
        "cores": str(os.cpu_count()),
        "load": " ".join(f"{x:.1f}" for x in load),
        "python": platform.python_version(),
        "pymunk": pymunk.version,
        "numpy": np.__version__,
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
    }


def measure(
    levels: Sequence[str] | None = None,
    sizes: Sequence[int] = PILE_SIZES,
    *,
    field_bodies: int = FIELD_BODIES,
    crossover: Sequence[int] = CROSSOVER_SIZES,
    split_sizes: Sequence[int] = SPLIT_SIZES,
    crowds: Sequence[int] = CROWD_SIZES,
    repeats: int = REPEATS,
    progress: bool = False,
    command: str = "playground bench overhead --json",
) -> Measurement:
    """Time every shipped level (or ``levels``), the piles of ``sizes``, the contact split off
    and on at ``split_sizes`` and the crowds of ``crowds`` actors.

    ``progress`` shows a bar on stderr when it is a terminal (tqdm).
    """
    from playground.level.files import shipped

    names = sorted(shipped()) if levels is None else list(levels)
    jobs: list[Callable[[], LevelRow | PileRow | CrowdRow]] = [
        *(lambda n=n: level_row(n, repeats) for n in names),
        *(lambda n=n: solver_row(n, repeats) for n in sizes),
        *(lambda n=n, s=s: split_row(n, s, repeats) for n in split_sizes for s in (False, True)),
        lambda: field_row(field_bodies, repeats),
        *(lambda n=n: no_effect_row(n, repeats) for n in sorted({min(sizes), field_bodies})),
        *(lambda n=n: crossover_row(n, repeats) for n in crossover),
        *(lambda n=n: crowd_row(n, repeats) for n in crowds),
    ]
    bar = _bar(len(jobs)) if progress else None
    rows = []
    for job in jobs:
        rows.append(job())
        if bar is not None:
            bar.update(1)
    if bar is not None:
        bar.close()
    level_rows = tuple(r for r in rows if isinstance(r, LevelRow))
    pile_rows = tuple(r for r in rows if isinstance(r, PileRow))
    crowd_rows = tuple(r for r in rows if isinstance(r, CrowdRow))
    return Measurement(
        machine=machine(),
        command=command,
        repeats=repeats,
        levels=level_rows,
        piles=pile_rows,
        crowds=crowd_rows,
    )


def _bar(total: int) -> Any:
    """A tqdm bar on stderr, shown only when stderr is a terminal (``disable=None``)."""
    from tqdm import tqdm

    return tqdm(total=total, unit="row", desc="performance", leave=False, disable=None)


def from_dict(data: dict[str, Any], source: str = "<data>") -> Measurement:
    """A :class:`Measurement` back from :meth:`Measurement.to_dict` (the JSON of ``bench overhead
    --json``; other keys are ignored). ``ValueError`` names ``source`` and the missing key."""

    def num(v: Any) -> float:
        return math.nan if v is None else float(v)

    try:
        levels = tuple(
            LevelRow(
                level=str(r["level"]),
                dt=num(r["dt"]),
                players=int(r["players"]),
                level_us=num(r["level_us"]),
                engine_us=num(r["engine_us"]),
                ratio=num(r["ratio"]),
                ratio_lo=num(r["ratio_lo"]),
                ratio_hi=num(r["ratio_hi"]),
                realtime=num(r["realtime"]),
                stages={str(k): num(v) for k, v in r["stages"].items()},
                scalar=bool(r["scalar"]),
            )
            for r in data["levels"]
        )
        piles = tuple(PileRow(**r) for r in data["piles"])
        # A run from before the crowds were measured has none.
        crowds = tuple(CrowdRow(**r) for r in data.get("crowds", ()))
        return Measurement(
            machine=dict(data["machine"]),
            command=str(data["command"]),
            repeats=int(data["repeats"]),
            levels=levels,
            piles=piles,
            crowds=crowds,
        )
    except KeyError as exc:
        raise ValueError(
            f"{source}: expected the key {exc} (the output of bench overhead --json)"
        ) from None
    except (TypeError, AttributeError, ValueError) as exc:
        raise ValueError(f"{source}: not the output of bench overhead --json ({exc})") from None
