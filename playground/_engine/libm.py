"""The C library's math over numpy arrays, element by element, with ``math``'s results bit for
bit: :func:`atan2`.

numpy's ``arctan2`` is not the C library's: on a CPU with AVX-512, numpy 2's SIMD loop gives
another last bit for about one pair in thirteen of [-1, 1]², and a crowd's law over arrays would
then differ from the same law of one controller in floats (``math.atan2``). Where the compiled
helper was built on install (:mod:`playground._engine._libm`, CPython's own ``math.atan2`` in a
C loop) one call does them all; without it :func:`atan2` maps ``math.atan2`` over the elements.
:data:`ATAN2_BY` says which path serves; both give ``math.atan2``'s results
(``tests/_engine/test_libm.py``).

>>> import math
>>> import numpy as np
>>> y, x = np.array([1.0, -0.0, 0.3]), np.array([-1.0, -2.0, 0.7])
>>> atan2(y, x).tolist() == [math.atan2(a, b) for a, b in zip(y.tolist(), x.tolist())]
True
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, Final, Literal

import numpy as np
from numpy.typing import NDArray

__all__ = ["ATAN2_BY", "atan2", "atan2_by_math"]


def _compiled() -> Callable[[Any, Any, Any], None] | None:
    try:
        from playground._engine import _libm
    except ImportError:
        return None
    return _libm.atan2


_atan2_c = _compiled()

ATAN2_BY: Final[Literal["compiled", "math"]] = "math" if _atan2_c is None else "compiled"
"""How :func:`atan2` runs, as the module was imported: ``"compiled"`` (the helper built on
install, one C call) or ``"math"`` (``math.atan2`` mapped over the elements)."""


def atan2_by_math(y: Any, x: Any) -> NDArray[np.float64]:
    """``math.atan2`` of each pair of ``y`` and ``x`` (arrays or floats, broadcast), rad: the
    reference :func:`atan2` answers as, and its path without the compiled helper."""
    yb, xb = np.broadcast_arrays(np.asarray(y, dtype=np.float64), np.asarray(x, dtype=np.float64))
    flat = map(math.atan2, yb.ravel().tolist(), xb.ravel().tolist())
    return np.fromiter(flat, np.float64, yb.size).reshape(yb.shape)


def atan2(y: Any, x: Any) -> NDArray[np.float64]:
    """``math.atan2(y, x)`` elementwise (arrays or floats, broadcast), rad."""
    if _atan2_c is None:
        return atan2_by_math(y, x)
    if isinstance(y, np.ndarray) and isinstance(x, np.ndarray) and y.shape == x.shape:
        # The common call: two arrays of one shape, read as they are where they are
        # C-contiguous float64 (the helper refuses anything else).
        out = np.empty(y.shape, dtype=np.float64)
        try:
            _atan2_c(y, x, out)
        except (TypeError, ValueError, BufferError):
            pass  # another dtype, or not C-contiguous (numpy says ValueError, others BufferError)
        else:
            return out
    yb, xb = np.broadcast_arrays(np.asarray(y, dtype=np.float64), np.asarray(x, dtype=np.float64))
    out = np.empty(yb.shape, dtype=np.float64)
    _atan2_c(np.ascontiguousarray(yb), np.ascontiguousarray(xb), out)
    return out
