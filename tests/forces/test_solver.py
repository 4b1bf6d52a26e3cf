"""Laws of the reverse-integration force solver (docs/design.md §2) and the exact answers of §5.

Two independent readings of what the engine did to a body must agree: reverse integration
``J = m·(v₁ − d·v₀) − (m·g + F)·h`` and the sum of the body's arbiter impulses. Their difference is
what joints did. Then the solver's readings must match scenes with answers known on paper.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pymunk
import pytest

from playground import (
    Elevator,
    GravityRule,
    Radial,
    Spin,
    Stage,
    Uniform,
    World,
    WorldConfig,
    ring_room,
)

G = 9.81
"""|g| used by every scene here, m/s² (the world's default)."""

TOL_REL = 1e-9
"""Two readings of the same impulses: they differ only by float rounding in sums of ~10 terms."""

TOL_ABS = 1e-9
"""Newtons: near-zero components (a resting body's horizontal force) compare absolutely."""

Scene = Callable[[WorldConfig], World]


def close(a: tuple[float, float], b: tuple[float, float], rel: float, abs_: float) -> bool:
    """|a − b| ≤ rel·max(|a|, |b|) + abs_ (vectors)."""
    scale = max(math.hypot(*a), math.hypot(*b))
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= rel * scale + abs_


def arbiter_force(world: World, name: str) -> tuple[float, float]:
    """Σ arbiter total impulse on the body over the last step / dt (valid with one substep)."""
    total = [0.0, 0.0]

    def add(arb: pymunk.Arbiter) -> None:
        total[0] += arb.total_impulse.x
        total[1] += arb.total_impulse.y

    world.body(name).each_arbiter(add)
    return (total[0] / world.config.dt, total[1] / world.config.dt)


def ground(world: World) -> None:
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0), radius=0.05)


def resting(cfg: WorldConfig) -> World:
    world = World(cfg)
    ground(world)
    world.add_box("box", mass=3.0, size=(1.0, 1.0), position=(0.0, 0.55))
    return world


def sliding(cfg: WorldConfig) -> World:
    world = World(cfg)
    ground(world)
    box = world.add_box("box", mass=2.0, size=(1.0, 0.5), position=(0.0, 0.3), friction=0.2)
    box.velocity = (6.0, 0.0)
    return world


def stack(cfg: WorldConfig) -> World:
    world = World(cfg)
    ground(world)
    for i, m in enumerate((1.0, 4.0, 2.0)):
        world.add_box(f"box{i}", mass=m, size=(1.0, 1.0), position=(0.1 * i, 0.55 + 1.0 * i))
    return world


def platform(cfg: WorldConfig) -> World:
    """A box on a kinematic platform accelerating up and to the right."""
    world = World(cfg)
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Poly.create_box(plat, (6.0, 0.2))
    shape.friction = 1.0
    world.add("platform", plat, shape)
    world.add_mover("platform", Elevator(axis=(1.0, 2.0), acceleration=3.0, start_time=0.1))
    world.add_box("box", mass=2.0, size=(1.0, 1.0), position=(0.0, 0.6))
    return world


def planet(cfg: WorldConfig) -> World:
    """Boxes on a small planet with a radial field (per-body gravity forces)."""
    world = World(cfg, gravity=Radial(center=(0.0, 0.0), surface_gravity=G, radius=5.0))
    world.add_static(pymunk.Circle(world.space.static_body, 5.0))
    world.add_box("box", mass=2.0, size=(1.0, 1.0), position=(0.0, 5.55))
    world.add_box("side", mass=1.0, size=(1.0, 1.0), position=(5.6, 0.3), angle=math.pi / 2)
    return world


def ruled(cfg: WorldConfig) -> World:
    """One box with gravity scaled, one pulled sideways by its own direction."""
    world = stack(cfg)
    world.set_gravity_rule("box2", GravityRule(scale=2.5))
    world.add_box("drift", mass=1.5, size=(0.5, 0.5), position=(5.0, 0.3))
    world.set_gravity_rule("drift", GravityRule(direction=(0.4, -1.0)))
    return world


SCENES: dict[str, Scene] = {
    "resting": resting,
    "sliding": sliding,
    "stack": stack,
    "platform": platform,
    "planet": planet,
    "ruled": ruled,
}

