"""Laws of the hover spring: stable exactly below :func:`hover_limit` for any number of substeps,
an undamped spring keeps its swing, and a spring unstable at the world's dt is refused."""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Controller, ControllerConfig, World
from playground.controller import hover_limit, hover_spring
from playground.world import Stage, WorldConfig


def flat_world() -> World:
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    return world


def test_unstable_hover_spring_is_refused() -> None:
    """The hover spring must satisfy 2π·f·dt < 2ζ + 2√(ζ² + 1) for the world's dt: a frequency
    just above the limit is refused, naming the field; just below is accepted."""
    with pytest.raises(ValueError, match="hover_frequency"):
        Controller(flat_world(), "player", (0.0, 1.0), ControllerConfig(hover_frequency=100.0))
    dt = WorldConfig().dt
    for zeta in (0.0, 1.0):
        f_max = hover_limit(zeta) / (2.0 * math.pi * dt)
        with pytest.raises(ValueError, match="hover_frequency"):
            Controller(
                flat_world(),
                "p",
                (0.0, 1.0),
                ControllerConfig(hover_frequency=1.01 * f_max, hover_damping=zeta),
            )
        Controller(
            flat_world(),
            "p",
            (0.0, 1.0),
            ControllerConfig(hover_frequency=0.99 * f_max, hover_damping=zeta),
        )


LIMIT_MARGIN = 0.02
"""Relative distance from the stability limit on 2πf·dt for the bounded/growing runs: close
enough to show the limit is where the formula puts it, far enough that the growth per step
shows within a second."""

GROWTH = 10.0
"""An unstable swing grows past this factor of its start in 1 s; a stable one never does (an
undamped one at 0.98 of the limit stays on semi-implicit Euler's invariant ellipse, at most
1/√(1 − 0.98²) ≈ 5× its start)."""

SWING_START = 1e-6
"""m: the spring's initial stretch (small, so a growing swing stays far from 1 m)."""


def spring_swing(omega_dt: float, zeta: float, substeps: int, seconds: float = 1.0) -> float:
    """A 1 kg body in zero gravity on :func:`hover_spring` (k = ω², c = 2ζω), the force put on it
    before each step as the hover does, released at rest SWING_START from rest length. Returns
    the largest |x| in the last tenth of the run, m."""
    world = World(WorldConfig(substeps=substeps), gravity=(0.0, 0.0))
    body = pymunk.Body(1.0, math.inf)
    world.add("bob", body)
    body.position = (SWING_START, 0.0)
    dt = world.config.dt
    w = omega_dt / dt
    k, c = w * w, 2.0 * zeta * w
    swing: list[float] = []

    def spring(wd: World) -> None:
        x, v = body.position.x, body.velocity.x
        swing.append(abs(x))
        if abs(x) < 1.0:
            wd.apply_force(body, (hover_spring(k, c, 1.0, -x, v, dt, substeps), 0.0))

    world.on(Stage.CONTROL, spring)
    world.run(seconds)
    return max(swing[-len(swing) // 10 :])


@pytest.mark.parametrize("substeps", [1, 4])
@pytest.mark.parametrize("zeta", [0.0, 0.5, 1.0])
def test_hover_spring_is_stable_exactly_below_its_limit(zeta: float, substeps: int) -> None:
    """Law (semi-implicit hover, any substeps): just below 2πf·dt = 2ζ + 2√(ζ² + 1) the swing
    stays bounded (undamped, it keeps its size: symplectic); just above it grows."""
    limit = hover_limit(zeta)
    assert spring_swing((1.0 - LIMIT_MARGIN) * limit, zeta, substeps) < GROWTH * SWING_START
    assert spring_swing((1.0 + LIMIT_MARGIN) * limit, zeta, substeps) > GROWTH * SWING_START


def test_an_undamped_hover_keeps_its_swing() -> None:
    """Law: an undamped hover (ζ = 0) at the default 5 Hz and dt conserves its energy instead of
    gaining it: the swing never exceeds the start's drop by more than semi-implicit Euler's
    invariant ellipse allows, drop/√(1 − (ωdt/2)²)."""
    cfg = ControllerConfig(hover_damping=0.0, lock_rotation=True)
    world = flat_world()
    floor_top = 0.05
    drop = 0.005
    player = Controller(world, "player", (0.0, floor_top + cfg.ride_height - drop), cfg)
    w = 2.0 * math.pi * cfg.hover_frequency * world.config.dt
    bound = drop / math.sqrt(1.0 - (w / 2.0) ** 2)
    peak = 0.0
    for _ in range(round(4.0 / world.config.dt)):
        world.step()
        peak = max(peak, abs(player.body.position.y - floor_top - cfg.ride_height))
    assert peak <= bound * (1.0 + TOL_SWING_REL)
    assert peak >= drop * (1.0 - TOL_SWING_REL)


TOL_SWING_REL = 1e-6
"""Relative: the undamped hover's peak against the invariant ellipse's (float rounding over
480 steps, far below the 0.9 % the ellipse itself allows)."""
