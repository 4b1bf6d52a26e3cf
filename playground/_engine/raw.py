"""Plumbing under pymunk's properties: one body's state, the space's gravity and a body's
arbiters read (and forces written) through Chipmunk's C functions directly, for the per-step hot
paths of a few bodies.

A pymunk property is a Python function that calls the C getter and wraps the result: most of
reading ``body.velocity`` is the wrapping (a ``Vec2d``), and ``body.id`` is a cast of the
user-data pointer (docs/performance.md, "The small costs", rows velocity and body_key). On a
one-player level the controller and the tracked bodies' scalar implementation read a dozen such
values a step, which is most of their bill.
These functions call the same C getters and setters pymunk's properties call, so they read and
write the very same doubles (``tests/_engine/test_raw.py`` checks them against the properties,
bit for bit, so an upgrade of pymunk that changed its internals fails there, not in a trajectory).

They take a body's *handle* (:func:`handle`, the ``cpBody*`` pymunk keeps), not the body; a
body's arbiters are iterated with a C callback that gets the arbiter's handle (no ``Arbiter``
object, no ``Vec2d``; docs/performance.md, contacts). This
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

import types
from collections.abc import Callable
from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

__all__ = [
    "NULL",
    "ArbiterHandle",
    "Handle",
    "angle",
    "angular_velocity",
    "arbiter_body_ids",
    "arbiter_callback",
    "arbiter_handle",
    "arbiter_impulse",
    "arbiter_shape_key",
    "body_id",
    "body_type",
    "c_callback",
    "c_callback_code",
    "centre_of_gravity",
    "collision_persistence",
    "current_time_step",
    "each_arbiter",
    "force",
    "get_force",
    "get_velocity",
    "gravity",
    "handle",
    "is_first_contact",
    "is_sleeping",
    "mass",
    "moment",
    "position",
    "rotation",
    "set_angular_velocity",
    "set_force",
    "set_torque",
    "set_velocity",
    "space_handle",
    "torque",
    "velocity",
]

Handle = Any
"""A ``cpBody*`` or a ``cpSpace*`` (a cffi pointer; untyped)."""
ArbiterHandle = Any
"""A ``cpArbiter*``, valid only inside the callback it is given to."""

_get_velocity = lib.cpBodyGetVelocity
_get_position = lib.cpBodyGetPosition
_get_rotation = lib.cpBodyGetRotation
_get_force = lib.cpBodyGetForce
_set_force = lib.cpBodySetForce
_set_velocity = lib.cpBodySetVelocity
_get_user_data = lib.cpBodyGetUserData
_get_cog = lib.cpBodyGetCenterOfGravity
_local_to_world = lib.cpBodyLocalToWorld
_get_gravity = lib.cpSpaceGetGravity
_total_impulse = lib.cpArbiterTotalImpulse
_normal = lib.cpArbiterGetNormal
_get_bodies = lib.cpArbiterGetBodies
_get_shapes = lib.cpArbiterGetShapes
_cast = ffi.cast
_new_callback = ffi.callback
_new = ffi.new

angle: Callable[[Handle], float] = lib.cpBodyGetAngle
"""``angle(h)``: the body's angle, rad."""
set_angular_velocity: Callable[[Handle, float], None] = lib.cpBodySetAngularVelocity
"""``set_angular_velocity(h, w)``: set the body's angular velocity, rad/s (wakes it, as
``body.angular_velocity = ...`` does)."""
get_velocity: Callable[[Handle], Any] = lib.cpBodyGetVelocity
"""``get_velocity(h)``: the body's velocity as Chipmunk's ``cpVect`` (read ``.x`` and ``.y`` at
once, m/s): :func:`velocity` without building a tuple, for the hottest loops."""
get_force: Callable[[Handle], Any] = lib.cpBodyGetForce
"""``get_force(h)``: the force set on the body for the coming step as a ``cpVect`` (N)."""
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
current_time_step: Callable[[Handle], float] = lib.cpSpaceGetCurrentTimeStep
"""``current_time_step(s)``: the length of the space's last step (``space.current_time_step``), s,
of a space handle (:func:`space_handle`)."""
collision_persistence: Callable[[Handle], int] = lib.cpSpaceGetCollisionPersistence
"""``collision_persistence(s)``: steps an arbiter outlives its contact
(``space.collision_persistence``), of a space handle."""
is_sleeping: Callable[[Handle], int] = lib.cpBodyIsSleeping
"""``is_sleeping(h)``: non-zero if the body sleeps (``body.is_sleeping``)."""
set_torque: Callable[[Handle, float], None] = lib.cpBodySetTorque
"""``set_torque(h, t)``: set the body's torque for the coming step, N·m (wakes it, as
``body.torque = ...`` does)."""


def handle(body: pymunk.Body) -> Handle:
    """The body's ``cpBody*``, valid as long as the body lives."""
    return body._body


def space_handle(space: pymunk.Space) -> Handle:
    """The space's ``cpSpace*``, valid as long as the space lives."""
    return space._space


