"""The crowd (:mod:`playground.controller.crowd`) against the scalar path: random crowds run
both ways, step by step, give the same bodies and the same readings to the last bit (the same
float operations in the same order: the laws are the same functions over
:data:`~playground.controller.elementwise.ARRAYS`, the ledger's rows the same additions); the
batch path does run (the oracle is not vacuous); a break that patches the laws sends every
member down the scalar path, so the fault catalogue still sees its break."""

from __future__ import annotations

import dataclasses
import struct
from typing import Any

import numpy as np
import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground import faults
from playground.controller import stairs
from playground.controller._vec import ZERO
from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.crowd import CROWD_MIN_ACTORS, Crowd
from playground.controller.crowd import crowd as crowd_module
from playground.controller.crowd.groups import ConfigArrays
from playground.controller.sensing import effort, effort_on, lean
from playground.controller.states import State
from playground.gravity import GravityRule
from playground.intents import Intent, Patrol, Script
from playground.level import find, load
from playground.scene import build
from playground.world.schedule import Stage
from playground.world.world import World

STEPS = 150
"""Steps each random crowd runs both ways (1.25 s: settling, walking, a push, a nullify)."""

JOIN = 60
"""The step at which a controller joins the random crowd and another leaves it."""

ALWAYS = 0
NEVER = 10**9
_NULL = GravityRule(scale=0.0)
"""Gravity nullified (an event of the random crowd)."""


def _crowd(spec: dict[str, Any], batch: bool) -> tuple[World, list[Controller]]:
    world = World()
    world.add_static_segment((-60.0, 0.0), (60.0, 0.0))
    world.add_box("crate", mass=spec["crate_mass"], size=(1.0, 1.0), position=(0.0, 0.5))
    Crowd.of(world).set_min_actors(ALWAYS if batch else NEVER)
    actors = []
    for i, a in enumerate(spec["actors"]):
        config = ControllerConfig(mass=a["mass"]) if a["own_config"] else None
        if a["script"]:
            timeline = (
                (0.0, Intent(move=a["move"])),
                (a["at"], Intent(move=a["move"], push=a["push"], jump=a["jump"])),
                (a["at"] + 0.3, Intent(move=-a["move"])),
            )
            source: Any = Script(timeline)
        else:
            source = Patrol(speed=a["speed"], period=a["period"])
        actors.append(
            Controller(
                world,
                f"a{i}",
                position=(a["x"], a["y"]),
                config=config,
                source=source,
                angle=a["angle"],
            )
        )
    if spec["nullify"] is not None:
        # Not a0: it leaves the crowd at JOIN.
        name = f"a{1 + spec['nullify'] % (len(actors) - 1)}"
        world.at(spec["nullify_at"], lambda w: w.set_gravity_rule(name, _NULL))
    return world, actors


def _readings(world: World, actors: list[Controller]) -> list[Any]:
    out: list[Any] = []
    for name in world.names:
        b = world.body(name)
        out.append((name, tuple(b.position), tuple(b.velocity), b.angle, b.angular_velocity))
    for c in actors:
        f = c.last_forces
        s = c.sensed
        out.append(
            (
                c.name, c.state, c.transition, f.hover, f.drive, f.push, f.balance_torque,
                f.torque, f.balance_short, f.own, s.up, s.perceived_up, s.gravity, s.load,
                s.ground.point if s.ground else None, s.ground.distance if s.ground else None,
                c.control_state.grounded_at, c.control_state.saturated,
                world.forces(c.name).support,
            )
        )  # fmt: skip
    return out


actor = st.fixed_dictionaries(
    {
        "x": st.floats(-50.0, 50.0),
        "y": st.floats(0.85, 2.5),
        "angle": st.floats(-0.4, 0.4),
        "mass": st.floats(20.0, 200.0),
        "own_config": st.booleans(),
        "script": st.booleans(),
        "move": st.floats(-1.0, 1.0),
        "at": st.floats(0.1, 1.0),
        "push": st.booleans(),
        "jump": st.booleans(),
        "speed": st.floats(0.0, 1.0),
        "period": st.floats(0.3, 3.0),
    }
)
crowds = st.fixed_dictionaries(
    {
        "actors": st.lists(actor, min_size=2, max_size=10),
        "crate_mass": st.floats(5.0, 500.0),
        "nullify": st.none() | st.integers(0, 9),
        "nullify_at": st.floats(0.1, 1.0),
    }
)


