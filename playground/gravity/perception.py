"""Perceived gravity: what a body's inner ear says "down" is.

The specific force f = support / m is what an accelerometer reads; the perceived gravity is −f,
smoothed by a 1€ filter (optionally after a median-of-3 spike stage) so it is steady at rest and
quick when the world turns. At rest it equals the real gravity; in free fall it is zero; inside a
spinning ring it points outward. The unit "up" is held while |perceived gravity| is below a
threshold, so a 180° flip (which passes through zero) never yields a NaN or zero-length up.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import OneEuroFilter
from playground.params import check, param

__all__ = ["PerceivedGravity", "Perception"]


@dataclass(frozen=True, slots=True)
class Perception:
    """How perceived gravity is filtered (a 1€ filter, optionally after a median-of-3 stage).

    A lower ``min_cutoff`` is steadier at rest and lags more; the cutoff rises by ``beta`` per
    m/s³ of change; ``spike_filter`` removes one-step impulse spikes at one step of delay (for a
    spike only).
    """

    min_cutoff: float = param(2.0, doc="1€ minimum cutoff.", unit="Hz", gt=0.0)
    beta: float = param(0.05, doc="1€ speed coefficient.", unit="s²/m", ge=0.0)
    d_cutoff: float = param(1.0, doc="Cutoff of the derivative's smoothing.", unit="Hz", gt=0.0)
    spike_filter: bool = param(True, doc="Median-of-3 stage before the 1€ filter.")
    up_threshold: float = param(
        1.0,
        doc="Below this |perceived gravity| up holds its last direction.",
        unit="m/s²",
        gt=0.0,
    )

    def __post_init__(self) -> None:
        check(self)


class PerceivedGravity:
    """Filtered −specific force and a held unit "up", one row per tracked body.

    >>> pg = PerceivedGravity(Perception(spike_filter=False))
    >>> pg.resize(np.array([-1]))
    >>> pg.update(np.array([[0.0, 9.81]]), np.array([True]), dt=0.01)
    >>> pg.gravity.tolist(), (pg.up + 0.0).tolist()  # + 0.0: no negative zeros
    ([[-0.0, -9.81]], [[0.0, 1.0]])
    """

    def __init__(self, config: Perception) -> None:
        self.config = config
        one_euro = OneEuroFilter(config.min_cutoff, config.beta, config.d_cutoff)
        self._one_euro = one_euro
        self._filter: OneEuroFilter | FilterChain = (
            FilterChain(Median3(), one_euro) if config.spike_filter else one_euro
        )
        self.gravity: NDArray[np.float64] = np.zeros((0, 2))
        self.up: NDArray[np.float64] = np.zeros((0, 2))
        self.up_complete = True
        """False while some row has not yet felt a reading strong enough to define its up."""
        self._rows = 0

    def tune(self, config: Perception) -> None:
        """Take new 1€ parameters and up threshold from the next step on, keeping the filter's
        state. Adding or removing the spike stage is not a tuning: it needs a new filter."""
        if config.spike_filter != self.config.spike_filter:
            raise ValueError("spike_filter: fixed when the perception is built")
        self._one_euro.tune(config.min_cutoff, config.beta, config.d_cutoff)
        self.config = config

    def resize(self, rows: NDArray[np.intp]) -> None:
        """Re-index after tracked bodies changed: new row i is old row rows[i] (−1: new)."""
        # Before the first sample the filter has no rows to keep: every row is new to it.
        fresh = self._filter.value is None
        self._filter.select(np.full(len(rows), -1, dtype=np.intp) if fresh else rows)
        keep = rows >= 0
        gravity = np.zeros((len(rows), 2))
        up = np.full((len(rows), 2), np.nan)
        if self._rows:
            gravity[keep] = self.gravity[rows[keep]]
            up[keep] = self.up[rows[keep]]
        self.gravity, self.up, self._rows = gravity, up, len(rows)
        self.up_complete = bool(np.isfinite(up).all())

    def update(
        self,
        specific: NDArray[np.float64],
        valid: NDArray[np.bool_],
        dt: float,
        *,
        all_valid: bool | None = None,
    ) -> None:
        """Feed this step's specific force (m/s², rows); invalid rows hold. ``all_valid``: whether
        every row of ``valid`` is true, if the caller knows (saves looking).

        Rows that have not yet felt a strong enough reading keep a NaN up; the caller supplies
        one (the world uses the gravity field at the body).
        """
        if len(specific) != self._rows:
            raise ValueError(
                f"specific: expected {self._rows} rows (call resize first), got {len(specific)}"
            )
        if all_valid is None:
            all_valid = bool(valid.all())
        sample = -specific if all_valid else np.where(valid[:, None], -specific, np.nan)
        out = np.ascontiguousarray(self._filter.filter_rows(sample, dt)).reshape(-1, 2)
        # Rows as complex numbers x + iy: magnitude and direction in whole contiguous operations
        # (an (N, 2) slice costs numpy several times more).
        z = out.view(np.complex128).ravel()
        norm = np.abs(z)
        threshold = self.config.up_threshold
        # Every row strong (the smallest norm at the threshold; NaN fails it): one pass.
        if all_valid and (len(norm) == 0 or norm.min() >= threshold):
            self.gravity = out
            self.up = (z / -norm).view(np.float64).reshape(-1, 2)
            self.up_complete = True
            return
        strong = norm >= threshold  # False for NaN rows
        finite = np.isfinite(norm)
        if finite.all():
            self.gravity = out
        else:
            np.copyto(self.gravity, out, where=finite[:, None])
        # Weak rows are dropped below; a subnormal norm may overflow there, harmlessly.
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            direction = z / -norm
        held = self.up.view(np.complex128).ravel()
        self.up = np.where(strong, direction, held).view(np.float64).reshape(-1, 2)
        if not self.up_complete:
            self.up_complete = bool(np.isfinite(self.up).all())
