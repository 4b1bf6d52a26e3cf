"""Laws of ledges, at 35, 70 and 140 kg and dt 1/60, 1/120 and 1/240 s: jumping next to a ledge
with the grab held catches its edge at the top of the jump and hangs from the joint alone
(m·g); a climb up lifts the body clear of the top and over it, and it stands there at ride
height (grounded → airborne → hanging → climbing → grounded, no flicker); the ledge is held on
its own body (a rising pillar carries the player) and feels the climb (a loose crate's floor
carries its weight plus all the player feels); a ceiling or a wall above the reach is no ledge,
and an edge is not caught while rising past it."""

from __future__ import annotations

import statistics

import pymunk
import pytest

from playground import Controller, ControllerConfig, Elevator, Intent, Script, State, World
from playground.controller import ledge
from playground.controller.config import G0
from playground.world.config import WorldConfig

MASSES = (35.0, 70.0, 140.0)
"""kg: half, once and twice the default player."""
DTS = (1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0)
"""s: the steps a game runs at."""
TOP = 2.6
"""m: the ledges' top; the floor's surface is at 0.05 m (a segment of radius 0.05)."""
FACE = -7.0
"""m: the x of the wall's face, the ledge to its left."""
GAP = 0.1
"""m: between the capsule and the face it stands by."""
CRATE = 300.0
"""kg: the loose crate."""
SCRIPT = Script(
    (
        (0.5, Intent(jump=True)),
        (0.85, Intent(grab=True)),
        (2.0, Intent(grab=True, climb=1.0)),
        (5.0, Intent()),
    )
)
"""Jump, grab at the top of the jump, climb from 2 s, let go once up."""

TOL_REST_REL = 1e-5
"""Hanging still or standing still, the joint's and the hover's force are the weight to the
last of the settling: the swing the grab set off at dt = 1/60 s is 8e-6 of the weight 1 s
later (1e-8 at 1/120 s)."""
TOL_HEIGHT = 1e-6
"""m: standing still on still ground, the hover rests exactly at ride height (1e-9 m
measured)."""
TOL_HEIGHT_LOOSE = 5e-5
"""m: on a loose crate the hover rests on a ground that still rocks a little on the floor (1e-5
m off 1.5 s after standing up at 140 kg, dt = 1/60 s)."""
TOL_MEAN_REL = 1e-4
"""Of the crate's weight: the crate rocks on the floor as the load at its edge changes, so its
contact differs from its weight plus what the player feels by its own m·a (up to 0.8 % of its
weight) step by step, but over a window it starts and ends at rest in, hardly at all."""
TOL_CARRIED = 0.01
"""m/s: hanging from a pillar rising at a constant speed, the player moves with it (the joint
holds its hands within the grip's slip)."""


def world_at(dt: float, contact_split: bool = False) -> World:
    world = World(WorldConfig(dt=dt, contact_split=contact_split))
    world.add_static_segment((-12.0, 0.0), (12.0, 0.0))
    return world


def add_wall(world: World) -> None:
    """A static wall to the left of x = FACE, TOP high."""
    body = world.space.static_body
    wall = pymunk.Poly(body, [(FACE - 2.0, 0.0), (FACE, 0.0), (FACE, TOP), (FACE - 2.0, TOP)])
    wall.friction = 1.0
    world.space.add(wall)


def player_by(world: World, face: float, mass: float) -> Controller:
    """A player standing GAP to the right of a face (looking right) at x = ``face``."""
    config = ControllerConfig(mass=mass)
    x = face + config.radius + GAP
    return Controller(world, "player", (x, 1.0), config=config, source=SCRIPT)


def states(world: World, player: Controller, seconds: float) -> list[State]:
    """Run ``seconds``; the states it went through, each once in order."""
    seen = [player.state]
    end = world.time + seconds
    while world.time < end - 0.5 * world.config.dt:
        world.step()
        if player.state is not seen[-1]:
            seen.append(player.state)
    return seen


@pytest.mark.parametrize("dt", DTS)
@pytest.mark.parametrize("mass", MASSES)
def test_hangs_from_a_static_edge_and_climbs_onto_it(mass: float, dt: float) -> None:
    """Hanging still, the joint alone carries m·g straight up and the grip reading is its force;
    climbing, it goes through each state once and stands past the edge at ride height with
    its weight on its feet."""
    world = world_at(dt)
    add_wall(world)
    player = player_by(world, FACE, mass)
    seen = states(world, player, 2.0)
    assert seen == [State.AIRBORNE, State.GROUNDED, State.AIRBORNE, State.HANGING]
    weight = mass * G0
    ex, ey = world.forces("player").engine
    assert abs(ex) < TOL_REST_REL * weight and abs(ey - weight) < TOL_REST_REL * weight
    assert abs(player.grip - weight) < TOL_REST_REL * weight
    seen = states(world, player, 4.0)
    assert seen == [State.HANGING, State.CLIMBING, State.GROUNDED]
    x, y = player.body.position
    assert x < FACE - player.config.radius
    assert abs(y - (TOP + player.config.ride_height)) < TOL_HEIGHT
    sx, sy = player.felt
    assert abs(sx) < TOL_REST_REL * weight and abs(sy - weight) < TOL_REST_REL * weight