@settings(max_examples=20, deadline=None)
@given(crowds)
def test_a_random_crowd_runs_as_one_as_it_runs_one_by_one(spec: dict[str, Any]) -> None:
    """Law: bodies, readings and force solver readings equal (as floats) at every step."""
    scalar, sa = _crowd(spec, batch=False)
    batch, sb = _crowd(spec, batch=True)
    for step in range(STEPS):
        if step == JOIN:
            # One joins and one leaves a running crowd (its arrays change shape).
            for world, actors in ((scalar, sa), (batch, sb)):
                actors.append(Controller(world, "late", position=(55.0, 0.95)))
                actors.pop(0).remove()
        scalar.step()
        batch.step()
        assert _readings(batch, sb) == _readings(scalar, sa), f"step {step}"


READ_EVERY = 7
"""Steps between two reads of one member's readings (each member at its own phase)."""


def _last_ground(c: Controller) -> Any:
    g = c.control_state.last_ground
    if g is None:
        return None
    return [getattr(g, f.name) for f in dataclasses.fields(g) if f.name != "body"]


@settings(max_examples=10, deadline=None)
@given(crowds)
def test_readings_read_now_and_then_are_those_of_the_scalar_path(spec: dict[str, Any]) -> None:
    """Law: a member read only every READ_EVERY steps (its readings unread arrays of older
    steps in between) reads what its scalar step gave, its last ground too."""
    scalar, sa = _crowd(spec, batch=False)
    batch, sb = _crowd(spec, batch=True)
    for step in range(STEPS):
        scalar.step()
        batch.step()
        for i, (a, b) in enumerate(zip(sa, sb, strict=True)):
            if (step + i) % READ_EVERY == 0:
                assert _readings(batch, [b])[-1] == _readings(scalar, [a])[-1], f"step {step}"
                assert _last_ground(b) == _last_ground(a), f"step {step}"


def test_the_batch_path_runs_most_of_a_patrolling_crowd() -> None:
    """The oracle above compares something: on a floor of patrolling enemies, the crowd runs
    nearly every member-step in batch (all but the first steps, before it lands)."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (80.0, 0.0))
    actors = [
        Controller(world, f"e{i}", position=(2.0 * i, 0.95), source=Patrol(0.5, 2.0 + 0.01 * i))
        for i in range(30)
    ]
    assert Crowd.of(world).active
    batched = 0
    for _ in range(120):
        world.step()
        batched += sum(c.stale is not None for c in actors)
    assert batched >= 0.95 * 120 * len(actors)


def test_the_crowd_level_runs_as_it_would_one_by_one() -> None:
    """The shipped ``crowd`` level (a nullify, a push, a crate) gives the same bodies both ways."""

    def scene(most: int) -> Any:
        s = build(load(find("crowd")))
        Crowd.of(s.world).set_min_actors(most)
        return s

    a, b = scene(NEVER), scene(ALWAYS)
    for step in range(150):
        a.world.step()
        b.world.step()
        for name in a.world.names:
            pa, pb = a.world.body(name), b.world.body(name)
            assert (tuple(pa.position), tuple(pa.velocity), pa.angle) == (
                tuple(pb.position), tuple(pb.velocity), pb.angle,
            ), (step, name)  # fmt: skip


def test_a_break_of_the_laws_sends_every_member_down_the_scalar_path() -> None:
    """With ``hover_removed`` open, controllers follow a patched hover: none runs in batch."""
    with faults.apply("hover_removed"):
        world = World()
        world.add_static_segment((-5.0, 0.0), (80.0, 0.0))
        actors = [Controller(world, f"e{i}", position=(2.0 * i, 0.95)) for i in range(30)]
        for _ in range(10):
            world.step()
    assert Crowd.of(world).active
    assert not any(c.stale is not None for c in actors)
    assert all(c.last_forces.hover == (0.0, 0.0) for c in actors)


def test_a_world_with_a_crowd_is_freed_when_dropped() -> None:
    """The crowd lives on its world (``World.crowd``), not in a table of worlds that its
    members, which hold their world, would keep alive forever."""
    import gc
    import weakref

    world = World()
    world.add_static_segment((-5.0, 0.0), (80.0, 0.0))
    for i in range(30):
        Controller(world, f"e{i}", position=(2.0 * i, 0.95))
    world.step()
    assert Crowd.of(world).active
    ref = weakref.ref(world)
    del world
    gc.collect()
    assert ref() is None


def _stairs_crowd(batch: bool) -> tuple[World, list[Controller]]:
    """Eight walkers on a floor with a flight of 0.2 m risers on 0.3 m treads up to a landing
    and down again (static boxes, sharp corners), some walking at full speed, some slowly."""
    world = World()
    world.add_static_segment((-20.0, 0.0), (40.0, 0.0), radius=0.0)
    body = world.space.static_body
    tops = [0.2, 0.4, 0.6, 0.8, 1.0, 1.0, 1.0, 1.0, 0.8, 0.6, 0.4, 0.2]
    boxes = [
        pymunk.Poly(body, [(0.3 * i, 0.0), (0.3 * i + 0.3, 0.0), (0.3 * i + 0.3, t), (0.3 * i, t)])
        for i, t in enumerate(tops)
    ]
    world.add_static(*boxes)
    Crowd.of(world).set_min_actors(ALWAYS if batch else NEVER)
    actors = [
        Controller(
            world,
            f"w{i}",
            position=(-6.0 + 0.7 * i, 0.95),
            source=Script(((0.0, Intent(move=1.0 if i % 2 == 0 else 0.4)),)),
        )
        for i in range(8)
    ]
    return world, actors


def test_a_crowd_walks_stairs_as_it_does_one_by_one() -> None:
    """Law: on stairs (a tread ahead to step up onto, a tread below to step down to, corners)
    the members whose probe reads another ground run their own step, and the crowd's bodies
    and readings equal the scalar path's at every step."""
    scalar, sa = _stairs_crowd(batch=False)
    batch, sb = _stairs_crowd(batch=True)
    climbed = 0.0
    for step in range(480):
        scalar.step()
        batch.step()
        assert _readings(batch, sb) == _readings(scalar, sa), f"step {step}"
        climbed = max(climbed, *(c.body.position.y for c in sb))
    assert climbed > 1.9  # m: over the landing (top 1.0 m) at ride height, not below the flight


