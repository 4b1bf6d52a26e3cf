"""Laws of the force ledger: totals per body, sums per category, torque from the point, flush."""

from __future__ import annotations

import math
import random

import pymunk
import pytest

from playground.forces.ledger import Category, ForceLedger


def body_at(x: float, y: float) -> pymunk.Body:
    body = pymunk.Body(2.0, 1.0)
    body.position = (x, y)
    return body


def test_forces_sum_per_body_and_per_category() -> None:
    """Each body's total is the sum of its forces; each category's sum is kept apart, in the
    documented order [passive x, y, applied x, y, support x, y]."""
    a, b = body_at(0.0, 0.0), body_at(5.0, 0.0)
    ledger = ForceLedger()
    ledger.add(a, (1.0, 2.0), category=Category.PASSIVE)
    ledger.add(a, (10.0, 0.0))  # APPLIED by default
    ledger.add(a, (0.0, -4.0), category=Category.SUPPORT)
    ledger.add(a, (0.5, 0.5), category=Category.SUPPORT)
    ledger.add(b, (3.0, 3.0), category=Category.SUPPORT)
    assert len(ledger) == 2
    parts = {body_id: p for body_id, p in ledger.items()}
    assert parts[a.id] == [1.0, 2.0, 10.0, 0.0, 0.5, -3.5]
    assert parts[b.id] == [0.0, 0.0, 0.0, 0.0, 3.0, 3.0]
    ledger.flush()
    assert a.force == (11.5, -1.5)
    assert b.force == (3.0, 3.0)


def test_a_force_off_the_centre_of_gravity_turns_the_body() -> None:
    """Torque about the centre of gravity is r × F, with r from the body's centre of gravity in
    the world (not the origin, not the body's position when its centre of gravity is offset);
    a pure torque adds to it."""
    body = pymunk.Body(2.0, 1.0)
    body.center_of_gravity = (0.0, 1.0)
    body.angle = math.pi / 2
    body.position = (3.0, 4.0)  # so the centre of gravity is at (3, 4) + (-1, 0) in the world
    ledger = ForceLedger()
    ledger.add(body, (0.0, 5.0), point=(4.0, 4.0))  # r = (2, 0): T = 2·5
    ledger.add_torque(body, -1.5, Category.APPLIED)
    ledger.flush()
    assert body.torque == pytest.approx(10.0 - 1.5, abs=1e-12)
    ledger.clear()
    ledger.add(body, (7.0, 0.0))  # at the centre of gravity: no torque
    ledger.flush()
    assert body.torque == 0.0


def test_flush_replaces_what_the_body_had() -> None:
    """pymunk clears forces after each step; flush writes the ledger's totals, not a sum with
    whatever the body held."""
    body = body_at(0.0, 0.0)
    body.force = (100.0, 100.0)
    body.torque = 9.0
    ledger = ForceLedger()
    ledger.add(body, (1.0, 0.0))
    ledger.flush()
    assert (body.force, body.torque) == ((1.0, 0.0), 0.0)


def test_on_first_is_called_when_an_empty_ledger_gets_an_entry() -> None:
    """The world's hook runs once per empty → non-empty change, not per force."""
    calls: list[int] = []
    body = body_at(0.0, 0.0)
    ledger = ForceLedger(on_first=lambda: calls.append(1))
    ledger.add(body, (1.0, 0.0))
    ledger.add(body, (1.0, 0.0))
    ledger.add_torque(body_at(1.0, 0.0), 1.0, Category.SUPPORT)
    assert len(calls) == 1
    ledger.clear()
    ledger.add_torque(body, 1.0, Category.SUPPORT)
    assert len(calls) == 2


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_non_finite_forces_and_torques_are_refused(bad: float) -> None:
    """A NaN or infinite force or torque is a ValueError naming the unit, and records nothing."""
    body = body_at(0.0, 0.0)
    ledger = ForceLedger()
    with pytest.raises(ValueError, match="force: expected a finite 2-vector in newtons"):
        ledger.add(body, (0.0, bad))
    with pytest.raises(ValueError, match="torque: expected a finite number in N·m"):
        ledger.add_torque(body, bad, Category.APPLIED)
    assert len(ledger) == 0


def test_add_all_is_one_add_each_in_order_bit_for_bit() -> None:
    """Law: recording forces with one ``add_all`` gives the body's totals and per-category sums
    of one ``add`` call each, in the same order, then one ``add_torque``, to the last bit (a
    body that already has an entry, with a torque, included), the forces at its centre of
    gravity or all at one point."""
    rng = random.Random(7)
    cats = list(Category)
    for _ in range(200):
        forces = [
            (rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), rng.choice(cats))
            for _ in range(rng.randint(1, 5))
        ]
        first = (rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0))
        at = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
        torque = rng.choice((None, rng.uniform(-1e3, 1e3)))
        point = rng.choice((None, (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0))))
        one, many = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
        one.position = many.position = (0.3, -0.7)
        a, b = ForceLedger(), ForceLedger()
        a.add(one, first, point=at)
        b.add(many, first, point=at)
        for fx, fy, cat in forces:
            a.add(one, (fx, fy), point=point, category=cat)
        if torque is not None:
            a.add_torque(one, torque, Category.APPLIED)
        b.add_all(many, forces, torque, point)
        a.flush()
        b.flush()
        assert (one.force.x, one.force.y, one.torque) == (many.force.x, many.force.y, many.torque)
        assert a.items()[0][1] == b.items()[0][1]


