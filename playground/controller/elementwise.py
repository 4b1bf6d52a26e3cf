"""The few operations the force laws need beyond + − × ÷, for plain floats (:data:`FLOATS`) and
for numpy arrays of many controllers at once (:data:`ARRAYS`), with the same results bit for bit:
a law written over ``ops`` serves one controller in floats and a crowd in arrays.

``ARRAYS.max(a, b)`` is Python's ``max(a, b)`` elementwise — ``a`` unless ``b > a`` — not
``np.maximum``, which gives −0.0 for ``max(0.0, −0.0)``; ``ARRAYS.atan2`` is ``math.atan2``
element by element (:func:`playground._engine.libm.atan2`), not ``np.arctan2``, whose SIMD loop
on a CPU with AVX-512 differs from libm in the last bit, and ``ARRAYS.hypot`` is
``math.hypot``'s, not ``np.hypot``'s (which rounds otherwise); ``np.cos`` and ``np.sin`` are
libm's (``tests/controller/test_elementwise.py`` checks each).

A branch of a law becomes :meth:`Ops.where` (a select, row by row), and its early return a
shortcut taken where :meth:`Ops.all` rows agree: one row for floats.

>>> FLOATS.max(0.0, -0.0), FLOATS.unless(True, 3.0), FLOATS.vector(0.0, 0.6, 0.8)
(0.0, 0.0, (0.0, 0.0))
>>> import numpy as np
>>> ARRAYS.max(np.array([0.0, 1.0]), np.array([-0.0, 2.0])).tolist()
[0.0, 2.0]
>>> FLOATS.where(False, 1.0, 2.0), ARRAYS.where(np.array([True, False]), 1.0, 2.0).tolist()
(2.0, [1.0, 2.0])
"""

from __future__ import annotations

import math
import operator
from typing import Any

import numpy as np

from playground._engine import libm
from playground.controller._vec import ZERO

__all__ = ["ARRAYS", "FLOATS", "Ops"]


class Ops:
    """Elementwise operations on floats (the base class) or arrays (:class:`_ArrayOps`)."""

    __slots__ = ()

    max: Any = staticmethod(max)
    """``a`` unless ``b > a`` (Python's ``max(a, b)``)."""
    min: Any = staticmethod(min)
    """``a`` unless ``b < a`` (Python's ``min(a, b)``)."""
    atan2: Any = staticmethod(math.atan2)
    """The angle of (x, y), rad (``atan2(y, x)``)."""
    hypot: Any = staticmethod(math.hypot)
    """The length of (x, y)."""
    cos: Any = staticmethod(math.cos)
    """The cosine of an angle, rad."""
    sin: Any = staticmethod(math.sin)
    """The sine of an angle, rad."""
    all: Any = staticmethod(bool)
    """Whether ``cond`` holds in every row (one row for floats)."""

    @staticmethod
    def where(cond: Any, a: Any, b: Any) -> Any:
        """``a`` where ``cond``, else ``b``."""
        return a if cond else b

    @staticmethod
    def unless(cond: Any, x: Any) -> Any:
        """0.0 where ``cond``, else ``x``."""
        return 0.0 if cond else x

    @staticmethod
    def vector(f: Any, tx: Any, ty: Any) -> Any:
        """The force ``f`` along (tx, ty): :data:`~playground.controller._vec.ZERO` itself where
        ``f`` is 0 (the laws' "no force")."""
        if f == 0.0:
            return ZERO
        return (f * tx, f * ty)


def _max(a: Any, b: Any) -> Any:
    return np.where(b > a, b, a)


def _min(a: Any, b: Any) -> Any:
    return np.where(b < a, b, a)


def _atan2(y: Any, x: Any) -> Any:
    # libm's atan2 on each pair (playground._engine.libm): numpy 2.4's float64 arctan2 on
    # AVX-512 (its SIMD loop) gives another last bit for about one pair in thirteen of [-1, 1]²,
    # and a crowd's balance torque would then differ from the same controller's alone.
    return libm.atan2(y, x)


def _hypot(x: Any, y: Any) -> Any:
    # math.hypot on each pair: CPython's own correctly rounded sum of squares, which np.hypot
    # (libm's hypot) misses in the last bit for about one pair in 170.
    xb, yb = np.broadcast_arrays(x, y)
    flat = map(math.hypot, xb.ravel().tolist(), yb.ravel().tolist())
    return np.array(list(flat), dtype=np.float64).reshape(xb.shape)


class _ArrayOps(Ops):
    __slots__ = ()

    max = staticmethod(_max)
    min = staticmethod(_min)
    atan2 = staticmethod(_atan2)
    hypot = staticmethod(_hypot)
    # numpy 2.4's float64 cos and sin give libm's bits here, unlike its arctan2 (the test
    # checks them, over all floats and densely over the angles a law turns by).
    cos = staticmethod(np.cos)
    sin = staticmethod(np.sin)
    # The array's own all(): np.all's Python wrapper costs as much again.
    all = staticmethod(operator.methodcaller("all"))

    @staticmethod
    def where(cond: Any, a: Any, b: Any) -> Any:
        return np.where(cond, a, b)

    @staticmethod
    def unless(cond: Any, x: Any) -> Any:
        return np.where(cond, 0.0, x)

    @staticmethod
    def vector(f: Any, tx: Any, ty: Any) -> Any:
        zero = f == 0.0
        return (np.where(zero, 0.0, f * tx), np.where(zero, 0.0, f * ty))


FLOATS = Ops()
"""The operations on plain floats: one controller."""
ARRAYS: Ops = _ArrayOps()
"""The operations on numpy arrays, one element per controller: a crowd."""
