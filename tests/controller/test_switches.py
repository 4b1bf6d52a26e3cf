"""Laws of the controller when gravity changes: a flipped room, own gravity, a nullified enemy.

"Up" follows the gravity field while airborne, so a player whose room flips rights itself in the
air and lands feet first; a body whose gravity is nullified has no normal force, hence no traction.
"""

from __future__ import annotations

import math

import pymunk

from playground import (
    Controller,
    GravityRule,
    Intent,
    Patrol,
    RotatingRoom,
    Script,
    State,
    Turn,
    World,
)

G = 9.81
"""|g| of the world's default field, m/s²."""

FEET_FIRST = math.radians(15.0)
"""Issue 3: the capsule's axis is within 15° of up at touchdown after a 180° flip."""

STANDING_TILT = math.radians(1.0)
"""Standing: the balance PD has brought the axis to up (it converges exponentially)."""

SKIN = 0.05
"""Radius of the room's static segments, m: their surfaces are this far from their centre lines."""

TOL_RIDE = 1e-3
"""Metres: standing at ride height on the new floor after the landing has damped out."""


def touching(player: Controller) -> bool:
    """The capsule's shape is in contact with something."""
    found: list[pymunk.Arbiter] = []
    player.body.each_arbiter(found.append)
    return bool(found)


def axis_angle(player: Controller) -> float:
    """Angle between the capsule's axis and the controller's up, rad."""
    return abs(player.tilt)


def test_flipped_gravity_lands_feet_first_on_the_old_ceiling() -> None:
    """Up follows the field in the air: after a 180° flip the floor lets go at once, the player
    rights itself while falling and lands feet first on the old ceiling (within 15° of up both
    when its hover catches it and when its body first touches the ceiling) and stands there."""
    ceiling = 7.0
    world = World(gravity=RotatingRoom(turns=(Turn(1.0, math.pi),)))
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0), SKIN)
    world.add_static_segment((-20.0, ceiling), (20.0, ceiling), SKIN)
    player = Controller(world, "player", (0.0, 0.95))
    world.run(1.0)
    assert player.state is State.GROUNDED
    catch_tilt = contact_tilt = None
    left = False
    while world.time < 4.0:
        world.step()
        left = left or player.state is State.AIRBORNE
        if left and catch_tilt is None and player.state is State.GROUNDED:
            # The hover catches it: the probe has found the ceiling.
            catch_tilt = axis_angle(player)
            assert player.probe is not None and player.probe.normal[1] < 0.0
        if contact_tilt is None and touching(player):
            # Its body touches the ceiling: the honest touchdown of the capsule itself.
            contact_tilt = axis_angle(player)
            assert player.body.position.y > ceiling / 2.0
    assert catch_tilt is not None and catch_tilt < FEET_FIRST
    assert contact_tilt is not None and contact_tilt < FEET_FIRST
    assert player.state is State.GROUNDED
    assert axis_angle(player) < STANDING_TILT
    assert player.up[1] < -0.999
    assert abs(player.body.position.y - (ceiling - SKIN - player.config.ride_height)) < TOL_RIDE


SPEED_BOUND = 0.01
"""m/s: a nullified enemy's speed may change only by the hover's last transient: with no gravity
pressing it onto the ground there is no normal force, hence no traction (drive ≤ traction·N)."""


def test_nullified_enemy_cannot_change_its_speed() -> None:
    """No gravity, no normal force, no traction: a patrolling enemy whose gravity the player
    nullifies keeps drifting at the speed it had, although its move input reverses."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    patrol = Patrol(speed=0.5, period=4.0)
    enemy = Controller(world, "enemy", (0.0, 0.95), source=patrol)
    Controller(world, "player", (-5.0, 0.95), source=Script(((1.0, Intent(nullify="enemy")),)))
    world.run(1.0)
    assert world.gravity_rule("enemy").scale == 1.0
    world.run(0.1)
    assert world.gravity_rule("enemy") == GravityRule(scale=0.0)
    v0 = enemy.body.velocity
    speeds = []
    while world.time < 5.0:
        world.step()
        speeds.append((enemy.body.velocity - v0).length)
    assert patrol.intent(3.0).move == -patrol.intent(1.0).move
    assert max(speeds) < SPEED_BOUND
    assert enemy.last_forces.drive == (0.0, 0.0)


def test_switching_own_gravity_and_jumping_lands_on_a_moving_creature() -> None:
    """Switch own gravity toward a large moving body, jump: the player falls toward it, rights
    itself in the air, lands on it and is carried along."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    beast = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    beast.position = (-3.0, 7.0)
    beast.velocity = (1.0, 0.0)
    world.add("beast", beast, pymunk.Poly.create_box(beast, (10.0, 2.0)))
    toward = (-2.0, 6.0)  # from the player at t = 1 s to where the beast's centre is then
    script = Script(((1.0, Intent(gravity=toward, jump=True)), (1.1, Intent(gravity=toward))))
    player = Controller(world, "player", (0.0, 0.95), source=script)
    world.run(1.0)
    assert player.state is State.GROUNDED
    world.run(3.0)
    assert world.gravity_rule("player").direction is not None
    assert player.state is State.GROUNDED
    assert player.probe is not None and player.probe.body is beast
    assert (player.body.velocity - beast.velocity).length < SPEED_BOUND


def test_own_gravity_switch_and_restore_act_once_per_new_intent() -> None:
    """A gravity switch sets one's own rule; restore_gravity returns to the field."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    script = Script(
        (
            (0.5, Intent(gravity=(1.0, 0.0))),
            (0.6, Intent(gravity=(1.0, 0.0))),
            (0.7, Intent(restore_gravity=True)),
        )
    )
    player = Controller(world, "player", (0.0, 0.95), source=script)
    world.run(0.55)
    assert world.gravity_rule("player").direction == (1.0, 0.0)
    assert world.gravity_at("player") == (G, 0.0)
    world.run(0.2)
    assert world.gravity_rule("player").is_default
    assert player.intent.restore_gravity
