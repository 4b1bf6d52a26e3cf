"""Laws of the controller's actions: jump, grab/hang/climb, push, and being crushed.

Each action works within a force budget; the world can overpower it (a grip budget below the load
lets go, a push budget below a crusher's weight leaves the player pinned).
"""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import (
    Controller,
    ControllerConfig,
    Elevator,
    Intent,
    Script,
    State,
    World,
)

G = 9.81
"""|g| of the world's default field, m/s²."""

M = ControllerConfig().mass
"""The default player's mass, kg."""

TOL_GRIP_REL = 0.01
"""Issue 3: grip = m·(g + a) within 1 % while hanging from a body accelerating up at a."""

TOL_TAKEOFF = 1e-9
"""m/s: the take-off step carries the weight, so the jump leaves at exactly jump_speed relative to
the ground (float rounding of one impulse)."""


def flyer(world: World, accel: float, bottom: float, start_time: float = 1.0) -> pymunk.Body:
    """A massive (kinematic) flying slab whose underside is at ``bottom`` (m), rising at ``accel``
    (m/s²) from ``start_time``."""
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("flyer", body, pymunk.Poly.create_box(body, (4.0, 0.5)))
    world.add_mover(
        "flyer", Elevator(start=(0.0, bottom + 0.25), acceleration=accel, start_time=start_time)
    )
    return body


@pytest.mark.parametrize("ground_speed", [0.0, 1.0])
def test_jump_leaves_at_jump_speed_relative_to_the_ground(ground_speed: float) -> None:
    """Jump: an impulse along up that sets the velocity relative to the ground to jump_speed."""
    world = World()
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("lift", plat, pymunk.Segment(plat, (-20.0, -0.05), (20.0, -0.05), 0.05))
    plat.velocity = (0.0, ground_speed)
    script = Script(((1.0, Intent(jump=True)), (1.1, Intent())))
    player = Controller(world, "player", (0.0, 0.95), source=script)
    world.run(1.0)
    assert player.state is State.GROUNDED
    world.step()
    assert player.state is State.AIRBORNE
    vy = player.body.velocity.y
    assert abs(vy - (ground_speed + player.config.jump_speed)) < TOL_TAKEOFF


def test_jump_input_buffer() -> None:
    """Input buffer: a press shortly before landing still jumps; a press long before does not."""
    cfg = ControllerConfig()
    for press_before, jumps in ((0.5 * cfg.jump_buffer, True), (3.0 * cfg.jump_buffer, False)):
        world = World()
        world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
        player = Controller(world, "player", (0.0, 2.0), cfg)
        landing = None
        while landing is None:
            world.step()
            if player.state is State.GROUNDED:
                landing = world.time
        world2 = World()
        world2.add_static_segment((-20.0, 0.0), (20.0, 0.0))
        press = landing - press_before
        script = Script(((press, Intent(jump=True)), (press + 0.02, Intent())))
        player2 = Controller(world2, "player", (0.0, 2.0), cfg, source=script)
        rise = 0.0
        while world2.time < landing + 0.3:
            world2.step()
            rise = max(rise, player2.body.velocity.y)
        assert (rise > 0.5 * cfg.jump_speed) is jumps


def test_coyote_time_allows_a_jump_just_after_walking_off_a_ledge() -> None:
    """Coyote time: a press within coyote_time of leaving the ground still jumps; later not."""
    cfg = ControllerConfig()

    def ledge(script: Script | None) -> tuple[World, Controller]:
        world = World()
        world.add_static_segment((-10.0, 0.0), (0.0, 0.0))
        world.add_static_segment((-10.0, -6.0), (20.0, -6.0))
        walk = Script(((0.0, Intent(move=1.0)),))
        return world, Controller(world, "player", (-2.0, 0.95), cfg, script or walk)

    world, player = ledge(None)
    while player.body.position.x < -0.5:
        world.step()
    assert player.state is State.GROUNDED
    while player.state is not State.AIRBORNE:
        world.step()
    left = world.time
    for press_after, jumps in ((0.5 * cfg.coyote_time, True), (3.0 * cfg.coyote_time, False)):
        press = left + press_after
        script = Script(
            (
                (0.0, Intent(move=1.0)),
                (press, Intent(move=1.0, jump=True)),
                (press + 0.05, Intent()),
            )
        )
        world, player = ledge(script)
        rise = -math.inf
        while world.time < press + 0.2:
            world.step()
            if world.time > press:
                rise = max(rise, player.body.velocity.y)
        assert (rise > 0.5 * cfg.jump_speed) is jumps


def test_hanging_grip_is_m_g_plus_a_and_letting_go_works() -> None:
    """Newton: hanging from a body accelerating up at a, the grip carries m·(g + a); releasing the
    grab lets go (free fall, no engine force)."""
    a = 2.0
    world = World()
    flyer(world, a, bottom=3.05)
    script = Script(((0.0, Intent(grab=True)), (3.0, Intent())))
    player = Controller(world, "player", (0.0, 2.0), source=script)
    world.run(0.1)
    assert player.state is State.HANGING
    world.run(2.8)
    expected = M * (G + a)
    assert abs(player.grip - expected) < TOL_GRIP_REL * expected
    engine = world.forces("player").engine
    assert abs(engine[1] - expected) < TOL_GRIP_REL * expected
    world.run(0.2)
    assert player.state is State.AIRBORNE
    assert player.joint is None
    assert abs(world.forces("player").engine[1]) < TOL_GRIP_REL * expected


