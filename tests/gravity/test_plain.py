"""Laws of a field evaluated body by body: the plain-float form of each shipped kind of field
equals its vectorised ``at`` bit for bit, rules included."""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pytest
from numpy.typing import NDArray

from playground.gravity import (
    GravityField,
    GravityRule,
    Radial,
    RotatingRoom,
    Turn,
    Uniform,
    Zone,
    Zones,
)
from playground.gravity.plain import PlainField, point_field

FIELDS: dict[str, GravityField] = {
    "uniform": Uniform((0.3, -9.81)),
    "rotating": RotatingRoom(angle=-1.0, rate=0.7, turns=(Turn(0.5, math.pi, 1.0),)),
    "radial": Radial(center=(1.0, -2.0), surface_gravity=9.81, radius=5.0, softening=0.5),
    "radial unsoftened": Radial(center=(0.0, 0.0), softening=0.0),
    "zones": Zones(
        Radial(center=(0.0, -30.0), radius=30.0),
        (
            Zone((-2.0, -2.0, 2.0, 2.0), Uniform((0.0, 9.81))),
            Zone((0.0, 0.0, 5.0, 5.0), RotatingRoom(rate=1.0)),
        ),
    ),
}


def _points() -> NDArray[np.float64]:
    rng = np.random.default_rng(7)
    pts = rng.uniform(-8.0, 8.0, (2000, 2))
    # The exact centre, zone edges and corners.
    return np.vstack([pts, [[0.0, 0.0], [1.0, -2.0], [2.0, 0.0], [0.0, 5.0], [-2.0, -2.0]]])


@pytest.mark.parametrize("name", sorted(FIELDS))
def test_the_point_form_equals_the_vectorised_field(name: str) -> None:
    """Law: at every point and time, the plain-float form gives the floats ``at`` gives."""
    field = FIELDS[name]
    at = point_field(field)
    assert at is not None
    pts = _points()
    for t in (0.0, 1.0, 7.3):
        want = field.at(pts, t)
        got = np.array([at(float(x), float(y), t) for x, y in pts])
        assert np.array_equal(got, want), name


def test_a_field_of_another_kind_has_no_point_form() -> None:
    """Law: a user's field (or zones holding one) is left to the batch implementation."""

    class Tilted:
        uniform = False

        def at(self, points: NDArray[np.float64], t: float) -> NDArray[np.float64]:
            return np.zeros_like(points)

    assert point_field(Tilted()) is None
    assert point_field(Zones(Uniform(), (Zone((0.0, 0.0, 1.0, 1.0), Tilted()),))) is None


def _body(x: float, y: float) -> pymunk.Body:
    body = pymunk.Body(2.0, 1.0)
    body.position = (x, y)
    return body


def test_forces_are_mass_times_the_ruled_field_where_each_body_is() -> None:
    """Law: each body's force is its mass times the field at its position with its rule."""
    field = Radial(softening=0.0)
    at = point_field(field)
    assert at is not None
    a, b = _body(0.0, 10.0), _body(20.0, 0.0)
    plain = PlainField(at, [(a, 2.0, GravityRule()), (b, 2.0, GravityRule(direction=(0.0, 1.0)))])
    forces = plain.forces(0.0)
    assert forces[a] == (-0.0, 2.0 * -9.81)
    assert forces[b] == (0.0, 2.0 * 2.4525)