CONFIGS = {
    "plain": WorldConfig(contact_split=True),
    "damped": WorldConfig(contact_split=True, damping=0.3),
    "substeps2": WorldConfig(contact_split=True, substeps=2),
    "substeps4-damped": WorldConfig(contact_split=True, substeps=4, damping=0.5),
}


def dynamic_names(world: World) -> list[str]:
    return [n for n in world.names if world.body(n).body_type == pymunk.Body.DYNAMIC]


@pytest.mark.parametrize("config", CONFIGS.values(), ids=CONFIGS.keys())
@pytest.mark.parametrize("scene", SCENES.values(), ids=SCENES.keys())
def test_reverse_integration_equals_arbiter_impulses(scene: Scene, config: WorldConfig) -> None:
    """Law: engine force (reverse integration) = Σ arbiter impulses / dt, every step, every body,
    with damping, substeps, kinematic platforms and per-body gravity; with one substep it also
    equals the sum read directly from ``body.each_arbiter``."""
    world = scene(config)
    names = dynamic_names(world)
    world.track(*names)
    checked = 0
    for _ in range(150):
        world.step()
        for name in names:
            f = world.forces(name)
            assert f.valid and f.split_valid
            assert close(f.engine, f.contact, TOL_REL, TOL_ABS), (name, world.steps, f)
            if config.substeps == 1:
                direct = arbiter_force(world, name)
                assert close(f.engine, direct, TOL_REL, TOL_ABS), (name, world.steps, direct)
            checked += math.hypot(*f.contact) > 1.0
    assert checked > 0, "the scene never touched anything: the law was not exercised"


def pendulum(cfg: WorldConfig, swing: bool) -> tuple[World, pymunk.PivotJoint]:
    world = World(cfg)
    bob = world.add_box("bob", mass=2.5, size=(0.4, 0.4), position=(0.0, -1.0))
    joint = pymunk.PivotJoint(world.space.static_body, bob, (0.0, 0.0), (0.0, 1.0))
    world.add_constraint(joint)
    if swing:
        bob.velocity = (3.0, 0.0)
        bob.angular_velocity = 3.0
    world.track("bob")
    return world, joint


@pytest.mark.parametrize("swing", [False, True], ids=["rest", "swing"])
def test_constraint_residual_equals_joint_impulse(swing: bool) -> None:
    """Law: for a body held only by a PivotJoint, |engine − contact| = joint.impulse / dt; at rest
    it is the weight m·g, pointing up."""
    world, joint = pendulum(WorldConfig(contact_split=True), swing)
    for _ in range(120):
        world.step()
        f = world.forces("bob")
        assert f.contact == (0.0, 0.0)
        residual = math.hypot(*f.constraint)
        expected = joint.impulse / world.config.dt
        assert abs(residual - expected) <= TOL_REL * expected + TOL_ABS, (world.steps, f)
    if not swing:
        weight = 2.5 * G
        assert abs(f.constraint[1] - weight) <= TOL_REL * weight
        assert abs(f.constraint[0]) <= TOL_ABS


# -- exact answers (docs/design.md §5) -------------------------------------------------------------

TOL_SETTLED_REL = 1e-6
"""A settled contact still carries Baumgarte position correction of the residual overlap (below
``collision_slop``); its velocity changes are < 1e-6 of m·g per step once at rest (1 s)."""


def settle(world: World, seconds: float = 1.5) -> None:
    world.run(seconds)


def test_rest_support_is_weight() -> None:
    """Law: a body at rest on flat ground is supported by exactly m·g, straight up."""
    world = resting(WorldConfig())
    world.track("box")
    settle(world)
    f = world.forces("box")
    weight = 3.0 * G
    assert abs(f.support[1] - weight) <= TOL_SETTLED_REL * weight
    assert abs(f.support[0]) <= TOL_SETTLED_REL * weight
    assert close(f.specific, (0.0, G), TOL_SETTLED_REL, 0.0)


