"""A body's contacts read through Chipmunk's arbiter iteration give pymunk's answers bit for bit:
the load pressing along a direction (the same terms summed in the same order), summed over a
step's substeps, and the touch."""

from __future__ import annotations

import math
import random
import struct

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import contacts
from playground._engine.contacts import (
    Contacts,
    ShapeSums,
    gather_by_pymunk,
    load_by_pymunk,
    touching_by_pymunk,
)

DT = 1.0 / 120.0
"""s."""


def _pile(seed: int, steps: int) -> tuple[pymunk.Space, list[pymunk.Body]]:
    """Boxes and balls dropped on a floor and on each other, after ``steps`` steps: bodies with
    no contact, one, and several (a pile's middle), spinning; with their space (which must
    live while their contacts are read)."""
    rng = random.Random(seed)
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.add(pymunk.Segment(space.static_body, (-4.0, 0.0), (4.0, 0.0), 0.05))
    bodies = []
    for i in range(8):
        body = pymunk.Body(rng.uniform(0.5, 5.0), rng.uniform(0.1, 2.0))
        body.position = (rng.uniform(-1.0, 1.0), 0.5 + 0.6 * i)
        body.angle = rng.uniform(-1.0, 1.0)
        shape: pymunk.Shape = rng.choice(
            (pymunk.Circle(body, 0.3), pymunk.Poly.create_box(body, (0.6, 0.4)))
        )
        shape.friction = 0.7
        space.add(body, shape)
        bodies.append(body)
    for _ in range(steps):
        space.step(DT)
    return space, bodies


def _bits(x: float) -> bytes:
    return struct.pack("d", x)


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 30), st.integers(0, 240), st.floats(-math.pi, math.pi), st.integers(1, 4))
def test_the_contacts_answer_as_pymunk(seed: int, steps: int, angle: float, substeps: int) -> None:
    ux, uy = math.cos(angle), math.sin(angle)
    h = DT / substeps
    _, bodies = _pile(seed, steps)
    for body in bodies:
        reader = Contacts(body)
        assert _bits(reader.load(ux, uy, h)) == _bits(load_by_pymunk(body, ux, uy, h))
        assert reader.touching() is touching_by_pymunk(body)
        both = reader.load_and_touching(ux, uy, h)
        assert _bits(both[0]) == _bits(load_by_pymunk(body, ux, uy, h))
        assert both[1] is touching_by_pymunk(body)


def test_a_pile_has_bodies_touching_and_pressed_from_above() -> None:
    """The scenes above exercise the sums: bodies in contact, loaded from above."""
    _, bodies = _pile(1, 240)
    assert any(Contacts(b).touching() for b in bodies)
    assert sum(Contacts(b).load(0.0, 1.0, DT) > 0.0 for b in bodies) >= 2
    _, unstepped = _pile(1, 0)
    assert not any(Contacts(b).touching() for b in unstepped)


def test_without_cffi_callbacks_the_contacts_ask_pymunk(monkeypatch: pytest.MonkeyPatch) -> None:
    _, bodies = _pile(2, 240)
    body = bodies[0]
    reader = Contacts(body)
    load, touching = reader.load(0.0, 1.0, DT), reader.touching()
    monkeypatch.setattr(contacts, "_load_callback", None)
    monkeypatch.setattr(contacts, "_touch_callback", None)
    assert _bits(reader.load(0.0, 1.0, DT)) == _bits(load) and reader.touching() is touching


def _step_gathering(
    space: pymunk.Space, bodies: list[pymunk.Body], substeps: int
) -> tuple[list[Contacts], list[ShapeSums]]:
    """One step of DT in ``substeps`` substeps, each body's contacts gathered after each
    substep but the last, by Contacts and by pymunk's functions."""
    readers = [Contacts(b) for b in bodies]
    sums: list[ShapeSums] = [{} for _ in bodies]
    for k in range(substeps):
        space.step(DT / substeps)
        if k < substeps - 1:
            for body, reader, summed in zip(bodies, readers, sums, strict=True):
                reader.gather()
                gather_by_pymunk(body, summed)
    return readers, sums


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 30), st.integers(0, 240), st.floats(-math.pi, math.pi), st.integers(2, 4))
def test_the_load_over_substeps_answers_as_pymunk(
    seed: int, steps: int, angle: float, substeps: int
) -> None:
    """Each contact's impulse summed over the substeps (ended contacts included) over the step,
    as pymunk's functions sum them, bit for bit; the sums start again after a load."""
    ux, uy = math.cos(angle), math.sin(angle)
    space, bodies = _pile(seed, steps)
    readers, sums = _step_gathering(space, bodies, substeps)
    for body, reader, summed in zip(bodies, readers, sums, strict=True):
        expected = load_by_pymunk(body, ux, uy, DT, summed)
        load, touching = reader.load_and_touching(ux, uy, DT)
        assert _bits(load) == _bits(expected)
        assert touching is touching_by_pymunk(body)
        assert _bits(reader.load(ux, uy, DT)) == _bits(load_by_pymunk(body, ux, uy, DT))


def test_a_resting_body_reads_its_weight_at_any_substeps() -> None:
    """A box at rest on the floor: the load along −up over one step is its weight, m·g, at 1 to
    4 substeps (the last substep's impulse over the step would read m·g / substeps)."""
    for substeps in (1, 2, 3, 4):
        space = pymunk.Space()
        space.gravity = (0.0, -10.0)
        space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
        box = pymunk.Body(2.0, 1.0)
        box.position = (0.0, 0.5)
        space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
        # Settled at the substep's length (a new length rescales the warm starts: the first
        # substep at it reports an impulse it did not apply, see forces.contact_split).
        for _ in range(120 * substeps):
            space.step(DT / substeps)
        readers, _ = _step_gathering(space, [box], substeps)
        assert readers[0].load(0.0, -1.0, DT) == pytest.approx(20.0, rel=1e-9)


def test_without_cffi_callbacks_the_sums_ask_pymunk(monkeypatch: pytest.MonkeyPatch) -> None:
    space, bodies = _pile(3, 200)
    readers, _ = _step_gathering(space, bodies, 3)
    expected = [r.load(0.0, 1.0, DT) for r in readers]
    space2, bodies2 = _pile(3, 200)
    monkeypatch.setattr(contacts, "_load_callback", None)
    monkeypatch.setattr(contacts, "_summed_load_callback", None)
    monkeypatch.setattr(contacts, "_gather_callback", None)
    readers2, _ = _step_gathering(space2, bodies2, 3)
    assert [_bits(r.load(0.0, 1.0, DT)) for r in readers2] == [_bits(x) for x in expected]
