"""Laws of the gravity stage: it runs only when needed, a rule in a uniform field costs one
correction force, a body that leaves takes its rule with it, and a ruled body falls at its rule's
gravity in every kind of field."""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pytest

from playground._engine.batch import BodyRows
from playground.forces import Category
from playground.gravity import GravityField, GravityRule, Radial, RotatingRoom, Uniform
from playground.vec import Vec
from playground.world.world import World

G = 9.81


def test_the_stage_runs_only_for_rules_or_a_field_that_varies() -> None:
    """Law: a uniform field with no rule is ``space.gravity`` alone; a rule or a field that
    varies in space turns the stage on; removing the last ruled body turns it off again."""
    world = World(gravity=(0.0, -G))
    world.add_box("a", mass=2.0, size=(1.0, 1.0), position=(0.0, 5.0))
    assert not world._gravity.active
    world.set_gravity_rule("a", GravityRule(scale=0.5))
    assert world._gravity.active
    world.remove("a")
    assert not world._gravity.active
    world.gravity = Radial(radius=1.0)
    assert world._gravity.active and world.space.gravity == (0.0, 0.0)
    world.gravity = Uniform((0.0, -G))
    assert not world._gravity.active


def test_a_rule_in_a_uniform_field_is_one_passive_correction_force() -> None:
    """Law: a half-gravity body gets m·(g/2 − g) as a PASSIVE ledger entry and falls at g/2;
    the field's force is not handed to the physics stage (``space.gravity`` does it)."""
    world = World(gravity=(0.0, -G))
    world.add_box("a", mass=2.0, size=(1.0, 1.0), position=(0.0, 50.0))
    world.set_gravity_rule("a", GravityRule(scale=0.5))
    assert world._gravity.apply(0.0) is None
    ((_, parts),) = world.ledger.items()
    i = 2 * Category.PASSIVE.value
    assert parts[i : i + 2] == [0.0, pytest.approx(2.0 * G / 2)]
    world.ledger.clear()
    world.run(1.0)
    assert world.body("a").velocity.y == pytest.approx(-G / 2, rel=1e-9)


@pytest.mark.parametrize("between", [False, True])
def test_a_field_that_varies_is_evaluated_at_the_bodies_of_one_read(between: bool) -> None:
    """Law: for a field that varies in space the stage hands the physics stage an evaluation at
    the bodies of its batch read: the rows of the named dynamic bodies (a slice when they are
    one run of rows, their indices when a kinematic body sits between them), with m·g at each
    one's position, and none for a kinematic body."""
    world = World(gravity=Radial(radius=1.0))
    world.add_box("a", mass=3.0, size=(0.2, 0.2), position=(0.0, 2.0))
    world.add("k", pymunk.Body(body_type=pymunk.Body.KINEMATIC))
    if between:
        world.add_box("b", mass=2.0, size=(0.2, 0.2), position=(1.0, 3.0))
    field = world._gravity.apply(0.0)
    assert callable(field)
    rows = BodyRows()
    rows.read(world.space, positions=True)
    at, force = field(rows.ids, rows.positions)
    assert isinstance(at, slice) is not between
    by_id = dict(zip(rows.ids[at].tolist(), force.tolist(), strict=True))
    expected = {world.body("a").id: [3.0 * g for g in world.gravity_at("a")]}
    if between:
        expected[world.body("b").id] = [2.0 * g for g in world.gravity_at("b")]
    assert by_id == expected


RULES = [
    GravityRule(scale, direction)
    for scale in (0.0, 0.5, 2.0)
    for direction in (None, (1.0, 0.0), (-0.6, 0.8))
]
"""Rules with and without their own direction, at scales that drop, halve and double gravity."""
FIELDS: dict[str, GravityField] = {
    "down": Uniform((0.0, -G)),
    "oblique": Uniform((3.0, -4.0)),
    "rotating room": RotatingRoom(rate=0.5),
    "planet": Radial(center=(0.0, -20.0), radius=20.0),
}
"""Uniform fields (a correction force on ``space.gravity``, in plain floats), one that turns in
time, and one that varies in space (the field evaluated at each body)."""
RULED_STEPS = 60
"""Steps of free fall checked (0.5 s at the default dt)."""
TOL_DV = 1e-12
"""m/s: a step's velocity change against g·dt, both a few float operations on |g| ≲ 20 m/s²."""


def _ruled(rule: GravityRule, field: GravityField, point: tuple[float, float], t: float) -> Vec:
    """The rule's gravity written out on its own (not through the rule's formula): scale × the
    field, or scale × |field| along the rule's direction, m/s²."""
    (fx, fy) = field.at(np.array([point]), t)[0]
    if rule.direction is None:
        return (rule.scale * fx, rule.scale * fy)
    size = rule.scale * math.hypot(fx, fy)
    return (size * rule.direction[0], size * rule.direction[1])


@pytest.mark.parametrize("rule", RULES, ids=lambda r: f"scale{r.scale:g}-{r.direction}")
@pytest.mark.parametrize("field", list(FIELDS))
def test_a_ruled_body_falls_at_its_rules_gravity_in_every_field(
    field: str, rule: GravityRule
) -> None:
    """Law: each step a free body with its own rule gains g·dt, g its rule's gravity where it
    is: the scale times the field, or the scale times |field| along its own direction — its
    scale counts with an own direction too — whichever way the stage applies it (a correction
    force on a uniform field, the field evaluated at the body where it varies); and the world
    reports that g."""
    world = World(gravity=FIELDS[field])
    world.add_box("a", mass=2.0, size=(0.2, 0.2), position=(0.5, 3.0))
    world.set_gravity_rule("a", rule)
    body = world.body("a")
    dt = world.config.dt
    for _ in range(RULED_STEPS):
        p, v0 = body.position, body.velocity
        gx, gy = _ruled(rule, FIELDS[field], (p.x, p.y), world.time)
        assert world.gravity_at("a") == (
            pytest.approx(gx, abs=TOL_DV),
            pytest.approx(gy, abs=TOL_DV),
        )
        world.step()
        dv = body.velocity - v0
        assert math.hypot(dv.x - gx * dt, dv.y - gy * dt) <= TOL_DV, (world.time, dv, (gx, gy))