@pytest.mark.parametrize("theta_deg", [10.0, 25.0])
def test_incline_static_friction(theta_deg: float) -> None:
    """Law: on an incline θ held by static friction, N = m·g·cosθ and f = m·g·sinθ."""
    theta = math.radians(theta_deg)
    world = World(WorldConfig(contact_split=True))
    c, s = math.cos(theta), math.sin(theta)
    world.add_static_segment((-10.0 * c, -10.0 * s), (10.0 * c, 10.0 * s), radius=0.05)
    m = 4.0
    # Friction 1.0 · 1.0 = μ 1 > tanθ: static. Centre half a box above the surface (+ radius).
    world.add_box(
        "box", mass=m, size=(1.0, 1.0), position=(-0.55 * s, 0.55 * c), angle=theta, friction=1.0
    )
    world.track("box")
    settle(world)
    f = world.forces("box")
    normal = math.hypot(*f.contact_normal)
    friction = math.hypot(*f.contact_friction)
    assert abs(normal - m * G * c) <= TOL_SETTLED_REL * m * G
    assert abs(friction - m * G * s) <= TOL_SETTLED_REL * m * G
    assert world.body("box").velocity.length < 1e-6


def box_on_platform(
    path: Elevator, *, friction: float, mass: float = 2.0, config: WorldConfig | None = None
) -> World:
    world = World(config or WorldConfig(contact_split=True))
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Poly.create_box(plat, (40.0, 0.2))
    shape.friction = 1.0
    world.add("platform", plat, shape)
    world.add_mover("platform", path)
    world.add_box("box", mass=mass, size=(1.0, 1.0), position=(0.0, 0.6), friction=friction)
    world.track("box")
    return world


TOL_ACCEL_REL = 1e-6
"""A body carried by an accelerating kinematic platform: once the contact has settled (1 s of
acceleration), the support follows m·(g + a) to the settled-contact accuracy."""


DESCENT_CHATTER = (
    "pymunk integrates positions before velocities and drops a contact once the shapes stop "
    "overlapping: a kinematic floor accelerating downward gains a·dt² of separation per step on "
    "the body it carries (no bias below collision_slop), so the body loses contact and lands again"
)


@pytest.mark.parametrize(
    "a",
    [1.0, 4.0, pytest.param(-3.0, marks=pytest.mark.xfail(strict=True, reason=DESCENT_CHATTER))],
)
def test_elevator_support(a: float) -> None:
    """Law: in an elevator accelerating at a (up positive), the floor pushes N = m·(g + a)."""
    m = 2.0
    world = box_on_platform(Elevator(acceleration=a, start_time=0.5), friction=0.8, mass=m)
    world.run(1.5)
    f = world.forces("box")
    assert abs(f.support[1] - m * (G + a)) <= TOL_ACCEL_REL * m * (G + abs(a))
    assert abs(f.support[0]) <= TOL_ACCEL_REL * m * G


TOL_HOP_REL = 1e-4
"""A body on a floor accelerating downward hops (see DESCENT_CHATTER): over a window its mean
support is exact but for the momentum change of a hop in progress at the window's ends. A window
that starts and ends on a step in contact has the body moving with the floor at both ends (to the
contact's bias velocity). Measured over 1 s: 2e-9 (a = −3 m/s²) and 9e-6 (a = −6 m/s²) of
m·(g + a); 1e-4 is 10× the larger. (A window cut mid-hop errs by m·Δv/T: 1 % for a = −3.)"""


def in_contact(world: World, name: str) -> bool:
    """The body touched something in the last step (its contact sum is not zero)."""
    return world.forces(name).contact != (0.0, 0.0)


@pytest.mark.parametrize("a", [-3.0, -6.0])
def test_descending_elevator_mean_support(a: float) -> None:
    """Law: in an elevator accelerating downward (|a| < g) the support averaged over a second is
    m·(g + a), even though contact is lost and regained within that second."""
    m = 2.0
    world = box_on_platform(Elevator(acceleration=a, start_time=0.5), friction=0.8, mass=m)
    world.run(1.0)
    while not in_contact(world, "box"):
        world.step()
    support: list[float] = []
    while len(support) < round(1.0 / world.config.dt) or not in_contact(world, "box"):
        world.step()
        support.append(world.forces("box").support[1])
    mean = float(np.mean(support))
    assert abs(mean - m * (G + a)) <= TOL_HOP_REL * m * (G + a)


@pytest.mark.parametrize("a", [1.0, 2.0, 3.5])
def test_platform_below_mu_g_carries(a: float) -> None:
    """Law: a platform accelerating sideways at a ≤ μ·g carries the body; friction = m·a."""
    m, mu = 2.0, 0.5  # μ = 0.5 · 1.0 (pymunk multiplies the two shapes' frictions)
    assert a < mu * G
    world = box_on_platform(
        Elevator(axis=(1.0, 0.0), acceleration=a, start_time=0.5), friction=mu, mass=m
    )
    world.run(1.5)
    f = world.forces("box")
    assert abs(f.contact_friction[0] - m * a) <= TOL_ACCEL_REL * m * G
    assert abs(f.contact_normal[1] - m * G) <= TOL_ACCEL_REL * m * G


