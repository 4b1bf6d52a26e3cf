"""Hostile calls to the world's public API: absurd arguments are refused with a ValueError naming
the argument, sleeping is safe in every state, and nothing ever aborts inside Chipmunk or leaves
NaN behind. Cases that could abort the process run in a subprocess, so an abort fails the test
instead of killing the run."""

from __future__ import annotations

import math
import re
import subprocess
import sys
import textwrap
from typing import Any

import pymunk
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from playground import Category, Intent, World, WorldConfig
from playground.controller import Controller
from playground.limits import MAX_COORDINATE, MAX_GRAVITY, MAX_MASS
from playground.world.guard import RunawayError

NAN, INF = math.nan, math.inf


def _world() -> World:
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    world.add_box("free", mass=2.0, size=(0.5, 0.5), position=(5.0, 3.0))
    world.track("crate")
    return world


@pytest.mark.parametrize(
    ("call", "argument"),
    [
        (lambda w: w.add_box("b", mass=1.0, size=(NAN, 1.0), position=(0.0, 2.0)), "size"),
        (lambda w: w.add_box("b", mass=1.0, size=(1e308, 1.0), position=(0.0, 2.0)), "size"),
        (lambda w: w.add_box("b", mass=1.0, size=(0.0, 1.0), position=(0.0, 2.0)), "size"),
        (lambda w: w.add_box("b", mass=1.0, size=(1.0, 1.0), position=(NAN, 2.0)), "position"),
        (lambda w: w.add_box("b", mass=1.0, size=(1.0, 1.0), position=(1e16, 2.0)), "position"),
        (lambda w: w.add_box("b", mass=1.0, size=(1.0, 1.0), position=(0, 2), angle=INF), "angle"),
        (lambda w: w.add_box("b", mass=1e308, size=(1.0, 1.0), position=(0.0, 2.0)), "mass"),
        (lambda w: w.add_box("b", mass=5e-324, size=(1.0, 1.0), position=(0.0, 2.0)), "mass"),
        (lambda w: w.apply_force("crate", (NAN, 0.0)), "force"),
        (lambda w: w.apply_force("crate", (1e300, 0.0)), "force"),
        (lambda w: w.apply_force("crate", (1.0, 0.0), point=(NAN, 0.0)), "point"),
        (lambda w: w.apply_force("crate", (1.0, 0.0), point=(1e300, 0.0)), "point"),
        (lambda w: w.apply_forces(w.body("crate"), [(0.0, NAN, Category.SUPPORT)]), "force"),
        (lambda w: w.apply_forces(w.body("crate"), [(1e300, 0.0, Category.SUPPORT)]), "force"),
        (lambda w: w.apply_forces(w.body("crate"), [], NAN), "torque"),
        (lambda w: w.apply_forces(w.body("crate"), [], point=(NAN, 0.0)), "point"),
        (lambda w: w.apply_forces(w.body("crate"), [], point=(0.0, 1e300)), "point"),
        (
            lambda w: w.apply_forces(w.body("crate"), [(1.0, 0.0, Category.SUPPORT)], -1e300),
            "torque",
        ),
        (lambda w: w.apply_impulse("crate", (INF, 0.0)), "impulse"),
        (lambda w: w.apply_impulse("crate", (1e9, 0.0)), "impulse"),
        (lambda w: w.set_mass("crate", 1e308), "mass"),
        (lambda w: w.set_mass("crate", NAN), "mass"),
        (lambda w: w.set_mass("crate", 1.0, moment=-1.0), "moment"),
        (lambda w: setattr(w, "gravity", (0.0, -1e308)), "gravity"),
        (lambda w: setattr(w, "gravity", (NAN, 0.0)), "gravity"),
        (lambda w: w.add_static_segment((0.0, 0.0), (INF, 0.0)), "b"),
        (lambda w: w.add_static_segment((0.0, 0.0), (1.0, 0.0), radius=1e308), "radius"),
        (lambda w: w.apply_force(World().space.static_body, (1.0, 0.0)), "body"),
    ],
)
def test_absurd_arguments_are_refused_naming_the_argument(call, argument) -> None:  # type: ignore[no-untyped-def]
    """Law: a non-finite or absurd argument raises ValueError naming it, and the world is left as
    it was (it still steps to a finite state)."""
    world = _world()
    with pytest.raises(ValueError, match=rf"^{argument}(\[\d\])?: expected"):
        call(world)
    world.run(0.5)
    for name in world.names:
        body = world.body(name)
        assert all(math.isfinite(v) for v in (*body.position, *body.velocity, body.angle))


