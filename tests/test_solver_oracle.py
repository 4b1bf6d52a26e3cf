"""The force solver's two paths against a slow, obviously-correct per-body oracle, and each other.

The oracle reads each body's velocity with plain attribute access just before the step and just
after it, knows every force it applied and the gravity each body gets, and computes, body by body,
``J = m·(v₁ − d·v₀) − (m·g + F)·h`` and ``L = I·(ω₁ − d·ω₀) − T·h`` (docs/design.md §2). Random
scenes add, remove and put bodies to sleep while the world runs.
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterator
from dataclasses import dataclass

import pymunk
import pytest

from playground import Category, GravityRule, Radial, Stage, World, WorldConfig
from playground.forces import BodyForces

TOL_REL = 1e-9
"""Relative to the size of the terms the formula subtracts (m·|v|/dt, m·g, |F|): the two sides
differ only by the order of float operations."""

STEPS = 240
"""Steps per random scene (2 s at 120 Hz): long enough for bodies to land, stack and sleep."""

G = (0.0, -9.81)


@dataclass
class Before:
    """What the oracle knows about a body just before the step."""

    v: tuple[float, float]
    w: float
    mass: float
    moment: float
    force: tuple[float, float]
    torque: float
    support: tuple[float, float]
    g: tuple[float, float]


@dataclass
class Expected:
    engine: tuple[float, float]
    torque: float
    support: tuple[float, float]
    scale: float
    torque_scale: float


class Oracle:
    """Random forces in CONTROL, per-body reverse integration in OBSERVE."""

    def __init__(self, world: World, rng: random.Random) -> None:
        self.world = world
        self.rng = rng
        self.tracked: set[str] = set()
        self.scales: dict[str, float] = {}
        self.pushed: set[str] = set()
        self.before: dict[str, Before] = {}
        self.expected: dict[str, Expected | None] = {}
        world.on(Stage.CONTROL, self.control)
        world.on(Stage.OBSERVE, self.observe)

    def control(self, world: World) -> None:
        self.before = {}
        for name in sorted(self.tracked):
            body = world.body(name)
            fx = fy = torque = sx = sy = 0.0
            # Forces wake a sleeper: only "pushed" bodies get them, the rest may settle and sleep.
            if name in self.pushed and not body.is_sleeping and self.rng.random() < 0.7:
                for category in Category:
                    f = (self.rng.uniform(-50, 50), self.rng.uniform(-50, 80))
                    c = body.local_to_world(body.center_of_gravity)
                    p = (c.x + self.rng.uniform(-0.3, 0.3), c.y + self.rng.uniform(-0.3, 0.3))
                    world.apply_force(name, f, point=p, category=category)
                    fx += f[0]
                    fy += f[1]
                    torque += (p[0] - c.x) * f[1] - (p[1] - c.y) * f[0]
                    if category is Category.SUPPORT:
                        sx += f[0]
                        sy += f[1]
            scale = self.scales.get(name, 1.0)
            self.before[name] = Before(
                v=(body.velocity.x, body.velocity.y),
                w=body.angular_velocity,
                mass=body.mass,
                moment=body.moment,
                force=(fx, fy),
                torque=torque,
                support=(sx, sy),
                g=(G[0] * scale, G[1] * scale),
            )

    def observe(self, world: World) -> None:
        h = world.config.dt
        d = world.config.damping**h
        self.expected = {}
        for name, b in self.before.items():
            body = world.body(name)
            if body.is_sleeping:
                self.expected[name] = None
                continue
            m, inertia = b.mass, b.moment
            v1, w1 = body.velocity, body.angular_velocity
            jx = m * (v1.x - d * b.v[0]) - (m * b.g[0] + b.force[0]) * h
            jy = m * (v1.y - d * b.v[1]) - (m * b.g[1] + b.force[1]) * h
            ang = inertia * (w1 - d * b.w) - b.torque * h
            engine = (jx / h, jy / h)
            speed = math.hypot(*b.v) + v1.length
            self.expected[name] = Expected(
                engine=engine,
                torque=ang / h,
                support=(engine[0] + b.support[0], engine[1] + b.support[1]),
                scale=m * speed / h + m * math.hypot(*b.g) + math.hypot(*b.force),
                torque_scale=inertia * (abs(b.w) + abs(w1)) / h + abs(b.torque),
            )


def spawn(world: World, oracle: Oracle, rng: random.Random, index: int) -> None:
    name = f"body{index}"
    x, y = rng.uniform(-8.0, 8.0), rng.uniform(0.5, 6.0)
    m = rng.uniform(0.5, 20.0)
    if rng.random() < 0.5:
        w, hgt = rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5)
        world.add_box(name, mass=m, size=(w, hgt), position=(x, y), angle=rng.uniform(0, 3))
    else:
        r = rng.uniform(0.1, 0.8)
        body = pymunk.Body(m, pymunk.moment_for_circle(m, 0.0, r))
        body.position = (x, y)
        shape = pymunk.Circle(body, r)
        shape.friction = 0.7
        world.add(name, body, shape)
    world.body(name).velocity = (rng.uniform(-3, 3), rng.uniform(-3, 3))
    if rng.random() < 0.2:
        oracle.scales[name] = rng.choice([0.0, 0.5, 2.0])
        world.set_gravity_rule(name, GravityRule(scale=oracle.scales[name]))
    if rng.random() < 0.85:
        world.track(name)
        oracle.tracked.add(name)
        if rng.random() < 0.4:
            oracle.pushed.add(name)


def touches_only_static(body: pymunk.Body) -> bool:
    """Chipmunk hangs in its next step if a body touching another dynamic body is put to sleep
    by hand (its sleeping components get linked into a cycle): the scenes avoid it."""
    others: list[pymunk.Body] = []
    body.each_arbiter(lambda arb: others.append(arb.bodies[1]))
    return all(b.body_type == pymunk.Body.STATIC for b in others)


PATHS = {"vector": 0, "scalar": 10**6, "switching": 12}
"""Most tracked bodies the scalar implementation may serve: never, always, and 12, which the scenes
(5–24 tracked bodies) cross both ways as bodies come and go, so the state moves between the
implementations."""

TOL_PATHS = 1e-12
"""Relative difference allowed between the scalar and batch implementations: the same operations in
the same order, except magnitudes (``math.hypot`` against numpy's complex ``abs``), which may
differ in the last place; the 1€ filter's feedback keeps that at round-off."""


KINDS = ("uniform", "split", "field", "substeps")
"""Scenes: uniform gravity; the contact split on (arbiters kept 1 or 3 steps); a radial field
(its forces per body) with some bodies given their own direction; 2 or 3 substeps with the split
on and forces set straight on bodies (re-applied before every substep)."""


def scene(
    seed: int, scalar_max: int, kind: str = "uniform"
) -> Iterator[tuple[World, Oracle, dict[str, BodyForces]]]:
    """A random scene stepped STEPS times: bodies spawned, removed and put to sleep. Yields the
    world and its oracle after every step, with the readings held from before it."""
    rng = random.Random(seed)
    split = kind in ("split", "substeps")
    substeps = rng.choice([2, 3]) if kind == "substeps" else 1
    cfg = WorldConfig(
        damping=rng.choice([1.0, 0.8, 0.3]),
        sleep_time=0.3,
        contact_split=split,
        substeps=substeps,
    )
    world = World(cfg)
    world.scalar_max_bodies = scalar_max
    if kind == "split":
        world.space.collision_persistence = rng.choice([1, 3])
    if kind == "field":
        # A planet far below: gravity about 9.8 m/s², its direction and size vary over the scene.
        world.gravity = Radial(center=(0.0, -60.0), surface_gravity=9.81, radius=60.0)
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0), radius=0.1)
    world.add_static_segment((-10.0, 0.0), (-10.0, 10.0), radius=0.1)
    world.add_static_segment((10.0, 0.0), (10.0, 10.0), radius=0.1)
    oracle = Oracle(world, rng)
    count = 0
    for _ in range(12):
        spawn(world, oracle, rng, count)
        count += 1
    for _ in range(STEPS):
        roll = rng.random()
        if roll < 0.06:
            spawn(world, oracle, rng, count)
            if kind == "field" and rng.random() < 0.3:
                direction = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
                world.set_gravity_rule(f"body{count}", GravityRule(0.8, direction))
            count += 1
        elif roll < 0.09 and oracle.tracked:
            name = rng.choice(sorted(oracle.tracked))
            world.remove(name)
            oracle.tracked.discard(name)
        elif roll < 0.2 and oracle.tracked - oracle.pushed:
            body = world.body(rng.choice(sorted(oracle.tracked - oracle.pushed)))
            if not body.is_sleeping and touches_only_static(body):
                body.sleep()
        if kind == "substeps" and rng.random() < 0.5:
            body = world.body(rng.choice(world.names))
            if not body.is_sleeping:
                body.force = (rng.uniform(-30.0, 30.0), rng.uniform(-30.0, 30.0))
        held = {n: world.forces(n) for n in oracle.tracked}
        world.step()
        yield world, oracle, held


