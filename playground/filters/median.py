"""Median of the last three samples, the spike pre-stage (the vector median for k-vectors).

Keeps its window per row and shares the interface, shapes and guards of
:class:`~playground.filters.row_filter.RowFilter`.
"""

from __future__ import annotations

import numpy as np

from playground.filters.row_filter import RowFilter
from playground.filters.rows import BoolArray, FloatArray, IndexArray, Layout, Packed, reindexed

__all__ = ["Median3"]


def _vector_median(layout: Layout, a: Packed, b: Packed, c: Packed) -> FloatArray:
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


class Median3(RowFilter):
    """Median of the last three samples: removes single-step spikes at one step of delay.

    For vectors it is the *vector median*: the one of the three samples minimising the sum of
    Euclidean distances to the other two, ties going to the middle sample, then to the older one.
    It is always one of the samples, it is rotation- and translation-equivariant, and for k = 1
    it is the ordinary median. Before a row has three samples, the median is taken over what
    there is with the same tie rule: the first output is the first sample and the second output
    is again the first sample (two samples always tie), so a spike at the second sample is
    removed too; a spike in the very first sample cannot be told from the signal and shows for
    two steps.

    ``dt`` (s) is used only for the guards (see :mod:`playground.filters.row_filter`).

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
        self._s0: Packed = np.zeros(0)
        self._s1: Packed = np.zeros(0)
        self._s2: Packed = np.zeros(0)

    def __repr__(self) -> str:
        return "Median3()"

    def _allocate(self, n: int) -> None:
        self._s0 = self._layout.zeros(n)
        self._s1 = self._layout.zeros(n)
        self._s2 = self._layout.zeros(n)

    def _reindex_state(self, keep: BoolArray, src: IndexArray) -> None:
        self._s0 = reindexed(self._s0, keep, src)
        self._s1 = reindexed(self._s1, keep, src)
        self._s2 = reindexed(self._s2, keep, src)

    def _start_rows(self, idx: IndexArray, x: Packed) -> None:
        # Filling the window with the first sample gives exactly the warm-up rule documented
        # above: median(x1, x1, x1) = x1, and median(x1, x1, x2) ties to the older x1.
        self._s0[idx] = x
        self._s1[idx] = x
        self._s2[idx] = x

    def _advance_all(self, x: FloatArray, dt: float) -> FloatArray:
        if not np.isfinite(x).all():
            return self._advance_masked(x, dt, dt_ok=True)
        self._s0, self._s1, self._s2 = self._s1, self._s2, self._s0
        self._s2[...] = self._layout.pack(x)
        return _vector_median(self._layout, self._s0, self._s1, self._s2)

    def _advance_rows(self, idx: IndexArray, x: Packed, dt: float) -> None:
        self._s0[idx] = self._s1[idx]
        self._s1[idx] = self._s2[idx]
        self._s2[idx] = x

    def _current(self) -> FloatArray:
        return _vector_median(self._layout, self._s0, self._s1, self._s2)