@pytest.mark.parametrize("a", [6.0, 12.0])
def test_platform_above_mu_g_slips(a: float) -> None:
    """Law: beyond μ·g the body slips and kinetic friction is μ·m·g (Coulomb, pymunk's clamp)."""
    m, mu = 2.0, 0.5
    assert a > mu * G
    world = box_on_platform(
        Elevator(axis=(1.0, 0.0), acceleration=a, start_time=0.5), friction=mu, mass=m
    )
    world.run(1.5)
    f = world.forces("box")
    plat_v = world.body("platform").velocity.x
    assert world.body("box").velocity.x < plat_v - 0.5, "the box should slip behind"
    assert abs(f.contact_friction[0] - mu * m * G) <= TOL_ACCEL_REL * m * G


def test_stack_head_and_ground_contacts() -> None:
    """Law: with mass M resting on a body of mass m, the head contact carries M·g (down on the
    body) and the ground contact (m + M)·g (up); the engine force is their sum, m·g."""
    m, big = 1.0, 6.0
    world = World(WorldConfig(contact_split=True))
    ground(world)
    world.add_box("player", mass=m, size=(1.0, 1.0), position=(0.0, 0.55))
    world.add_box("load", mass=big, size=(1.2, 1.0), position=(0.0, 1.55))
    world.track("player")
    settle(world)
    head = [0.0, 0.0]
    floor = [0.0, 0.0]
    load = world.body("load")

    def split(arb: pymunk.Arbiter) -> None:
        other = arb.bodies[1]
        target = head if other is load else floor
        target[0] += arb.total_impulse.x / world.config.dt
        target[1] += arb.total_impulse.y / world.config.dt

    world.body("player").each_arbiter(split)
    assert abs(head[1] + big * G) <= TOL_SETTLED_REL * big * G
    assert abs(floor[1] - (m + big) * G) <= TOL_SETTLED_REL * (m + big) * G
    f = world.forces("player")
    assert abs(f.engine[1] - m * G) <= TOL_SETTLED_REL * (m + big) * G


RING_RADIUS = 4.0
"""Inner radius of the ring's wall (chord midpoints), m."""

BOX = 0.5
"""Side of the rider, m."""

SPIN = 1.5
"""Ring rate, rad/s."""

TOL_RING_REL = 1e-3
"""The rider is not welded to the wall: under the wall's friction it creeps along its chord (its
speed is ~0.2 % below ω·r and changes by ~1e-4 per step), so the force averaged over a step and
v²/r taken at step ends agree to a few 1e-4; averaged over a second of steps."""

TOL_RING_SPEED_REL = 5e-3
"""How far the rider's speed may lag the speed ω·r a rigid carry would give (creep, above)."""


TOL_RING_RADIUS = 0.015
"""m. The rider sinks into the wall by collision_slop (5 mm) plus the overlap the position bias
has not yet removed: it moves on a tangent each step while the wall curves, r·ω²·dt²/2 ≈ 0.3 mm
per step (≈ 5 mm at equilibrium, measured)."""


def test_spinning_ring_normal_is_centripetal() -> None:
    """Law: a rider carried round a spinning ring (no gravity) is pushed toward the centre with
    N = m·v²/r, where r is the radius of its centre of mass and v the speed it is carried at.

    Nominally r = inner radius − half the rider's size (3.75 m here) and v = ω·r; the test uses the
    measured r and v of the centre of mass, and checks they are close to the nominal ones.
    """
    m = 3.0
    segments = 48
    world = World(WorldConfig(contact_split=True), gravity=Uniform((0.0, 0.0)))
    ring = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("ring", ring, *ring_room(ring, RING_RADIUS, segments=segments))
    world.add_mover("ring", Spin(rate=SPIN))
    # Sit at the middle of a chord (where the wall's inner face is at RING_RADIUS), carried along.
    phi = 2.0 * math.pi * 36.5 / segments
    r = RING_RADIUS - BOX / 2
    rider = world.add_box(
        "rider", mass=m, size=(BOX, BOX), position=(r * math.cos(phi), r * math.sin(phi)), angle=phi
    )
    rider.velocity = (-SPIN * r * math.sin(phi), SPIN * r * math.cos(phi))
    rider.angular_velocity = SPIN
    world.track("rider")
    world.run(1.0)
    support, centripetal, radius, speed = [], [], [], []
    for _ in range(120):
        world.step()
        f = world.forces("rider")
        pos, vel = rider.position, rider.velocity
        inward = np.array([-pos.x, -pos.y]) / pos.length
        support.append(float(np.dot(f.support, inward)))
        centripetal.append(m * vel.length**2 / pos.length)
        radius.append(pos.length)
        speed.append(vel.length)
    n_mean, c_mean = float(np.mean(support)), float(np.mean(centripetal))
    assert abs(n_mean - c_mean) <= TOL_RING_REL * c_mean
    r_mean = float(np.mean(radius))
    assert abs(r_mean - r) <= TOL_RING_RADIUS
    assert abs(float(np.mean(speed)) - SPIN * r_mean) <= TOL_RING_SPEED_REL * SPIN * r_mean


