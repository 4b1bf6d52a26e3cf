"""The settings guide: what each knob does to what a player feels, and what it costs per frame.

Every scenario (:mod:`tools.scenarios`) runs at the defaults, with each knob of
:data:`~tools.guide_settings.KNOBS` moved one at a time, and with the combinations of
:data:`~tools.guide_settings.COMBOS` (knobs that trade one measure for another). All the
runs of a scenario advance in lockstep, a quarter of a simulated second at a time, each timed, so a
busy spell of the machine hits every setting alike: the cost is the median over those blocks, with
the 10th and 90th percentiles as its spread; each block is divided by the defaults' block of the
same round (paired, so the machine's changing load cancels) and scaled by the defaults' median.
Beside it, the hover's error against the exact oscillator over a grid of frequencies and steps
(:func:`hover_table`). :mod:`tools.guide_report` writes the section and the figure.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from tools.guide_settings import COMBOS, KNOBS, Combo, Knob, Run
from tools.scenarios import SCENARIOS, build_with

__all__ = [
    "BLOCK",
    "HOVER_DTS",
    "HOVER_FREQUENCIES",
    "guide",
    "hover_error",
    "hover_table",
    "run_scenario",
]

BLOCK = 0.25
"""s of simulated time per timed block (every run of a scenario advances one block per round)."""


@dataclass(slots=True)
class _Live:
    """A scenario run in progress: its scene, what it has measured so far, its timed blocks."""

    knob: str
    value: float | bool
    scene: Any
    state: dict[str, float]
    blocks: list[float]


Setting = tuple[Knob | Combo | None, float | bool]
"""A knob and its value, or a combination of knobs (its value unused), or (None, 0.0): the
defaults."""


def _settings() -> list[Setting]:
    out: list[Setting] = [(None, 0.0)]
    for knob in KNOBS:
        out += [(knob, v) for v in knob.values[1:]]
    out += [(combo, math.nan) for combo in COMBOS]
    return out


def run_scenario(name: str, settings: Sequence[Setting] | None = None) -> list[Run]:
    """Run scenario ``name`` at every setting (default: the defaults, each knob's other values
    and the combinations of :data:`COMBOS`), all in lockstep, and return one :class:`Run` each.
    The first setting is the reference the costs are paired with."""
    make, observe, measures = SCENARIOS[name]
    base = make()
    live = []
    for knob, value in settings if settings is not None else _settings():
        scene = build_with(base, knob, value)
        if isinstance(knob, Combo):
            live.append(_Live(knob.name, math.nan, scene, {}, []))
        else:
            live.append(_Live("defaults" if knob is None else knob.name, value, scene, {}, []))
    seconds = base.settings.seconds
    rounds = math.ceil(seconds / BLOCK - 1e-9)
    for r in range(rounds):
        for run in live:
            world = run.scene.world
            steps = round(min(BLOCK, seconds - r * BLOCK) / world.config.dt)
            t0 = time.perf_counter()
            for _ in range(steps):
                world.step()
                observe(run.scene, run.state)
            if steps:
                run.blocks.append(1e6 * (time.perf_counter() - t0) / steps)
    # Each block against the defaults' block of the same round (the first run): the machine's
    # load changes from round to round, and a paired ratio cancels it.
    reference = live[0].blocks
    base_us = statistics.median(reference)
    out = []
    for run in live:
        if run is live[0]:
            q = np.percentile(reference, [10, 50, 90])  # its own blocks: paired with itself is 1
        else:
            ratios = [a / b for a, b in zip(run.blocks, reference, strict=True)]
            q = base_us * np.percentile(ratios, [10, 50, 90])
        out.append(
            Run(
                scenario=name,
                knob=run.knob,
                value=run.value,
                measures={m: run.state.get(m, math.nan) for m in measures},
                cost_us=float(q[1]),
                cost_lo=float(q[0]),
                cost_hi=float(q[2]),
                dt=run.scene.world.config.dt,
            )
        )
    return out


def guide(progress: bool = False) -> list[Run]:
    """Every scenario at every setting (a few hundred runs of a few seconds)."""
    bar = None
    if progress:
        import importlib

        bar = importlib.import_module("tqdm").tqdm(
            total=len(SCENARIOS), desc="guide", unit="scenario"
        )
    out: list[Run] = []
    for name in SCENARIOS:
        out += run_scenario(name)
        if bar is not None:
            bar.update(1)
    if bar is not None:
        bar.close()
    return out


HOVER_FREQUENCIES = (2.0, 5.0, 10.0, 20.0, 40.0)
"""Hz: the hover frequencies of the f × dt table."""

HOVER_DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240)
"""s: the steps of the f × dt table."""


def hover_error(frequency: float, damping: float, dt: float) -> float:
    """RMS over 1 s of (height − the continuous damped oscillator's) / drop, for a player released
    5 mm below its ride height; inf if the controller refuses the setting (beyond its limit)."""
    from playground.controller.config import ControllerConfig
    from playground.controller.controller import Controller
    from playground.world.config import WorldConfig
    from playground.world.world import World

    drop = 0.005
    try:
        cfg = ControllerConfig(hover_frequency=frequency, hover_damping=damping, lock_rotation=True)
        world = World(WorldConfig(dt=dt))
        world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
        player = Controller(world, "player", (0.0, 0.05 + cfg.ride_height - drop), config=cfg)
    except ValueError:
        return math.inf
    w0 = 2.0 * math.pi * frequency
    errs = []
    for _ in range(round(1.0 / dt)):
        world.step()
        t = world.time
        x = player.body.position.y - 0.05 - cfg.ride_height
        if damping < 1.0:
            wd = w0 * math.sqrt(1.0 - damping**2)
            exact = (
                -drop
                * math.exp(-damping * w0 * t)
                * (math.cos(wd * t) + damping * w0 / wd * math.sin(wd * t))
            )
        elif damping == 1.0:
            exact = -drop * math.exp(-w0 * t) * (1.0 + w0 * t)
        else:
            s = w0 * math.sqrt(damping**2 - 1.0)
            r1, r2 = -damping * w0 + s, -damping * w0 - s
            exact = -drop * (r2 * math.exp(r1 * t) - r1 * math.exp(r2 * t)) / (r2 - r1)
        errs.append((x - exact) / drop)
    return math.sqrt(statistics.fmean(e * e for e in errs))


def hover_table(damping: float = 1.0) -> dict[tuple[float, float], float]:
    """(frequency Hz, dt s) → :func:`hover_error`, over HOVER_FREQUENCIES × HOVER_DTS."""
    return {(f, dt): hover_error(f, damping, dt) for f in HOVER_FREQUENCIES for dt in HOVER_DTS}
