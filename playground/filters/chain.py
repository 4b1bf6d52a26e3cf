"""A chain of filter stages, each one's output the next one's input (e.g. median of 3, then 1€)."""

from __future__ import annotations

from typing import overload

import numpy as np
from numpy.typing import ArrayLike

from playground.filters.row_filter import Filter
from playground.filters.rows import BoolArray, FloatArray, IndexArray, as_rows, finite_rows, shaped

__all__ = ["FilterChain"]


class FilterChain:
    """Stages applied in order, each one's output being the next one's input.

    The chain keeps the guard contract of a single filter: a row whose input sample is
    non-finite is held in *every* stage (a stage after the first receives NaN for that row
    instead of the first stage's held output), so no stage's state moves for it.

    >>> from playground.filters import Median3, OneEuroFilter
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
    def filter(self, x: ArrayLike, dt: float) -> FloatArray: ...
    def filter(self, x: float | ArrayLike, dt: float) -> float | FloatArray:
        """Feed one sample per row through every stage; same shapes and guards as the stages."""
        rows, form = as_rows(x)
        held: BoolArray | None = None
        if not np.isfinite(rows).all():
            held = ~finite_rows(rows)
        y = self._stages[0].filter(rows, dt)
        for stage in self._stages[1:]:
            if held is not None:
                y = np.array(y, dtype=np.float64)
                y[held] = np.nan
            y = stage.filter(y, dt)
        return shaped(y, form)

    def filter_rows(self, x: FloatArray, dt: float) -> FloatArray:
        """:meth:`filter` for (N, k) float rows: the same output and state, each stage taking
        its own shortcut (``filter_rows``) when every row of ``x`` is finite (a row that is not
        is held in every stage, as :meth:`filter` holds it)."""
        if not np.isfinite(x).all():
            return self.filter(x, dt)
        y = x
        for stage in self._stages:
            y = stage.filter_rows(y, dt)
        return y

    def reset(self) -> None:
        """Reset every stage."""
        for stage in self._stages:
            stage.reset()

    def select(self, rows: IndexArray) -> None:
        """Re-index the rows of every stage (see ``OneEuroFilter.select``)."""
        for stage in self._stages:
            stage.select(rows)

    @property
    def value(self) -> FloatArray | None:
        """The last stage's last output, shape (N, k); None before any sample."""
        return self._stages[-1].value
