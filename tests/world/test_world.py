"""Laws of the world: stages and their timings, names, mass changes, perceived gravity, and a
core that never imports the renderer."""

from __future__ import annotations

import math
import subprocess
import sys

import pymunk
import pytest

from playground import (
    GravityRule,
    Perception,
    RotatingRoom,
    Spin,
    Stage,
    Turn,
    Uniform,
    World,
    WorldConfig,
)
from playground.world.physics import PhysicsStage

G = 9.81

TOL_SETTLED_REL = 1e-6
"""A settled contact's support matches m·g to < 1e-6 once at rest (tests/forces/test_solver.py)."""

TOL_PERCEIVED_REL = 1e-3
"""Perceived gravity is 1€-filtered (min cutoff 2 Hz, time constant 80 ms): after 1.5 s at rest
the filter has converged to far below 1e-3 of |g|."""

FREE_FALL_MAX = 1e-6
"""m/s²: in free fall the engine does nothing, so the specific force is rounding only."""


def resting_world(config: WorldConfig | None = None, mass: float = 3.0) -> World:
    world = World(config or WorldConfig())
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0))
    world.add_box("box", mass=mass, size=(1.0, 1.0), position=(0.0, 0.55))
    return world


def test_stage_timings_are_per_stage_and_unneeded_stages_do_not_run() -> None:
    """Law: with timing on, each stage that runs counts one call per step with a positive time;
    a stage the scene does not need (no hooks, no events, uniform gravity, no movers, no tracked
    body, no perceiver) is never run."""
    world = resting_world(WorldConfig(timing=True))
    world.run(0.25)
    n = world.steps
    t = world.timings
    assert t[Stage.PHYSICS].calls == n and t[Stage.PHYSICS].total > 0.0
    assert t[Stage.PHYSICS].mean == pytest.approx(t[Stage.PHYSICS].total / n)
    for stage in Stage:
        if stage is not Stage.PHYSICS:
            assert t[stage].calls == 0, stage
    world.track("box", perceive=False)
    world.run(0.25)
    assert t[Stage.FORCES].calls == world.steps - n
    assert t[Stage.FILTER].calls == 0
    world.track("box")
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("plat", plat)
    world.add_mover("plat", Spin(position=(5.0, 5.0)))
    world.on(Stage.CONTROL, lambda w: None)
    world.at(world.time + 0.05, lambda w: None)
    m = world.steps
    world.run(0.25)
    for stage in (Stage.FILTER, Stage.MOVERS, Stage.CONTROL):
        assert t[stage].calls == world.steps - m, stage
    assert t[Stage.EVENTS].calls == 1
    assert t[Stage.GRAVITY].calls == 0


def test_timing_off_records_nothing() -> None:
    """Law: timing is off by default and then no stage records a call."""
    world = resting_world()
    world.track("box")
    world.run(0.1)
    assert all(timing.calls == 0 for timing in world.timings.values())


