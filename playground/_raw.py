"""Plumbing under pymunk's properties: one body's state read and written through Chipmunk's C
functions directly, for the per-step hot paths of a few bodies.

A pymunk property is a Python function that calls the C getter and wraps the result: reading
``body.velocity`` costs ~0.5 µs, of which the C call is ~0.1 µs and the rest the wrapping (a
``Vec2d``), ``body.id`` ~0.45 µs (a cast of the user-data pointer). On a one-player level the
controller and the scalar path read a dozen such values a step, which is most of their bill.
These functions call the same C getters and setters pymunk's properties call, so they read and
write the very same doubles (``tests/test_raw.py`` checks them against the properties, bit for
bit, so an upgrade of pymunk that changed its internals fails there, not in a trajectory).

They take a body's *handle* (:func:`handle`, the ``cpBody*`` pymunk keeps), not the body. This
reaches into pymunk's private ``_body`` and ``_chipmunk_cffi``: pymunk's major version is pinned
(``pymunk>=7.3,<8``) for its batch API, which is experimental in the same way.

>>> import pymunk
>>> body = pymunk.Body(2.0, 1.0)
>>> body.velocity = (1.5, -0.25)
>>> velocity(handle(body)) == tuple(body.velocity)
True
>>> set_force(handle(body), 3.0, 4.0); tuple(body.force)
(3.0, 4.0)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

__all__ = [
    "Handle",
    "angular_velocity",
    "body_id",
    "body_type",
    "centre_of_gravity",
    "force",
    "handle",
    "mass",
    "moment",
    "position",
    "rotation",
    "set_force",
    "set_torque",
    "torque",
    "velocity",
]

Handle = Any
"""A ``cpBody*`` (a cffi pointer; untyped)."""

_get_velocity = lib.cpBodyGetVelocity
_get_position = lib.cpBodyGetPosition
_get_rotation = lib.cpBodyGetRotation
_get_force = lib.cpBodyGetForce
_set_force = lib.cpBodySetForce
_set_torque = lib.cpBodySetTorque
_get_user_data = lib.cpBodyGetUserData
_get_cog = lib.cpBodyGetCenterOfGravity
_local_to_world = lib.cpBodyLocalToWorld
_cast = ffi.cast

angular_velocity: Callable[[Handle], float] = lib.cpBodyGetAngularVelocity
"""``angular_velocity(h)``: the body's angular velocity, rad/s."""
torque: Callable[[Handle], float] = lib.cpBodyGetTorque
"""``torque(h)``: the torque set on the body for the coming step, N·m."""
mass: Callable[[Handle], float] = lib.cpBodyGetMass
"""``mass(h)``: the body's mass, kg."""
moment: Callable[[Handle], float] = lib.cpBodyGetMoment
"""``moment(h)``: the body's moment of inertia, kg·m²."""
body_type: Callable[[Handle], int] = lib.cpBodyGetType
"""``body_type(h)``: ``pymunk.Body.DYNAMIC``, ``KINEMATIC`` or ``STATIC`` (ints)."""


def handle(body: pymunk.Body) -> Handle:
    """The body's ``cpBody*``, valid as long as the body lives."""
    return body._body


def body_id(body: pymunk.Body) -> int:
    """``body.id`` (the int pymunk.batch reports for the body), without the property's cost."""
    return int(_cast("uintptr_t", _get_user_data(body._body)))


def velocity(h: Handle) -> tuple[float, float]:
    """The body's velocity, m/s."""
    v = _get_velocity(h)
    return v.x, v.y


def position(h: Handle) -> tuple[float, float]:
    """The body's position (the origin of its own frame, in world coordinates), m."""
    p = _get_position(h)
    return p.x, p.y


def rotation(h: Handle) -> tuple[float, float]:
    """(cos, sin) of the body's angle: ``body.rotation_vector``."""
    r = _get_rotation(h)
    return r.x, r.y


def centre_of_gravity(h: Handle) -> tuple[float, float]:
    """The body's centre of gravity in world coordinates, m:
    ``body.local_to_world(body.center_of_gravity)`` (the same C calls, no Vec2d between them)."""
    c = _local_to_world(h, _get_cog(h))
    return c.x, c.y


def force(h: Handle) -> tuple[float, float]:
    """The force set on the body for the coming step, N."""
    f = _get_force(h)
    return f.x, f.y


def set_force(h: Handle, fx: float, fy: float) -> None:
    """Set the body's force for the coming step, N (wakes it, as ``body.force = ...`` does)."""
    _set_force(h, (fx, fy))


def set_torque(h: Handle, t: float) -> None:
    """Set the body's torque for the coming step, N·m (wakes it, as ``body.torque = ...``)."""
    _set_torque(h, t)