def test_add_refuses_a_body_with_non_finite_state_or_shape() -> None:
    """Law: :meth:`World.add` checks what a hand-built body carries before pymunk sees it."""
    import pymunk

    world = World()
    body = pymunk.Body(1.0, 1.0)
    body.position = (NAN, 0.0)
    with pytest.raises(ValueError, match=r"^b\.position\[0\]: expected a finite number"):
        world.add("b", body, pymunk.Circle(body, 0.5))
    body = pymunk.Body(1.0, 1.0)
    with pytest.raises(ValueError, match=r"^b\.shapes\[0\]\.radius: expected"):
        world.add("b", body, pymunk.Circle(body, 1e308))
    other = pymunk.Body(1.0, 1.0)
    with pytest.raises(ValueError, match=r"^b\.shapes\[0\]: expected a shape of this body"):
        world.add("b", body, pymunk.Circle(other, 0.5))
    world.add("b", body, pymunk.Circle(body, 0.5))
    with pytest.raises(ValueError, match=r"^c: the body is already in a space"):
        world.add("c", body)


def test_intent_with_nan_move_is_refused() -> None:
    """Law: an intent whose move is NaN never reaches the drive: Intent refuses it, and a source
    returning something that is not an Intent (a duck type skipping the check) stops the step with
    a ValueError naming the actor — it never gets the full drive budget."""
    with pytest.raises(ValueError, match=r"^move: expected a number in \[-1, 1\], got nan"):
        Intent(move=NAN)

    class Sneaky:
        def intent(self, t: float) -> object:
            return type("FakeIntent", (), {"move": NAN, "jump": False})()

    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    Controller(world, "player", (0.0, 1.2), source=Sneaky())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^player: the intent source returned"):
        world.step()


# -- sleeping, each case in its own process ------------------------------------------------------

_SLEEP_SETUP = """
import math
from playground import World, WorldConfig
import pymunk
world = World(WorldConfig(sleep_time=SLEEP))
world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
world.add_box("a", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
world.add_box("b", mass=1.0, size=(1.0, 1.0), position=(0.0, 1.5))
world.add_box("c", mass=1.0, size=(1.0, 1.0), position=(6.0, 0.5))
world.track("a")
world.run(0.05)
"""

_SLEEP_CHECK = """
world.run(1.0)
for name in world.names:
    body = world.body(name)
    assert all(math.isfinite(v) for v in (*body.position, *body.velocity)), name
print("survived")
"""

SLEEP_CASES = {
    # a touches b: the pair sleeps as a group (alone, a corrupts Chipmunk's memory)
    "touching another body": ("1.0", 'world.sleep("a")\nassert world.body("b").is_sleeping'),
    "twice (aborts in raw pymunk)": ("1.0", 'world.sleep("a")\nworld.sleep("a")'),
    "alone": ("1.0", 'world.sleep("c")\nassert world.body("c").is_sleeping'),
    "jointed": (
        "1.0",
        'world.add_constraint(pymunk.PinJoint(world.body("a"), world.body("c")))\n'
        'world.sleep("c")\nassert world.body("a").is_sleeping',
    ),
    "each of a group in turn": ("1.0", 'world.sleep("b")\nworld.sleep("a")\nworld.sleep("c")'),
    "then removed": ("1.0", 'world.sleep("a")\nworld.remove("a")\nworld.remove("b")'),
    "then pushed": ("1.0", 'world.sleep("a")\nworld.apply_force("b", (50.0, 0.0))'),
    "then heavier": ("1.0", 'world.sleep("a")\nworld.set_mass("b", 3.0)'),
    "then gravity flips": ("1.0", 'world.sleep("a")\nworld.gravity = (0.0, 9.81)'),
    "then tracked": ("1.0", 'world.sleep("a")\nworld.track("b", "c")'),
    "then woken": ("1.0", 'world.sleep("a")\nworld.wake("b")\nworld.wake("a")'),
    "sleeping off": (
        "math.inf",
        'try:\n    world.sleep("a")\nexcept ValueError as exc:\n'
        '    assert "sleeping is off" in str(exc), exc\nelse:\n    raise SystemExit("accepted")',
    ),
    "a static body": (
        "1.0",
        'k = pymunk.Body(body_type=pymunk.Body.KINEMATIC)\nworld.add("k", k)\n'
        'try:\n    world.sleep("k")\nexcept ValueError as exc:\n'
        '    assert "only a dynamic body" in str(exc), exc\n'
        'else:\n    raise SystemExit("accepted")',
    ),
}


