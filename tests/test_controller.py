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
from playground.controller import hover_limit, hover_spring
from playground.movers import Spin, ring_room
from playground.world import Stage, WorldConfig

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
    """The hover spring must satisfy 2π·f·dt < 2ζ + 2√(ζ² + 1) for the world's dt: a frequency
    just above the limit is refused, naming the field; just below is accepted."""
    with pytest.raises(ValueError, match="hover_frequency"):
        Controller(flat_world(), "player", (0.0, 1.0), ControllerConfig(hover_frequency=100.0))
    dt = WorldConfig().dt
    for zeta in (0.0, 1.0):
        f_max = hover_limit(zeta) / (2.0 * math.pi * dt)
        with pytest.raises(ValueError, match="hover_frequency"):
            Controller(
                flat_world(),
                "p",
                (0.0, 1.0),
                ControllerConfig(hover_frequency=1.01 * f_max, hover_damping=zeta),
            )
        Controller(
            flat_world(),
            "p",
            (0.0, 1.0),
            ControllerConfig(hover_frequency=0.99 * f_max, hover_damping=zeta),
        )


LIMIT_MARGIN = 0.02
"""Relative distance from the stability limit on 2πf·dt for the bounded/growing runs: close
enough to show the limit is where the formula puts it, far enough that the growth per step
shows within a second."""

GROWTH = 10.0
"""An unstable swing grows past this factor of its start in 1 s; a stable one never does (an
undamped one at 0.98 of the limit stays on semi-implicit Euler's invariant ellipse, at most
1/√(1 − 0.98²) ≈ 5× its start)."""

SWING_START = 1e-6
"""m: the spring's initial stretch (small, so a growing swing stays far from 1 m)."""


def spring_swing(omega_dt: float, zeta: float, substeps: int, seconds: float = 1.0) -> float:
    """A 1 kg body in zero gravity on :func:`hover_spring` (k = ω², c = 2ζω), the force put on it
    before each step as the hover does, released at rest SWING_START from rest length. Returns
    the largest |x| in the last tenth of the run, m."""
    world = World(WorldConfig(substeps=substeps), gravity=(0.0, 0.0))
    body = pymunk.Body(1.0, math.inf)
    world.add("bob", body)
    body.position = (SWING_START, 0.0)
    dt = world.config.dt
    w = omega_dt / dt
    k, c = w * w, 2.0 * zeta * w
    swing: list[float] = []

    def spring(wd: World) -> None:
        x, v = body.position.x, body.velocity.x
        swing.append(abs(x))
        if abs(x) < 1.0:
            wd.apply_force(body, (hover_spring(k, c, 1.0, -x, v, dt, substeps), 0.0))

    world.on(Stage.CONTROL, spring)
    world.run(seconds)
    return max(swing[-len(swing) // 10 :])


@pytest.mark.parametrize("substeps", [1, 4])
@pytest.mark.parametrize("zeta", [0.0, 0.5, 1.0])
def test_hover_spring_is_stable_exactly_below_its_limit(zeta: float, substeps: int) -> None:
    """Law (semi-implicit hover, any substeps): just below 2πf·dt = 2ζ + 2√(ζ² + 1) the swing
    stays bounded (undamped, it keeps its size: symplectic); just above it grows."""
    limit = hover_limit(zeta)
    assert spring_swing((1.0 - LIMIT_MARGIN) * limit, zeta, substeps) < GROWTH * SWING_START
    assert spring_swing((1.0 + LIMIT_MARGIN) * limit, zeta, substeps) > GROWTH * SWING_START


def test_an_undamped_hover_keeps_its_swing() -> None:
    """Law: an undamped hover (ζ = 0) at the default 5 Hz and dt conserves its energy instead of
    gaining it: the swing never exceeds the start's drop by more than semi-implicit Euler's
    invariant ellipse allows, drop/√(1 − (ωdt/2)²)."""
    cfg = ControllerConfig(hover_damping=0.0, lock_rotation=True)
    world = flat_world()
    floor_top = 0.05
    drop = 0.005
    player = Controller(world, "player", (0.0, floor_top + cfg.ride_height - drop), cfg)
    w = 2.0 * math.pi * cfg.hover_frequency * world.config.dt
    bound = drop / math.sqrt(1.0 - (w / 2.0) ** 2)
    peak = 0.0
    for _ in range(round(4.0 / world.config.dt)):
        world.step()
        peak = max(peak, abs(player.body.position.y - floor_top - cfg.ride_height))
    assert peak <= bound * (1.0 + TOL_SWING_REL)
    assert peak >= drop * (1.0 - TOL_SWING_REL)


TOL_SWING_REL = 1e-6
"""Relative: the undamped hover's peak against the invariant ellipse's (float rounding over
480 steps, far below the 0.9 % the ellipse itself allows)."""


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


def test_a_removed_controller_takes_its_hooks_with_it() -> None:
    """remove() also unregisters the controller's input and control hooks (World.off): nothing
    of it runs any more, so a world left with no effect steps bare again."""
    world = flat_world()
    player = Controller(world, "player", (0.0, 1.0), source=Script(((0.0, Intent(move=1.0)),)))
    world.run(0.1)
    player.remove()
    for stage, hook in ((Stage.INPUTS, player._read_source), (Stage.CONTROL, player._control)):
        with pytest.raises(ValueError, match="not registered"):
            world.off(stage, hook)


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
