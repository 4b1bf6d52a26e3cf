"""Laws of the state machine (:func:`playground.controller.decision.decide`): the player's forces
react on what it stands on, and a floor that tilts faster than the balance budget can follow
knocks it over — after which it gets back up; and, as a function of what was sensed, the jump,
the coyote time, the balance's shortfall, the crush and the grip."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import pymunk
import pytest

from playground import Controller, ControllerConfig, Intent, State, World
from playground._engine.state import BodyState
from playground.controller import ControllerState, GroundHit, Sensed
from playground.controller.decision import decide
from playground.controller.grab import Grip, Impulses
from playground.intents import IDLE
from playground.level import find, load
from playground.scene import build

SEESAW_TIP = math.radians(5.0)
"""rad: the seesaw has clearly tipped toward the player (its free travel is about 19°)."""

STANDING_TILT = math.radians(1.0)
"""rad: standing again, the balance PD has brought the axis to up."""

TOL_RIDE = 1e-3
"""m: standing again at ride height once the spring has settled."""


def smoothstep(s: float) -> float:
    s = min(1.0, max(0.0, s))
    return s * s * (3.0 - 2.0 * s)


@dataclass(frozen=True, slots=True)
class Tilt:
    """A floor pivoting about the origin: to ``angle`` (rad) over ``duration`` (s) from t = 1 s,
    back to level over 2 s from t = 3 s."""

    angle: float
    duration: float

    def pose(self, t: float) -> tuple[tuple[float, float], float]:
        a = self.angle * (smoothstep((t - 1.0) / self.duration) - smoothstep((t - 3.0) / 2.0))
        return ((0.0, 0.0), a)


def tilting_room(tilt: Tilt) -> tuple[World, Controller]:
    """A 6 m kinematic floor with walls, tilting under a player standing over its pivot."""
    world = World()
    floor = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shapes = [
        pymunk.Segment(floor, (-3.0, -0.05), (3.0, -0.05), 0.05),
        pymunk.Segment(floor, (-3.0, -0.05), (-3.0, 2.0), 0.05),
        pymunk.Segment(floor, (3.0, -0.05), (3.0, 2.0), 0.05),
    ]
    for shape in shapes:
        shape.friction = 1.0
    world.add("floor", floor, *shapes)
    world.add_mover("floor", tilt)
    return world, Controller(world, "player", (0.0, 0.95))


def test_seesaw_tips_toward_the_side_the_player_stands_on() -> None:
    """Newton's third law: the hover's reaction pushes the plank down under the player."""
    for side in (1.0, -1.0):
        world = World()
        world.add_static_segment((-10.0, 0.0), (10.0, 0.0))
        plank = world.add_box("plank", mass=40.0, size=(6.0, 0.1), position=(0.0, 1.0))
        world.add_constraint(pymunk.PivotJoint(world.space.static_body, plank, (0.0, 1.0)))
        player = Controller(world, "player", (2.0 * side, 1.05 + 0.95))
        world.run(1.0)
        assert player.state is State.GROUNDED
        assert player.probe is not None and player.probe.body is plank
        assert -side * plank.angle > SEESAW_TIP


BLOW = 300.0
"""N·s: a blow on the head, sideways (4.3 m/s on 70 kg, 0.65 m above the centre): its spin
needs more than the balance budget for longer than balance_loss_time."""


def test_a_blow_beyond_the_balance_budget_knocks_the_player_over() -> None:
    """Beyond the balance budget for longer than balance_loss_time: off balance (hover and drive
    let go); once still, it gets up and stands upright at ride height again. (A floor tilting
    under it does not: its up stays within max_lean of the field's, and a hover turns nothing.)
    """
    world = World()
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0))
    player = Controller(world, "player", (0.0, 0.95))
    world.run(1.0)
    head = player.body.local_to_world((0.0, player.config.half_length))
    player.body.apply_impulse_at_world_point((BLOW, 0.0), head)
    seen = [player.state]
    while world.time < 9.0:
        world.step()
        if player.state is not seen[-1]:
            seen.append(player.state)
    assert State.OFF_BALANCE in seen
    fell = seen.index(State.OFF_BALANCE)
    assert State.GETTING_UP in seen[fell:]
    assert player.state is State.GROUNDED
    assert abs(player.tilt) < STANDING_TILT
    assert player.probe is not None
    assert abs(player.probe.distance - player.config.ride_height) < TOL_RIDE


def test_a_slow_tilt_within_the_walkable_slope_keeps_the_player_standing() -> None:
    """Within the budget: a floor tilting slowly to a walkable slope never knocks it over."""
    world, player = tilting_room(Tilt(math.radians(25.0), 3.0))
    while world.time < 6.0:
        world.step()
        assert player.state is State.GROUNDED


# -- decide as a function of what was sensed ----------------------------------------------------

CONFIG = ControllerConfig()
DT = 1 / 120
"""s: the step of the sensed values below."""
CRUSH = CONFIG.crush_threshold(CONFIG.mass)
"""N: the load that crushes the sensed body below (of the config's mass)."""


def standing(t: float = 1.0, *, vy: float = 0.0, load: float = 0.0) -> Sensed:
    """Sensed at ``t`` (s): upright at ride height over flat static ground, rising at ``vy``
    (m/s), ``load`` (N) pressing from above through contacts."""
    hit = GroundHit(
        body=pymunk.Body(body_type=pymunk.Body.STATIC),
        point=(0.0, 0.0),
        normal=(0.0, 1.0),
        distance=CONFIG.ride_height,
        walkable=True,
        frame_velocity=(0.0, 0.0),
        frame_acceleration=(0.0, 0.0),
        own_acceleration=(0.0, 0.0),
        spin=0.0,
        dynamic=False,
    )
    body = BodyState(0.0, CONFIG.ride_height, 0.0, vy, 1.0, 0.0, 0.0, CONFIG.mass, 20.0)
    return Sensed(
        body=body,
        up=(0.0, 1.0),
        time=t,
        dt=DT,
        gravity=(0.0, -9.81),
        ground=hit,
        contact_load=load,
        load=load,
    )


def airborne(t: float = 1.0) -> Sensed:
    """Sensed at ``t`` (s) with no ground under it."""
    return dataclasses.replace(standing(t), ground=None)


GROUNDED = ControllerState(state=State.GROUNDED, grounded_at=1.0 - DT)


def test_decide_returns_a_new_state_and_leaves_its_input_as_it_was() -> None:
    """Law: decide is a function: the state it is given is not changed."""
    before = dataclasses.replace(GROUNDED)
    after = decide(standing(), GROUNDED, Intent(jump=True), CONFIG)
    assert after is not GROUNDED
    assert before == GROUNDED


def test_a_jump_press_on_the_ground_takes_off_from_the_grounded_state() -> None:
    """A new press takes off at once: the state is airborne and rising, the press used up, and
    the take-off step's forces still follow the grounded state it leaves."""
    after = decide(standing(), GROUNDED, Intent(jump=True), CONFIG)
    assert after.state is State.AIRBORNE
    assert after.take_off_from is State.GROUNDED and after.footing is State.GROUNDED
    assert after.rising and after.jump_pressed_at == -math.inf
    held = decide(standing(1.0 + DT), after, Intent(jump=True), CONFIG)
    assert held.take_off_from is None


def test_already_rising_at_jump_speed_there_is_no_take_off() -> None:
    """A press while moving up at jump_speed relative to the ground is used up, no take-off."""
    after = decide(standing(vy=CONFIG.jump_speed), GROUNDED, Intent(jump=True), CONFIG)
    assert after.take_off_from is None and after.jump_pressed_at == -math.inf


@pytest.mark.parametrize(("since", "takes_off"), [(0.05, True), (0.2, False)])
def test_a_coyote_jump_works_only_within_coyote_time(since: float, takes_off: bool) -> None:
    """Airborne ``since`` s after the ground, a press takes off within coyote_time (0.1 s)."""
    state = ControllerState(state=State.AIRBORNE, grounded_at=1.0 - since)
    after = decide(airborne(1.0), state, Intent(jump=True), CONFIG)
    assert (after.take_off_from is State.AIRBORNE) is takes_off


def test_needing_more_than_the_balance_budget_for_too_long_loses_balance() -> None:
    """The balance's shortfall is counted over the steps while touching; past
    balance_loss_time the controller is off balance and lets go of any grip; a step without it
    starts the count again."""
    state = GROUNDED
    short = dataclasses.replace(standing(), balance_short=True)
    steps = 0
    while state.state is not State.OFF_BALANCE:
        state = decide(short, state, IDLE, CONFIG)
        steps += 1
    # Off balance on the step whose count passes balance_loss_time (float sums of dt decide
    # which of the two steps around it).
    assert steps == pytest.approx(CONFIG.balance_loss_time / DT, abs=1.0)
    assert state.grip is None and state.saturated == 0.0
    counted = decide(short, GROUNDED, IDLE, CONFIG)
    assert counted.saturated == DT
    ok = dataclasses.replace(standing(), balance_short=False)
    assert decide(ok, counted, IDLE, CONFIG).saturated == 0.0


@pytest.mark.parametrize(("load", "state"), [(1.1, State.CRUSHED), (0.9, State.GROUNDED)])
def test_a_load_above_the_crush_force_crushes(load: float, state: State) -> None:
    """Bearing more than crush_force from above through contacts is crushed."""
    after = decide(standing(load=load * CRUSH), GROUNDED, IDLE, CONFIG)
    assert after.state is state


def test_a_grip_is_taken_while_grabbing_and_dropped_when_let_go_or_slipped() -> None:
    """A handhold within reach is taken while the grab is held (hanging); releasing the grab,
    or anchors slipped beyond grip_slip, drops it."""
    a, b = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    grip = Grip(pymunk.PivotJoint(a, b, (0.0, 0.0)), pymunk.Circle(b, 0.1), Impulses())
    taking = dataclasses.replace(airborne(), handhold=grip)
    hanging = decide(taking, ControllerState(), Intent(grab=True), CONFIG)
    assert hanging.state is State.HANGING and hanging.grip is grip
    kept = decide(airborne(), hanging, Intent(grab=True), CONFIG)
    assert kept.grip is grip and kept.state is State.HANGING
    assert decide(airborne(), hanging, IDLE, CONFIG).grip is None
    slipped = dataclasses.replace(airborne(), slip=2.0 * CONFIG.grip_slip)
    assert decide(slipped, hanging, Intent(grab=True), CONFIG).grip is None


def test_a_crushed_controller_stays_crushed_through_a_moment_of_relief() -> None:
    """Hysteresis in time: once crushed, a load dropping to crush_force or below (or off) for
    less than crush_release_time keeps the state; longer, it stands again."""
    crushed = ControllerState(state=State.CRUSHED)
    relief = standing(load=0.5 * CRUSH)
    state = decide(relief, crushed, IDLE, CONFIG)
    assert state.state is State.CRUSHED and state.relieved == DT
    steps = 1
    while state.state is State.CRUSHED:
        state = decide(relief, state, IDLE, CONFIG)
        steps += 1
    assert state.state is State.GROUNDED and state.relieved == 0.0
    assert steps == pytest.approx(CONFIG.crush_release_time / DT, abs=1.0)
    pressed_again = decide(standing(load=2.0 * CRUSH), state, IDLE, CONFIG)
    assert pressed_again.state is State.CRUSHED


def test_a_bouncing_crate_crushes_a_light_player_once() -> None:
    """crusher with both players at half the mass (35 kg): the 250 kg crate bounces on the
    lighter player's hover, its load swinging around crush_force and off; each player is
    crushed once, not crushed, standing, crushed again."""
    level = load(find("crusher"))
    actors = [
        a.model_copy(update={"controller": a.controller.model_copy(update={"mass": 35.0})})
        if a.controller is not None
        else a
        for a in level.actors
    ]
    scene = build(level.model_copy(update={"actors": actors}))
    changes = {name: 0 for name in scene.controllers}
    while scene.world.time < 2.0:
        before = {name: c.state for name, c in scene.controllers.items()}
        scene.world.step()
        for name, c in scene.controllers.items():
            changes[name] += c.state is not before[name] and scene.world.time > 0.1
    assert changes == {name: 1 for name in scene.controllers}


def test_a_take_off_rises_until_it_stops_rising_out_of_the_grounds_reach() -> None:
    """Rising, with no ground in reach the take-off lasts while it moves up relative to the
    world (a platform it jumps up through is not stood on on the way up), and ends at the top."""
    rising = dataclasses.replace(GROUNDED, state=State.AIRBORNE, rising=True)
    up = dataclasses.replace(airborne(), body=dataclasses.replace(airborne().body, vy=2.0))
    assert decide(up, rising, Intent(), CONFIG).rising
    down = dataclasses.replace(airborne(), body=dataclasses.replace(airborne().body, vy=-0.1))
    assert not decide(down, rising, Intent(), CONFIG).rising
