"""Bodies as the world accepts them: the checks that keep pymunk from aborting or carrying NaN,
and the groups of bodies Chipmunk puts to sleep together.

>>> check_size("size", (1.0, -2.0))
Traceback (most recent call last):
...
ValueError: size[1]: expected a length > 0 m, got -2.0
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TypeVar

import pymunk

from playground.limits import (
    MAX_ANGLE,
    MAX_ANGULAR_SPEED,
    MAX_COORDINATE,
    MAX_FORCE,
    MAX_LENGTH,
    MAX_MASS,
    MAX_MOMENT,
    MAX_SPEED,
    MIN_MASS,
    MIN_MOMENT,
)
from playground.params import bounded, bounded_vec, in_range

__all__ = ["check_body", "check_shapes", "check_size", "check_surface", "group", "surfaced"]


def check_surface(prefix: str, friction: float, elasticity: float) -> None:
    """Friction (Coulomb coefficient) in [0, 1000] and elasticity (restitution) in [0, 1]."""
    in_range(f"{prefix}friction", friction, 0.0, 1e3, "(Coulomb coefficient)")
    in_range(f"{prefix}elasticity", elasticity, 0.0, 1.0, "(restitution)")


S = TypeVar("S", bound=pymunk.Shape)


def surfaced(shape: S, friction: float, elasticity: float) -> S:
    """``shape`` with its friction and elasticity set (checked by :func:`check_surface`)."""
    shape.friction = friction
    shape.elasticity = elasticity
    return shape


def check_size(name: str, size: Sequence[float]) -> None:
    """A (w, h) of positive lengths, m, within the world's size."""
    bounded_vec(name, size, MAX_LENGTH, "m")
    for i, v in enumerate(size):
        if v <= 0.0:
            raise ValueError(f"{name}[{i}]: expected a length > 0 m, got {v!r}")


def check_body(name: str, body: pymunk.Body, shapes: Sequence[pymunk.Shape]) -> None:
    """Refuse what pymunk asserts on, aborts on or turns into NaN, before it sees it."""
    if not isinstance(body, pymunk.Body):
        raise ValueError(f"{name}: expected a pymunk.Body, got {body!r}")
    if body.space is not None:
        raise ValueError(f"{name}: the body is already in a space")
    if body.body_type == pymunk.Body.DYNAMIC:
        in_range(f"{name}.mass", body.mass, MIN_MASS, MAX_MASS, "kg")
        if body.moment != math.inf:
            in_range(f"{name}.moment", body.moment, MIN_MOMENT, MAX_MOMENT, "kg·m²")
    bounded_vec(f"{name}.position", tuple(body.position), MAX_COORDINATE, "m")
    bounded(f"{name}.angle", body.angle, MAX_ANGLE, "rad")
    bounded_vec(f"{name}.velocity", tuple(body.velocity), MAX_SPEED, "m/s")
    bounded(f"{name}.angular_velocity", body.angular_velocity, MAX_ANGULAR_SPEED, "rad/s")
    bounded_vec(f"{name}.force", tuple(body.force), MAX_FORCE, "N")
    check_shapes(name, body, shapes)


def check_shapes(name: str, body: pymunk.Body, shapes: Sequence[pymunk.Shape]) -> None:
    """Each shape belongs to ``body``, is in no space, and has a surface, radius and points in
    range (``name`` prefixes the errors)."""
    for i, shape in enumerate(shapes):
        where = f"{name}.shapes[{i}]"
        if not isinstance(shape, pymunk.Shape) or shape.body is not body:
            raise ValueError(f"{where}: expected a shape of this body, got {shape!r}")
        if shape.space is not None:
            raise ValueError(f"{where}: the shape is already in a space")
        check_surface(f"{where}.", shape.friction, shape.elasticity)
        in_range(f"{where}.radius", _radius(shape), 0.0, MAX_LENGTH, "m")
        for j, point in enumerate(_points(shape)):
            bounded_vec(f"{where}.points[{j}]", tuple(point), MAX_COORDINATE, "m (body frame)")


def _radius(shape: pymunk.Shape) -> float:
    if isinstance(shape, pymunk.Circle | pymunk.Segment | pymunk.Poly):
        return float(shape.radius)
    return 0.0


def _points(shape: pymunk.Shape) -> list[pymunk.Vec2d]:
    """A shape's defining points in the body's frame."""
    if isinstance(shape, pymunk.Circle):
        return [shape.offset]
    if isinstance(shape, pymunk.Segment):
        return [shape.a, shape.b]
    if isinstance(shape, pymunk.Poly):
        return list(shape.get_vertices())
    return []


def group(body: pymunk.Body) -> list[pymunk.Body]:
    """The dynamic bodies connected to ``body`` by contacts or joints, ``body`` first (static and
    kinematic bodies do not connect, as in Chipmunk's own sleeping). Only joints and bodies of
    ``body``'s space count: ``Body.constraints`` keeps a joint after it left the space, and the
    body at its other end may have left too (putting it to sleep raised pymunk's bare
    ``Exception('Body not added to space')``)."""
    space = body.space
    live = set(space.constraints) if space is not None else set()
    members = [body]
    seen = {body.id}
    k = 0
    while k < len(members):
        current = members[k]
        k += 1
        neighbours = _touching(current)
        neighbours.extend(b for c in current.constraints if c in live for b in (c.a, c.b))
        for other in neighbours:
            in_space = other.space is space
            if in_space and other.body_type == pymunk.Body.DYNAMIC and other.id not in seen:
                seen.add(other.id)
                members.append(other)
    return members


def _touching(body: pymunk.Body) -> list[pymunk.Body]:
    """The bodies of every arbiter of ``body`` (itself included)."""
    out: list[pymunk.Body] = []
    body.each_arbiter(lambda arb: out.extend(shape.body for shape in arb.shapes))
    return out
