"""The 1€ filter and its β = 0 special case, the exponential moving average.

Casiez, Roussel & Vogel, "1€ Filter", CHI 2012, doi:10.1145/2207676.2208639. Both keep their
state per row and share the interface, shapes and guards of
:class:`~playground.filters.row_filter.RowFilter`.
"""

from __future__ import annotations

import math
from typing import Final

import numpy as np

from playground.filters.row_filter import RowFilter
from playground.filters.rows import (
    BoolArray,
    FloatArray,
    IndexArray,
    Packed,
    check_param,
    finite_rows,
    reindexed,
)

__all__ = ["ExponentialMovingAverage", "OneEuroFilter"]

_TWO_PI: Final = 2.0 * math.pi


class OneEuroFilter(RowFilter):
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
        self._xh: Packed = np.zeros(0)  # X̂, last filtered value
        self._dxh: Packed = np.zeros(0)  # Ẋ̂, smoothed derivative, unit/s

    def tune(self, min_cutoff: float, beta: float, d_cutoff: float) -> None:
        """Change the parameters from the next sample on, keeping the filter's state (a live
        tuning panel turns them while the signal flows).

        >>> f = OneEuroFilter(min_cutoff=1.0)
        >>> _ = f.filter(0.0, dt=0.01)
        >>> f.tune(min_cutoff=1e6, beta=0.0, d_cutoff=1.0)  # a cutoff this high passes the input
        >>> round(f.filter(1.0, dt=0.01), 4)
        1.0
        """
        self._min_cutoff = check_param(
            "min_cutoff", min_cutoff, "a finite frequency > 0 Hz", strictly_positive=True
        )
        self._beta = check_param("beta", beta, "a finite number >= 0", strictly_positive=False)
        self._d_cutoff = check_param(
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

    def _reindex_state(self, keep: BoolArray, src: IndexArray) -> None:
        self._xh = reindexed(self._xh, keep, src)
        self._dxh = reindexed(self._dxh, keep, src)

    def _start_rows(self, idx: IndexArray, x: Packed) -> None:
        self._xh[idx] = x  # X̂_1 = X_1
        self._dxh[idx] = 0.0  # Ẋ_1 = 0, hence Ẋ̂_1 = 0

    def _step(self, x: Packed, xh: Packed, dxh: Packed, dt: float) -> tuple[Packed, Packed]:
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

    def _advance_all(self, x: FloatArray, dt: float) -> FloatArray:
        xh, dxh = self._step(self._layout.pack(x), self._xh, self._dxh, dt)
        if np.isfinite(xh.view(np.float64)).all():
            self._xh, self._dxh = xh, dxh
            return self._layout.unpack(xh).copy()
        ok = finite_rows(self._layout.unpack(xh))
        self._xh[ok] = xh[ok]
        self._dxh[ok] = dxh[ok]
        return self._current()

    def _advance_rows(self, idx: IndexArray, x: Packed, dt: float) -> None:
        xh, dxh = self._step(x, self._xh[idx], self._dxh[idx], dt)
        ok = finite_rows(self._layout.unpack(xh))
        self._xh[idx[ok]] = xh[ok]
        self._dxh[idx[ok]] = dxh[ok]

    def _current(self) -> FloatArray:
        return self._layout.unpack(self._xh).copy()


class ExponentialMovingAverage(RowFilter):
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
        self._cutoff = check_param(
            "cutoff", cutoff, "a finite frequency > 0 Hz", strictly_positive=True
        )
        self._w = _TWO_PI * self._cutoff  # rad/s, so that r = 2π·fc·Te = w·dt
        self._xh: Packed = np.zeros(0)

    @property
    def cutoff(self) -> float:
        """Cutoff frequency, Hz."""
        return self._cutoff

    def __repr__(self) -> str:
        return f"ExponentialMovingAverage(cutoff={self._cutoff!r})"

    def _allocate(self, n: int) -> None:
        self._xh = self._layout.zeros(n)

    def _reindex_state(self, keep: BoolArray, src: IndexArray) -> None:
        self._xh = reindexed(self._xh, keep, src)

    def _start_rows(self, idx: IndexArray, x: Packed) -> None:
        self._xh[idx] = x

    def _step(self, x: Packed, xh: Packed, dt: float) -> Packed:
        r = self._w * dt
        dev = x - xh
        dev *= r / (1.0 + r)
        dev += xh  # X̂_{i−1} + α·(X_i − X̂_{i−1}), exact for a constant input
        return dev

    def _advance_all(self, x: FloatArray, dt: float) -> FloatArray:
        xh = self._step(self._layout.pack(x), self._xh, dt)
        if np.isfinite(xh.view(np.float64)).all():
            self._xh = xh
            return self._layout.unpack(xh).copy()
        ok = finite_rows(self._layout.unpack(xh))
        self._xh[ok] = xh[ok]
        return self._current()

    def _advance_rows(self, idx: IndexArray, x: Packed, dt: float) -> None:
        xh = self._step(x, self._xh[idx], dt)
        ok = finite_rows(self._layout.unpack(xh))
        self._xh[idx[ok]] = xh[ok]

    def _current(self) -> FloatArray:
        return self._layout.unpack(self._xh).copy()