def test_fresh_intents_every_step_do_not_pile_up_in_the_crowd() -> None:
    """A source that makes a new Intent every step (as a keyboard does): the crowd keeps the
    intents of its members' last step only, not of every step run."""

    class Fresh:
        def intent(self, t: float) -> Intent:
            return Intent(move=0.25)

    world = World()
    world.add_static_segment((-5.0, 0.0), (80.0, 0.0))
    for i in range(30):
        Controller(world, f"e{i}", position=(2.0 * i, 0.95), source=Fresh())
    crowd = Crowd.of(world)
    for _ in range(40):
        world.step()
    # One per member (a cache of every intent seen would hold 40 × 30 = 1 200).
    assert crowd.active and len(crowd._intents) == 30
    assert crowd._moves.tolist() == [0.25] * 30


def test_the_crowds_tread_ahead_misses_no_step_up(monkeypatch: pytest.MonkeyPatch) -> None:
    """Law: where ``stairs.step_up`` finds a tread ahead for a walking member, the crowd's test
    on arrays (``crowd.step_up.may_step_up``) sends that member to its own step; on the stairs
    it does so at every step up, and on a flat floor for no one."""
    seen = {"walking": 0, "steps": 0, "flagged": 0}
    test = crowd_module.may_step_up
    crowds: list[Crowd] = []  # the crowd of the world being stepped, last

    def checked(sweeps: Any, per_config: ConfigArrays, walking: Any, px: Any, py: Any, rvx: Any,
                rvy: Any, ux: Any, uy: Any, move: Any, ground: Any) -> Any:  # fmt: skip
        may = test(sweeps, per_config, walking, px, py, rvx, rvy, ux, uy, move, ground)
        configs = crowds[-1]._configs
        for i in np.flatnonzero(walking).tolist():
            found: Any = (None, ground[0][i], ground[1][i], ground[2][i], ground[3][i])
            step = stairs.step_up(sweeps[i], found, px[i], py[i], rvx[i], rvy[i], ux[i],
                                  uy[i], move[i], configs[i])  # fmt: skip
            seen["walking"] += 1
            seen["flagged"] += bool(may[i])
            if step is not None:
                seen["steps"] += 1
                assert may[i]
        return may

    monkeypatch.setattr(crowd_module, "may_step_up", checked)
    world, _ = _stairs_crowd(batch=True)
    crowds.append(Crowd.of(world))
    for _ in range(480):
        world.step()
    assert seen["steps"] > 0 and seen["flagged"] >= seen["steps"]
    seen.update(walking=0, flagged=0)
    floor = World()
    floor.add_static_segment((-5.0, 0.0), (80.0, 0.0))
    for i in range(30):
        Controller(floor, f"e{i}", position=(2.0 * i, 0.95), source=Patrol(0.5, 2.0 + 0.01 * i))
    crowds.append(Crowd.of(floor))
    for _ in range(120):
        floor.step()
    assert seen["walking"] > 1000 and seen["flagged"] == 0


