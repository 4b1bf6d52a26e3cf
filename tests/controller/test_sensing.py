"""Laws of sensing: the ground's frame read by the probe (its velocity, its turn and its own
acceleration) lets a player ride a spinning ring and an accelerating platform without drifting.

The drive's goal is the ground's velocity, and the ground's own acceleration is fed forward (read
from how a kinematic ground's velocity changed since the last step), so the drive and the hover
keep up with the platform instead of lagging a·drive_time behind it.
"""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Controller, ControllerConfig, Elevator, State, World
from playground.gravity import GravityRule, Radial
from playground.movers import Spin, ring_room

M = ControllerConfig().mass
"""The default player's mass, kg."""

TOL_RING_REL = 1e-4
"""Relative, support against m·ω²·r inside the spinning ring: the step turns the frame by
θ = ω·dt, so the discrete orbit needs m·ω²·r·(sin(θ/2)/(θ/2))², short by θ²/12 ≈ 1.3e-5."""

TOL_RING_FELT_REL = 0.01
"""Relative, |perceived gravity| against ω²·r: the 1€ filter's lag on a vector turning at
1.5 rad/s shortens it by under 0.3 %."""

TOL_RING_DRIFT = 1e-6
"""rad: the player's bearing relative to the ring's floor over 6 s (the drive's goal is the
velocity the floor gives the centre, so a settled rider does not move relative to it at all)."""


def test_riding_a_spinning_ring_feels_m_v2_over_r_and_keeps_its_place() -> None:
    """docs/design.md §5: inside a ring spinning at ω (no gravity) the player is grounded, carried
    at the floor's angular rate (its drive's goal is the ground's velocity at its centre, ω·r, not
    the rim's ω·R under its feet), and its support is N = m·v²/r = m·ω²·r toward the centre with r
    the radius of its centre of mass; its perceived gravity points outward with magnitude ω²·r."""
    rate, radius = 1.5, 5.0
    world = World(gravity=(0.0, 0.0))
    ring = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("ring", ring, *ring_room(ring, radius, segments=64))
    world.add_mover("ring", Spin(rate=rate))
    r0 = radius - ControllerConfig().ride_height
    player = Controller(world, "player", (0.0, -r0))
    player.body.velocity = (rate * r0, 0.0)
    player.body.angular_velocity = rate

    def bearing() -> float:
        """The player's polar angle relative to the ring, rad in (−π, π]."""
        p = player.body.position
        c, s = math.cos(ring.angle), math.sin(ring.angle)
        return math.atan2(c * p.y - s * p.x, c * p.x + s * p.y)

    world.run(2.0)
    start = bearing()
    for _ in range(round(6.0 / world.config.dt)):
        world.step()
        assert player.state is State.GROUNDED
        p = player.body.position
        r = math.hypot(p.x, p.y)
        support = world.forces("player").support
        assert abs(math.hypot(*support) - M * rate**2 * r) < TOL_RING_REL * M * rate**2 * r
        # Toward the centre: the support is antiparallel to the position.
        assert support[0] * p.x + support[1] * p.y < 0.0
    felt = world.perceived_gravity("player")
    r = player.body.position.length
    assert abs(math.hypot(*felt) - rate**2 * r) < TOL_RING_FELT_REL * rate**2 * r
    assert felt[0] * player.body.position.x + felt[1] * player.body.position.y > 0.0
    assert abs(bearing() - start) < TOL_RING_DRIFT


JERK_MARGIN = 1.05
"""The feed-forward reads the platform's acceleration one step late where it starts and stops:
each jerk leaves a velocity error a·dt that the drive closes with its time constant, a drift of
a·dt·drive_time which the next jerk undoes (measured: exactly that to 3 digits sideways, less
along the hover). 5 % for the hover's coupling and rounding."""

CASES = {
    "sideways-1": ((1.0, 0.0), 1.0),
    "sideways-4": ((1.0, 0.0), 4.0),
    "diagonal-2": ((1.0, 1.0), 2.0),
    "lift-up-2": ((0.0, 1.0), 2.0),
    "lift-down-3": ((0.0, -1.0), 3.0),
}


@pytest.mark.parametrize(("axis", "a"), CASES.values(), ids=CASES.keys())
def test_carried_without_drift(axis: tuple[float, float], a: float) -> None:
    """Law: on a platform that accelerates at a for 1 s (within the drive's budget) and then
    glides, the player's position relative to the platform changes by at most a·dt·drive_time
    (about 0.4 mm per m/s²) through the whole run, acceleration included."""
    world = World()
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Poly.create_box(plat, (6.0, 0.2))
    shape.friction = 1.0
    world.add("platform", plat, shape)
    path = Elevator(start=(0.0, -0.1), axis=axis, acceleration=a, start_time=0.5, duration=1.0)
    world.add_mover("platform", path)
    player = Controller(world, "player", position=(0.0, 0.95))
    world.step()
    start = player.body.position - plat.position
    drift = 0.0
    for _ in range(round(3.0 / world.config.dt)):
        world.step()
        assert player.state is State.GROUNDED, world.time
        drift = max(drift, (player.body.position - plat.position - start).length)
    bound = JERK_MARGIN * a * world.config.dt * player.config.drive_time
    assert drift <= bound, f"drifted {drift * 1e3:.2f} mm (bound {bound * 1e3:.2f} mm)"
    assert bound < 0.01 and math.isfinite(drift)


