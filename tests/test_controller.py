"""Laws of the capsule controller on still and moving ground (issue 3's first acceptance scenes).

Each scene is built here from World + Controller (level files come later). Hovering bodies never
touch the floor, so the solver's support force is exactly the controller's hover and drive: the
laws below hold to float rounding once the spring has settled.
"""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Controller, ControllerConfig, Elevator, Intent, Script, State, World

G = 9.81
"""|g| of the world's default field, m/s²."""

M = ControllerConfig().mass
"""The default player's mass, kg."""

TOL_SUPPORT_REL = 1e-6
"""Issue 3: support = m·g within 1e-6 relative once settled (a critically damped 5 Hz spring is
settled to ~1e-60 after 3 s; what is left is float rounding)."""

TOL_RIDE = 1e-6
"""Metres: the hover rests at ride height (gravity feed-forward leaves no static sag)."""

DRIFT_MAX = 0.01
"""Issue 3: less than 1 cm of drift relative to a constant-velocity platform in 10 s."""

TOL_DRIVE_REL = 1e-6
"""Drive force on a uniformly accelerating platform equals m·a once the drive's first-order lag
(time constant 0.05 s) has decayed: e^(−3/0.05) is far below this."""


def flat_world() -> World:
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    return world


def platform(world: World, name: str = "platform") -> pymunk.Body:
    """A long kinematic platform whose top surface is at y = 0."""
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Segment(body, (-200.0, -0.05), (200.0, -0.05), 0.05)
    shape.friction = 1.0
    world.add(name, body, shape)
    return body


def test_idle_settles_at_ride_height_and_feels_its_weight() -> None:
    """Idle on flat ground: ride height, support = m·g, perceived gravity = g."""
    world = flat_world()
    player = Controller(world, "player", (0.0, 1.2))
    world.run(3.0)
    support = world.forces("player").support
    perceived = world.perceived_gravity("player")
    assert player.state is State.GROUNDED
    assert player.probe is not None
    assert abs(player.probe.distance - player.config.ride_height) < TOL_RIDE
    assert abs(support[0]) < TOL_SUPPORT_REL * M * G
    assert abs(support[1] - M * G) < TOL_SUPPORT_REL * M * G
    assert abs(perceived[0]) < TOL_SUPPORT_REL * G
    assert abs(perceived[1] + G) < TOL_SUPPORT_REL * G


def test_no_drift_on_a_platform_at_constant_velocity() -> None:
    """Galilean invariance: with no input, the player keeps its place on a moving platform."""
    world = World()
    plat = platform(world)
    plat.velocity = (1.5, 0.0)
    player = Controller(world, "player", (0.0, 1.0))
    world.run(2.0)
    start = player.body.position - plat.position
    world.run(10.0)
    drift = (player.body.position - plat.position) - start
    assert drift.length < DRIFT_MAX
    assert player.state is State.GROUNDED


@pytest.mark.parametrize("accel", [0.5, 2.0, 4.0])
def test_drive_force_on_an_accelerating_platform_is_m_a(accel: float) -> None:
    """Newton's second law: below the traction limit the drive carries the player at the
    platform's acceleration, so the drive force (and the horizontal support) is m·a."""
    cfg = ControllerConfig()
    assert accel < min(cfg.traction * G, cfg.ground_force / cfg.mass)
    world = World()
    platform(world)
    world.add_mover("platform", Elevator(axis=(1.0, 0.0), acceleration=accel, start_time=0.5))
    player = Controller(world, "player", (0.0, 1.0), cfg)
    world.run(3.0)
    drive = player.last_forces.drive
    support = world.forces("player").support
    assert abs(drive[0] - M * accel) < TOL_DRIVE_REL * M * accel
    assert abs(support[0] - M * accel) < TOL_DRIVE_REL * M * accel
    assert player.state is State.GROUNDED