def test_the_crowds_lean_is_each_members_own(monkeypatch: pytest.MonkeyPatch) -> None:
    """Law: the members whose perceived up is beyond ``max_lean`` of the field's lean on arrays
    (``sensing.lean`` and ``sensing.effort_on`` over ARRAYS) as each would alone, to the bit:
    the walkers that turn (leaning into their own step: an effort from the arrays of their last
    batch step) and those that stop (no effort of their own: held to max_lean)."""
    seen = {"own, held": 0, "own, kept": 0, "held": 0}
    efforts = Crowd._efforts
    arrays = crowd_module._lean

    def same(got: tuple[float, float], want: tuple[float, float]) -> None:
        assert struct.pack("<2d", *got) == struct.pack("<2d", *want)

    def checked_efforts(self: Crowd, rows: Any, own: Any) -> Any:
        ex, ey = efforts(self, rows, own)
        for j, i in enumerate(rows.tolist()):
            c, view = self.members[i], self._views[i]
            if not own[j]:
                want = ZERO
            elif c.stale is not self:
                want = effort(c.last_forces.drive, c.sensed)
            else:  # the floats of its last batch step
                drive = (view["drive_x"][i], view["drive_y"][i]) if view["drive_on"][i] else ZERO
                _, _, nx, ny, *_ = view["hits"]
                normal = None if view["ground"][i] is None else (nx[i], ny[i])
                body, _, _, _, gx, gy, *_ = view["sensed"]
                want = effort_on(drive, normal, (gx[i], gy[i]), body.mass[i])
            same((ex[j], ey[j]), (float(want[0]), float(want[1])))
        return ex, ey

    def checked_lean(perceived: Any, level: Any, own: Any, weight: Any, most: Any, ops: Any) -> Any:
        x, y = arrays(perceived, level, own, weight, most, ops)
        for k in range(len(x)):
            p = (float(perceived[0][k]), float(perceived[1][k]))
            e = (float(own[0][k]), float(own[1][k]))
            want = lean(p, (float(level[0][k]), float(level[1][k])), e, float(weight[k]),
                        float(most[k]))  # fmt: skip
            same((x[k], y[k]), want)
            mine = e != (0.0, 0.0)
            seen[("own, " if mine else "") + ("kept" if want is p else "held")] += 1
        return x, y

    monkeypatch.setattr(Crowd, "_efforts", checked_efforts)
    monkeypatch.setattr(crowd_module, "_lean", checked_lean)
    world = World()
    world.add_static_segment((-5.0, 0.0), (80.0, 0.0))
    for i in range(30):
        walk = Intent(move=1.0 if i % 2 else -0.6)
        source: Any = (
            Patrol(0.5 + 0.01 * i, 1.0 + 0.03 * i)
            if i % 3
            else Script(((0.0, walk), (0.4 + 0.02 * i, Intent())))
        )
        Controller(world, f"e{i}", position=(2.0 * i, 0.95), source=source)
    assert Crowd.of(world).active
    for _ in range(240):
        world.step()
    assert min(seen.values()) > 50, seen


def _switching_crowd(most: int) -> tuple[World, list[Controller]]:
    """Thirty on a floor with a crate at x = 0: walkers, patrols, and scripts that walk, jump
    (between 1.1 and 1.7 s) and push the crate (from 0.9 s), run from the start with ``most``
    as the crowd's fewest members."""
    world = World()
    world.add_static_segment((-40.0, 0.0), (80.0, 0.0))
    world.add_box("crate", mass=40.0, size=(1.0, 1.0), position=(0.0, 0.5))
    Crowd.of(world).set_min_actors(most)
    actors = []
    for i in range(30):
        at = 1.1 + 0.02 * i
        source: Any = (
            Patrol(0.5 + 0.01 * i, 1.0 + 0.05 * i)
            if i % 3 == 0
            else Script(
                (
                    (0.0, Intent(move=0.8 if i % 2 else -0.5)),
                    (0.9, Intent(move=1.0, push=True)),
                    (at, Intent(move=0.3, jump=True)),
                    (at + 0.05, Intent(move=0.3)),
                )
            )
        )
        x = -2.2 if i == 1 else 2.0 * i
        actors.append(Controller(world, f"e{i}", position=(x, 0.95), source=source))
    return world, actors


