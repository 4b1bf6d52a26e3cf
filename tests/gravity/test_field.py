"""Laws of the gravity fields and of how the world applies them (docs/design.md §4, stage 3).

Fields are pure functions of position and time; a uniform field is ``space.gravity`` (no GRAVITY
stage), anything else is a per-body force the solver knows about.
"""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pytest

from playground import (
    GravityRule,
    Radial,
    RotatingRoom,
    Stage,
    Turn,
    Uniform,
    World,
    WorldConfig,
    Zone,
    Zones,
)

TOL_FIELD = 1e-12
"""m/s²: fields are closed-form; rotations and translations of the input change only rounding."""

TOL_FORCE_ABS = 1e-9
"""N: a body in free space feels no engine force; reverse integration leaves rounding only."""

RNG = np.random.default_rng(7)
POINTS = RNG.uniform(-20.0, 20.0, size=(50, 2))


def rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def test_uniform_is_the_same_everywhere() -> None:
    """Law: a uniform field gives its g at every point and time."""
    g = Uniform((1.5, -3.0)).at(POINTS, 12.0)
    assert (g == np.array([1.5, -3.0])).all()


def test_rotating_room_direction_and_magnitude() -> None:
    """Law: a rotating room keeps |g| and turns at its rate plus its scheduled turns."""
    room = RotatingRoom(magnitude=7.0, angle=0.3, rate=0.5, turns=(Turn(2.0, math.pi, 1.0),))
    for t in np.linspace(0.0, 5.0, 21):
        gx, gy = room.vector(float(t))
        assert abs(math.hypot(gx, gy) - 7.0) <= TOL_FIELD
        expected = 0.3 + 0.5 * t + math.pi * Turn(2.0, math.pi, 1.0).progress(float(t))
        assert abs(math.remainder(math.atan2(gy, gx) - expected, 2 * math.pi)) <= 1e-12
        assert (room.at(POINTS, float(t)) == np.array([gx, gy])).all()


def test_rotating_room_is_rotation_equivariant() -> None:
    """Law: starting the room δ further round rotates its field by δ."""
    delta = 0.7
    a = RotatingRoom(angle=0.2, rate=0.4)
    b = RotatingRoom(angle=0.2 + delta, rate=0.4)
    for t in (0.0, 1.3, 4.0):
        assert np.allclose(rotation(delta) @ np.array(a.vector(t)), b.vector(t), 0, TOL_FIELD)


def test_turn_easing() -> None:
    """Law: a turn's progress goes 0 → 1 monotonically, symmetric about its middle, starting and
    ending at rest (smoothstep); a zero-duration turn is a step."""
    turn = Turn(start=1.0, angle=math.pi, duration=2.0)
    ts = np.linspace(0.0, 4.0, 401)
    p = np.array([turn.progress(float(t)) for t in ts])
    assert p[0] == 0.0 and p[-1] == 1.0
    assert (np.diff(p) >= 0.0).all()
    for s in np.linspace(0.0, 1.0, 11):
        a = turn.progress(1.0 + 2.0 * s)
        b = turn.progress(1.0 + 2.0 * (1.0 - s))
        assert abs(a + b - 1.0) <= 1e-12
    eps = 1e-4
    assert turn.progress(1.0 + eps) / eps < 1e-3  # slope ~ 0 at the start
    assert (1.0 - turn.progress(3.0 - eps)) / eps < 1e-3  # and at the end
    flip = Turn(start=1.0, angle=math.pi)
    assert flip.progress(0.999) == 0.0 and flip.progress(1.0) == 1.0