@pytest.mark.parametrize("path", sorted(PATHS))
@pytest.mark.parametrize("seed", range(5))
def test_solver_equals_per_body_oracle(seed: int, path: str) -> None:
    """Law: for every tracked body and step, the engine force, torque and support of either path
    (numpy and batch, or plain floats) equal the per-body oracle's; a body asleep after the step
    has no reading (``valid`` False, last values held); added, removed and slept bodies never
    disturb the other rows."""
    compared = invalid = 0
    for world, oracle, held in scene(seed, PATHS[path]):
        for name, exp in oracle.expected.items():
            f = world.forces(name)
            if exp is None:
                assert not f.valid, name
                assert f.engine == held[name].engine, name
                invalid += 1
                continue
            assert f.valid, name
            tol = TOL_REL * exp.scale
            assert math.dist(f.engine, exp.engine) <= tol, (name, f.engine, exp.engine)
            assert math.dist(f.support, exp.support) <= tol, (name, f.support, exp.support)
            assert abs(f.engine_torque - exp.torque) <= TOL_REL * exp.torque_scale, name
            compared += 1
    assert compared > 500


def _close(a: tuple[float, float], b: tuple[float, float]) -> bool:
    scale = max(1.0, math.hypot(*a), math.hypot(*b))
    return math.dist(a, b) <= TOL_PATHS * scale or (a == b)


