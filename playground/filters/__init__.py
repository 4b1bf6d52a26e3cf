"""Smoothing filters for noisy per-step signals (measured forces, accelerations, gravity).

Owns the 1€ filter (Casiez, Roussel & Vogel, CHI 2012, doi:10.1145/2207676.2208639), its β = 0
special case the exponential moving average (:mod:`~playground.filters.one_euro`), a median-of-3
spike pre-stage (:mod:`~playground.filters.median`) and a chain of stages
(:mod:`~playground.filters.chain`). All of them share one interface, ``filter(x, dt)``,
``reset()``, ``select(rows)``, ``value``, with the shapes and guards that
:mod:`~playground.filters.row_filter` states; :mod:`~playground.filters.rows` holds the row
layout they are built on.

>>> f = FilterChain(Median3(), OneEuroFilter(min_cutoff=1.0, beta=0.5))
>>> [f.filter(v, dt=0.01) for v in (2.5, 2.5, 90.0, 2.5)]
[2.5, 2.5, 2.5, 2.5]
"""

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter
from playground.filters.row_filter import Filter

__all__ = ["ExponentialMovingAverage", "Filter", "FilterChain", "Median3", "OneEuroFilter"]