def test_exceeding_the_grip_budget_drops_the_player() -> None:
    """A grip budget between m·g and m·(g + a) holds the player until the flyer accelerates."""
    a = 3.0
    cfg = ControllerConfig(grip_force=M * (G + 0.5 * a))
    world = World()
    flyer(world, a, bottom=3.05)
    player = Controller(world, "player", (0.0, 2.0), cfg, Script(((0.0, Intent(grab=True)),)))
    world.run(0.9)
    assert player.state is State.HANGING
    world.run(1.0)
    assert player.state is not State.HANGING
    assert player.joint is None


def test_climbing_moves_the_grip_along_the_held_body() -> None:
    """Climb slides the held anchor along the held body's surface at climb_speed."""
    world = World()
    flyer(world, 0.0, bottom=3.05)
    script = Script(((0.0, Intent(grab=True)), (0.5, Intent(grab=True, climb=1.0))))
    player = Controller(world, "player", (0.0, 2.0), source=script)
    world.run(0.5)
    assert player.joint is not None
    x0 = player.joint.anchor_b.x
    world.run(1.0)
    assert player.joint is not None
    moved = abs(player.joint.anchor_b.x - x0)
    assert abs(moved - player.config.climb_speed * 1.0) < 0.02 * player.config.climb_speed


CRUSHER_MASS = 200.0
"""kg: its weight (1962 N) is above the default crush threshold."""

FLOOR_SKIN = 0.05
"""m: radius of the static floor segment: its surface is this far above its centre line."""

TOL_LOAD_REL = 1e-3
"""Resting stack 1.5 s after the drop: the contact's bounce has decayed below 0.1 %."""

PINNED = 0.05
"""m: a pinned player does not get out from under the crusher (it moves less than this)."""


def crusher_scene(push_force: float) -> tuple[World, Controller, pymunk.Body]:
    """A heavy box dropped on an idle player who, from 2 s on, pushes and tries to walk out."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    script = Script(((2.0, Intent(push=True)), (2.5, Intent(push=True, move=1.0))))
    cfg = ControllerConfig(push_force=push_force)
    player = Controller(world, "player", (0.0, 0.95), cfg, source=script)
    box = world.add_box("crusher", mass=CRUSHER_MASS, size=(1.0, 0.5), position=(0.0, 3.0))
    return world, player, box


def test_a_heavy_box_dropped_on_the_player_crushes_it() -> None:
    """Crushed: the load from above exceeds crush_force; the player bears it (support along up
    is the player's and the box's weight, held by the hover)."""
    world, player, _ = crusher_scene(push_force=1000.0)
    world.run(2.0)
    weight = CRUSHER_MASS * G
    assert player.config.crush_force < weight
    assert player.state is State.CRUSHED
    assert abs(player.load - weight) < TOL_LOAD_REL * weight
    assert abs(player.last_forces.hover[1] - (M * G + weight)) < TOL_LOAD_REL * weight


def test_a_push_budget_above_the_weight_pushes_the_crusher_off() -> None:
    """Push budget > the crusher's weight: it is lifted off and the player walks out from under
    it within a few seconds."""
    world, player, box = crusher_scene(push_force=1.3 * CRUSHER_MASS * G)
    world.run(2.0)
    assert player.state is State.CRUSHED
    world.run(3.0)
    assert player.state is State.GROUNDED
    assert abs(player.body.position.x - box.position.x) > 0.5 + player.config.radius + 1.0


def test_a_push_budget_below_the_weight_stays_pinned() -> None:
    """Push budget < the crusher's weight: the player stays crushed and cannot walk out."""
    world, player, box = crusher_scene(push_force=0.75 * CRUSHER_MASS * G)
    world.run(5.0)
    assert player.state is State.CRUSHED
    assert abs(player.body.position.x) < PINNED
    assert abs(box.position.x) < PINNED


def test_the_hover_never_exceeds_the_legs_budget() -> None:
    """Hover budget: under a load beyond it the hover pushes with hover_force and the capsule
    bottoms out; the floor's contact takes the rest."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0), FLOOR_SKIN)
    cfg = ControllerConfig(hover_force=2.0 * M * G)
    player = Controller(world, "player", (0.0, 0.95), cfg)
    world.add_box("anvil", mass=CRUSHER_MASS, size=(1.0, 0.5), position=(0.0, 2.2))
    world.run(2.0)
    assert cfg.hover_force < (M + CRUSHER_MASS) * G
    assert player.last_forces.hover[1] == cfg.hover_force
    assert player.state is State.CRUSHED
    bottom = player.body.position.y - 0.5 * cfg.height
    assert bottom < FLOOR_SKIN + world.config.collision_slop
