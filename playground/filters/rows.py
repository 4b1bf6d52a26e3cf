"""How the filters hold rows of k-vectors: sample forms, packed storage, parameter and row checks.

A sample is a float, a k-vector or (N, k) rows (see :mod:`playground.filters.row_filter`);
:func:`as_rows` turns it into (N, k) rows and :func:`shaped` gives an output back in the
sample's form. :class:`Layout` stores the rows flat so that per-row factors broadcast cheaply.

>>> rows, form = as_rows([3.0, 4.0])
>>> rows.shape, Layout(2).norm(Layout(2).pack(rows)).tolist()
((1, 2), [5.0])
>>> shaped(rows, form).tolist()
[3.0, 4.0]
"""

from __future__ import annotations

import math
from typing import Any, Final

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "BoolArray",
    "FloatArray",
    "IndexArray",
    "Layout",
    "Packed",
    "as_rows",
    "check_param",
    "finite_rows",
    "reindexed",
    "row_index",
    "shaped",
]

FloatArray = NDArray[np.float64]
BoolArray = NDArray[np.bool_]
IndexArray = NDArray[np.intp]
# Rows as stored internally: see Layout (float or complex, 1-D or 2-D).
Packed = NDArray[Any]

# Forms of an input sample, remembered so the output comes back in the same form.
_SCALAR: Final = 0
_VECTOR: Final = 1
_ROWS: Final = 2


def check_param(name: str, value: float, expected: str, *, strictly_positive: bool) -> float:
    """Return ``value`` as a float, or raise ``ValueError`` naming the parameter."""
    v = float(value)
    if not math.isfinite(v) or v < 0.0 or (strictly_positive and v == 0.0):
        raise ValueError(f"{name}: expected {expected}, got {value!r}")
    return v


def as_rows(x: float | ArrayLike) -> tuple[FloatArray, int]:
    """Return ``x`` as an (N, k) float64 array (a view when possible) and its input form."""
    a = np.asarray(x, dtype=np.float64)
    if a.ndim == 0:
        return a.reshape(1, 1), _SCALAR
    if a.ndim > 2 or a.shape[-1] == 0:
        raise ValueError(
            f"x: expected a float, a k-vector (k,) or rows of k-vectors (N, k) with k >= 1, "
            f"got shape {a.shape}"
        )
    if a.ndim == 1:
        return a.reshape(1, -1), _VECTOR
    return a, _ROWS


def shaped(out: FloatArray, form: int) -> float | FloatArray:
    """Give ``out`` (N, k) back in the form of the input sample."""
    if form == _SCALAR:
        return float(out[0, 0])
    if form == _VECTOR:
        return out.reshape(-1)
    return out


def finite_rows(x: FloatArray) -> BoolArray:
    """Per row of ``x`` (N, k): are all components finite? -> (N,)."""
    ok: BoolArray = np.logical_and.reduce(np.isfinite(x), axis=1)
    return ok


def reindexed(a: Packed, keep: BoolArray, src: IndexArray) -> Packed:
    """Rows ``a[src]`` placed where ``keep`` is true; zeros (uninitialised) elsewhere."""
    out = np.zeros((keep.shape[0], *a.shape[1:]), dtype=a.dtype)
    out[keep] = a[src]
    return out


def row_index(rows: ArrayLike) -> IndexArray:
    """Validate a ``select`` argument: a 1-D integer array."""
    r = np.asarray(rows)
    if r.ndim != 1 or (r.size > 0 and r.dtype.kind not in "iu"):
        raise ValueError(f"rows: expected a 1-D integer array, got {r.dtype} of shape {r.shape}")
    return r.astype(np.intp, copy=False)


class Layout:
    """How rows of k-vectors are stored so that per-row factors broadcast cheaply.

    numpy is several times slower at (N, 2) * (N, 1) than at flat arrays, and a physics step has
    no time to spare. So rows are stored flat: k = 1 as (N,) floats, k = 2 as (N,) complex
    numbers x + iy (the very memory of C-ordered (N, 2) floats, so packing is a view), and only
    k >= 3 as (N, k) with (N, 1) factors. ``abs`` of a complex number is the Euclidean norm.
    """

    def __init__(self, k: int) -> None:
        self.k = k

    def pack(self, x: FloatArray) -> Packed:
        """(M, k) floats -> packed rows; a view when ``x`` is C-contiguous."""
        if self.k == 1:
            return x.reshape(-1)
        if self.k == 2:
            return np.ascontiguousarray(x).view(np.complex128).reshape(-1)
        return x

    def unpack(self, p: Packed) -> FloatArray:
        """Packed rows -> an (M, k) float view of the same memory."""
        if self.k == 1:
            return p.reshape(-1, 1)
        if self.k == 2:
            return p.view(np.float64).reshape(-1, 2)
        return p

    def zeros(self, n: int) -> Packed:
        """Packed storage for n rows, all zero."""
        if self.k == 1:
            return np.zeros(n)
        if self.k == 2:
            return np.zeros(n, dtype=np.complex128)
        return np.zeros((n, self.k))

    def norm(self, p: Packed) -> FloatArray:
        """Euclidean norm of each packed row -> (M,) floats, fresh."""
        if self.k <= 2:
            return np.abs(p)
        squares: FloatArray = np.einsum("ij,ij->i", p, p)
        return np.sqrt(squares)

    def per_row(self, a: NDArray[Any]) -> NDArray[Any]:
        """An (M,) per-row array, shaped to broadcast against packed rows."""
        return a if self.k <= 2 else a[:, None]