@pytest.mark.parametrize("case", list(SLEEP_CASES))
def test_sleeping_is_safe_in_every_state(case: str) -> None:
    """Law: :meth:`World.sleep` and :meth:`World.wake` never abort the process nor corrupt it: every
    case either works (the world then steps a second to a finite state) or is refused with a
    ValueError saying why. Run in a subprocess so an abort inside Chipmunk fails the test."""
    sleep_time, body = SLEEP_CASES[case]
    code = _SLEEP_SETUP.replace("SLEEP", sleep_time) + body + "\n" + _SLEEP_CHECK
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip() == "survived"


# -- the property over the whole API ------------------------------------------------------------


class _Source:
    """An intent source whose intent the property sets."""

    current = Intent()

    def intent(self, t: float) -> Intent:
        return self.current


SOURCE = _Source()

HOSTILE = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -1.0, 5e-324, 1e-300, 1e16, -1e16, 1e308, -1e308, NAN, INF, -INF]),
    st.floats(-100.0, 100.0),
)
PAIR = st.tuples(HOSTILE, HOSTILE)


def _op(world: World, kind: str, a: float, v: tuple[float, float], w: tuple[float, float]) -> None:
    if kind == "add_box":
        world.add_box("new", mass=a, size=v, position=w, angle=a)
    elif kind == "add":
        import pymunk

        # pymunk itself aborts on a non-finite mass given to Body(): that is out of our reach.
        # What it accepts without complaint — any state, any circle — goes to World.add.
        body = pymunk.Body(1.0, 1.0)
        body.position = w
        body.velocity = v
        body.angle = a
        world.add("new", body, pymunk.Circle(body, v[0], offset=w))
    elif kind == "apply_force":
        world.apply_force("crate", v, point=w)
    elif kind == "apply_force_free":
        world.apply_force("free", v)
    elif kind == "apply_impulse":
        world.apply_impulse("free", v, point=w)
    elif kind == "set_mass":
        world.set_mass("crate", a, moment=v[0])
    elif kind == "intent":
        # What a keyboard or script may send: Intent refuses it, or the player acts on it.
        SOURCE.current = Intent(move=a, climb=v[0], gravity=w, jump=True)
    elif kind == "gravity":
        world.gravity = v
    else:
        world.add_static_segment(v, w, radius=a)


