"""The interface every filter shares, and the per-row machinery behind it: shapes, guards, rows.

All the filters share one interface: ``filter(x, dt)``, ``reset()``, ``select(rows)``, ``value``
(:class:`Filter`). :class:`RowFilter` implements it once for the filters that keep per-row state
(1€, exponential moving average, median of 3); each of them supplies only its arithmetic.

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

Guards, common to every filter: ``dt`` is the sample period in seconds, passed explicitly and
never read from a clock. A ``dt`` that is <= 0 or not finite holds every initialised row (state
untouched, output = previous output); a row's very first sample needs no ``dt`` and is accepted
anyway. A row whose sample has any non-finite component holds the same way; a row that was never
initialised and gets a non-finite sample stays uninitialised and outputs NaN. Other rows in the
same call proceed normally, and nothing ever writes NaN or inf into the state.

>>> from playground.filters import OneEuroFilter
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
from typing import Protocol, overload

import numpy as np
from numpy.typing import ArrayLike

from playground.filters.rows import (
    BoolArray,
    FloatArray,
    IndexArray,
    Layout,
    Packed,
    as_rows,
    finite_rows,
    row_index,
    shaped,
)

__all__ = ["Filter", "RowFilter"]


class Filter(Protocol):
    """What every filter here (and every ``FilterChain`` stage) provides; see the module doc."""

    @overload
    def filter(self, x: float, dt: float) -> float: ...
    @overload
    def filter(self, x: ArrayLike, dt: float) -> FloatArray: ...
    def filter_rows(self, x: FloatArray, dt: float) -> FloatArray:
        """``filter`` for (N, k) float rows, the same output and state, cheaper when every row
        has started and ``dt`` is valid."""

    def reset(self) -> None:
        """Forget all state, shape included."""

    def select(self, rows: IndexArray) -> None:
        """Re-index the rows: new row i takes old row ``rows[i]``, -1 makes a fresh row."""

    @property
    def value(self) -> FloatArray | None:
        """Last output, shape (N, k); NaN rows were never initialised; None before any sample."""


class RowFilter(ABC):
    """Shape bookkeeping, guards and row selection shared by the per-row filters.

    Subclasses keep their state as packed rows (see :class:`~playground.filters.rows.Layout`)
    and implement the arithmetic for an all-rows step (every row initialised and dt valid: the
    fast path) and for a subset.
    """

    def __init__(self) -> None:
        self._shape: tuple[int, int] | None = None
        self._layout = Layout(1)
        self._init: BoolArray = np.zeros(0, dtype=np.bool_)
        self._all_init = False

    # -- the interface --------------------------------------------------------------------------

    @overload
    def filter(self, x: float, dt: float) -> float: ...
    @overload
    def filter(self, x: ArrayLike, dt: float) -> FloatArray: ...
    def filter(self, x: float | ArrayLike, dt: float) -> float | FloatArray:
        """Feed one sample per row, taken ``dt`` seconds after the previous one; return the output.

        ``x`` is a float, a k-vector or (N, k) rows (see the module doc); the output has the same
        form and is a fresh array. Invalid ``dt`` and non-finite rows hold, as the module doc says.
        """
        rows, form = as_rows(x)
        self._fix_shape(rows)
        dt = float(dt)
        dt_ok = dt > 0.0 and math.isfinite(dt)
        # Non-finite samples are expected input here, handled row by row: no warnings.
        with np.errstate(all="ignore"):
            if self._all_init and dt_ok:
                out = self._advance_all(rows, dt)
            else:
                out = self._advance_masked(rows, dt, dt_ok)
        return shaped(out, form)

    def filter_rows(self, x: FloatArray, dt: float) -> FloatArray:
        """:meth:`filter` for (N, k) float rows: the same output and state, without the generic
        bookkeeping when the rows have the shape the filter holds, every row has started and
        ``dt`` is valid (a world's perceived gravity calls it every step); any other sample
        goes through :meth:`filter`.

        >>> from playground.filters import OneEuroFilter
        >>> f = OneEuroFilter(beta=0.1)
        >>> _ = f.filter(np.array([[0.0, 0.0], [1.0, 1.0]]), dt=0.01)
        >>> g = OneEuroFilter(beta=0.1)
        >>> _ = g.filter(np.array([[0.0, 0.0], [1.0, 1.0]]), dt=0.01)
        >>> x = np.array([[0.5, -0.5], [2.0, 1.0]])
        >>> bool((f.filter_rows(x, 0.01) == g.filter(x, 0.01)).all())
        True
        """
        if self._all_init and x.shape == self._shape and dt > 0.0 and math.isfinite(dt):
            with np.errstate(all="ignore"):
                return self._advance_all(x, dt)
        return self.filter(x, dt)

    def reset(self) -> None:
        """Forget all state, shape included: the filter behaves as newly constructed."""
        self._shape = None
        self._init = np.zeros(0, dtype=np.bool_)
        self._all_init = False

    def select(self, rows: IndexArray) -> None:
        """Re-index the rows: new row i takes old row ``rows[i]`` (its whole history), and
        ``rows[i] == -1`` makes a new, uninitialised row. The row count becomes ``len(rows)``.

        Before the first sample there are no rows to take, so only -1 entries are allowed and the
        call changes nothing (the next sample fixes the shape).

        >>> from playground.filters import OneEuroFilter
        >>> f = OneEuroFilter()
        >>> _ = f.filter([[1.0, 1.0], [2.0, 2.0], [3.0, 3.0]], dt=0.01)
        >>> f.select(np.array([2, -1, 0]))  # drop row 1, swap 0 and 2, add a new row
        >>> f.value.tolist()
        [[3.0, 3.0], [nan, nan], [1.0, 1.0]]
        """
        take = row_index(rows)
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
    def value(self) -> FloatArray | None:
        """Last output, shape (N, k); NaN rows were never initialised; None before any sample."""
        if self._shape is None:
            return None
        return self._output()

    # -- shared machinery -----------------------------------------------------------------------

    def _fix_shape(self, rows: FloatArray) -> None:
        n, k = rows.shape
        if self._shape is None:
            self._shape = (n, k)
            self._layout = Layout(k)
            self._allocate(n)
            self._init = np.zeros(n, dtype=np.bool_)
            self._all_init = n == 0
        elif rows.shape != self._shape:
            raise ValueError(
                f"x: the filter holds {self._shape[0]} row(s) of {self._shape[1]} component(s) "
                f"but the sample has shape {rows.shape} as rows; the state shape is fixed by the "
                f"first sample (call select() to add, remove or reorder rows)"
            )

    def _advance_masked(self, rows: FloatArray, dt: float, dt_ok: bool) -> FloatArray:
        """The general path: start fresh rows, step valid ones, hold the rest."""
        good = finite_rows(rows)
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

    def _output(self) -> FloatArray:
        out = self._current()
        if not self._all_init:
            out[~self._init] = np.nan
        return out

    # -- what a subclass provides ---------------------------------------------------------------

    @abstractmethod
    def _allocate(self, n: int) -> None:
        """Create state for n rows (all uninitialised) with ``self._layout``."""

    @abstractmethod
    def _reindex_state(self, keep: BoolArray, src: IndexArray) -> None:
        """Apply ``reindexed(array, keep, src)`` to every state array."""

    @abstractmethod
    def _start_rows(self, idx: IndexArray, x: Packed) -> None:
        """Initialise rows ``idx`` from their first samples ``x`` (packed, finite)."""

    @abstractmethod
    def _advance_rows(self, idx: IndexArray, x: Packed, dt: float) -> None:
        """Step the initialised rows ``idx`` with finite packed samples ``x``; dt is valid.

        A row whose update would not be finite (overflow) must keep its state.
        """

    @abstractmethod
    def _advance_all(self, x: FloatArray, dt: float) -> FloatArray:
        """Step every row (all initialised, dt valid); return a fresh (N, k) output.

        Rows of ``x`` may be non-finite: they, and rows whose update would overflow, hold.
        """

    @abstractmethod
    def _current(self) -> FloatArray:
        """A fresh (N, k) copy of the output the state stands for (uninitialised rows: any)."""
