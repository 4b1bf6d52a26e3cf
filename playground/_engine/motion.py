"""Plumbing under pymunk's ``body.velocity``, ``body.angular_velocity``, ``body.force`` and
``body.torque``: a fixed list of bodies' motion read in one call, as plain floats, for the
scalar implementation of the tracked bodies (before each step and after each substep).

Where the optional compiled helper was built on install (:mod:`playground._engine._motion`, a
small C extension), one C call reads every body through Chipmunk's own getters
(``cpBodyGetVelocity``, ``cpBodyGetAngularVelocity``, ``cpBodyGetForce``, ``cpBodyGetTorque``,
the ones pymunk's properties call); without it each is read through cffi
(:mod:`playground._engine.raw`), two to four calls a body, each releasing and taking back the
GIL. Both read the very doubles the properties read (``tests/_engine/test_motion.py``);
:data:`MOTION_BY` says which path serves. Like :mod:`playground._engine.raw` this reaches into
pymunk's private ``_chipmunk_cffi`` (pymunk's major version is pinned).

>>> import pymunk
>>> a, b = pymunk.Body(2.0, 0.5), pymunk.Body(70.0, 1.25)
>>> a.velocity, b.angular_velocity, b.force = (1.5, -0.25), 2.0, (0.0, -686.7)
>>> motions = Motions([a, b])
>>> motions.velocities()
[(1.5, -0.25, 0.0), (0.0, 0.0, 2.0)]
>>> motions.velocities_and_forces()[1]
(0.0, 0.0, 2.0, 0.0, -686.7, 0.0)
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Sequence
from typing import Any, Final, Literal

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

from playground._engine import raw

__all__ = [
    "MOTION_BY",
    "Motion",
    "Motions",
    "Velocity",
    "velocities_and_forces_by_cffi",
    "velocities_by_cffi",
]

Velocity = tuple[float, float, float]
"""(vx, vy, w): a body's velocity (m/s) and angular velocity (rad/s)."""
Motion = tuple[float, float, float, float, float, float]
"""(vx, vy, w, fx, fy, t): :data:`Velocity` and the force (N) and torque (N·m) set on the body
for the coming step."""

# What the compiled helper declares of Chipmunk (playground/_engine/_motion.c), as pymunk's cffi
# names it: the helper is used only if pymunk declares the very same getters and vector.
_VECT: Final = "struct cpVect(*)(struct cpBody *)"
_FLOAT: Final = "double(*)(struct cpBody *)"
_DECLARED_IN_C: Final = ((_VECT, _FLOAT, _VECT, _FLOAT), (("x", "double"), ("y", "double")))

_GETTERS: Final = ("cpBodyGetVelocity", "cpBodyGetAngularVelocity", "cpBodyGetForce",
                   "cpBodyGetTorque")  # fmt: skip

_ADDRESS: Final = next(c for c in "LQ" if array(c).itemsize == ffi.sizeof("void *"))
"""The array typecode of a C pointer."""


def _declared() -> tuple[tuple[str, ...], tuple[tuple[str, str], ...]]:
    """pymunk's cffi declarations of the getters the compiled helper calls, and of ``cpVect``."""
    getters = tuple(ffi.typeof(getattr(lib, name)).cname for name in _GETTERS)
    vect = ffi.typeof("cpVect")
    return getters, tuple((name, f.type.cname) for name, f in vect.fields or ())


def _address(pointer: Any) -> int:
    """A cffi pointer (or a C function of pymunk's lib) as an int."""
    return int(ffi.cast("uintptr_t", pointer))


def _compiled_helper() -> Callable[..., list[Any]] | None:
    """The compiled helper's ``motion``, if it was built and matches pymunk's declarations,
    else None."""
    try:
        from playground._engine import _motion
    except ImportError:
        return None
    return _motion.motion if _declared() == _DECLARED_IN_C else None


_motion = _compiled_helper()
_VELOCITY, _ANGULAR_VELOCITY, _FORCE, _TORQUE = (
    _address(ffi.addressof(lib, name)) for name in _GETTERS
)

MOTION_BY: Final[Literal["compiled", "cffi"]] = "cffi" if _motion is None else "compiled"
"""How :class:`Motions` reads, as the module was imported: ``"compiled"`` (the helper built on
install, one C call for all) or ``"cffi"`` (the getters through cffi, a body at a time)."""


class Motions:
    """The motion of a fixed list of bodies, read in one call. It keeps the bodies' ``cpBody*``
    handles, so they live as long as it does."""

    __slots__ = ("_addresses", "_handles")

    def __init__(self, bodies: Sequence[pymunk.Body]) -> None:
        self._handles = [raw.handle(b) for b in bodies]
        self._addresses = array(_ADDRESS, [_address(h) for h in self._handles])

    def velocities(self) -> list[Velocity]:
        """Each body's (vx, vy, w) now, in the list's order: a new list."""
        if _motion is None:
            return velocities_by_cffi(self._handles)
        velocities: list[Velocity] = _motion(
            _VELOCITY, _ANGULAR_VELOCITY, _FORCE, _TORQUE, self._addresses, False
        )
        return velocities

    def velocities_and_forces(self) -> list[Motion]:
        """Each body's (vx, vy, w, fx, fy, t) now, in the list's order: a new list."""
        if _motion is None:
            return velocities_and_forces_by_cffi(self._handles)
        motion: list[Motion] = _motion(
            _VELOCITY, _ANGULAR_VELOCITY, _FORCE, _TORQUE, self._addresses, True
        )
        return motion


def velocities_by_cffi(handles: Sequence[raw.Handle]) -> list[Velocity]:
    """(vx, vy, w) of the bodies of ``handles`` (:func:`raw.handle`), each through its cffi
    getters: :meth:`Motions.velocities` without the compiled helper."""
    get_velocity, angular_velocity = raw.get_velocity, raw.angular_velocity
    out = []
    for h in handles:
        v = get_velocity(h)
        out.append((v.x, v.y, angular_velocity(h)))
    return out


def velocities_and_forces_by_cffi(handles: Sequence[raw.Handle]) -> list[Motion]:
    """(vx, vy, w, fx, fy, t) of the bodies of ``handles``, each through its cffi getters:
    :meth:`Motions.velocities_and_forces` without the compiled helper."""
    get_velocity, angular_velocity = raw.get_velocity, raw.angular_velocity
    get_force, torque = raw.get_force, raw.torque
    out = []
    for h in handles:
        v = get_velocity(h)
        f = get_force(h)
        out.append((v.x, v.y, angular_velocity(h), f.x, f.y, torque(h)))
    return out
