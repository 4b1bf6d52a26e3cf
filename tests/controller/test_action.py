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
from playground.world.config import WorldConfig

CONFIG = ControllerConfig()
G = 9.81
DT = 1 / 120
LAW_HOVER = 123.0
"""N: the hover of a replaced law, far from the weight (686.7 N) the default one gives."""


def standing(*, dynamic: bool = False, short_tilt: float = 0.0, lever: float = math.inf) -> Sensed:
    """Sensed upright at ride height over flat ground (a dynamic body if ``dynamic``, holding
    the feet's centre of pressure ``lever`` m off the hit), leaning by ``short_tilt`` rad."""
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
        lever=lever,
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


LEVER = 0.05
"""m: how far a loose tile holds the feet's centre of pressure off the hit (sensing.footing)."""


def test_the_feet_twist_a_loose_ground_only_as_hard_as_its_load_holds_it() -> None:
    """Law: through a loose dynamic ground the balance torque is at most the hover's force
    times the ground's lever, its reaction the opposite; on a static ground the same lean gets
    all it asks; the balance falls short only past its own budget."""
    lean = 0.05
    on_floor = act(standing(short_tilt=lean), GROUNDED, Intent(), CONFIG, Laws())
    need = on_floor.balance_torque
    assert abs(need) < CONFIG.balance_budget(CONFIG.mass) and on_floor.balance_short is False
    on_tile = act(
        standing(dynamic=True, short_tilt=lean, lever=LEVER), GROUNDED, Intent(), CONFIG, Laws()
    )
    weight = CONFIG.mass * G
    assert on_tile.hover == (0.0, weight) and abs(need) > weight * LEVER
    assert on_tile.balance_torque == math.copysign(weight * LEVER, need)
    assert on_tile.reaction_torque == -on_tile.balance_torque
    assert on_tile.balance_short is False
    jointed = act(standing(dynamic=True, short_tilt=lean), GROUNDED, Intent(), CONFIG, Laws())
    assert jointed.balance_torque == need and jointed.reaction_torque == -need


TILE_TIP = 0.05
"""rad: what a loose tile may turn under a walker's feet: settling under its load, its corners
sink into the contact slop (5 mm over 25 cm: 0.02 rad); measured at most 0.031 rad."""


@pytest.mark.parametrize("mass", [35.0, 70.0, 140.0])
@pytest.mark.parametrize(("dt", "substeps"), [(1 / 60, 1), (1 / 120, 2), (1 / 240, 4)])
def test_walking_over_loose_tiles_tips_none(mass: float, dt: float, substeps: int) -> None:
    """Law, at any mass, step and substeps: walking at top speed over loose 3 kg tiles lying
    on a floor, the feet twist none of them past what its load holds down, so none tips (before
    the bound, the balance's reaction spun them at hundreds of rad/s) and the walker keeps its
    pace (8.4 m at 2.5 s on a bare floor)."""
    world = World(WorldConfig(dt=dt, substeps=substeps))
    world.add_static_segment((-5.0, -0.05), (20.0, -0.05), radius=0.05)
    tiles = [
        world.add_box(f"tile{i}", mass=3.0, size=(0.25, 0.04), position=(2.0 + 0.5 * i, 0.02))
        for i in range(6)
    ]
    player = Controller(world, "player", (0.0, 0.95), ControllerConfig(mass=mass))
    player.intent = Intent(move=1.0)
    turned = 0.0
    for _ in range(round(2.5 / dt)):
        world.step()
        turned = max(turned, *(abs(tile.angle) for tile in tiles))
    assert turned < TILE_TIP
    assert player.body.position.x > 8.0


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