def test_a_crate_under_the_player_feels_the_player_as_a_contact_load() -> None:
    """Newton's third law with the right category: the hover's reaction on a dynamic crate is a
    SUPPORT force, so the crate's floor carries both weights while the crate itself still feels
    only its own weight (perceived gravity g), and the player feels its own."""
    crate_mass = 20.0
    world = flat_world()
    world.add_box("crate", mass=crate_mass, size=(2.0, 0.5), position=(0.0, 0.25))
    world.track("crate")
    player = Controller(world, "player", (0.0, 0.5 + 0.95))
    world.run(3.0)
    assert player.probe is not None and player.probe.body is world.body("crate")
    crate = world.forces("crate")
    total = (crate_mass + M) * G
    assert abs(crate.engine[1] - total) < TOL_SUPPORT_REL * total
    assert abs(crate.support[1] - crate_mass * G) < TOL_SUPPORT_REL * total
    assert abs(world.perceived_gravity("crate")[1] + G) < TOL_SUPPORT_REL * G * total / crate_mass
    assert abs(world.forces("player").support[1] - M * G) < TOL_SUPPORT_REL * M * G


def test_walking_reaches_max_speed_relative_to_the_ground() -> None:
    """Drive goal: ground velocity + move·max_speed along the tangent (right for up = +y)."""
    world = World()
    plat = platform(world)
    plat.velocity = (-1.0, 0.0)
    script = Script(((0.0, Intent(move=0.5)),))
    player = Controller(world, "player", (0.0, 1.0), source=script)
    world.run(3.0)
    expected = -1.0 + 0.5 * player.config.max_speed
    assert abs(player.body.velocity.x - expected) < TOL_DRIVE_REL * player.config.max_speed


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("mass", 0.0),
        ("height", -1.0),
        ("radius", 1.0),
        ("ride_height", 2.0),
        ("max_slope", 2.0),
        ("air_force", -1.0),
        ("hover_frequency", math.nan),
    ],
)
def test_bad_config_names_the_field(field: str, value: float) -> None:
    """Bad input gets a clear error naming the field."""
    with pytest.raises(ValueError, match=field):
        ControllerConfig(**{field: value})


def test_unstable_hover_spring_is_refused() -> None:
    """The hover spring must satisfy 2π·f·dt < 2 for the world's dt."""
    with pytest.raises(ValueError, match="hover_frequency"):
        Controller(flat_world(), "player", (0.0, 1.0), ControllerConfig(hover_frequency=100.0))


def test_same_inputs_give_bit_identical_trajectories() -> None:
    """Determinism: two runs of the same scene replay exactly."""

    def run() -> tuple[float, float, float]:
        world = flat_world()
        script = Script(((0.0, Intent(move=1.0)), (0.5, Intent(jump=True)), (1.0, Intent())))
        player = Controller(world, "player", (0.0, 1.0), source=script)
        world.run(2.0)
        return (player.body.position.x, player.body.position.y, player.body.angle)

    assert run() == run()


def test_air_steering_never_brakes_and_stays_within_its_budget() -> None:
    """In the air there is no ground to push on: with no input the horizontal velocity is kept
    exactly; against the motion the speed changes by at most air_force·T/m."""
    cfg = ControllerConfig()
    flight = 0.5
    for move, bound in ((0.0, 0.0), (-1.0, cfg.air_force * flight / cfg.mass)):
        world = World()
        player = Controller(world, "player", (0.0, 100.0), cfg, Script(((0.0, Intent(move=move)),)))
        player.body.velocity = (2.0, 0.0)
        world.run(flight)
        assert player.state is State.AIRBORNE
        change = abs(player.body.velocity.x - 2.0)
        assert change <= bound + TOL_DRIVE_REL * bound


def test_a_removed_controller_leaves_the_world() -> None:
    """remove(): the body and shape go and the world keeps stepping without it."""
    world = flat_world()
    player = Controller(world, "player", (0.0, 1.0), source=Script(((0.0, Intent(move=1.0)),)))
    world.run(0.5)
    player.remove()
    assert "player" not in world.names
    world.run(0.5)
    assert player.removed
