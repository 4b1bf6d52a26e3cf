"""Chapter 2, reverse force integration (docs/chapters/02-reverse-integration.md): the
engine force against the contact sum and the naive estimate that forgets damping, a joint's share
on the seesaw, and the chapter's figure."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np

from playground.controller.config import ControllerConfig
from playground.world.config import WorldConfig
from playground.world.world import World
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, Array, G, level_scene, record

SLIDE_DAMPING = 0.5
"""Chapter 2's world keeps half its velocity per second: damping large enough to see."""


@cache
def slide_run() -> Array:
    """A 10 kg box thrown sideways at 3 m/s onto a floor, in a world with damping 0.5.

    Columns: t (s), engine force x, y (reverse integration), contact sum x, y, and the naive
    estimate x, y that forgets damping, m·(v₁ − v₀)/dt − m·g (N).
    """
    world = World(WorldConfig(damping=SLIDE_DAMPING, contact_split=True))
    world.add_static_segment((-5.0, 0.0), (20.0, 0.0))
    box = world.add_box("box", mass=10.0, size=(0.5, 0.5), position=(0.0, 0.5), friction=0.3)
    box.velocity = (3.0, 0.0)
    world.track("box")
    last = [box.velocity.x, box.velocity.y]

    def probe(w: World) -> list[float]:
        f = w.forces("box")
        v = box.velocity
        m, dt = box.mass, w.config.dt
        naive = [m * (v.x - last[0]) / dt, m * (v.y - last[1]) / dt + m * G]
        last[:] = [v.x, v.y]
        return [*f.engine, *f.contact, *naive]

    return record(world, 1.5, probe)


@number
def ch2_ghost_exercise() -> float:
    """The exercise's ghost force: 10 kg at 6 m/s, damping 0.9, dt = 1/120 s, N."""
    return 10.0 * (1.0 - float(0.9**DT)) * 6.0 / DT


@number
def ch2_max_disagreement() -> float:
    """Largest |engine − contact sum| over the run, as a fraction of the box's weight."""
    r = slide_run()
    return float(np.max(np.hypot(r[:, 1] - r[:, 3], r[:, 2] - r[:, 4])) / (10.0 * G))


@number
def ch2_ghost_force() -> float:
    """The naive estimate's x force on the first step (nothing touches the box yet), N."""
    return float(slide_run()[0, 5])


@cache
def seesaw_run() -> Array:
    """The seesaw level with the contact split on. Columns: t (s), the plank's engine force y,
    contact y and constraint (joint) y (N), and the hover's reaction on the plank y (N)."""
    scene = level_scene("seesaw", contact_split=True)
    player = scene.controllers["player"]

    def probe(w: World) -> list[float]:
        f = w.forces("plank")
        return [f.engine[1], f.contact[1], f.constraint[1], -player.last_forces.hover[1]]

    return record(scene.world, scene.level.settings.seconds, probe)


def _last_second(r: Array, col: int) -> float:
    return float(np.mean(r[r[:, 0] > r[-1, 0] - 1.0, col]))


@number
def ch2_plank_joint() -> float:
    """Mean joint force on the plank over the last second (the residual engine − contact), N."""
    return _last_second(seesaw_run(), 3)


@number
def ch2_plank_contact() -> float:
    """Mean contact force on the plank over the last second, N."""
    return _last_second(seesaw_run(), 2)


@number
def ch2_total_weight() -> float:
    """Weight of the plank (20 kg) and the player (70 kg), N."""
    return (20.0 + ControllerConfig().mass) * G


@figure("02-reverse-integration.png")
def fig_ch2(path: Path) -> Path:
    """Reverse integration against the contact sum, the naive estimate, and a joint's share."""
    r = slide_run()
    s = seesaw_run()
    fig, (a, b, c) = axes(3, height=2.6)
    a.plot(r[:, 0], r[:, 1], lw=3, alpha=0.5, label="reverse integration (damping included)")
    a.plot(r[:, 0], r[:, 3], "k--", lw=1, label="sum of contact impulses / dt")
    a.plot(r[:, 0], r[:, 5], color="C3", label="naive: m·Δv/dt − m·g (damping forgotten)")
    a.set_ylim(-40.0, 10.0)
    a.set_ylabel("force x (N)")
    a.set_title(
        f"a 10 kg box thrown at 3 m/s, damping 0.5: friction along x "
        f"(clipped: the landing reaches {np.min(r[:, 1]):.0f} N)",
        fontsize=10,
    )
    a.legend(fontsize=8, loc="lower right")
    b.plot(r[:, 0], r[:, 2], lw=3, alpha=0.5, label="reverse integration")
    b.plot(r[:, 0], r[:, 4], "k--", lw=1, label="contact sum")
    b.set_ylabel("force y (N)")
    b.set_xlabel("time (s)")
    b.legend(fontsize=8)
    c.plot(s[:, 0], s[:, 1], lw=3, alpha=0.5, label="plank: engine force (reverse integration)")
    c.plot(s[:, 0], s[:, 2], "k--", label="plank: contact sum")
    c.plot(s[:, 0], s[:, 3], color="C3", label="residual engine − contact = joints")
    c.set_ylim(-100, 1200)
    c.set_xlabel("time (s)")
    c.set_ylabel("force y (N)")
    c.set_title(
        f"seesaw: the pivot carries plank and player (clipped at 1200 N; the plank hitting "
        f"its limit: {np.max(s[:, 1]):.0f} N)",
        fontsize=10,
    )
    c.legend(fontsize=8)
    return save(fig, path)
