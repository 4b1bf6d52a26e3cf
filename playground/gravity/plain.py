"""A gravity field that varies in space, body by body in plain floats, for a few bodies.

The gravity stage evaluates such a field once per step at every named dynamic body
(:meth:`GravityField.at <playground.gravity.GravityField.at>` on an (N, 2) array) and the batch
implementation of the tracked bodies adds the forces to its read of every body. For a few bodies
both cost more than the physics, so while the scalar implementation serves, the shipped kinds of
field are evaluated point by point (:func:`point_field`) with the same float operations in the
same order, and it adds each body's force to what it has. Forces agree with the vectorised ones
bit for bit (both apply a rule through :func:`playground.gravity.rule.ruled`). A field of another
kind is always evaluated vectorised.

>>> from playground.gravity import GravityRule, Radial
>>> body = pymunk.Body(2.0, 1.0)
>>> body.position = (0.0, 10.0)
>>> at = point_field(Radial(softening=0.0))
>>> at is not None and at(0.0, 10.0, 0.0)
(-0.0, -9.81)
>>> field = PlainField(at, [(body, 2.0, GravityRule(scale=0.5))])
>>> field.forces(0.0)[body]
(-0.0, -9.81)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import pymunk

from playground._engine import raw
from playground.gravity.field import GravityField, Radial, RotatingRoom, Uniform, Zones
from playground.gravity.rule import GravityRule, ruled
from playground.vec import Vec

__all__ = ["PlainField", "PointField", "point_field"]
PointField = Callable[[float, float, float], Vec]
"""Acceleration (m/s²) at the point (x, y) (m) at time t (s)."""


def point_field(field: GravityField) -> PointField | None:
    """``field`` as a function of one point in plain floats, or None for a kind it does not know
    (:class:`~playground.gravity.Uniform`, :class:`~playground.gravity.RotatingRoom`,
    :class:`~playground.gravity.Radial` and :class:`~playground.gravity.Zones` of these)."""
    if isinstance(field, Uniform):
        g = field.g
        return lambda x, y, t: g
    if isinstance(field, RotatingRoom):
        return lambda x, y, t: field.vector(t)
    if isinstance(field, Radial):
        return _radial(field)
    if isinstance(field, Zones):
        return _zones(field)
    return None


def _radial(field: Radial) -> PointField:
    """:meth:`Radial.at <playground.gravity.Radial.at>`, one point at a time."""
    cx, cy = field.center
    eps2 = field.softening**2
    gm = field.surface_gravity * field.radius**2

    def at(x: float, y: float, t: float) -> Vec:
        rx, ry = x - cx, y - cy
        d2 = rx * rx + ry * ry + eps2
        # Zero at the exact centre of an unsoftened planet (no direction to pull in).
        scale = -gm / (d2 * math.sqrt(d2)) if d2 > 0.0 else 0.0
        return (rx * scale, ry * scale)

    return at


def _zones(field: Zones) -> PointField | None:
    """:meth:`Zones.at <playground.gravity.Zones.at>`, one point at a time: the first zone
    containing the point wins."""
    base = point_field(field.base)
    zones = [(zone.box, point_field(zone.field)) for zone in field.zones]
    if base is None or any(f is None for _, f in zones):
        return None
    known = [(box, f) for box, f in zones if f is not None]

    def at(x: float, y: float, t: float) -> Vec:
        for (x0, y0, x1, y1), f in known:
            if x >= x0 and x <= x1 and y >= y0 and y <= y1:
                return f(x, y, t)
        assert base is not None
        return base(x, y, t)

    return at


class PlainField:
    """A field's force on each of a few bodies: (body, mass in kg, its rule) each, the masses as
    the world registered them."""

    __slots__ = ("_at", "_bodies")

    def __init__(
        self, at: PointField, bodies: Sequence[tuple[pymunk.Body, float, GravityRule]]
    ) -> None:
        self._at = at
        self._bodies = [(b, m, rule.scale, rule.direction) for b, m, rule in bodies]

    def forces(self, t: float) -> dict[pymunk.Body, Vec]:
        """The field's force on each body at time ``t`` (s) where it is now, N (the rule's
        scale and direction applied as :func:`~playground.gravity.apply_rules` does)."""
        at = self._at
        position = raw.position
        out: dict[pymunk.Body, Vec] = {}
        for body, m, scale, direction in self._bodies:
            x, y = position(raw.handle(body))
            gx, gy = at(x, y, t)
            gx, gy = ruled(gx, gy, scale, direction)
            out[body] = (gx * m, gy * m)
        return out