def test_radial_value() -> None:
    """Law: without softening, |g| = g_surface at the surface radius, falls as 1/r², and points to
    the centre."""
    planet = Radial(center=(1.0, -2.0), surface_gravity=9.81, radius=5.0, softening=0.0)
    for angle in np.linspace(0.0, 2 * math.pi, 9):
        for r in (5.0, 10.0):
            p = np.array([[1.0 + r * math.cos(angle), -2.0 + r * math.sin(angle)]])
            g = planet.at(p, 0.0)[0]
            assert abs(np.hypot(*g) - 9.81 * (5.0 / r) ** 2) <= TOL_FIELD
            inward = np.array([-math.cos(angle), -math.sin(angle)])
            assert np.allclose(g / np.hypot(*g), inward, 0, TOL_FIELD)
    soft = Radial(center=(0.0, 0.0), softening=0.5)
    assert np.isfinite(soft.at(np.zeros((1, 2)), 0.0)).all()


def test_radial_columns_equal_the_vector_formula_bit_for_bit() -> None:
    """Law: the field, evaluated column by column, is the formula written on (N, 2) rows
    (``r = p − c``, ``|r|² + ε²``, ``−g·R²·r / (|r|² + ε²)^{3/2}``, zero at the very centre), to
    the last bit: the same products and sums; strided rows (a batch read) too."""
    rng = np.random.default_rng(12)
    for softening in (0.0, 0.5):
        planet = Radial(center=(3.0, -40.0), surface_gravity=7.5, radius=30.0, softening=softening)
        rows = rng.normal(size=(500, 5)) * 50.0
        rows[0, 0:2] = planet.center  # the very centre
        rows[1, 0:2] = (3.0, -0.0)
        for points in (rows[:, 0:2], np.ascontiguousarray(rows[:, 0:2])):
            r = points - np.asarray(planet.center)
            d2 = np.einsum("ij,ij->i", r, r) + softening**2
            gm = planet.surface_gravity * planet.radius**2
            scale = np.divide(-gm, d2 * np.sqrt(d2), out=np.zeros_like(d2), where=d2 > 0.0)
            expected = r * scale[:, None]
            got = planet.at(points, 0.0)
            assert got.tobytes() == expected.tobytes()


def test_radial_is_equivariant() -> None:
    """Law: rotating the points about the centre rotates the field; moving the planet and the
    points together leaves it unchanged."""
    planet = Radial(center=(0.0, 0.0), radius=4.0)
    rot = rotation(1.1)
    g = planet.at(POINTS, 0.0)
    assert np.allclose(planet.at(POINTS @ rot.T, 0.0), g @ rot.T, 0, TOL_FIELD)
    shift = np.array([3.0, -7.5])
    moved = Radial(center=(3.0, -7.5), radius=4.0)
    assert np.allclose(moved.at(POINTS + shift, 0.0), g, 0, TOL_FIELD)


def test_zones_first_match_wins() -> None:
    """Law: a point takes the field of the first zone containing it, else the base field."""
    up = Uniform((0.0, 9.81))
    side = Uniform((4.0, 0.0))
    zones = Zones(
        Uniform((0.0, -9.81)),
        (Zone((0.0, 0.0, 2.0, 2.0), up), Zone((1.0, 1.0, 3.0, 3.0), side)),
    )
    pts = np.array([[0.5, 0.5], [1.5, 1.5], [2.5, 2.5], [5.0, 5.0]])
    g = zones.at(pts, 0.0)
    assert g.tolist() == [[0.0, 9.81], [0.0, 9.81], [4.0, 0.0], [0.0, -9.81]]


def free_box(world: World, name: str = "box", position: tuple[float, float] = (0.0, 50.0)) -> None:
    world.add_box(name, mass=2.0, size=(1.0, 1.0), position=position)
    world.track(name)


def test_uniform_field_is_space_gravity_and_skips_the_stage() -> None:
    """Law: a uniform field is ``space.gravity``; the GRAVITY stage never runs."""
    world = World(WorldConfig(timing=True), gravity=(0.0, -4.0))
    free_box(world)
    world.run(0.5)
    assert world.space.gravity == (0.0, -4.0)
    assert world.timings[Stage.GRAVITY].calls == 0
    assert world.timings[Stage.PHYSICS].calls == world.steps


