"""Laws of balance: the player's forces react on what it stands on, and a floor that tilts faster
than the balance budget can follow knocks it over — after which it gets back up."""

from __future__ import annotations

import math
from dataclasses import dataclass

import pymunk

from playground import Controller, State, World

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


def test_a_floor_tilting_faster_than_the_balance_budget_knocks_the_player_over() -> None:
    """Beyond the balance budget for longer than balance_loss_time: off balance (hover and drive
    let go); once still, it gets up and stands upright at ride height again."""
    world, player = tilting_room(Tilt(math.radians(50.0), 0.4))
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
