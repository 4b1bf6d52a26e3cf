"""The scalar implementation stays scalar: a step of a world with one tracked body calls neither
numpy nor ``pymunk.batch`` (counted through patched modules), so the fast path cannot silently
regress: a bare world, a level with the contact split and a level with a field that varies in space.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from typing import Any

import numpy
import pymunk.batch
import pytest

from playground import Stage, World, WorldConfig
from playground.forces.scalar.bodies import _add_forces
from playground.gravity import Uniform
from playground.level import find, load
from playground.scene import build
from playground.world.guard import GUARD_EVERY

TOL_FIELD = 0.01
"""Relative: the field's force is taken where the player was when the step began; walking at
1.2 m/s it has since moved 1 cm around a radius of 11 m, which turns the field by 1e-3 rad."""

TOL_SETTLING = 1e-3
"""Relative: the box still settles half a second after it is placed (its support reads
−0.6 mN sideways on 19.6 N); a thousandth says it reads its weight and feels g."""


class Counting:
    """Stands in for a module: every function (and ufunc) read from it counts its calls."""

    def __init__(self, module: Any, calls: list[str]) -> None:
        self._module = module
        self._calls = calls

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._module, name)
        if not callable(value) or isinstance(value, type):
            return value  # constants, and dtypes (passed as dtype=, compared with is)
        calls = self._calls

        def counted(*args: Any, **kwargs: Any) -> Any:
            calls.append(name)
            return value(*args, **kwargs)

        return counted


def counting(monkeypatch: pytest.MonkeyPatch) -> tuple[list[str], list[str]]:
    """Patch numpy in every loaded module of the package that imports it as ``np`` (controller,
    world stages, solver, filters, ...) and the batch functions; returns the two call logs."""
    np_calls: list[str] = []
    batch_calls: list[str] = []
    stand_in = Counting(numpy, np_calls)
    for name, module in list(sys.modules.items()):
        if name.startswith("playground.") and getattr(module, "np", None) is numpy:
            monkeypatch.setattr(module, "np", stand_in)
    for name in ("get_space_bodies", "set_space_bodies", "get_space_arbiters"):
        original: Callable[..., Any] = getattr(pymunk.batch, name)

        def counted(*args: Any, _f: Callable[..., Any] = original, _n: str = name) -> Any:
            batch_calls.append(_n)
            return _f(*args)

        monkeypatch.setattr(pymunk.batch, name, counted)
    return np_calls, batch_calls


def between_checks(world: World, monkeypatch: pytest.MonkeyPatch) -> tuple[list[str], list[str]]:
    """Step from just after one full check of all bodies (a batch read every GUARD_EVERY steps)
    to just before the next, counting; returns the numpy and the batch calls."""
    while world.steps % GUARD_EVERY != 1:
        world.step()
    np_calls, batch_calls = counting(monkeypatch)
    for _ in range(GUARD_EVERY - 2):
        world.step()
    return np_calls, batch_calls


def one_box() -> World:
    """A box resting on a floor, tracked and perceived; uniform gravity, the default config."""
    world = World(WorldConfig(timing=False))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0), radius=0.05)
    world.add_box("box", mass=2.0, size=(0.5, 0.5), position=(0.0, 0.3))
    world.track("box")
    return world


def test_one_tracked_body_steps_without_numpy_or_batch(monkeypatch: pytest.MonkeyPatch) -> None:
    """Law: between the every-GUARD_EVERY-steps check of all bodies (one batch read), a step of a
    world with one tracked, perceived body makes no numpy call and no batch call, and still
    reads the box's support (its weight) and perceived gravity (g)."""
    world = one_box()
    ran: list[Stage] = []
    world.on(Stage.OBSERVE, lambda w: ran.append(Stage.OBSERVE))
    np_calls, batch_calls = between_checks(world, monkeypatch)
    assert np_calls == []
    assert batch_calls == []
    # It did the work: a reading and perceived gravity, as the batch implementation gives them.
    f = world.forces("box")
    assert f.valid
    assert f.support == pytest.approx((0.0, 2.0 * 9.81), abs=TOL_SETTLING * 2.0 * 9.81)
    assert world.perceived_gravity("box") == pytest.approx((0.0, -9.81), abs=TOL_SETTLING * 9.81)
    world.step()  # the full check: its one batch read, nothing else
    world.step()
    assert batch_calls == ["get_space_bodies"]


def test_the_count_sees_the_vectorised_path(monkeypatch: pytest.MonkeyPatch) -> None:
    """The counting itself works: with the scalar implementation off, the same steps call both."""
    world = one_box()
    world.scalar_max_bodies = 0
    world.step()
    np_calls, batch_calls = counting(monkeypatch)
    world.step()
    assert np_calls and batch_calls


@pytest.mark.parametrize("level", ["rest", "planet"])
def test_a_one_player_level_steps_without_numpy_or_batch(
    level: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Law: between full checks, a step of ``rest`` (the contact split on) and of ``planet`` (a
    radial field: a force per body) with its one player makes no numpy call and no batch call,
    controller included, and reads the split or the field."""
    world = build(load(find(level))).world
    assert len(world.tracked_bodies) == 1
    # What the level asks of the step: the case this test is for.
    if level == "rest":
        assert world.config.contact_split
    else:
        assert not isinstance(world.gravity, Uniform) and not world.gravity.uniform
    assert between_checks(world, monkeypatch) == ([], [])
    assert world.tracked_kind == "scalar"
    f = world.forces("player")
    assert f.valid
    if level == "rest":  # hovering: nothing touches the player, a known split of zero
        assert f.split_valid and f.contact == (0.0, 0.0)
    else:  # the field's pull on the player (0.83 g where it hovers) is its passive force
        m = world.body("player").mass
        gx, gy = world.gravity_at("player")
        assert math.dist(f.passive, (m * gx, m * gy)) <= TOL_FIELD * m * math.hypot(gx, gy)


def test_the_write_adds_to_the_force_and_spares_an_idle_sleeper() -> None:
    """Law: a field's force handed body by body adds to what a body has; with sleeping on, a body
    left with no force and no torque is not written (a write restarts its idle clock), so it falls
    asleep; written every step it never does."""
    space = pymunk.Space()
    space.sleep_time_threshold = 0.3
    space.idle_speed_threshold = 0.01
    pushed, idle = pymunk.Body(2.0, 1.0), pymunk.Body(2.0, 1.0)
    idle.position = (5.0, 0.0)
    for body in (pushed, idle):
        space.add(body, pymunk.Circle(body, 0.5))
    pushed.force = (1.0, 2.0)
    _add_forces({pushed: (0.5, -3.0)}, sleeping=True)
    assert pushed.force == (1.5, -1.0)
    for sleeping, asleep in ((False, False), (True, True)):
        idle.activate()
        for _ in range(20):  # 2 s, well past the threshold
            _add_forces({idle: (0.0, 0.0)}, sleeping=sleeping)
            space.step(0.1)
        assert idle.is_sleeping is asleep
