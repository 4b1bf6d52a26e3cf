"""Signals and helpers the filter tests share, as fixtures (any test module here can use them)."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from numpy.typing import NDArray

from playground.filters import Filter

DT = 1 / 60
"""The physics step, s: the sample period of the signals here."""

Array = NDArray[np.float64]
Signal = Callable[[np.random.Generator, int, int], Array]
Rotation = Callable[..., Array]
Run = Callable[[Filter, Array, Array], Array]


def _signal(rng: np.random.Generator, n: int, k: int) -> Array:
    """n samples of k-vectors: a slow random walk plus a fast sine burst plus noise."""
    t = np.arange(n)[:, None] * DT
    walk = np.cumsum(rng.normal(0.0, 0.05, size=(n, k)), axis=0)
    burst = 3.0 * np.sin(2 * np.pi * rng.uniform(0.5, 3.0, size=k) * t + rng.uniform(0, 6, size=k))
    out: Array = walk + burst * (t > n * DT / 2) + rng.normal(0.0, 0.1, size=(n, k))
    return out


def _rotation(theta: float, k: int = 2) -> Array:
    """A rotation by theta (rad) in the first two axes of k-space."""
    r = np.eye(k)
    c, s = math.cos(theta), math.sin(theta)
    r[:2, :2] = [[c, -s], [s, c]]
    return r


def _run(f: Filter, xs: Array, dts: Array) -> Array:
    """Feed samples xs[i] with periods dts[i]; stack the outputs."""
    return np.array([f.filter(x, float(dt)) for x, dt in zip(xs, dts, strict=True)])


@pytest.fixture(scope="session")
def signal() -> Signal:
    """``signal(rng, n, k)``: n samples of k-vectors, a random walk with a burst and noise."""
    return _signal


@pytest.fixture(scope="session")
def rotation() -> Rotation:
    """``rotation(theta, k=2)``: a rotation by theta (rad) in the first two axes of k-space."""
    return _rotation


@pytest.fixture(scope="session")
def run() -> Run:
    """``run(filter, xs, dts)``: feed xs[i] with periods dts[i]; the stacked outputs."""
    return _run
