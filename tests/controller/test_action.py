"""Laws of acting (:mod:`playground.controller.action`): :func:`act` turns the state just
decided into forces through the controller's :class:`Laws` — the laws it is given, not others —
with their reactions on a dynamic ground, and :func:`exert` puts them into the world."""

from __future__ import annotations

import dataclasses
import math

import pymunk
import pytest

from playground import Controller, ControllerConfig, Intent, State, World
from playground._engine.state import BodyState
from playground.controller import ControllerState, GroundHit, Laws, Sensed
from playground.controller.action import NO_FORCES, ControllerForces, act, exert
from playground.forces.ledger import Category

CONFIG = ControllerConfig()
G = 9.81
DT = 1 / 120
LAW_HOVER = 123.0
"""N: the hover of a replaced law, far from the weight (686.7 N) the default one gives."""


def standing(*, dynamic: bool = False, short_tilt: float = 0.0) -> Sensed:
    """Sensed upright at ride height over flat ground (a dynamic body if ``dynamic``), leaning
    by ``short_tilt`` rad."""
    kind = pymunk.Body.DYNAMIC if dynamic else pymunk.Body.STATIC
    ground = pymunk.Body(10.0, 1.0, body_type=kind)
    hit = GroundHit(
        body=ground,
        point=(0.0, 0.0),
        normal=(0.0, 1.0),
        distance=CONFIG.ride_height,
        walkable=True,
        frame_velocity=(0.0, 0.0),
        frame_acceleration=(0.0, 0.0),
        own_acceleration=(0.0, 0.0),
        spin=0.0,
        dynamic=dynamic,
    )
    body = BodyState(
        0.0, CONFIG.ride_height, 0.0, 0.0, math.cos(short_tilt), math.sin(short_tilt), 0.0,
        CONFIG.mass, 20.0,
    )  # fmt: skip
    return Sensed(body=body, up=(0.0, 1.0), time=1.0, dt=DT, gravity=(0.0, -G), ground=hit)


GROUNDED = ControllerState(state=State.GROUNDED)


def test_standing_still_the_hover_carries_the_weight_and_nothing_else_acts() -> None:
    forces = act(standing(), GROUNDED, Intent(), CONFIG, Laws())
    assert forces.hover == (0.0, CONFIG.mass * G)
    assert forces.own == [(0.0, CONFIG.mass * G, Category.SUPPORT)]
    assert forces.ground is None and forces.reactions == []
    assert forces.balance_torque == 0.0 and forces.balance_short is False


def test_a_replaced_law_is_the_one_that_acts() -> None:
    """A controller's Laws decide its forces: a hover law replaced by a constant gives that
    hover, on our body and (on a dynamic ground) back on the ground."""
    laws = dataclasses.replace(Laws(), hover=lambda sensed, state, hit, config: LAW_HOVER)
    forces = act(standing(dynamic=True), GROUNDED, Intent(), CONFIG, laws)
    assert forces.hover == (0.0, LAW_HOVER)
    assert forces.reactions == [(-0.0, -LAW_HOVER, Category.SUPPORT)]


def test_a_break_through_the_laws_changes_the_forces_in_a_world() -> None:
    """A controller built with a broken law follows it: with no hover it sinks onto its end cap
    (its probe meets the floor nearer than ride height) while the default one rides."""
    heights = []
    for laws in (Laws(), dataclasses.replace(Laws(), hover=lambda *a: 0.0)):
        world = World()
        world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
        player = Controller(world, "p", (0.0, 1.0), laws=laws)
        world.run(2.0)
        assert player.probe is not None
        heights.append(player.probe.distance)
    assert heights[0] == pytest.approx(CONFIG.ride_height, abs=1e-6)
    assert heights[1] < CONFIG.ride_height - 0.01


def test_reactions_go_onto_a_dynamic_ground_only() -> None:
    """Newton's third law: on a dynamic ground the hover's, the drive's and the balance
    torque's reactions are its, equal and opposite; a static ground takes none."""
    walking = Intent(move=1.0)
    on_crate = act(standing(dynamic=True, short_tilt=0.1), GROUNDED, walking, CONFIG, Laws())
    assert on_crate.ground is not None
    (hx, hy, _), (dx, dy, _) = on_crate.reactions
    assert (hx, hy) == (-on_crate.hover[0], -on_crate.hover[1])
    assert (dx, dy) == (-on_crate.drive[0], -on_crate.drive[1])
    assert on_crate.reaction_torque == -on_crate.balance_torque != 0.0
    on_floor = act(standing(short_tilt=0.1), GROUNDED, walking, CONFIG, Laws())
    assert on_floor.ground is None and on_floor.reaction_torque is None


def test_the_take_off_step_still_carries_the_weight() -> None:
    """Taking off from the ground, the hover acts once more beside the jump's force, so the
    body leaves at exactly jump_speed."""
    taking_off = ControllerState(state=State.AIRBORNE, take_off_from=State.GROUNDED)
    forces = act(standing(), taking_off, Intent(jump=True), CONFIG, Laws())
    jump_force = CONFIG.mass * CONFIG.jump_speed / DT
    assert forces.own[0] == (0.0, jump_force, Category.SUPPORT)
    assert forces.hover == (0.0, CONFIG.mass * G)


def test_off_balance_nothing_acts() -> None:
    fallen = ControllerState(state=State.OFF_BALANCE)
    assert act(standing(), fallen, Intent(move=1.0, push=True), CONFIG, Laws()) is NO_FORCES


def test_the_balance_reports_when_it_falls_short() -> None:
    """Needing more torque than balance_torque while touching is a shortfall (counted by the
    next step's state machine); not while getting up."""
    leaning = standing(short_tilt=1.2)
    assert act(leaning, GROUNDED, Intent(), CONFIG, Laws()).balance_short is True
    rising = ControllerState(state=State.GETTING_UP)
    assert act(leaning, rising, Intent(), CONFIG, Laws()).balance_short is False


def test_exert_puts_the_push_on_the_pushed_body() -> None:
    """exert writes the push on the pushed body (and our own forces on ours): one step later the
    pushed body has gained F/m·dt."""
    world = World()
    world.gravity = (0.0, 0.0)
    crate = pymunk.Body(10.0, 1.0)
    world.add("crate", crate, pymunk.Circle(crate, 0.2))
    me = pymunk.Body(1.0, 1.0)
    world.add("me", me, pymunk.Circle(me, 0.2))
    me.position = (3.0, 0.0)
    forces = ControllerForces(pushed=(crate, (0.0, 0.0), (50.0, 0.0)))
    exert(world, me, forces)
    world.step()
    assert crate.velocity.x == pytest.approx(50.0 / 10.0 * world.config.dt, rel=1e-12)
    assert me.velocity.x == 0.0