def test_forces_only_for_tracked_bodies() -> None:
    """Law: no tracked body, no solver stage; asking for an untracked body names the fix."""
    world = resting(WorldConfig(timing=True))
    world.run(0.1)
    assert world.timings[Stage.FORCES].calls == 0
    with pytest.raises(KeyError, match="track"):
        world.forces("box")


def test_solver_arrays_are_finite() -> None:
    """Law: every reading of a valid row is finite."""
    world = stack(WorldConfig(contact_split=True))
    world.track(*dynamic_names(world))
    world.run(0.5)
    s = world.readings()
    for arr in (s.engine, s.support, s.specific, s.contact, s.constraint):
        assert np.isfinite(arr[s.valid]).all()


@pytest.mark.parametrize(
    "block",
    [(0, 1, 2), (2, 0, 1), (0, 1, 2, 3), (3, 2, 1)],
    ids=["tracked-order", "shuffled", "run-and-untracked", "shuffled-and-untracked"],
)
def test_a_block_of_rows_reads_as_entries_body_by_body(block: tuple[int, ...]) -> None:
    """Law: forces entered as a block of rows (a crowd's) give the solver's readings the very
    bits the same forces give entered body by body, whether the block's bodies are the tracked
    rows in order (read as one slice), in another order, or include an untracked body."""
    from playground.forces.batch import BatchBodies
    from playground.forces.ledger import Category, ForceLedger, ForceRows, RowBodies

    dt = 1.0 / 120.0
    rng = np.random.default_rng(11)
    forces = rng.normal(scale=50.0, size=(4, 3, 2))  # per body: passive, applied, support (N)
    categories = (Category.PASSIVE, Category.APPLIED, Category.SUPPORT)

    def readings(as_rows: bool) -> list[bytes]:
        space = pymunk.Space()
        space.gravity = (0.0, -G)
        space.sleep_time_threshold = math.inf
        bodies = [pymunk.Body(1.0 + i, 0.5 + i) for i in range(4)]
        for i, b in enumerate(bodies):
            b.velocity = (0.5 * i, -0.25 * i)
            space.add(b, pymunk.Circle(b, 0.2))
        tracked = BatchBodies(space, WorldConfig())
        for b in bodies[:3]:
            tracked.track(b)
        ledger = ForceLedger()
        chosen = [bodies[i] for i in block]
        if as_rows:
            total = np.array([0.0 + f[0] + f[1] + f[2] for f in forces[list(block)]])
            parts = np.array([(0.0 + f).reshape(-1) for f in forces[list(block)]])
            ids = np.array([b.id for b in chosen], dtype=np.uintp)
            rows = ForceRows(RowBodies(chosen, ids), total, np.zeros(len(chosen)), parts)
            ledger.add_rows(rows)
        else:
            for i, b in zip(block, chosen, strict=True):
                ledger.add_all(b, [(*forces[i, k].tolist(), c) for k, c in enumerate(categories)])
        ledger.flush()
        tracked.before_step(None, 1)
        space.step(dt)
        tracked.after_substep(last=True, stamp=1, rescaled=False)
        tracked.finish(dt=dt, substeps=1, damping=1.0, space_gravity=(0.0, -G), ledger=ledger)
        table = tracked.table()
        return [a.tobytes() for a in (table.engine, table.support, table.passive, table.applied)]

    assert readings(as_rows=True) == readings(as_rows=False)
