"""Stability: hard scenes × dt × solver iterations keep every invariant, every step.

The scenes and the invariants live in :mod:`tools.stability` (the stability chapter
draws the same matrix); :func:`~tools.stability.run_checked` raises an
``InvariantError`` (an AssertionError) naming the step and the invariant at the first breach.
"""

from __future__ import annotations

import math

import pytest

from playground.controller import Controller, ControllerConfig
from playground.intents import Idle, Intent, Script
from playground.world import World, WorldConfig
from tools.stability import SCENES, check_budgets, run_checked

DTS = (1 / 60, 1 / 240)
"""Steps of the matrix, s: a coarse game rate and a fine one."""

ITERATIONS = (2, 10)
"""Solver iterations of the matrix: starved and the default."""


@pytest.mark.parametrize("iterations", ITERATIONS)
@pytest.mark.parametrize("dt", DTS, ids=lambda dt: f"dt=1/{round(1 / dt)}")
@pytest.mark.parametrize("scene", list(SCENES))
def test_hard_scene_keeps_invariants(scene: str, dt: float, iterations: int) -> None:
    """Law: a hard scene keeps every invariant of the module doc at every step."""
    run_checked(SCENES[scene](WorldConfig(dt=dt, iterations=iterations)))


@pytest.mark.parametrize("dt", [1 / 20, 1e-4], ids=["dt=1/20", "dt=1e-4"])
@pytest.mark.parametrize("scene", ["crusher", "elastic chaos", "gravity flip"])
def test_extreme_dt_keeps_invariants(scene: str, dt: float) -> None:
    """Law: the invariants hold at extreme steps too (20 Hz physics, and 10 kHz).

    At 1/20 s the default 5 Hz hover is near its stability limit (2π·f·dt = 1.57 < 2).
    """
    hard = SCENES[scene](WorldConfig(dt=dt))
    run_checked(hard, seconds=min(hard.seconds, 1000 * dt))


IDLE_DRIFT = 1e-3
"""An idle player may drift at most 1 mm (the issue's bound)."""


def _idle_drift(seconds: float) -> float:
    world = World()
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0), radius=0.05)
    player = Controller(world, "player", position=(0.0, 1.0), source=Idle())
    world.run(2.0)  # land and settle
    x0, y0 = player.body.position
    world.run(seconds)
    assert all(math.isfinite(v) for v in player.body.position)
    check_budgets(player, "end")
    x1, y1 = player.body.position
    return math.hypot(x1 - x0, y1 - y0)


def test_idle_player_does_not_drift() -> None:
    """Law: an idle player standing on flat ground for a simulated minute drifts < 1 mm."""
    assert _idle_drift(60.0) < IDLE_DRIFT


@pytest.mark.slow
def test_idle_player_does_not_drift_for_ten_minutes() -> None:
    """Law: ... and for ten simulated minutes."""
    assert _idle_drift(600.0) < IDLE_DRIFT


def test_controller_budget_config_is_used() -> None:
    """Law: a smaller budget bounds the commanded force (the budget check is not vacuous)."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0), radius=0.05)
    cfg = ControllerConfig(ground_force=50.0)
    player = Controller(
        world, "player", position=(0.0, 1.0), config=cfg,
        source=Script(((0.0, Intent()), (1.0, Intent(move=1.0)))),
    )  # fmt: skip
    peak = 0.0
    for _ in range(240):
        world.step()
        check_budgets(player, "budget")
        peak = max(peak, math.hypot(*player.last_forces.drive))
    assert peak == pytest.approx(cfg.ground_force)