OFF_AT, ON_AT = 100, 200
"""Steps at which the crowd of :func:`_switching_crowd` stops (``NEVER``) and runs again
(``ALWAYS``): at the default dt (1/120 s), from 0.83 s to 1.67 s its members run their own
steps (pushing the crate, jumping: half of them in the air when it runs again)."""

BATCHED_AGAIN = 0.5
"""Fewest of the member-steps after :data:`ON_AT` that the crowd runs in batch (the oracles
below compare something; measured 0.75: those in the air or against the crate run their own)."""


def test_a_crowd_stopped_and_started_again_runs_as_it_does_one_by_one() -> None:
    """Law: a crowd that stops (``set_min_actors(NEVER)``) while its members push and jump
    alone, then runs again (``set_min_actors(ALWAYS)``), starts from each member's state of
    now, not from its arrays of when it stopped: bodies and readings equal the scalar path's
    at every step, and the batch path runs again."""
    scalar, sa = _switching_crowd(NEVER)
    batch, sb = _switching_crowd(ALWAYS)
    crowd = Crowd.of(batch)
    airborne = batched = 0
    for step in range(ON_AT + 120):
        if step == OFF_AT:
            crowd.set_min_actors(NEVER)
        if step == ON_AT:
            crowd.set_min_actors(ALWAYS)
            # Not vacuous: some of the members the arrays last saw grounded are in the air.
            airborne = sum(c.state is not State.GROUNDED for c in sb)
        scalar.step()
        batch.step()
        if step >= ON_AT:  # (before the readings are read: reading builds them)
            batched += sum(c.stale is not None for c in sb)
        assert _readings(batch, sb) == _readings(scalar, sa), f"step {step}"
    assert airborne > 0
    assert batched >= BATCHED_AGAIN * 120 * len(sb)


def test_a_member_joining_a_crowd_run_one_by_one_starts_it_as_it_is() -> None:
    """Law: members that ran their own steps below ``min_actors`` (pushing, jumping), then
    one joins and the crowd runs: bodies and readings equal the scalar path's at every step."""
    scalar, sa = _switching_crowd(NEVER)
    batch, sb = _switching_crowd(31)
    assert not Crowd.of(batch).active
    batched = 0
    for step in range(ON_AT + 120):
        if step == ON_AT:
            for world, actors in ((scalar, sa), (batch, sb)):
                actors.append(Controller(world, "late", position=(70.0, 0.95)))
            assert Crowd.of(batch).active
        scalar.step()
        batch.step()
        if step >= ON_AT:
            batched += sum(c.stale is not None for c in sb)
        assert _readings(batch, sb) == _readings(scalar, sa), f"step {step}"
    assert batched >= BATCHED_AGAIN * 120 * len(sb)


class _Logged:
    """A source that logs its name each time it is read, then walks."""

    def __init__(self, name: str, log: list[str]) -> None:
        self.name, self.log = name, log

    def intent(self, t: float) -> Intent:
        self.log.append(self.name)
        return Intent(move=0.5)


def _logged_steps(min_actors: int, between: int | None) -> tuple[list[str], int]:
    """The log of reads and INPUTS hooks of a crowd of 16 logged members (another hook
    registered before member ``between``, and one after them all) over steps in which one
    joins and one leaves; and how many members the crowd read in its own hook."""
    log: list[str] = []
    world = World()
    world.add_static_segment((-5.0, 0.0), (60.0, 0.0))
    Crowd.of(world).set_min_actors(min_actors)
    actors = []
    for i in range(16):
        if i == between:
            world.on(Stage.INPUTS, lambda w: log.append("between"))
        actors.append(Controller(world, f"e{i}", (2.0 * i, 0.95), source=_Logged(f"e{i}", log)))
    world.on(Stage.INPUTS, lambda w: log.append("after"))
    world.run(0.05)
    read_by_crowd = len(Crowd.of(world)._readers)
    Controller(world, "late", (40.0, 0.95), source=_Logged("late", log))
    actors.pop(3).remove()
    world.run(0.05)
    return log, read_by_crowd


@pytest.mark.parametrize("between", [None, 5])
def test_a_crowd_reads_its_members_sources_in_their_hooks_order(between: int | None) -> None:
    """Law: an active crowd reads its members' sources in one INPUTS hook only where their own
    hooks ran one right after another (a hook between them: each reads its own), so every
    source and hook is read in the order it was without the crowd."""
    alone, none_read = _logged_steps(NEVER, between)
    crowd, read = _logged_steps(CROWD_MIN_ACTORS, between)
    assert crowd == alone
    assert none_read == 0 and read == (16 if between is None else 0)
