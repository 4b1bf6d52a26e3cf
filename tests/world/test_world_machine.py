"""A stateful fuzzer over the World API (hypothesis' RuleBasedStateMachine): bodies added and
removed, tracked, pushed, jointed, put to sleep, their gravity changed, hooks and events that
call the API from inside a step — including a step — and steps in between. The law: every call
returns or raises the World's own errors (ValueError or KeyError naming the argument,
WorldUsageError for a call at the wrong moment, RunawayError from the guard), never a foreign
exception (AssertionError, pymunk's bare Exception, RecursionError, ZeroDivisionError...), and
every body stays finite.

Every run makes :data:`CI_RUNS` runs of the machine; the ``slow`` tier :data:`SLOW_RUNS`, at
least :data:`SLOW_CALLS` API calls in all (the issue's acceptance: 50 000).
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Callable
from typing import Any

import pymunk
import pytest
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from hypothesis.stateful import RuleBasedStateMachine, invariant, rule

from playground import World, WorldConfig
from playground.gravity import GravityRule, Radial, Uniform
from playground.world.errors import WorldUsageError
from playground.world.guard import GUARD_EVERY, RunawayError
from playground.world.schedule import Stage

CI_RUNS = 30
"""Runs of the machine every run (a couple of seconds)."""

SLOW_RUNS = 600
"""Runs in the ``slow`` tier."""

STEPS_PER_RUN = 100
"""Rules per run: SLOW_RUNS × STEPS_PER_RUN ≥ SLOW_CALLS."""

SLOW_CALLS = 50_000
"""API calls the slow tier must make (counted, not assumed)."""

OWN_ERRORS = (ValueError, KeyError, WorldUsageError, RunawayError)
"""What the World may raise: its own refusals (ValueError includes pymunk-free NaN checks)."""

NAMES = st.sampled_from(["a", "b", "c", "d", "ghost"])
NUMBER = st.sampled_from([0.0, 1.0, -3.5, 10.0, 1e-9, 1e6, 1e300, math.nan, math.inf, -math.inf])
VEC = st.tuples(NUMBER, NUMBER)
CALLS = [0]
"""API calls made so far (the slow tier checks the total)."""


def _fresh() -> World:
    world = World(WorldConfig(sleep_time=0.5))
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    return world


def _finite(body: pymunk.Body) -> bool:
    state = (*body.position, *body.velocity, body.angle, body.angular_velocity)
    return all(math.isfinite(v) for v in state)


class WorldMachine(RuleBasedStateMachine):
    """One world, driven through its public API."""

    def __init__(self) -> None:
        super().__init__()
        self.world = _fresh()

    def call(self, action: Callable[[], object]) -> None:
        """Make one API call: it returns or raises one of :data:`OWN_ERRORS`."""
        CALLS[0] += 1
        with contextlib.suppress(*OWN_ERRORS):
            action()

    def _body(self, name: str) -> pymunk.Body:
        return self.world.body(name) if name != "static" else self.world.space.static_body

    @rule(name=NAMES, mass=NUMBER, size=VEC, position=VEC)
    def add_box(self, name: str, mass: float, size: tuple[float, float], position: Any) -> None:
        self.call(lambda: self.world.add_box(name, mass=mass, size=size, position=position))

    @rule(name=NAMES, x=st.floats(-10.0, 10.0), y=st.floats(0.5, 10.0))
    def add_plain_box(self, name: str, x: float, y: float) -> None:
        self.call(lambda: self.world.add_box(name, mass=2.0, size=(1.0, 1.0), position=(x, y)))

    @rule(name=NAMES)
    def remove(self, name: str) -> None:
        self.call(lambda: self.world.remove(name))

    @rule(name=NAMES, perceive=st.booleans())
    def track(self, name: str, perceive: bool) -> None:
        self.call(lambda: self.world.track(name, perceive=perceive))

    @rule(name=NAMES, force=VEC, point=st.none() | VEC)
    def apply_force(self, name: str, force: Any, point: Any) -> None:
        self.call(lambda: self.world.apply_force(name, force, point=point))

    @rule(name=NAMES, impulse=VEC)
    def apply_impulse(self, name: str, impulse: Any) -> None:
        self.call(lambda: self.world.apply_impulse(name, impulse))

    @rule(name=NAMES, torque=NUMBER)
    def apply_torque(self, name: str, torque: float) -> None:
        self.call(lambda: self.world.apply_torque(name, torque))

    @rule(name=NAMES, scale=NUMBER, direction=st.none() | VEC)
    def gravity_rule(self, name: str, scale: float, direction: Any) -> None:
        self.call(lambda: self.world.set_gravity_rule(name, GravityRule(scale, direction)))

    @rule(name=NAMES)
    def restore_gravity(self, name: str) -> None:
        self.call(lambda: self.world.set_gravity_rule(name, None))

    @rule(g=VEC, radial=st.booleans())
    def field(self, g: Any, radial: bool) -> None:
        def change() -> None:
            self.world.gravity = Radial((0.0, -20.0), g[0]) if radial else Uniform(g)

        self.call(change)

    @rule(name=NAMES, mass=NUMBER, moment=st.none() | NUMBER)
    def set_mass(self, name: str, mass: float, moment: float | None) -> None:
        self.call(lambda: self.world.set_mass(name, mass, moment))

    @rule(
        kind=st.sampled_from(["pivot", "pin", "gear", "spring", "motor"]),
        a=st.sampled_from(["a", "b", "c", "static"]),
        b=st.sampled_from(["a", "b", "c", "static"]),
        value=NUMBER,
    )
    def joint(self, kind: str, a: str, b: str, value: float) -> None:
        def add() -> None:
            ba, bb = self._body(a), self._body(b)
            if ba is bb or all(x.body_type != pymunk.Body.DYNAMIC for x in (ba, bb)):
                return  # pymunk's own constructor refuses these (its assert, not our path)
            joint: pymunk.Constraint
            if kind == "pivot":
                joint = pymunk.PivotJoint(ba, bb, (0.0, 1.0))
            elif kind == "pin":
                joint = pymunk.PinJoint(ba, bb)
            elif kind == "gear":
                joint = pymunk.GearJoint(ba, bb, 0.0, value)
            elif kind == "spring":
                joint = pymunk.DampedSpring(ba, bb, (0, 0), (0, 0), 1.0, value, 1.0)
            else:
                joint = pymunk.SimpleMotor(ba, bb, value)
            self.world.add_constraint(joint)

        self.call(add)

    @rule(name=NAMES)
    def sleep(self, name: str) -> None:
        self.call(lambda: self.world.sleep(name))

    @rule(name=NAMES)
    def wake(self, name: str) -> None:
        self.call(lambda: self.world.wake(name))

    @rule(
        stage=st.sampled_from(list(Stage)),
        what=st.sampled_from(["step", "track", "remove", "add", "sleep", "impulse"]),
        name=NAMES,
        once=st.booleans(),
    )
    def hook(self, stage: Stage, what: str, name: str, once: bool) -> None:
        """A hook (or a timed event) that calls the API from inside a step."""
        world = self.world

        def inside(w: World) -> None:
            actions: dict[str, Callable[[], object]] = {
                "step": w.step,
                "track": lambda: w.track(name),
                "remove": lambda: w.remove(name),
                "add": lambda: w.add_box(name, mass=1.0, size=(0.5, 0.5), position=(0.0, 4.0)),
                "sleep": lambda: w.sleep(name),
                "impulse": lambda: w.apply_impulse(name, (0.0, 1.0)),
            }
            self.call(actions[what])

        if once:
            self.call(lambda: world.at(world.time + world.config.dt, inside))
        else:
            self.call(lambda: world.on(stage, inside))

    @rule(n=st.integers(1, 5))
    def step(self, n: int) -> None:
        for _ in range(n):
            self.call(self.world.step)

    @invariant()
    def bodies_are_finite_or_reported(self) -> None:
        """Every body is finite — or, where finite parameters made an unstable system blow up,
        the guard reports it (RunawayError) within :data:`GUARD_EVERY` steps, as documented."""
        if all(_finite(self.world.body(n)) for n in self.world.names):
            return
        with pytest.raises(RunawayError):
            for _ in range(GUARD_EVERY + 1):
                self.world.step()
        self.world = _fresh()


def _run(runs: int) -> int:
    """Run the machine ``runs`` times with a fixed seed; the API calls it made."""
    before = CALLS[0]
    test = WorldMachine.TestCase
    test.settings = settings(
        max_examples=runs,
        stateful_step_count=STEPS_PER_RUN,
        derandomize=True,
        deadline=None,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    test("runTest").runTest()
    return CALLS[0] - before


def test_world_api_machine_ci() -> None:
    """Law: :data:`CI_RUNS` runs of the machine raise nothing foreign and keep every body
    finite."""
    calls = _run(CI_RUNS)
    print(f"world machine: {calls} API calls")
    assert calls >= CI_RUNS


@pytest.mark.slow
def test_world_api_machine_slow() -> None:
    """The same law over :data:`SLOW_RUNS` runs, at least :data:`SLOW_CALLS` API calls."""
    calls = _run(SLOW_RUNS)
    print(f"world machine (slow): {calls} API calls")
    assert calls >= SLOW_CALLS
