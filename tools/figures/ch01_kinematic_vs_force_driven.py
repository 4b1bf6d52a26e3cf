"""Chapter 1, kinematic and force-driven characters
(docs/chapters/01-kinematic-vs-force-driven.md): who stays on an accelerating platform, the
player's drift with and without the ground's acceleration fed forward, and the chapter's figure."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pymunk

from playground.controller.config import ControllerConfig
from playground.world.world import World
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, Array, record


@cache
def platform_run(acceleration: float = 1.0, feed_forward: bool = True) -> Array:
    """The moving_platform level (its platform accelerating at ``acceleration``, m/s², for 1 s),
    plus a kinematic character placed beside the player; ``feed_forward`` False runs it under
    the ``ground_acceleration_ignored`` break (the drive no longer feeds the platform's
    acceleration forward).

    Columns: t (s), platform x, player x, kinematic character x (m), drive force x (N).
    The kinematic character's velocity is its input (zero): nothing the world does can move it.
    """
    if not feed_forward:
        from playground.faults.catalog import apply

        with apply("ground_acceleration_ignored"):
            return _platform_run(acceleration)
    return _platform_run(acceleration)


def _platform_run(acceleration: float) -> Array:
    from playground.level.files import find
    from playground.level.loading import load
    from playground.scene import build

    level = load(find("moving_platform"))
    mover = level.movers[0]
    path = mover.path.model_copy(update={"acceleration": acceleration})
    level = level.model_copy(update={"movers": [mover.model_copy(update={"path": path})]})
    scene = build(level)
    world = scene.world
    kin = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    kin.position = (0.0, 0.95)
    world.add("kinematic", kin)
    player = scene.controllers["player"]

    def probe(w: World) -> list[float]:
        kin.velocity = (0.0, 0.0)  # input says "stand still": a kinematic body obeys exactly
        return [
            w.body("platform").position.x,
            w.body("player").position.x,
            kin.position.x,
            player.last_forces.drive[0],
        ]

    return record(world, scene.level.settings.seconds, probe)


@number
def ch1_platform_travel() -> float:
    """How far the platform travels during the level, m."""
    r = platform_run()
    return float(r[-1, 1] - r[0, 1])


@number
def ch1_player_drift_cm(acceleration: float = 1.0, feed_forward: bool = True) -> float:
    """Largest drift of the force-driven player relative to the platform, cm."""
    r = platform_run(acceleration, feed_forward)
    rel = (r[:, 2] - r[:, 1]) - (r[0, 2] - r[0, 1])
    return float(np.max(np.abs(rel)) * 100.0)


@number
def ch1_predicted_drift_cm() -> float:
    """Drift with the ground's acceleration fed forward: the acceleration is read one step late
    where it starts, a velocity gap a·dt closed with time constant τ: a·dt·τ (1 m/s², 1/120 s,
    0.05 s), cm."""
    return 1.0 * DT * ControllerConfig().drive_time * 100.0


@number
def ch1_lag_drift_cm() -> float:
    """Drift of a drive without the feed-forward, a first-order lag: a·τ·T (1 m/s², 0.05 s,
    1 s), cm."""
    return 1.0 * ControllerConfig().drive_time * 1.0 * 100.0


@number
def ch1_lag_simulated_cm() -> float:
    """The level's drift under the ``ground_acceleration_ignored`` break, cm."""
    return ch1_player_drift_cm(1.0, feed_forward=False)


@number
def ch1_drift_2_cm() -> float:
    """The exercise: the same drift with the platform accelerating at 2 m/s², cm."""
    return ch1_player_drift_cm(2.0)


@number
def ch1_budget_accel() -> float:
    """The largest acceleration the drive budget can follow: ground_force / mass, m/s²."""
    c = ControllerConfig()
    return c.ground_budget(c.mass) / c.mass


@number
def ch1_kinematic_drift() -> float:
    """Drift of the kinematic character relative to the platform at the end, m."""
    r = platform_run()
    rel = (r[:, 3] - r[:, 1]) - (r[0, 3] - r[0, 1])
    return float(abs(rel[-1]))


@number
def ch1_drive_accel() -> float:
    """Mean drive force while the platform accelerates (t in [0.75, 1.5] s), N."""
    r = platform_run()
    window = (r[:, 0] >= 0.75) & (r[:, 0] <= 1.5)
    return float(np.mean(r[window, 4]))


@figure("01-kinematic-vs-force-driven.png")
def fig_ch1(path: Path) -> Path:
    """Drift relative to the platform (the kinematic character's, then the player's with and
    without the feed-forward, in mm), and the drive force that carries the player."""
    r = platform_run()
    lag = platform_run(feed_forward=False)

    def rel(run: Array, col: int) -> Array:
        out: Array = (run[:, col] - run[:, 1]) - (run[0, col] - run[0, 1])
        return out

    fig, (a, b, c) = axes(3, height=2.6)
    a.plot(r[:, 0], 100 * rel(r, 2), label="force-driven player")
    a.plot(r[:, 0], 100 * rel(r, 3), label="kinematic character")
    a.set_ylabel("x relative to platform (cm)")
    a.set_title("moving_platform: who stays on the platform?")
    a.legend()
    b.plot(r[:, 0], 1000 * rel(r, 2), label="force-driven player")
    b.plot(lag[:, 0], 1000 * rel(lag, 2), ls=":", color="C3", label="acceleration not fed forward")
    b.set_ylabel("x relative to platform (mm)")
    b.set_title("the force-driven player, closer")
    b.legend()
    c.plot(r[:, 0], r[:, 4], color="C2", label="drive force on the player")
    c.axhline(70.0, color="k", ls="--", lw=1, label="m·a = 70 kg · 1 m/s²")
    c.set_xlabel("time (s)")
    c.set_ylabel("drive force x (N)")
    c.legend()
    return save(fig, path)