@pytest.mark.parametrize(
    ("kind", "dynamic"),
    [(pymunk.Body.DYNAMIC, True), (pymunk.Body.KINEMATIC, False), (pymunk.Body.STATIC, False)],
    ids=["dynamic", "kinematic", "static"],
)
def test_the_probe_says_whether_the_ground_takes_reactions(kind: int, dynamic: bool) -> None:
    """Law: the hit is ``dynamic`` exactly over a dynamic body, the only kind the world puts a
    reaction on."""
    world = World()
    world.add_static_segment((-5.0, -0.5), (5.0, -0.5), radius=0.0)
    slab = pymunk.Body(200.0, 1e4, body_type=kind)
    slab.position = (0.0, -0.25)
    world.add("slab", slab, pymunk.Poly.create_box(slab, (4.0, 0.5)))
    player = Controller(world, "player", position=(0.0, 1.0))
    world.run(0.5)
    assert player.probe is not None and player.probe.body is slab
    assert player.probe.dynamic is dynamic


TILE = (0.25, 0.04)
"""m: a loose tile's length and thickness."""
TILE_MASS = 3.0
"""kg."""


def _on_a_tile(offset: float, *, jointed: bool = False) -> Controller:
    """A player standing ``offset`` m to the right of a loose tile's centre (its probe's axis
    there), the tile lying on a floor (held by a pivot to the static body if ``jointed``)."""
    world = World()
    world.add_static_segment((-5.0, -0.05), (5.0, -0.05), radius=0.05)
    tile = world.add_box("tile", mass=TILE_MASS, size=TILE, position=(0.0, TILE[1] / 2.0))
    if jointed:
        world.space.add(pymunk.PivotJoint(tile, world.space.static_body, (0.0, TILE[1] / 2.0)))
    player = Controller(world, "player", position=(offset, TILE[1] + 0.95))
    world.step()
    return player


def test_the_probe_reads_how_far_a_loose_ground_holds_the_feet_off_centre() -> None:
    """Law (sensing.footing): on a loose tile the lever is its radius of gyration √(I/m) less
    the hit's offset from its centre along its top, 0 past it; a jointed tile and the static
    floor hold any torque (infinite)."""
    gyration = math.sqrt((TILE[0] ** 2 + TILE[1] ** 2) / 12.0)
    for offset in (0.0, 0.05):
        probe = _on_a_tile(offset).probe
        assert probe is not None and probe.dynamic
        assert probe.lever == pytest.approx(gyration - offset, abs=1e-12)
    off_centre = _on_a_tile(0.1).probe
    assert off_centre is not None and off_centre.dynamic and off_centre.lever == 0.0
    held = _on_a_tile(0.05, jointed=True).probe
    assert held is not None and held.dynamic and held.lever == math.inf
    floor = _on_a_tile(1.0).probe
    assert floor is not None and not floor.dynamic and floor.lever == math.inf


def test_the_probe_reads_the_spin_of_a_turning_ground() -> None:
    """Law: the hit's ``spin`` is the ground's angular velocity (the balance damps ours relative
    to it), here a slab turning slowly under the player."""
    world = World()
    slab = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    slab.position = (0.0, -0.25)
    slab.angular_velocity = 0.2
    world.add("slab", slab, pymunk.Poly.create_box(slab, (4.0, 0.5)))
    player = Controller(world, "player", position=(0.0, 1.0))
    world.run(0.5)
    assert player.probe is not None and player.probe.body is slab
    assert player.probe.spin == slab.angular_velocity


def test_the_sensed_gravity_follows_every_change_of_the_field_and_the_rule() -> None:
    """Law: the gravity a controller senses (it keeps its rule and whether the field is uniform
    between steps) is the world's ``gravity_at`` after each change made between steps: its own
    rule set and cleared, a uniform field replaced by a planet and by another uniform field."""
    world = World()
    player = Controller(world, "p", (0.0, 50.0))
    changes = [
        lambda: world.set_gravity_rule("p", GravityRule(scale=0.5, direction=(1.0, 0.0))),
        lambda: setattr(world, "gravity", Radial(center=(30.0, 50.0), radius=30.0)),
        lambda: world.set_gravity_rule("p", None),
        lambda: setattr(world, "gravity", (0.0, 4.0)),
    ]
    versions = {world.gravity_version}
    for change in changes:
        change()
        versions.add(world.gravity_version)
        world.step()
        assert player.senses.gravity(world) == world.gravity_at("p")
    assert len(versions) == len(changes) + 1


def test_the_probe_looks_past_a_one_way_platform_it_starts_inside() -> None:
    """Standing on the floor with its centre inside a one-way platform, the probe finds the
    floor, not the platform; standing on the platform, it finds the platform."""
    from playground.world import one_way

    world = World()
    floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    low = pymunk.Poly(world.space.static_body, [(-1.0, 0.8), (1.0, 0.8), (1.0, 1.3), (-1.0, 1.3)])
    one_way.make_one_way(world.space, low)
    world.space.add(low)
    player = Controller(world, "player", (0.0, 1.0))
    world.run(0.5)
    assert player.state is State.GROUNDED and player.probe is not None
    assert player.probe.point[1] == pytest.approx(floor.radius)
    on_top = Controller(world, "on_top", (0.6, 1.3 + ControllerConfig().ride_height))
    world.run(0.5)
    assert on_top.probe is not None and on_top.probe.point[1] == pytest.approx(1.3)
