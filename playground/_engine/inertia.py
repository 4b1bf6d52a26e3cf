"""Plumbing under pymunk's ``body.mass`` and ``body.moment``: the mass and moment of inertia of
many bodies read in one call, every step (a game may change them at any time).

Where the optional compiled helper was built on install (:mod:`playground._engine._inertia`, a
small C extension), one C call reads them all through Chipmunk's own getters
(``cpBodyGetMass``, ``cpBodyGetMoment``, the ones pymunk's properties call); without it each is
read through cffi (:func:`playground._engine.raw.mass`, :func:`~playground._engine.raw.moment`),
two calls a body. Both read the very doubles the properties read (``tests/_engine/
test_inertia.py``); :data:`INERTIA_BY` says which path serves. Like :mod:`playground._engine.raw`
this reaches into pymunk's private ``_chipmunk_cffi`` (pymunk's major version is pinned).

>>> import pymunk
>>> a, b = pymunk.Body(2.0, 0.5), pymunk.Body(70.0, 1.25)
>>> mass, moment = Inertia([a, b]).read()
>>> mass.tolist(), moment.tolist()
([2.0, 70.0], [0.5, 1.25])
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, Final, Literal

import numpy as np
import pymunk
from numpy.typing import NDArray
from pymunk._chipmunk_cffi import ffi, lib

from playground._engine import raw

__all__ = ["INERTIA_BY", "Inertia"]

# What the compiled helper declares of Chipmunk (playground/_engine/_inertia.c), as pymunk's cffi
# names it: the helper is used only if pymunk declares the very same getters.
_DECLARED_IN_C: Final = ("double(*)(struct cpBody *)", "double(*)(struct cpBody *)")


def _declared() -> tuple[str, str]:
    """pymunk's cffi declarations of the getters the compiled helper calls."""
    return ffi.typeof(lib.cpBodyGetMass).cname, ffi.typeof(lib.cpBodyGetMoment).cname


def _address(pointer: Any) -> int:
    """A cffi pointer (or a C function of pymunk's lib) as an int."""
    return int(ffi.cast("uintptr_t", pointer))


def _compiled_helper() -> Callable[[int, int, Any, Any], None] | None:
    """The compiled helper's ``mass_moment``, if it was built and matches pymunk's
    declarations, else None."""
    try:
        from playground._engine import _inertia
    except ImportError:
        return None
    return _inertia.mass_moment if _declared() == _DECLARED_IN_C else None


_mass_moment = _compiled_helper()
_MASS_ADDRESS = _address(ffi.addressof(lib, "cpBodyGetMass"))
_MOMENT_ADDRESS = _address(ffi.addressof(lib, "cpBodyGetMoment"))

INERTIA_BY: Final[Literal["compiled", "cffi"]] = "cffi" if _mass_moment is None else "compiled"
"""How :meth:`Inertia.read` runs, as the module was imported: ``"compiled"`` (the helper built
on install, one C call for all) or ``"cffi"`` (the getters through cffi, two calls a body)."""


class Inertia:
    """The mass (kg) and moment of inertia (kg·m²) of a fixed list of bodies, read in one call
    (:meth:`read`). It keeps the bodies' ``cpBody*`` handles, so they live as long as it does."""

    __slots__ = ("_addresses", "_handles")

    def __init__(self, bodies: Sequence[pymunk.Body]) -> None:
        self._handles = [raw.handle(b) for b in bodies]
        self._addresses = np.array([_address(h) for h in self._handles], dtype=np.uintp)

    def read(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Each body's mass and moment now, in the list's order: new arrays each call (a
        caller may keep them)."""
        n = len(self._handles)
        if _mass_moment is None:
            return read_by_cffi(self._handles)
        out = np.empty((2, n))
        _mass_moment(_MASS_ADDRESS, _MOMENT_ADDRESS, self._addresses, out)
        return out[0], out[1]


def read_by_cffi(handles: Sequence[raw.Handle]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The mass (kg) and moment (kg·m²) of the bodies of ``handles`` (:func:`raw.handle`), each
    through its cffi getter: :meth:`Inertia.read` without the compiled helper."""
    n = len(handles)
    mass = np.fromiter(map(raw.mass, handles), np.float64, n)
    moment = np.fromiter(map(raw.moment, handles), np.float64, n)
    return mass, moment