@pytest.mark.filterwarnings("error::RuntimeWarning")  # an overflow on the way is a failure too
@settings(
    max_examples=300,
    derandomize=True,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(
    ops=st.lists(
        st.tuples(
            st.sampled_from(
                [
                    "add_box",
                    "add",
                    "apply_force",
                    "apply_force_free",
                    "apply_impulse",
                    "set_mass",
                    "gravity",
                    "segment",
                    "intent",
                ]
            ),
            HOSTILE,
            PAIR,
            PAIR,
        ),
        min_size=1,
        max_size=4,
    )
)
def test_hostile_calls_are_refused_or_leave_a_finite_world(
    ops: list[tuple[str, float, tuple[float, float], tuple[float, float]]],
) -> None:
    """Law: every call with non-finite or huge arguments either raises ValueError, or the world
    steps on with every body finite — or the runtime guard stops it with RunawayError before
    anything non-finite is read. Never an abort, never NaN."""
    world = _world()
    SOURCE.current = Intent()
    player = Controller(world, "player", (-8.0, 1.2), source=SOURCE)
    for kind, a, v, w in ops:
        try:
            _op(world, kind, a, v, w)
        except ValueError:
            continue
        try:
            for _ in range(4):
                world.step()
        except RunawayError:
            return
        for name in world.names:
            body = world.body(name)
            state = (*body.position, *body.velocity, body.angle, body.angular_velocity)
            assert all(math.isfinite(x) for x in state), (name, state)
            assert abs(body.position.x) < 1e12 and abs(body.position.y) < 1e12
        assert all(math.isfinite(x) for x in world.forces("crate").engine)
        assert all(math.isfinite(x) for x in (*player.up, *player.last_forces.drive))
        g = world.gravity_at("crate")
        assert math.hypot(*g) <= MAX_GRAVITY * math.sqrt(2)


def test_bounds_cover_what_a_level_holds() -> None:
    """The bounds leave room for game-scale scenes: a 1000 t body 10 km away in 100 g."""
    world = World()
    world.add_box("heavy", mass=MAX_MASS, size=(10.0, 10.0), position=(MAX_COORDINATE, 0.0))
    world.gravity = (0.0, -MAX_GRAVITY)
    world.run(0.5)
    assert math.isfinite(world.body("heavy").position.y)


def test_guard_off_accepts_any_finite_force() -> None:
    """With the guard off (watching a blow-up on purpose) only finiteness is checked."""
    world = World(WorldConfig(guard=False))
    world.add_box("b", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.0))
    body = world.body("b")
    world.apply_force("b", (1e300, 0.0))
    world.apply_forces(body, [(-1e300, 1e300, Category.SUPPORT)], 1e300)
    world.apply_torque("b", -1e300)
    refused = [
        (lambda: world.apply_force("b", (INF, 0.0)), r"force\[0\]"),
        (lambda: world.apply_force("b", (0.0, 1.0), point=(0.0, NAN)), r"point\[1\]"),
        (lambda: world.apply_forces(body, [(0.0, -INF, Category.SUPPORT)]), r"force\[1\]"),
        (lambda: world.apply_forces(body, [], INF), "torque"),
        (lambda: world.apply_torque("b", NAN), "torque"),
    ]
    for call, name in refused:
        with pytest.raises(ValueError, match=rf"^{name}: expected a finite number"):
            call()


# -- misuse: the World's own errors (issue 23) ----------------------------------------------------


def test_a_step_inside_a_step_is_refused_and_the_world_steps_on() -> None:
    """Law: a hook that steps the world it runs in gets WorldUsageError (it recursed to
    RecursionError, and after one nested step the outer step ran unlocked); the world is not
    left stepping: the next step runs, locked as usual."""
    from playground.world.errors import WorldUsageError
    from playground.world.schedule import Stage

    world = _world()
    seen: list[str] = []

    def nested(w: World) -> None:
        try:
            w.step()
        except WorldUsageError as exc:
            seen.append(str(exc))

    world.on(Stage.CONTROL, nested)
    world.on(Stage.OBSERVE, lambda w: seen.append(f"locked={w.locked}"))
    world.step()
    world.step()
    assert world.steps == 2
    assert seen[0].startswith("step: the world is already stepping")
    assert seen[1] == "locked=True" and len(seen) == 4


def test_tracking_again_from_an_input_hook_under_a_radial_field_runs() -> None:
    """Law: tracking a tracked body again from an INPUTS hook under a radial field (which hands
    the physics stage per-body forces) steps on with finite readings; it tripped a bare
    ``assert field is None or callable(field)`` because the field came in the form of the
    implementation planned before the hook changed it."""
    from playground.gravity import Radial
    from playground.world.schedule import Stage

    world = World(gravity=Radial((0.0, 0.0), 9.81))
    world.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 5.0))
    world.track("crate")
    world.on(Stage.INPUTS, lambda w: w.track("crate"))
    for _ in range(10):
        world.step()
    assert all(math.isfinite(v) for v in world.forces("crate").engine)
    assert world.body("crate").position.y < 5.0