@pytest.mark.parametrize("dt", DTS)
@pytest.mark.parametrize("mass", MASSES)
def test_a_rising_pillar_carries_its_hanging_player_and_it_climbs_on(
    mass: float, dt: float
) -> None:
    """The edge is held on the pillar's own body: hanging, the player rises with it; climbing
    relative to it, it ends standing on it at ride height, moving with it."""
    world = world_at(dt)
    pillar = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("pillar", pillar, pymunk.Poly.create_box(pillar, (1.0, TOP)))
    # From 1.2 s it rises at 1 m/s² for 0.5 s, then at 0.5 m/s.
    path = Elevator(start=(0.0, TOP / 2.0), acceleration=1.0, start_time=1.2, duration=0.5)
    world.add_mover("pillar", path)
    player = player_by(world, 0.5, mass)
    seen = states(world, player, 2.0)
    assert seen == [State.AIRBORNE, State.GROUNDED, State.AIRBORNE, State.HANGING]
    vx, vy = player.body.velocity - pillar.velocity
    assert abs(vx) < TOL_CARRIED and abs(vy) < TOL_CARRIED
    assert states(world, player, 4.0) == [State.HANGING, State.CLIMBING, State.GROUNDED]
    height = player.body.position.y - (pillar.position.y + TOP / 2.0)
    assert abs(height - player.config.ride_height) < TOL_HEIGHT
    vx, vy = player.body.velocity - pillar.velocity
    assert abs(vx) < TOL_CARRIED and abs(vy) < TOL_CARRIED


@pytest.mark.parametrize("dt", DTS)
@pytest.mark.parametrize("mass", MASSES)
def test_a_loose_crate_feels_the_hang_and_the_climb(mass: float, dt: float) -> None:
    """Newton's third law on a 300 kg crate: the floor under it carries its weight plus all
    the player feels, the joint's force while it hangs and the climb's while it climbs (its
    reaction on the crate's edge), in the mean over each."""
    world = world_at(dt, contact_split=True)
    world.add_box("crate", mass=CRATE, size=(1.5, TOP), position=(8.0, 0.05 + TOP / 2.0))
    world.track("crate")
    player = player_by(world, 8.0 + 0.75, mass)

    def mean_load(seconds: float) -> tuple[float, float]:
        """The crate's floor contact minus what the player feels, mean over ``seconds``, N."""
        xs, ys = [], []
        end = world.time + seconds
        while world.time < end - 0.5 * dt:
            world.step()
            (cx, cy), (sx, sy) = world.forces("crate").contact, player.felt
            xs.append(cx - sx)
            ys.append(cy - sy)
        return statistics.fmean(xs), statistics.fmean(ys)

    world.run(1.5)
    assert player.state is State.HANGING
    weight = CRATE * G0
    lx, ly = mean_load(0.5)
    assert abs(lx) < TOL_MEAN_REL * weight and abs(ly - weight) < TOL_MEAN_REL * weight
    lx, ly = mean_load(2.5)
    assert player.state is not State.HANGING
    assert abs(lx) < TOL_MEAN_REL * weight and abs(ly - weight) < TOL_MEAN_REL * weight
    world.run(2.0)
    assert player.state is State.GROUNDED
    height = player.body.position.y - world.body("crate").position.y - TOP / 2.0
    assert abs(height - player.config.ride_height) < TOL_HEIGHT_LOOSE


def test_a_ceiling_and_a_wall_above_the_reach_are_no_ledges() -> None:
    """A slab straight above the head has no edge beside it; a wall whose top is beyond
    ``ledge_grab`` above the head has none within reach; the same wall cut to a reachable top
    has one, at its corner, toward the wall."""
    config = ControllerConfig()
    space = pymunk.Space()
    body = pymunk.Body(70.0, 1.0)
    body.position = (0.0, 1.0)
    head = 1.0 + config.half_length
    up = (0.0, 1.0)
    low_side = head + config.radius + 0.1
    ceiling = pymunk.Poly(
        space.static_body, [(-2.0, low_side), (2.0, low_side), (2.0, 3.0), (-2.0, 3.0)]
    )
    space.add(ceiling)
    assert ledge.find(space, body, pymunk.ShapeFilter(), up, config) is None
    space.remove(ceiling)
    face = -(config.radius + GAP)
    high = pymunk.Poly(space.static_body, [(face - 1.0, 0.0), (face, 0.0), (face, 5.0), (-2, 5.0)])
    space.add(high)
    assert ledge.find(space, body, pymunk.ShapeFilter(), up, config) is None
    space.remove(high)
    top = head + 0.3
    low = pymunk.Poly(space.static_body, [(face - 1.0, 0.0), (face, 0.0), (face, top), (-2, top)])
    space.add(low)
    found = ledge.find(space, body, pymunk.ShapeFilter(), up, config)
    assert found is not None
    assert found.edge == pytest.approx((face, top)) and found.side == pytest.approx((-1.0, 0.0))


def test_an_edge_is_not_caught_while_rising_past_it() -> None:
    """Rising relative to the ledge, the hands do not close on it; at rest or falling they do."""
    config = ControllerConfig()
    space = pymunk.Space()
    face = -(config.radius + GAP)
    top = 1.0 + config.half_length + 0.3
    wall = pymunk.Poly(space.static_body, [(-2.0, 0.0), (face, 0.0), (face, top), (-2.0, top)])
    space.add(wall)
    body = pymunk.Body(70.0, 1.0)
    body.position = (0.0, 1.0)
    found = ledge.find(space, body, pymunk.ShapeFilter(), (0.0, 1.0), config)
    assert found is not None
    body.velocity = (0.0, 0.5)
    assert not ledge.catching(found, body, (0.0, 1.0))
    body.velocity = (0.0, -0.5)
    assert ledge.catching(found, body, (0.0, 1.0))