def test_forces_every_step_do_not_plan_again_and_bare_steps_come_back(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Law: a ledger that fills and empties every step (a controller's forces) does not make
    the world decide again what its steps run; once the forces stop, the steps are bare again
    (``space.step`` alone, no physics stage) while the force acted on every step it was put."""
    world = resting_world()
    plans: list[int] = []
    physics: list[int] = []
    plan, physics_step = World._plan, PhysicsStage.step

    def counted_plan(self: World) -> None:
        plans.append(self.steps)
        plan(self)

    def counted_physics(self: PhysicsStage, field: object) -> None:
        physics.append(world.steps)
        physics_step(self, field)  # type: ignore[arg-type]

    monkeypatch.setattr(World, "_plan", counted_plan)
    monkeypatch.setattr(PhysicsStage, "step", counted_physics)
    box = world.body("box")
    world.run(0.1)
    lift = (0.0, 2.0 * box.mass * G)
    for _ in range(30):
        world.apply_force("box", lift)
        world.step()
    assert box.velocity.y > 0.0  # the force acted: twice the weight lifts the box
    lifted = world.steps
    world.run(0.1)
    assert plans == [0]
    assert physics == list(range(lifted - 30, lifted))


def test_names_and_remove() -> None:
    """Law: names are unique; an unknown name's error lists the known ones; a removed body is gone
    (its shapes too) and the other tracked rows keep reading their own bodies."""
    world = resting_world()
    world.add_box("other", mass=1.0, size=(0.5, 0.5), position=(3.0, 0.3))
    with pytest.raises(ValueError, match="box"):
        world.add_box("box", mass=1.0, size=(1.0, 1.0), position=(0.0, 3.0))
    with pytest.raises(KeyError, match="known: box, other"):
        world.body("nope")
    world.track("box", "other")
    world.run(0.5)
    world.remove("box")
    assert world.names == ["other"]
    assert all(s.body is not None and s.body.space is not None for s in world.space.shapes)
    with pytest.raises(KeyError):
        world.forces("box")
    world.run(0.5)
    f = world.forces("other")
    assert abs(f.support[1] - 1.0 * G) <= TOL_SETTLED_REL * G


def test_set_mass_is_followed_by_the_solver() -> None:
    """Law: after a mass change the support settles to the new m·g (the solver uses the new m)."""
    world = resting_world(mass=3.0)
    world.track("box")
    world.run(1.0)
    world.set_mass("box", 7.0)
    world.run(1.0)
    f = world.forces("box")
    assert abs(f.support[1] - 7.0 * G) <= TOL_SETTLED_REL * 7.0 * G
    assert f.specific[1] == pytest.approx(G, rel=TOL_SETTLED_REL)
    with pytest.raises(ValueError, match="mass"):
        world.set_mass("box", 0.0)


def test_perceived_gravity_at_rest_is_gravity() -> None:
    """Law: a body at rest perceives the real gravity, and "up" points against it."""
    world = resting_world()
    world.track("box")
    world.run(1.5)
    gx, gy = world.perceived_gravity("box")
    assert abs(gx) <= TOL_PERCEIVED_REL * G and abs(gy + G) <= TOL_PERCEIVED_REL * G
    assert world.perceived_up("box") == pytest.approx((0.0, 1.0), abs=TOL_PERCEIVED_REL)


def test_free_fall_feels_nothing() -> None:
    """Law: in free fall the specific force is zero, so the perceived gravity decays to ~0."""
    world = World(WorldConfig())
    world.add_box("box", mass=2.0, size=(1.0, 1.0), position=(0.0, 100.0))
    world.track("box")
    for _ in range(120):
        world.step()
        assert math.hypot(*world.forces("box").specific) <= FREE_FALL_MAX
    assert math.hypot(*world.perceived_gravity("box")) <= FREE_FALL_MAX
    up = world.perceived_up("box")
    assert math.isfinite(up[0]) and math.hypot(*up) == pytest.approx(1.0)


def test_gravity_flip_never_loses_up() -> None:
    """Law: through a 180° gravity flip (the perceived gravity passes through zero), "up" is
    always a finite unit vector, held below the threshold; after landing on the old ceiling it
    points the new way."""
    room = RotatingRoom(angle=-math.pi / 2, turns=(Turn(1.0, math.pi),))
    world = World(WorldConfig(perception=Perception(up_threshold=1.0)), gravity=room)
    world.add_static_segment((-3.0, 0.0), (3.0, 0.0))
    world.add_static_segment((-3.0, 3.0), (3.0, 3.0))
    world.add_box("box", mass=1.0, size=(0.5, 0.5), position=(0.0, 0.3))
    world.track("box")
    ups = []
    for _ in range(round(4.0 / world.config.dt)):
        world.step()
        up = world.perceived_up("box")
        assert all(math.isfinite(c) for c in up)
        assert math.hypot(*up) == pytest.approx(1.0, abs=1e-12)
        ups.append(up)
    assert ups[100][1] == pytest.approx(1.0, abs=1e-3)
    assert ups[-1][1] == pytest.approx(-1.0, abs=1e-3)


def test_gravity_setter_accepts_a_vector() -> None:
    """Law: a plain (gx, gy) becomes a Uniform field; a non-finite one is refused."""
    world = World()
    world.gravity = (1.0, -2.0)
    assert world.gravity == Uniform((1.0, -2.0))
    assert world.space.gravity == (1.0, -2.0)
    with pytest.raises(ValueError, match="gravity"):
        world.gravity = (math.inf, 0.0)


def test_import_does_not_load_pygame() -> None:
    """Law: the core imports pymunk and numpy only; pygame stays out of ``import playground``."""
    code = "import sys, playground; print('pygame' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def sleepy_world(config: WorldConfig) -> World:
    world = resting_world(config)
    world.add_box("floater", mass=1.0, size=(0.5, 0.5), position=(5.0, 5.0))
    world.track("floater")
    return world


def test_resting_bodies_sleep_while_a_gravity_stage_runs() -> None:
    """Law: a per-body rule on one body does not keep the rest of the world awake (setting
    ``space.gravity`` wakes every body, so the world sets it only when it changes)."""
    world = sleepy_world(WorldConfig(sleep_time=0.2))
    world.set_gravity_rule("floater", GravityRule(scale=0.0))
    world.run(1.5)
    assert world.body("box").is_sleeping


def test_resting_bodies_sleep_with_substeps() -> None:
    """Law: with substeps, re-applying forces between substeps touches only bodies that have a
    force (setting one restarts a body's idle clock), so resting bodies still fall asleep."""
    world = sleepy_world(WorldConfig(sleep_time=0.2, substeps=3))
    world.run(1.5)
    assert world.body("box").is_sleeping


def test_the_world_is_composed_not_inherited() -> None:
    """Law: World derives from nothing but object; it holds its parts (registry, schedule,
    gravity stage, forces in, physics stage) and every public name of the registry is World's
    too, delegated."""
    from playground.world.force_input import ForceInput
    from playground.world.gravity_stage import GravityStage
    from playground.world.registry import BodyRegistry
    from playground.world.schedule import Schedule

    assert World.__mro__ == (World, object)
    world = World()
    parts = {type(v) for v in vars(world).values()}
    for part in (BodyRegistry, Schedule, GravityStage, ForceInput, PhysicsStage):
        assert part in parts, part
    public = {n for n in dir(BodyRegistry) if not n.startswith("_")}
    kept = {"by_name", "id_by_name", "name_by_id", "own", "require", "lock", "unlock"}
    # The step's own bookkeeping, which World calls itself.
    missing = public - kept - {"run_pending", "forget_departed"} - set(dir(World))
    assert not missing, missing


def _crate_on_the_floor(world: World) -> pymunk.Body:
    """A 10 kg crate added straight to the world's space, resting on a floor added likewise."""
    floor = pymunk.Segment(world.space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.05)
    crate = pymunk.Body(10.0, pymunk.moment_for_box(10.0, (1.0, 1.0)))
    crate.position = (0.0, 0.55)
    world.space.add(floor, crate, pymunk.Poly.create_box(crate, (1.0, 1.0)))
    return crate


TOL_REST = 1e-6
"""Relative: a box at rest on the floor for a second reads its weight to rounding."""


@pytest.mark.parametrize("named", [False, True])
def test_a_body_the_game_added_itself_can_be_tracked(named: bool) -> None:
    """Law: a body added with ``world.space.add`` is tracked like one of the world's, named by
    ``adopt`` or anonymous (read by the body itself): a 10 kg crate at rest reads its weight,
    98.1 N, and perceives g; untracked, its readings are refused by name."""
    world = World()
    crate = _crate_on_the_floor(world)
    key: str | pymunk.Body = crate
    if named:
        world.adopt("crate", crate)
        key = "crate"
        assert world.body("crate") is crate and world.names == ["crate"]
    world.track(key)
    world.run(1.0)
    assert world.tracked_bodies == [crate]
    support = world.forces(key).support
    assert support[1] == pytest.approx(98.1, rel=TOL_REST) and abs(support[0]) < 1e-9
    assert world.perceived_gravity(key) == pytest.approx((0.0, -9.81), rel=TOL_REST, abs=1e-9)
    world.untrack(key)
    assert world.tracked_bodies == []
    with pytest.raises(KeyError, match="not tracked"):
        world.forces(key)


@pytest.mark.parametrize("when", ["between steps", "in INPUTS", "in OBSERVE"])
def test_a_nameless_tracked_body_taken_out_with_space_remove_is_untracked(when: str) -> None:
    """Rule (World.track): a body tracked without a name leaves with ``space.remove``; the next
    step untracks it before its gravity stage (one removed by an INPUTS hook, in that step),
    and reading it says it left. Put back and tracked again, it reads its weight again."""
    world = World()
    crate = _crate_on_the_floor(world)
    (box,) = crate.shapes
    world.track(crate)
    world.run(0.5)

    def take_out(w: World) -> None:
        w.space.remove(crate, box)
        w.off(stage, take_out)

    stage = Stage.INPUTS if when == "in INPUTS" else Stage.OBSERVE
    if when == "between steps":
        world.space.remove(crate, box)
    else:
        world.on(stage, take_out)
    world.step()
    left_in_that_step = when != "in OBSERVE"
    assert world.tracked_bodies == ([] if left_in_that_step else [crate])
    world.step()
    assert world.tracked_bodies == []
    with pytest.raises(KeyError, match="not in the world's space"):
        world.forces(crate)
    world.run(0.5)  # stepping on without it
    crate.position, crate.velocity = (0.0, 0.55), (0.0, 0.0)
    world.space.add(crate, box)
    world.track(crate)
    world.run(1.0)
    assert world.forces(crate).support[1] == pytest.approx(98.1, rel=TOL_REST)


def test_a_nameless_body_named_later_leaves_by_name() -> None:
    """A tracked body adopted after it was tracked is a named body: ``World.remove`` takes it
    out of the space and untracks it."""
    world = World()
    crate = _crate_on_the_floor(world)
    world.track(crate)
    world.adopt("crate", crate)
    world.run(0.5)
    world.remove("crate")
    world.step()
    assert world.tracked_bodies == [] and crate.space is None


@pytest.mark.parametrize("how", ["added by name", "adopted"])
@pytest.mark.parametrize("when", ["between steps", "in INPUTS", "in OBSERVE"])
def test_a_named_body_taken_out_with_space_remove_leaves_the_world(how: str, when: str) -> None:
    """Rule (World.track): a named body the game takes out with ``space.remove`` leaves the
    world at the next step, before its gravity stage (in that step if an INPUTS hook took it),
    as with ``World.remove``: its name, tracking and gravity rule go, reading it says it left,
    and the name is free again. Put back and adopted, it reads its weight again."""
    world = World()
    if how == "adopted":
        crate = world.adopt("crate", _crate_on_the_floor(world))
    else:
        world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
        crate = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.55))
    world.track("crate")
    world.set_gravity_rule("crate", GravityRule(scale=0.5))
    world.run(0.5)
    (box,) = crate.shapes

    def take_out(w: World) -> None:
        w.space.remove(crate, box)
        w.off(stage, take_out)

    stage = Stage.INPUTS if when == "in INPUTS" else Stage.OBSERVE
    if when == "between steps":
        world.space.remove(crate, box)
    else:
        world.on(stage, take_out)
    world.step()
    left_in_that_step = when != "in OBSERVE"
    assert world.names == ([] if left_in_that_step else ["crate"])
    world.step()
    assert world.names == [] and world.tracked_bodies == [] and world.name_of(crate) is None
    for read in (world.forces, world.body, world.gravity_rule, world.is_tracked):
        with pytest.raises(KeyError, match=r"taken out of the space with space\.remove"):
            read("crate")
    world.run(0.5)  # stepping on without it
    crate.position, crate.velocity = (0.0, 0.55), (0.0, 0.0)
    world.space.add(crate, box)
    world.adopt("crate", crate)
    assert world.gravity_rule("crate") == GravityRule()  # its old rule went with its name
    world.track("crate")
    world.run(1.0)
    assert world.forces("crate").support[1] == pytest.approx(98.1, rel=TOL_REST)


def test_world_remove_after_space_remove_takes_out_only_what_is_left() -> None:
    """``World.remove`` of a named body whose body the game already took out with
    ``space.remove`` (before the world noticed) removes its shapes and joints still in the
    space, and the world steps on."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    crate = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.55))
    pin = world.add_constraint(pymunk.PivotJoint(crate, world.space.static_body, (0.0, 0.55)))
    world.run(0.1)
    world.space.remove(crate)
    world.remove("crate")
    assert not world.space.shapes - {s for s in world.space.static_body.shapes}
    assert pin not in world.space.constraints and world.names == []
    world.run(0.1)


def test_a_body_of_another_space_is_refused_by_track_and_adopt() -> None:
    """Law: ``track`` and ``adopt`` refuse a body that is not in the world's space, and
    ``adopt`` a second name, saying why."""
    world = World()
    stranger = pymunk.Body(1.0, 1.0)
    with pytest.raises(ValueError, match="body of this world"):
        world.track(stranger)
    with pytest.raises(ValueError, match=r"space\.add"):
        world.adopt("stranger", stranger)
    crate = _crate_on_the_floor(world)
    world.adopt("crate", crate)
    with pytest.raises(ValueError, match="already called 'crate'"):
        world.adopt("box", crate)