@pytest.mark.parametrize(
    ("make", "expected"),
    [
        (lambda a, s, k: pymunk.GearJoint(a, s, 0.0, 0.0), "ratio: a gear's ratio must not be 0"),
        (lambda a, s, k: pymunk.GearJoint(a, s, 0.0, NAN), "ratio: expected a finite number"),
        (lambda a, s, k: k, "needs a dynamic body"),
        (
            lambda a, s, k: pymunk.DampedSpring(a, s, (0, 0), (0, 0), 1.0, INF, 0.0),
            "stiffness: expected a finite number",
        ),
        (
            lambda a, s, k: pymunk.SimpleMotor(a, s, NAN),
            "rate: expected a finite number",
        ),
        (
            lambda a, s, k: pymunk.DampedSpring(a, s, (0, 0), (0, 0), 1.0, 1e300, 0.0),
            "stiffness: expected at most 1e+09",
        ),
    ],
    ids=[
        "gear ratio 0",
        "gear ratio nan",
        "kinematic-static",
        "spring inf",
        "motor nan",
        "spring 1e300",
    ],
)
def test_a_joint_the_engine_cannot_solve_is_refused(make: Any, expected: str) -> None:
    """Law: add_constraint refuses a joint the engine cannot solve, at once and naming why: a
    gear of ratio 0 (a body went NaN from step 2 and nothing said so until the guard, 254 steps
    later), no dynamic end (Chipmunk's assertion at the first step), a non-finite parameter.
    Nothing was added: the world steps on, finite."""
    world = _world()
    # pymunk refuses a joint with no dynamic end when it is made, not when its body turns
    # kinematic afterwards: this one reaches the world with no dynamic end.
    lift = pymunk.Body(1.0, 1.0)
    turned = pymunk.PivotJoint(lift, world.space.static_body, (0.0, 3.0))
    lift.body_type = pymunk.Body.KINEMATIC
    lift.position = (0.0, 3.0)
    world.add("lift", lift, pymunk.Poly.create_box(lift, (1.0, 0.2)))
    joint = make(world.body("crate"), world.space.static_body, turned)
    with pytest.raises(ValueError, match=re.escape(expected)):
        world.add_constraint(joint)
    assert list(world.space.constraints) == []
    world.run(0.5)
    assert all(math.isfinite(v) for v in world.body("crate").position)


def test_sleeping_a_body_once_jointed_to_a_removed_one_works() -> None:
    """Law: sleeping a body whose joint was removed, and the body at the joint's other end too,
    puts it to sleep (``Body.constraints`` keeps the removed joint: the group walked into the
    removed body and pymunk raised its bare ``Exception('Body not added to space')``)."""
    world = World(WorldConfig(sleep_time=0.5))
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    a = world.add_box("a", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
    b = world.add_box("b", mass=1.0, size=(1.0, 1.0), position=(3.0, 0.5))
    pin = world.add_constraint(pymunk.PinJoint(a, b))
    world.step()
    world.remove(pin)
    world.remove("b")
    world.sleep("a")
    assert a.is_sleeping


def test_sleeping_a_body_not_yet_in_the_space_is_refused() -> None:
    """Law: sleeping a body added during this step (it joins the space at the step's end) is
    refused saying when it joins, not pymunk's bare Exception; from the next step on it
    sleeps."""
    from playground.world.schedule import Stage

    world = World(WorldConfig(sleep_time=0.5))
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    errors: list[str] = []

    def add_and_sleep(w: World) -> None:
        if w.steps == 1:
            w.add_box("late", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
            try:
                w.sleep("late")
            except KeyError as exc:
                errors.append(exc.args[0])

    world.on(Stage.OBSERVE, add_and_sleep)
    world.step()
    assert errors == ["late: added during this step; it joins when the step ends"]
    world.sleep("late")
    assert world.body("late").is_sleeping
