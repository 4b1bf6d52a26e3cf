"""A body's contacts read through Chipmunk's arbiter iteration give pymunk's answers bit for bit:
the load pressing along a direction (the same terms summed in the same order) and the touch."""

from __future__ import annotations

import math
import random
import struct

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import contacts
from playground._engine.contacts import Contacts, load_by_pymunk, touching_by_pymunk

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