def body_id(body: pymunk.Body) -> int:
    """``body.id`` (the int pymunk.batch reports for the body), without the property's cost."""
    return int(_cast("uintptr_t", _get_user_data(body._body)))


def velocity(h: Handle) -> tuple[float, float]:
    """The body's velocity, m/s."""
    v = _get_velocity(h)
    return v.x, v.y


def gravity(s: Handle) -> tuple[float, float]:
    """The space's gravity (``space.gravity``) of a space handle (:func:`space_handle`), m/s²."""
    g = _get_gravity(s)
    return g.x, g.y


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


def set_velocity(h: Handle, vx: float, vy: float) -> None:
    """Set the body's velocity, m/s (wakes it, as ``body.velocity = ...`` does)."""
    _set_velocity(h, (vx, vy))


def set_force(h: Handle, fx: float, fy: float) -> None:
    """Set the body's force for the coming step, N (wakes it, as ``body.force = ...`` does)."""
    _set_force(h, (fx, fy))


# -- a body's arbiters ---------------------------------------------------------------------------

NULL = ffi.NULL
"""The null pointer, for the ``data`` argument of :func:`each_arbiter`."""

each_arbiter: Callable[[Handle, Any, Any], None] = lib.cpBodyEachArbiter
"""``each_arbiter(h, callback, NULL)``: call ``callback`` (:func:`arbiter_callback`) on each
arbiter of the body, in the order ``Body.each_arbiter`` gives them and, as there, presented from
the body's side (its impulse is the one the body received; the normal points away from it)."""

is_first_contact: Callable[[ArbiterHandle], int] = lib.cpArbiterIsFirstContact
"""``is_first_contact(arb)``: non-zero on the first step the shapes touch
(``arbiter.is_first_contact``)."""


def arbiter_callback(visit: Callable[[Handle, ArbiterHandle, Any], None]) -> Any:
    """A C callback for :func:`each_arbiter` that calls ``visit(body, arb, data)`` with the
    handles, or None where the platform refuses cffi callbacks (memory both writable and
    executable): then iterate with ``Body.each_arbiter`` and :func:`arbiter_handle`. Keep it as
    long as it is used. ``visit`` must not raise: an exception in a C callback is printed, not
    raised (read plain values only, as pymunk's own callbacks do)."""
    return c_callback("void(cpBody *, cpArbiter *, void *)", visit)


_C_CALLBACK_CODE: set[types.CodeType] = set()
"""The code of every function called back from C through :func:`c_callback`."""


def c_callback(c_type: str, keep: Callable[..., None]) -> Any:
    """A C callback of type ``c_type`` that calls ``keep``, or None where the platform refuses
    cffi callbacks (memory both writable and executable): the callers then fall back to pymunk's
    own iteration or query."""
    code = getattr(keep, "__code__", None)
    if isinstance(code, types.CodeType):
        _C_CALLBACK_CODE.add(code)
    try:
        return _new_callback(c_type, keep)
    except (
        MemoryError,
        RuntimeError,
    ):  # a platform without cffi callbacks (tests/_engine/test_raw.py)
        return None


def c_callback_code(code: types.CodeType) -> bool:
    """Whether ``code`` is a function that C calls back through :func:`c_callback`: an exception
    raised there is printed and dropped by cffi, never seen by the caller (a Ctrl-C handler
    waits until Python is out of it)."""
    return code in _C_CALLBACK_CODE


def arbiter_handle(arb: pymunk.Arbiter) -> ArbiterHandle:
    """The ``cpArbiter*`` of an arbiter pymunk gives a callback, valid only inside it."""
    return arb._arbiter


def arbiter_impulse(arb: ArbiterHandle) -> tuple[float, float, float, float]:
    """(jx, jy, nx, ny): ``arbiter.total_impulse`` (N·s) and ``arbiter.normal`` of an arbiter
    seen from the iterated body's side."""
    j = _total_impulse(arb)
    n = _normal(arb)
    return j.x, j.y, n.x, n.y


def arbiter_body_ids(arb: ArbiterHandle) -> tuple[int, int]:
    """The ``id`` of each of the arbiter's bodies (``arbiter.bodies``), in that order."""
    a = _new("cpBody *[1]")
    b = _new("cpBody *[1]")
    _get_bodies(arb, a, b)
    return (
        int(_cast("uintptr_t", _get_user_data(a[0]))),
        int(_cast("uintptr_t", _get_user_data(b[0]))),
    )


_shape_a = _new("cpShape *[1]")
_shape_b = _new("cpShape *[1]")


def arbiter_shape_key(arb: ArbiterHandle) -> tuple[int, int]:
    """The addresses of the arbiter's two shapes (``arbiter.shapes``), in that order: the same
    pair names the same contact in every substep of a step (a new ``cpArbiter`` may reuse a
    freed one's memory, its shapes' addresses stay theirs while they live)."""
    _get_shapes(arb, _shape_a, _shape_b)
    return int(_cast("uintptr_t", _shape_a[0])), int(_cast("uintptr_t", _shape_b[0]))
