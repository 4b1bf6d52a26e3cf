"""Chapter 8, the fixed step (docs/chapters/08-fixed-step.md): the accumulator's steps per
frame, a jump and the hover stepped at different rates, and the chapter's figure."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np

from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.spring import hover_limit
from playground.intents import Intent, Script
from playground.world.config import WorldConfig
from playground.world.world import World
from tools.figures.ch05_floating_capsule import HOVER_DROP, hover_run, hover_theory
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, G

CH8_DISPLAYS = (60.0, 144.0)
"""Display rates of chapter 8's frame timelines, Hz."""

CH8_FRAMES = 24
"""Frames drawn in each timeline."""

CH8_HITCH = 0.1
"""s: one slow frame (a hitch) in chapter 8's 60 Hz timeline."""


def steps_per_frame(frame_times: list[float], dt: float) -> list[int]:
    """Physics steps a fixed-step accumulator runs at each frame of the given wall durations (s):
    the whole steps of ``dt`` that fit in the time so far, less those already run. (This is the
    view's Accumulator without its cap on steps per frame.)

    >>> steps_per_frame([1 / 60] * 4, 1 / 120)
    [2, 2, 2, 2]
    """
    total, done, out = 0.0, 0, []
    for elapsed in frame_times:
        total += elapsed
        n = int((total + 1e-9 * dt) // dt) - done
        done += n
        out.append(n)
    return out


@number
def ch8_idle_frames_144() -> float:
    """Share of a 144 Hz display's frames that run no physics step at dt = 1/120 s, %."""
    n = steps_per_frame([1.0 / 144.0] * 144, DT)
    return 100.0 * n.count(0) / len(n)


@number
def ch8_hitch_steps() -> float:
    """Steps the accumulator runs on one 0.1 s frame at dt = 1/120 s."""
    return float(steps_per_frame([CH8_HITCH], DT)[0])


@cache
def jump_apex(dt: float) -> float:
    """How high the default player's jump lifts its centre, m, with physics stepped at ``dt``."""
    world = World(WorldConfig(dt=dt))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    script = Script(((0.0, Intent()), (1.0, Intent(jump=True)), (1.1, Intent())))
    player = Controller(world, "player", (0.0, 0.95), source=script)
    world.run(1.0)
    y0 = top = player.body.position.y
    for _ in range(round(1.5 / dt)):
        world.step()
        top = max(top, player.body.position.y)
    return top - y0


CH8_RATES = (20.0, 30.0, 60.0, 120.0, 144.0, 240.0)
"""Hz: the rates chapter 8 steps the jump at, as a game that steps at its display rate would."""


@number
def ch8_apex_60() -> float:
    """Jump apex at dt = 1/60 s, cm."""
    return 100.0 * jump_apex(1.0 / 60.0)


@number
def ch8_apex_144() -> float:
    """Jump apex at dt = 1/144 s, cm."""
    return 100.0 * jump_apex(1.0 / 144.0)


@number
def ch8_apex_exact() -> float:
    """The continuous apex v²/(2g) of the 4 m/s take-off, cm."""
    v = ControllerConfig().jump_speed
    return 100.0 * v * v / (2.0 * G)


@number
def ch8_apex_first_order_60() -> float:
    """v²/(2g) + v·dt/2 at dt = 1/60 s: the first-order estimate of the stepped apex, cm."""
    v = ControllerConfig().jump_speed
    return ch8_apex_exact() + 100.0 * v * (1.0 / 60.0) / 2.0


@number
def ch8_hover_limit_hitch() -> float:
    """The highest hover frequency (ζ = 1) still stable on a 0.1 s step, Hz."""
    return hover_limit(1.0) / (2.0 * math.pi * CH8_HITCH)


@number
def ch8_hover_overshoot_20() -> float:
    """Overshoot of the critically damped 5 Hz hover stepped at 1/20 s, fraction of the drop."""
    return float(np.max(hover_run(1.0, 1.0 / 20.0)[:, 1]) / HOVER_DROP)


@number
def ch8_hover_overshoot_120() -> float:
    """The same at the levels' 1/120 s (critical damping: no overshoot in theory)."""
    return float(np.max(hover_run(1.0, DT)[:, 1]) / HOVER_DROP)


@figure("08-fixed-step.png")
def fig_ch8(path: Path) -> Path:
    """Steps per frame of the accumulator; the jump stepped at display rates; the hover's dt."""
    fig, (a, b, c) = axes(3, height=2.7)
    frames = np.arange(1, CH8_FRAMES + 1)
    for i, hz in enumerate(CH8_DISPLAYS):
        n = steps_per_frame([1.0 / hz] * CH8_FRAMES, DT)
        a.step(frames, np.array(n) + 0.06 * i, where="mid", label=f"{hz:g} Hz display")
    hitch = [1.0 / 60.0] * CH8_FRAMES
    hitch[CH8_FRAMES // 2] = CH8_HITCH
    a.step(
        frames, np.array(steps_per_frame(hitch, DT)) - 0.06, where="mid",
        ls="--", label=f"60 Hz display, one {1000 * CH8_HITCH:.0f} ms hitch",
    )  # fmt: skip
    a.set_xlabel("frame")
    a.set_ylabel("physics steps run")
    a.set_title("fixed step dt = 1/120 s: the accumulator runs whole steps, whatever the display")
    a.legend(fontsize=8)
    rates = np.array(CH8_RATES)
    b.plot(rates, [100 * jump_apex(1.0 / r) for r in rates], "o-", label="simulated apex")
    b.axhline(ch8_apex_exact(), color="k", ls="--", lw=1, label="v²/2g (continuous)")
    b.set_xscale("log")
    b.set_xticks(rates, [f"{r:g}" for r in rates])
    b.minorticks_off()
    b.set_xlabel("physics rate 1/dt (Hz) — what a game stepping at its display rate would get")
    b.set_ylabel("jump height (cm)")
    b.set_title("the same jump, stepped at different rates")
    b.legend(fontsize=8)
    for dt, color in ((1.0 / 20.0, "C3"), (1.0 / 60.0, "C1"), (DT, "C0")):
        h = hover_run(1.0, dt)
        c.plot(h[:, 0], 1000 * h[:, 1], ".-", color=color, ms=4, label=f"dt = 1/{round(1 / dt)} s")
    c.plot(
        hover_run(1.0)[:, 0], 1000 * hover_theory(1.0, hover_run(1.0)[:, 0]), "k--", lw=1,
        label="continuous",
    )  # fmt: skip
    c.set_xlabel("time (s)")
    c.set_ylabel("height − ride height (mm)")
    c.set_title("the 5 Hz, ζ = 1 hover released 5 mm low, at three steps")
    c.legend(fontsize=8)
    return save(fig, path)
