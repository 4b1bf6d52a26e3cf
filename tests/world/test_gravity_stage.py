"""Laws of the gravity stage: it runs only when needed, a rule in a uniform field costs one
correction force, and a body that leaves takes its rule with it."""

from __future__ import annotations

import pymunk
import pytest

from playground._engine.batch import BodyRows
from playground.forces import Category
from playground.gravity import GravityRule, Radial, Uniform
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