def test_per_body_field_is_a_recorded_force() -> None:
    """Law: a field that varies in space is applied as forces (space.gravity stays zero), recorded
    as passive forces; a body in free fall feels no engine force."""
    planet = Radial(center=(0.0, 0.0), radius=10.0)
    world = World(WorldConfig(timing=True), gravity=planet)
    free_box(world, position=(3.0, 30.0))
    for _ in range(60):
        before = world.body("box").position
        world.step()
        f = world.forces("box")
        expected = 2.0 * planet.at(np.array([[before.x, before.y]]), 0.0)[0]
        assert np.allclose(f.passive, expected, 0, TOL_FIELD * 10)
        assert math.hypot(*f.engine) <= TOL_FORCE_ABS
    assert world.space.gravity == (0.0, 0.0)
    assert world.timings[Stage.GRAVITY].calls == world.steps


@pytest.mark.parametrize("field", [Uniform(), Radial(radius=10.0)], ids=["uniform", "radial"])
def test_scale_zero_floats(field: Uniform | Radial) -> None:
    """Law: GravityRule(scale=0) nullifies gravity: in free space the body stays where it is and
    feels no engine force."""
    world = World(WorldConfig(), gravity=field)
    free_box(world, position=(2.0, 20.0))
    world.set_gravity_rule("box", GravityRule(scale=0.0))
    world.run(1.0)
    assert world.body("box").position == (2.0, 20.0)
    assert world.gravity_at("box") == (0.0, 0.0)
    assert math.hypot(*world.forces("box").engine) <= TOL_FORCE_ABS


def test_own_direction() -> None:
    """Law: a body with its own direction falls that way at |g|: v = n·|g|·dt after n steps."""
    world = World(WorldConfig())
    free_box(world)
    world.set_gravity_rule("box", GravityRule(direction=(1.0, 0.0)))
    n = 90
    for _ in range(n):
        world.step()
    v = world.body("box").velocity
    assert abs(v.x - n * 9.81 * world.config.dt) <= 1e-12 * n
    assert abs(v.y) <= 1e-12
    assert math.hypot(*world.forces("box").engine) <= TOL_FORCE_ABS


def test_rule_removed_restores_field() -> None:
    """Law: setting the rule to None gives the body the field again."""
    world = World(WorldConfig())
    free_box(world)
    world.set_gravity_rule("box", GravityRule(scale=0.0))
    world.set_gravity_rule("box", None)
    assert world.gravity_at("box") == (0.0, -9.81)
    kinematic = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("plat", kinematic)
    with pytest.raises(ValueError, match="dynamic"):
        world.set_gravity_rule("plat", GravityRule(scale=0.0))


def test_field_validation() -> None:
    """Law: bad field parameters raise ValueError naming the parameter."""
    with pytest.raises(ValueError, match="radius"):
        Radial(radius=0.0)
    with pytest.raises(ValueError, match="duration"):
        Turn(0.0, 1.0, -1.0)
    with pytest.raises(ValueError, match="direction"):
        GravityRule(direction=(0.0, 0.0))
    with pytest.raises(ValueError, match="g"):
        Uniform((math.nan, 0.0))


def test_field_follows_bodies_added_and_removed() -> None:
    """Law: bodies added or removed mid-run under a per-body field still get exactly their field
    force (a free body's engine force stays zero; its passive force is m·g at its position)."""
    planet = Radial(center=(0.0, 0.0), radius=10.0)
    world = World(WorldConfig(), gravity=planet)
    free_box(world, "a", position=(0.0, 40.0))
    free_box(world, "b", position=(20.0, 0.0))
    world.run(0.2)
    free_box(world, "c", position=(-30.0, 5.0))
    world.remove("a")
    for _ in range(30):
        before = {n: world.body(n).position for n in ("b", "c")}
        world.step()
        for name, p in before.items():
            f = world.forces(name)
            assert math.hypot(*f.engine) <= TOL_FORCE_ABS
            expected = 2.0 * planet.at(np.array([[p.x, p.y]]), 0.0)[0]
            assert np.allclose(f.passive, expected, 0, TOL_FIELD * 10)