def test_parts_of_a_body_are_its_items_and_none_without_forces() -> None:
    """Law: ``parts(body)`` is what ``items()`` lists for that body's id (its per-category sums),
    and None for a body with no forces."""
    bodies = [pymunk.Body(1.0, 1.0) for _ in range(3)]
    ledger = ForceLedger()
    ledger.add(bodies[0], (1.0, 2.0), category=Category.SUPPORT)
    ledger.add(bodies[2], (-3.0, 0.5), category=Category.PASSIVE)
    ledger.add(bodies[2], (0.25, 4.0))
    by_id = dict(ledger.items())
    assert ledger.parts(bodies[0]) == by_id[bodies[0].id] == [0.0, 0.0, 0.0, 0.0, 1.0, 2.0]
    assert ledger.parts(bodies[2]) == by_id[bodies[2].id] == [-3.0, 0.5, 0.25, 4.0, 0.0, 0.0]
    assert ledger.parts(bodies[1]) is None


def test_a_cleared_ledger_starts_from_nothing_for_the_same_bodies() -> None:
    """Law: after ``clear`` a body's forces, torque and per-category sums start again from zero
    (the ledger reuses its entries for the bodies of the last step), and the first new entry
    calls ``on_first`` again."""
    calls: list[int] = []
    body, other = pymunk.Body(2.0, 1.0), pymunk.Body(1.0, 1.0)
    ledger = ForceLedger(on_first=lambda: calls.append(1))
    ledger.add(body, (5.0, -1.0), point=(0.0, 1.0), category=Category.SUPPORT)
    ledger.add(other, (1.0, 1.0), category=Category.PASSIVE)
    ledger.clear()
    ledger.add(body, (0.5, 2.0), category=Category.APPLIED)
    ledger.add_torque(body, 0.25, Category.APPLIED)
    fresh = ForceLedger()
    fresh.add(body, (0.5, 2.0), category=Category.APPLIED)
    fresh.add_torque(body, 0.25, Category.APPLIED)
    assert ledger.items() == fresh.items() == [(body.id, [0.0, 0.0, 0.5, 2.0, 0.0, 0.0])]
    ledger.flush()
    assert (body.force, body.torque) == ((0.5, 2.0), 0.25)
    assert ledger.parts(other) is None
    assert calls == [1, 1]


def test_a_row_adds_as_add_all_and_a_later_force_adds_to_it() -> None:
    """Law: a body's row, then a force added to it (once the row is active), sums as add_all of
    its forces then add of the force; a row not yet active leaves the body to an entry of its
    own and is dropped; the solver's view (row_block, parts) follows."""
    import numpy as np

    from playground.forces.ledger import ForceRows, RowBodies

    a, b = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    own = [(0.1, 0.7, Category.SUPPORT), (0.2, -0.3, Category.APPLIED)]
    push = (1e-17, 3.3)
    reference = ForceLedger()
    reference.add_all(a, own, 0.25)
    reference.add(a, push, category=Category.SUPPORT)
    reference.add(b, push, category=Category.SUPPORT)
    reference.flush()
    expected = (tuple(a.force), a.torque, reference.parts(a), tuple(b.force))

    ledger = ForceLedger()
    fx = 0.0 + 0.1 + 0.2
    fy = 0.0 + 0.7 + -0.3
    parts = np.array([[0.0, 0.0, 0.0 + 0.2, 0.0 + -0.3, 0.0 + 0.1, 0.0 + 0.7]] * 2)
    rows = ForceRows(
        RowBodies([a, b], np.array([a.id, b.id], dtype=np.uintp)),
        np.array([[fx, fy], [fx, fy]]),
        np.array([0.0 + 0.25, 0.0 + 0.25]),
        parts,
    )
    ledger.add_rows(rows)
    rows.active[0] = True  # a's turn has come, b's not yet
    ledger.add(a, push, category=Category.SUPPORT)
    ledger.add(b, push, category=Category.SUPPORT)
    ledger.drop_row(b)
    block = ledger.row_block()
    assert block is not None and len(block[0]) == 0
    a.force = b.force = (9.0, 9.0)
    ledger.flush()
    assert (tuple(a.force), a.torque, ledger.parts(a), tuple(b.force)) == expected


def test_rows_flush_in_one_batch_call_as_body_by_body() -> None:
    """Law: the rows of bodies in a space that cannot sleep are written in one batch call
    (ForceWrites), with the bits the setters write body by body (a space that can sleep, or
    none); a dropped row leaves its body to its entry, and bodies without a row keep theirs."""
    import math

    import numpy as np

    from playground.forces.ledger import ForceRows, RowBodies

    def flushed(sleep_time: float | None) -> list[str]:
        space = pymunk.Space()
        if sleep_time is not None:
            space.sleep_time_threshold = sleep_time
        bodies = [pymunk.Body(1.0, 1.0) for _ in range(4)]
        space.add(*bodies)
        if sleep_time is None:
            space.remove(*bodies)
        bodies[3].force, bodies[3].torque = (7.0, 8.0), 9.0
        ledger = ForceLedger()
        rows = ForceRows(
            RowBodies(bodies[:3], np.array([b.id for b in bodies[:3]], dtype=np.uintp)),
            np.array([[0.1, 0.2], [1e-17, -3.3], [5.0, 6.0]]),
            np.array([0.3, -0.0, 2.5]),
            np.zeros((3, 6)),
        )
        ledger.add_rows(rows)
        ledger.add(bodies[2], (1.0, 1.0))  # before its row's turn: an entry of its own
        ledger.drop_row(bodies[2])
        ledger.flush()
        return [repr((*b.force, b.torque)) for b in bodies]  # repr: -0.0 is not 0.0

    batch = flushed(math.inf)
    assert batch == flushed(1.0) == flushed(None)
    assert batch[1] == repr((1e-17, -3.3, -0.0))
    assert batch[2] == repr((1.0, 1.0, 0.0)) and batch[3] == repr((7.0, 8.0, 9.0))
