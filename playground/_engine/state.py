"""A body's state and the space's gravity read through Chipmunk's C getters in one call, as
plain floats: what a controller needs of its own body (:func:`body_state`), of the ground under
it (:func:`body_motion`, :func:`centre_of_gravity`, :func:`radius_of_gyration`, :func:`jointed`)
and of the space (:func:`space_gravity`), without a pymunk property's ``Vec2d``.

Each function reads the very doubles pymunk's properties read (``tests/_engine/test_state.py``
compares them, and what it computes from them, bit for bit).

>>> import pymunk
>>> body = pymunk.Body(2.0, 1.0)
>>> body.velocity = (1.5, -0.25)
>>> s = body_state(body)
>>> (s.vx, s.vy, s.mass, s.cos, s.sin)
(1.5, -0.25, 2.0, 1.0, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pymunk
from pymunk._chipmunk_cffi import lib

from playground._engine import raw
from playground.vec import Vec

__all__ = [
    "BodyState",
    "body_motion",
    "body_state",
    "centre_of_gravity",
    "jointed",
    "radius_of_gyration",
    "space_gravity",
]


@dataclass(slots=True)
class BodyState:
    """A body's state now (a plain value; read-only by convention, not frozen: one is built
    every control step and a frozen dataclass is dearer to build: docs/performance.md,
    plain_dataclass).

    Attributes:
        x, y: position (the origin of its own frame, in world coordinates), m.
        vx, vy: velocity, m/s.
        cos, sin: cosine and sine of its angle (``body.rotation_vector``).
        spin: angular velocity, rad/s (counter-clockwise).
        mass: kg.
        moment: moment of inertia, kg·m² (infinite for a body that never turns).
    """

    x: float
    y: float
    vx: float
    vy: float
    cos: float
    sin: float
    spin: float
    mass: float
    moment: float


# The C getters pymunk's properties call (see playground._engine.raw).
_position = lib.cpBodyGetPosition
_velocity = lib.cpBodyGetVelocity
_rotation = lib.cpBodyGetRotation
_angular_velocity = lib.cpBodyGetAngularVelocity
_mass = lib.cpBodyGetMass
_moment = lib.cpBodyGetMoment
_body_type = lib.cpBodyGetType
_gravity = lib.cpSpaceGetGravity


def body_state(body: pymunk.Body) -> BodyState:
    """The body's position, velocity, rotation, spin, mass and moment now."""
    h = body._body
    p = _position(h)
    v = _velocity(h)
    r = _rotation(h)
    return BodyState(p.x, p.y, v.x, v.y, r.x, r.y, _angular_velocity(h), _mass(h), _moment(h))


def body_motion(body: pymunk.Body) -> tuple[int, float, float, float]:
    """The body's type (``pymunk.Body.DYNAMIC``, ``KINEMATIC`` or ``STATIC``), its velocity
    (m/s) and its angular velocity (rad/s): ``(type, vx, vy, spin)``."""
    h = body._body
    v = _velocity(h)
    return _body_type(h), v.x, v.y, _angular_velocity(h)


def radius_of_gyration(body: pymunk.Body) -> float:
    """A dynamic body's radius of gyration √(I/m), m: how far from its centre of gravity its
    whole mass would have its moment of inertia (a slab w wide and h thick: √((w² + h²)/12)).

    >>> round(radius_of_gyration(pymunk.Body(3.0, 3.0 * (0.25**2 + 0.05**2) / 12.0)), 4)
    0.0736
    """
    h = body._body
    return math.sqrt(_moment(h) / _mass(h))


def jointed(body: pymunk.Body) -> bool:
    """Whether a joint (a pymunk constraint) holds the body to another one.

    >>> jointed(pymunk.Body(1.0, 1.0))
    False
    """
    return bool(body.constraints)


def centre_of_gravity(body: pymunk.Body) -> Vec:
    """The body's centre of gravity in world coordinates, m."""
    return raw.centre_of_gravity(body._body)


def space_gravity(space: pymunk.Space) -> Vec:
    """The space's gravity (``space.gravity``), m/s²."""
    g = _gravity(space._space)
    return g.x, g.y