def _same(a: tuple[float, float], b: tuple[float, float]) -> bool:
    """Equal, NaN equal to NaN (an unknown split)."""
    return all(x == y or (math.isnan(x) and math.isnan(y)) for x, y in zip(a, b, strict=True))


SEEDS = {"uniform": range(5), "split": range(3), "field": range(3), "substeps": range(3)}


@pytest.mark.parametrize(("kind", "seed"), [(kind, seed) for kind in KINDS for seed in SEEDS[kind]])
def test_scalar_and_vector_paths_give_one_answer(kind: str, seed: int) -> None:
    """Law: the scalar implementation (always, or switching at the crossover as bodies come and go)
    and the batch implementation give the same readings and perceived gravity on every step of the
    same random scene, within TOL_PATHS; the contact split (contact, its normal part, the
    constraint's, and whether it is known) bit for bit; in a field that varies in space, the same
    trajectory bit for bit. The arrays of ``world.readings()`` hold the values the serving
    implementation reads out body by body, whichever serves."""
    runs = [scene(seed, PATHS[p], kind) for p in ("vector", "scalar", "switching")]
    split_known = 0
    served = 0
    for (ref, _, _), *others in zip(*runs, strict=True):
        names = sorted(n for n in ref.names if ref.is_tracked(n))
        for world, _, _ in others:
            for name in names:
                a, b = ref.forces(name), world.forces(name)
                assert a.valid == b.valid, name
                for field in ("engine", "support", "specific", "passive", "applied"):
                    assert _close(getattr(a, field), getattr(b, field)), (name, field)
                assert _close((a.engine_torque, 0.0), (b.engine_torque, 0.0)), name
                assert _close(ref.perceived_gravity(name), world.perceived_gravity(name)), name
                assert _close(ref.perceived_up(name), world.perceived_up(name)), name
                for w in (ref, world):
                    both = (w.perceived_up(name), w.perceived_gravity(name))
                    assert w.perceived_up_and_gravity(name) == both, name
                assert a.split_valid == b.split_valid, name
                for field in ("contact", "contact_normal", "contact_friction", "constraint"):
                    assert _same(getattr(a, field), getattr(b, field)), (name, field)
                split_known += b.split_valid
                body_a, body_b = ref.body(name), world.body(name)
                assert (body_a.position, body_a.velocity) == (body_b.position, body_b.velocity)
            served += world.tracked_kind == "scalar"
        if ref.steps % 60 == 0:
            # The arrays hold what the readers give, for the batch and the scalar worlds alike.
            for world in (ref, others[0][0]):
                table = world.readings()
                rows = {body: i for i, body in enumerate(table.bodies)}
                assert list(table.bodies) == world.tracked_bodies
                for name in names:
                    row = rows[world.body(name)]
                    g = table.perceived_gravity[row]
                    assert (float(g[0]), float(g[1])) == world.perceived_gravity(name), name
                    e = table.engine[row]
                    assert (float(e[0]), float(e[1])) == world.forces(name).engine, name
    assert (
        served > STEPS
    )  # the scalar implementation served every step of one run, some of the other
    assert (split_known > STEPS) == (kind in ("split", "substeps"))
