"""Smoothing filters for noisy per-step signals (measured forces, accelerations, gravity).

Owns the 1€ filter (Casiez, Roussel & Vogel, CHI 2012, doi:10.1145/2207676.2208639), its β = 0
special case the exponential moving average, a median-of-3 spike pre-stage, and a chain of stages.
All of them share one interface: ``filter(x, dt)``, ``reset()``, ``select(rows)``, ``value``.

Shapes: the LAST axis is the vector.

* A Python ``float`` (or any 0-d value) is a 1-vector, and ``filter`` returns a ``float``.
* A 1-D array of length k is one k-vector (e.g. a 2-vector force); ``filter`` returns shape (k,).
* A 2-D array (N, k) is N independent rows ("channels") of k-vectors, filtered in one vectorised
  numpy pass; ``filter`` returns shape (N, k).

The state layout (N, k) is fixed by the first sample. Later samples must have the same number of
rows and components (a float or 1-D sample counts as one row) or ``filter`` raises ``ValueError``;
``select`` re-indexes the rows when tracked bodies are added, removed or reordered, and is the only
way to change the row count. ``reset`` forgets everything, shape included. ``value`` is the last
output in the (N, k) layout, NaN for rows that were never initialised, ``None`` before any sample.

Guards, common to every filter here: ``dt`` is the sample period in seconds, passed explicitly and
never read from a clock. A ``dt`` that is <= 0 or not finite holds every initialised row (state
untouched, output = previous output); a row's very first sample needs no ``dt`` and is accepted
anyway. A row whose sample has any non-finite component holds the same way; a row that was never
initialised and gets a non-finite sample stays uninitialised and outputs NaN. Other rows in the
same call proceed normally, and nothing ever writes NaN or inf into the state.

>>> f = OneEuroFilter(min_cutoff=1.0, beta=0.5)
>>> [f.filter(2.5, dt=0.01) for _ in range(3)]
[2.5, 2.5, 2.5]
>>> f.filter(float("nan"), dt=0.01)
2.5
>>> g = OneEuroFilter()
>>> g.filter(np.array([[0.0, -9.81], [1.0, 2.0]]), dt=1 / 60).tolist()
[[0.0, -9.81], [1.0, 2.0]]
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from typing import Any, Final, Protocol, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["ExponentialMovingAverage", "Filter", "FilterChain", "Median3", "OneEuroFilter"]

_TWO_PI: Final = 2.0 * math.pi

_FloatArray = NDArray[np.float64]
_BoolArray = NDArray[np.bool_]
_IndexArray = NDArray[np.intp]
# Rows as stored internally: see _Layout (float or complex, 1-D or 2-D).
_Packed = NDArray[Any]

# Forms of an input sample, remembered so the output comes back in the same form.
_SCALAR: Final = 0
_VECTOR: Final = 1
_ROWS: Final = 2


class Filter(Protocol):
    """What every filter here (and every ``FilterChain`` stage) provides; see the module doc."""

    @overload
    def filter(self, x: float, dt: float) -> float: ...
    @overload
    def filter(self, x: ArrayLike, dt: float) -> _FloatArray: ...
    def reset(self) -> None:
        """Forget all state, shape included."""

    def select(self, rows: _IndexArray) -> None:
        """Re-index the rows: new row i takes old row ``rows[i]``, -1 makes a fresh row."""

    @property
    def value(self) -> _FloatArray | None:
        """Last output, shape (N, k); NaN rows were never initialised; None before any sample."""


def _check_param(name: str, value: float, expected: str, *, strictly_positive: bool) -> float:
    """Return ``value`` as a float, or raise ``ValueError`` naming the parameter."""
    v = float(value)
    if not math.isfinite(v) or v < 0.0 or (strictly_positive and v == 0.0):
        raise ValueError(f"{name}: expected {expected}, got {value!r}")
    return v


def _as_rows(x: float | ArrayLike) -> tuple[_FloatArray, int]:
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


def _shaped(out: _FloatArray, form: int) -> float | _FloatArray:
    """Give ``out`` (N, k) back in the form of the input sample."""
    if form == _SCALAR:
        return float(out[0, 0])
    if form == _VECTOR:
        return out.reshape(-1)
    return out


def _finite_rows(x: _FloatArray) -> _BoolArray:
    """Per row of ``x`` (N, k): are all components finite? -> (N,)."""
    ok: _BoolArray = np.logical_and.reduce(np.isfinite(x), axis=1)
    return ok


def _reindexed(a: _Packed, keep: _BoolArray, src: _IndexArray) -> _Packed:
    """Rows ``a[src]`` placed where ``keep`` is true; zeros (uninitialised) elsewhere."""
    out = np.zeros((keep.shape[0], *a.shape[1:]), dtype=a.dtype)
    out[keep] = a[src]
    return out


def _row_index(rows: ArrayLike) -> _IndexArray:
    """Validate a ``select`` argument: a 1-D integer array."""
    r = np.asarray(rows)
    if r.ndim != 1 or (r.size > 0 and r.dtype.kind not in "iu"):
        raise ValueError(f"rows: expected a 1-D integer array, got {r.dtype} of shape {r.shape}")
    return r.astype(np.intp, copy=False)


class _Layout:
    """How rows of k-vectors are stored so that per-row factors broadcast cheaply.

    numpy is several times slower at (N, 2) * (N, 1) than at flat arrays, and a physics step has
    no time to spare. So rows are stored flat: k = 1 as (N,) floats, k = 2 as (N,) complex
    numbers x + iy (the very memory of C-ordered (N, 2) floats, so packing is a view), and only
    k >= 3 as (N, k) with (N, 1) factors. ``abs`` of a complex number is the Euclidean norm.
    """

    def __init__(self, k: int) -> None:
        self.k = k

    def pack(self, x: _FloatArray) -> _Packed:
        """(M, k) floats -> packed rows; a view when ``x`` is C-contiguous."""
        if self.k == 1:
            return x.reshape(-1)
        if self.k == 2:
            return np.ascontiguousarray(x).view(np.complex128).reshape(-1)
        return x

    def unpack(self, p: _Packed) -> _FloatArray:
        """Packed rows -> an (M, k) float view of the same memory."""
        if self.k == 1:
            return p.reshape(-1, 1)
        if self.k == 2:
            return p.view(np.float64).reshape(-1, 2)
        return p

    def zeros(self, n: int) -> _Packed:
        """Packed storage for n rows, all zero."""
        if self.k == 1:
            return np.zeros(n)
        if self.k == 2:
            return np.zeros(n, dtype=np.complex128)
        return np.zeros((n, self.k))

    def norm(self, p: _Packed) -> _FloatArray:
        """Euclidean norm of each packed row -> (M,) floats, fresh."""
        if self.k <= 2:
            return np.abs(p)
        squares: _FloatArray = np.einsum("ij,ij->i", p, p)
        return np.sqrt(squares)

    def per_row(self, a: NDArray[Any]) -> NDArray[Any]:
        """An (M,) per-row array, shaped to broadcast against packed rows."""
        return a if self.k <= 2 else a[:, None]


class _RowFilter(ABC):
    """Shape bookkeeping, guards and row selection shared by the per-row filters.

    Subclasses keep their state as packed rows (see ``_Layout``) and implement the arithmetic
    for an all-rows step (every row initialised and dt valid: the fast path) and for a subset.
    """

    def __init__(self) -> None:
        self._shape: tuple[int, int] | None = None
        self._layout = _Layout(1)
        self._init: _BoolArray = np.zeros(0, dtype=np.bool_)
        self._all_init = False

    # -- the interface --------------------------------------------------------------------------

    @overload
    def filter(self, x: float, dt: float) -> float: ...
    @overload
    def filter(self, x: ArrayLike, dt: float) -> _FloatArray: ...
    def filter(self, x: float | ArrayLike, dt: float) -> float | _FloatArray:
        """Feed one sample per row, taken ``dt`` seconds after the previous one; return the output.

        ``x`` is a float, a k-vector or (N, k) rows (see the module doc); the output has the same
        form and is a fresh array. Invalid ``dt`` and non-finite rows hold, as the module doc says.
        """
        rows, form = _as_rows(x)
        self._fix_shape(rows)
        dt = float(dt)
        dt_ok = dt > 0.0 and math.isfinite(dt)
        # Non-finite samples are expected input here, handled row by row: no warnings.
        with np.errstate(all="ignore"):
            if self._all_init and dt_ok:
                out = self._advance_all(rows, dt)
            else:
                out = self._advance_masked(rows, dt, dt_ok)
        return _shaped(out, form)

    def reset(self) -> None:
        """Forget all state, shape included: the filter behaves as newly constructed."""
        self._shape = None
        self._init = np.zeros(0, dtype=np.bool_)
        self._all_init = False

    def select(self, rows: _IndexArray) -> None:
        """Re-index the rows: new row i takes old row ``rows[i]`` (its whole history), and
        ``rows[i] == -1`` makes a new, uninitialised row. The row count becomes ``len(rows)``.

        Before the first sample there are no rows to take, so only -1 entries are allowed and the
        call changes nothing (the next sample fixes the shape).

        >>> f = OneEuroFilter()
        >>> _ = f.filter([[1.0, 1.0], [2.0, 2.0], [3.0, 3.0]], dt=0.01)
        >>> f.select(np.array([2, -1, 0]))  # drop row 1, swap 0 and 2, add a new row
        >>> f.value.tolist()
        [[3.0, 3.0], [nan, nan], [1.0, 1.0]]
        """
        take = _row_index(rows)
        if self._shape is None:
            if np.any(take != -1):
                raise ValueError("rows: before the first sample only new rows (-1) can be selected")
            return
        n, k = self._shape
        if take.size and (int(take.min()) < -1 or int(take.max()) >= n):
            raise ValueError(f"rows: expected indices in [-1, {n - 1}], got {take.tolist()}")
        keep = take >= 0
        src = take[keep]
        self._reindex_state(keep, src)
        init = np.zeros(take.shape[0], dtype=np.bool_)
        init[keep] = self._init[src]
        self._init = init
        self._all_init = bool(init.all())
        self._shape = (take.shape[0], k)

    @property
    def value(self) -> _FloatArray | None:
        """Last output, shape (N, k); NaN rows were never initialised; None before any sample."""
        if self._shape is None:
            return None
        return self._output()

    # -- shared machinery -----------------------------------------------------------------------

    def _fix_shape(self, rows: _FloatArray) -> None:
        n, k = rows.shape
        if self._shape is None:
            self._shape = (n, k)
            self._layout = _Layout(k)
            self._allocate(n)
            self._init = np.zeros(n, dtype=np.bool_)
            self._all_init = n == 0
        elif rows.shape != self._shape:
            raise ValueError(
                f"x: the filter holds {self._shape[0]} row(s) of {self._shape[1]} component(s) "
                f"but the sample has shape {rows.shape} as rows; the state shape is fixed by the "
                f"first sample (call select() to add, remove or reorder rows)"
            )

    def _advance_masked(self, rows: _FloatArray, dt: float, dt_ok: bool) -> _FloatArray:
        """The general path: start fresh rows, step valid ones, hold the rest."""
        good = _finite_rows(rows)
        step = good & self._init
        fresh = good & ~self._init
        if fresh.any():
            idx = np.flatnonzero(fresh)
            self._start_rows(idx, self._layout.pack(rows[idx]))
            self._init[idx] = True
            self._all_init = bool(self._init.all())
        if dt_ok and step.any():
            idx = np.flatnonzero(step)
            self._advance_rows(idx, self._layout.pack(rows[idx]), dt)
        return self._output()

    def _output(self) -> _FloatArray:
        out = self._current()
        if not self._all_init:
            out[~self._init] = np.nan
        return out

    # -- what a subclass provides ---------------------------------------------------------------

    @abstractmethod
    def _allocate(self, n: int) -> None:
        """Create state for n rows (all uninitialised) with ``self._layout``."""

    @abstractmethod
    def _reindex_state(self, keep: _BoolArray, src: _IndexArray) -> None:
        """Apply ``_reindexed(array, keep, src)`` to every state array."""

    @abstractmethod
    def _start_rows(self, idx: _IndexArray, x: _Packed) -> None:
        """Initialise rows ``idx`` from their first samples ``x`` (packed, finite)."""

    @abstractmethod
    def _advance_rows(self, idx: _IndexArray, x: _Packed, dt: float) -> None:
        """Step the initialised rows ``idx`` with finite packed samples ``x``; dt is valid.

        A row whose update would not be finite (overflow) must keep its state.
        """

    @abstractmethod
    def _advance_all(self, x: _FloatArray, dt: float) -> _FloatArray:
        """Step every row (all initialised, dt valid); return a fresh (N, k) output.

        Rows of ``x`` may be non-finite: they, and rows whose update would overflow, hold.
        """

    @abstractmethod
    def _current(self) -> _FloatArray:
        """A fresh (N, k) copy of the output the state stands for (uninitialised rows: any)."""


class OneEuroFilter(_RowFilter):
    """The 1€ filter: an exponential smoother whose cutoff rises with the signal's speed.

    Casiez, Roussel & Vogel, "1€ Filter", CHI 2012, doi:10.1145/2207676.2208639. With sample
    period Te = ``dt`` (s)::

        τ(fc) = 1/(2π·fc);  α(fc) = 1/(1 + τ/Te)
        Ẋ_1 = 0,  Ẋ_i = (X_i − X̂_{i−1}) / Te      (against the previous *filtered* value)
        Ẋ̂_i = α(d_cutoff)·Ẋ_i + (1 − α(d_cutoff))·Ẋ̂_{i−1}
        fc_i = min_cutoff + β·‖Ẋ̂_i‖
        X̂_1 = X_1,  X̂_i = α(fc_i)·X_i + (1 − α(fc_i))·X̂_{i−1}

    For vectors, one cutoff per row comes from the Euclidean norm of the row's smoothed derivative
    and applies to all components, which makes the filter rotation-equivariant (filtering the
    components separately is not); for k = 1 this is the paper's scalar filter.

    Args:
        min_cutoff: cutoff at rest, Hz (> 0). Lower it until the signal at rest stops jittering.
        beta: cutoff increase per unit of speed, Hz per (unit/s), i.e. 1/unit (>= 0). Raise it
            until fast changes stop lagging. β = 0 is a plain exponential moving average.
        d_cutoff: cutoff of the derivative smoother, Hz (> 0).

    Raises:
        ValueError: a parameter is not finite or out of range; the message names it.

    A constant is returned unchanged, and so is the first sample:

    >>> f = OneEuroFilter(min_cutoff=0.5, beta=0.02)
    >>> [f.filter(3.0, dt=1 / 60) for _ in range(3)]
    [3.0, 3.0, 3.0]

    A step is followed with a lag that β shortens:

    >>> slow, fast = OneEuroFilter(beta=0.0), OneEuroFilter(beta=1.0)
    >>> for f in (slow, fast):
    ...     _ = f.filter(0.0, dt=0.01)
    ...     y = [f.filter(1.0, dt=0.01) for _ in range(5)]
    ...     print(round(y[-1], 3))
    0.263
    0.931

    >>> OneEuroFilter(min_cutoff=0.0)
    Traceback (most recent call last):
    ValueError: min_cutoff: expected a finite frequency > 0 Hz, got 0.0
    """

    def __init__(self, min_cutoff: float = 1.0, beta: float = 0.0, d_cutoff: float = 1.0) -> None:
        super().__init__()
        self.tune(min_cutoff, beta, d_cutoff)
        self._xh: _Packed = np.zeros(0)  # X̂, last filtered value
        self._dxh: _Packed = np.zeros(0)  # Ẋ̂, smoothed derivative, unit/s

    def tune(self, min_cutoff: float, beta: float, d_cutoff: float) -> None:
        """Change the parameters from the next sample on, keeping the filter's state (a live
        tuning panel turns them while the signal flows).

        >>> f = OneEuroFilter(min_cutoff=1.0)
        >>> _ = f.filter(0.0, dt=0.01)
        >>> f.tune(min_cutoff=1e6, beta=0.0, d_cutoff=1.0)  # a cutoff this high passes the input
        >>> round(f.filter(1.0, dt=0.01), 4)
        1.0
        """
        self._min_cutoff = _check_param(
            "min_cutoff", min_cutoff, "a finite frequency > 0 Hz", strictly_positive=True
        )
        self._beta = _check_param("beta", beta, "a finite number >= 0", strictly_positive=False)
        self._d_cutoff = _check_param(
            "d_cutoff", d_cutoff, "a finite frequency > 0 Hz", strictly_positive=True
        )
        # α(fc) = 1/(1 + τ/Te) = r/(1 + r) with r = 2π·fc·Te; keep 2π·fc precomputed (rad/s).
        self._w_min = _TWO_PI * self._min_cutoff
        self._w_beta = _TWO_PI * self._beta
        self._w_d = _TWO_PI * self._d_cutoff

    @property
    def min_cutoff(self) -> float:
        """Cutoff at rest, Hz."""
        return self._min_cutoff

    @property
    def beta(self) -> float:
        """Cutoff increase per unit of speed, Hz per (unit/s)."""
        return self._beta

    @property
    def d_cutoff(self) -> float:
        """Cutoff of the derivative smoother, Hz."""
        return self._d_cutoff

    def __repr__(self) -> str:
        return (
            f"OneEuroFilter(min_cutoff={self._min_cutoff!r}, beta={self._beta!r}, "
            f"d_cutoff={self._d_cutoff!r})"
        )

    def _allocate(self, n: int) -> None:
        self._xh = self._layout.zeros(n)
        self._dxh = self._layout.zeros(n)

    def _reindex_state(self, keep: _BoolArray, src: _IndexArray) -> None:
        self._xh = _reindexed(self._xh, keep, src)
        self._dxh = _reindexed(self._dxh, keep, src)

    def _start_rows(self, idx: _IndexArray, x: _Packed) -> None:
        self._xh[idx] = x  # X̂_1 = X_1
        self._dxh[idx] = 0.0  # Ẋ_1 = 0, hence Ẋ̂_1 = 0

    def _step(self, x: _Packed, xh: _Packed, dxh: _Packed, dt: float) -> tuple[_Packed, _Packed]:
        """One 1€ step on packed rows; returns fresh (X̂_i, Ẋ̂_i), non-finite where x is."""
        r_d = self._w_d * dt
        a_d = r_d / (1.0 + r_d)
        dev = x - xh  # X_i − X̂_{i−1}
        # Ẋ̂_i = α_d·(dev/Te) + (1 − α_d)·Ẋ̂_{i−1}
        dxh_new = np.multiply(dev, a_d / dt)
        dxh_new += (1.0 - a_d) * dxh
        # r = 2π·fc·Te with fc = min_cutoff + β·‖Ẋ̂_i‖, then α = r/(1 + r). A non-finite Ẋ̂_i
        # (non-finite sample, overflow) makes α NaN and so X̂_i NaN: the caller's one check.
        r = self._layout.norm(dxh_new)
        r *= self._w_beta * dt
        r += self._w_min * dt
        alpha = r / (r + 1.0)
        # X̂_i = X̂_{i−1} + α·(X_i − X̂_{i−1}): the same as α·X_i + (1 − α)·X̂_{i−1}, but a
        # constant input then stays exactly constant.
        dev *= self._layout.per_row(alpha)
        dev += xh
        return dev, dxh_new

    def _advance_all(self, x: _FloatArray, dt: float) -> _FloatArray:
        xh, dxh = self._step(self._layout.pack(x), self._xh, self._dxh, dt)
        if np.isfinite(xh.view(np.float64)).all():
            self._xh, self._dxh = xh, dxh
            return self._layout.unpack(xh).copy()
        ok = _finite_rows(self._layout.unpack(xh))
        self._xh[ok] = xh[ok]
        self._dxh[ok] = dxh[ok]
        return self._current()

    def _advance_rows(self, idx: _IndexArray, x: _Packed, dt: float) -> None:
        xh, dxh = self._step(x, self._xh[idx], self._dxh[idx], dt)
        ok = _finite_rows(self._layout.unpack(xh))
        self._xh[idx[ok]] = xh[ok]
        self._dxh[idx[ok]] = dxh[ok]

    def _current(self) -> _FloatArray:
        return self._layout.unpack(self._xh).copy()


class ExponentialMovingAverage(_RowFilter):
    """Exponential moving average, X̂_i = α·X_i + (1 − α)·X̂_{i−1}, X̂_1 = X_1.

    α = 1/(1 + τ/Te) with τ = 1/(2π·cutoff) and Te = ``dt`` (s), so the smoothing is a
    first-order low-pass at ``cutoff`` whatever the step. It equals
    ``OneEuroFilter(min_cutoff=cutoff, beta=0)``, with less work per step.

    Args:
        cutoff: cutoff frequency, Hz (> 0).

    >>> f = ExponentialMovingAverage(cutoff=1.0)
    >>> f.filter([0.0, 2.0], dt=0.1).tolist()
    [0.0, 2.0]
    >>> f.filter([1.0, 2.0], dt=0.1).round(4).tolist()
    [0.3859, 2.0]
    """

    def __init__(self, cutoff: float = 1.0) -> None:
        super().__init__()
        self._cutoff = _check_param(
            "cutoff", cutoff, "a finite frequency > 0 Hz", strictly_positive=True
        )
        self._w = _TWO_PI * self._cutoff  # rad/s, so that r = 2π·fc·Te = w·dt
        self._xh: _Packed = np.zeros(0)

    @property
    def cutoff(self) -> float:
        """Cutoff frequency, Hz."""
        return self._cutoff

    def __repr__(self) -> str:
        return f"ExponentialMovingAverage(cutoff={self._cutoff!r})"

    def _allocate(self, n: int) -> None:
        self._xh = self._layout.zeros(n)

    def _reindex_state(self, keep: _BoolArray, src: _IndexArray) -> None:
        self._xh = _reindexed(self._xh, keep, src)

    def _start_rows(self, idx: _IndexArray, x: _Packed) -> None:
        self._xh[idx] = x

    def _step(self, x: _Packed, xh: _Packed, dt: float) -> _Packed:
        r = self._w * dt
        dev = x - xh
        dev *= r / (1.0 + r)
        dev += xh  # X̂_{i−1} + α·(X_i − X̂_{i−1}), exact for a constant input
        return dev

    def _advance_all(self, x: _FloatArray, dt: float) -> _FloatArray:
        xh = self._step(self._layout.pack(x), self._xh, dt)
        if np.isfinite(xh.view(np.float64)).all():
            self._xh = xh
            return self._layout.unpack(xh).copy()
        ok = _finite_rows(self._layout.unpack(xh))
        self._xh[ok] = xh[ok]
        return self._current()

    def _advance_rows(self, idx: _IndexArray, x: _Packed, dt: float) -> None:
        xh = self._step(x, self._xh[idx], dt)
        ok = _finite_rows(self._layout.unpack(xh))
        self._xh[idx[ok]] = xh[ok]

    def _current(self) -> _FloatArray:
        return self._layout.unpack(self._xh).copy()


def _vector_median(layout: _Layout, a: _Packed, b: _Packed, c: _Packed) -> _FloatArray:
    """Per row, the one of a (oldest), b, c (newest) minimising the summed distance to the others.

    The sum for a is |ab| + |ac| = perimeter − |bc|, so the winner is the sample opposite the
    longest side of the triangle. Ties go to b, then a: the middle sample, then the older.
    Returns a fresh (M, k) array.
    """
    d_ab = layout.norm(a - b)
    d_bc = layout.norm(b - c)
    d_ac = layout.norm(a - c)
    pick_b = (d_ac >= d_ab) & (d_ac >= d_bc)
    pick_a = (d_bc >= d_ab) & ~pick_b
    med = np.where(layout.per_row(pick_b), b, np.where(layout.per_row(pick_a), a, c))
    return layout.unpack(med)


class Median3(_RowFilter):
    """Median of the last three samples: removes single-step spikes at one step of delay.

    For vectors it is the *vector median*: the one of the three samples minimising the sum of
    Euclidean distances to the other two, ties going to the middle sample, then to the older one.
    It is always one of the samples, it is rotation- and translation-equivariant, and for k = 1
    it is the ordinary median. Before a row has three samples, the median is taken over what
    there is with the same tie rule: the first output is the first sample and the second output
    is again the first sample (two samples always tie), so a spike at the second sample is
    removed too; a spike in the very first sample cannot be told from the signal and shows for
    two steps.

    ``dt`` (s) is used only for the guards (see the module doc).

    >>> m = Median3()
    >>> [m.filter(v, dt=0.01) for v in (1.0, 2.0, 100.0, 4.0, 5.0)]
    [1.0, 1.0, 2.0, 4.0, 5.0]
    >>> m.filter([[0.0, 0.0], [1.0, 1.0]], dt=0.01)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ValueError: x: the filter holds 1 row(s) of 1 component(s) but the sample has shape (2, 2)...
    """

    def __init__(self) -> None:
        super().__init__()
        # The last three samples, oldest first; rotated by reference, not copied.
        self._s0: _Packed = np.zeros(0)
        self._s1: _Packed = np.zeros(0)
        self._s2: _Packed = np.zeros(0)

    def __repr__(self) -> str:
        return "Median3()"

    def _allocate(self, n: int) -> None:
        self._s0 = self._layout.zeros(n)
        self._s1 = self._layout.zeros(n)
        self._s2 = self._layout.zeros(n)

    def _reindex_state(self, keep: _BoolArray, src: _IndexArray) -> None:
        self._s0 = _reindexed(self._s0, keep, src)
        self._s1 = _reindexed(self._s1, keep, src)
        self._s2 = _reindexed(self._s2, keep, src)

    def _start_rows(self, idx: _IndexArray, x: _Packed) -> None:
        # Filling the window with the first sample gives exactly the warm-up rule documented
        # above: median(x1, x1, x1) = x1, and median(x1, x1, x2) ties to the older x1.
        self._s0[idx] = x
        self._s1[idx] = x
        self._s2[idx] = x

    def _advance_all(self, x: _FloatArray, dt: float) -> _FloatArray:
        if not np.isfinite(x).all():
            return self._advance_masked(x, dt, dt_ok=True)
        self._s0, self._s1, self._s2 = self._s1, self._s2, self._s0
        self._s2[...] = self._layout.pack(x)
        return _vector_median(self._layout, self._s0, self._s1, self._s2)

    def _advance_rows(self, idx: _IndexArray, x: _Packed, dt: float) -> None:
        self._s0[idx] = self._s1[idx]
        self._s1[idx] = self._s2[idx]
        self._s2[idx] = x

    def _current(self) -> _FloatArray:
        return _vector_median(self._layout, self._s0, self._s1, self._s2)


class FilterChain:
    """Stages applied in order, each one's output being the next one's input.

    The chain keeps the guard contract of a single filter: a row whose input sample is
    non-finite is held in *every* stage (a stage after the first receives NaN for that row
    instead of the first stage's held output), so no stage's state moves for it.

    >>> chain = FilterChain(Median3(), OneEuroFilter(min_cutoff=1.0, beta=0.1))
    >>> [round(chain.filter(v, dt=0.01), 3) for v in (0.0, 0.0, 50.0, 0.0, 0.0)]
    [0.0, 0.0, 0.0, 0.0, 0.0]
    """

    def __init__(self, *stages: Filter) -> None:
        if not stages:
            raise ValueError("stages: expected at least one filter")
        self._stages = stages

    @property
    def stages(self) -> tuple[Filter, ...]:
        """The stages, first applied first."""
        return self._stages

    def __repr__(self) -> str:
        return f"FilterChain({', '.join(repr(s) for s in self._stages)})"

    @overload
    def filter(self, x: float, dt: float) -> float: ...
    @overload
    def filter(self, x: ArrayLike, dt: float) -> _FloatArray: ...
    def filter(self, x: float | ArrayLike, dt: float) -> float | _FloatArray:
        """Feed one sample per row through every stage; same shapes and guards as the stages."""
        rows, form = _as_rows(x)
        held: _BoolArray | None = None
        if not np.isfinite(rows).all():
            held = ~_finite_rows(rows)
        y = self._stages[0].filter(rows, dt)
        for stage in self._stages[1:]:
            if held is not None:
                y = np.array(y, dtype=np.float64)
                y[held] = np.nan
            y = stage.filter(y, dt)
        return _shaped(y, form)

    def reset(self) -> None:
        """Reset every stage."""
        for stage in self._stages:
            stage.reset()

    def select(self, rows: _IndexArray) -> None:
        """Re-index the rows of every stage (see ``OneEuroFilter.select``)."""
        for stage in self._stages:
            stage.select(rows)

    @property
    def value(self) -> _FloatArray | None:
        """The last stage's last output, shape (N, k); None before any sample."""
        return self._stages[-1].value
