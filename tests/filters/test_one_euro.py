"""Laws of the 1€ filter and the exponential moving average: the reference, β = 0, frames."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.typing import NDArray
from OneEuroFilter import OneEuroFilter as ReferenceOneEuro

from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter

# The reference and we evaluate the same formulas in a different order (it divides by
# 1/freq, we multiply by 2π·fc·Te): rounding differences of ~1e-15 per step, far below this.
TOL_REFERENCE = 1e-9
# OneEuroFilter(beta=0) and ExponentialMovingAverage evaluate the same α in different code.
TOL_EMA = 1e-12
# A rotation changes the norm of the derivative by a few ulps only; signals are O(1) to O(10).
TOL_EQUIVARIANT = 1e-12
# Translating by up to 10 units loses the low bits of O(1) signals: ~ulp(10) = 2e-15 per step.
TOL_TRANSLATION = 1e-11
# How many times our rotation error the per-component filter's error must at least be, for
# per-component filtering to count as clearly not equivariant (ours is at rounding level).
NOT_EQUIVARIANT_FACTOR = 1e6

Helper = Callable[..., NDArray[np.float64]]
"""The type of the ``signal``, ``run`` and ``rotation`` fixtures (tests/filters/conftest.py)."""

DT = 1 / 60  # s, the physics step

PARAMS = [  # (min_cutoff Hz, beta 1/unit, d_cutoff Hz)
    (1.0, 0.0, 1.0),
    (1.0, 0.007, 1.0),
    (0.3, 0.5, 1.0),
    (2.5, 5.0, 0.4),
    (0.05, 40.0, 3.0),
]


@pytest.mark.parametrize("params", PARAMS)
@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("variable_dt", [False, True])
def test_scalar_matches_reference(
    params: tuple[float, float, float], seed: int, variable_dt: bool, signal: Helper
) -> None:
    """Scalar mode is the paper's filter: it matches the reference OneEuroFilter 0.2.1.

    The reference takes timestamps (and treats 0.0 as "none"), so they start at 1 s and our
    dt is the difference of the very timestamps it sees.
    """
    rng = np.random.default_rng(seed)
    n = 400
    xs = signal(rng, n, 1)[:, 0]
    steps = rng.uniform(0.004, 0.04, size=n) if variable_dt else np.full(n, DT)
    stamps = 1.0 + np.cumsum(steps)
    dts = np.diff(stamps, prepend=stamps[0] - steps[0])
    mc, beta, dc = params
    ref = ReferenceOneEuro(freq=60.0, mincutoff=mc, beta=beta, dcutoff=dc)
    expected = [ref(float(x), float(t)) for x, t in zip(xs, stamps, strict=True)]
    ours = OneEuroFilter(min_cutoff=mc, beta=beta, d_cutoff=dc)
    got = [ours.filter(float(x), float(dt)) for x, dt in zip(xs, dts, strict=True)]
    assert all(isinstance(y, float) for y in got)
    np.testing.assert_allclose(got, expected, rtol=0, atol=TOL_REFERENCE)


@pytest.mark.parametrize("seed", [0, 1])
def test_beta_zero_is_ema(seed: int, signal: Helper, run: Helper) -> None:
    """With β = 0 the 1€ filter is the exponential moving average at min_cutoff."""
    rng = np.random.default_rng(seed)
    xs = signal(rng, 300, 2).reshape(300, 1, 2) * [[1.0, 1.0], [2.0, -1.0], [0.5, 3.0]]
    dts = rng.uniform(0.004, 0.04, size=300)
    one_euro = run(OneEuroFilter(min_cutoff=0.7, beta=0.0, d_cutoff=2.0), xs, dts)
    ema = run(ExponentialMovingAverage(cutoff=0.7), xs, dts)
    np.testing.assert_allclose(one_euro, ema, rtol=0, atol=TOL_EMA)


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(-math.pi, math.pi), seed=st.integers(0, 2**32 - 1))
def test_vector_mode_is_rotation_equivariant(
    theta: float, seed: int, signal: Helper, run: Helper, rotation: Helper
) -> None:
    """Rotating the input sequence rotates the output: filter(R·x) = R·filter(x)."""
    rng = np.random.default_rng(seed)
    xs = signal(rng, 200, 2)
    rot = rotation(theta)
    f, g = OneEuroFilter(0.5, 2.0, 1.0), OneEuroFilter(0.5, 2.0, 1.0)
    plain = run(f, xs, np.full(200, DT))
    rotated = run(g, xs @ rot.T, np.full(200, DT))
    np.testing.assert_allclose(rotated, plain @ rot.T, rtol=0, atol=TOL_EQUIVARIANT)


def test_three_vectors_are_rotation_equivariant(signal: Helper, run: Helper) -> None:
    """The general k >= 3 layout shares the law: filter(R·x) = R·filter(x) in 3-D."""
    rng = np.random.default_rng(7)
    xs = signal(rng, 200, 3)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    plain = run(OneEuroFilter(0.5, 2.0), xs, np.full(200, DT))
    rotated = run(OneEuroFilter(0.5, 2.0), xs @ q.T, np.full(200, DT))
    np.testing.assert_allclose(rotated, plain @ q.T, rtol=0, atol=TOL_EQUIVARIANT)


@settings(max_examples=40, deadline=None)
@given(
    shift=st.tuples(st.floats(-10, 10), st.floats(-10, 10)),
    seed=st.integers(0, 2**32 - 1),
)
def test_vector_mode_is_translation_equivariant(
    shift: tuple[float, float], seed: int, signal: Helper, run: Helper
) -> None:
    """Shifting the input sequence shifts the output: filter(x + t) = filter(x) + t."""
    rng = np.random.default_rng(seed)
    xs = signal(rng, 200, 2)
    t = np.array(shift)
    plain = run(OneEuroFilter(0.5, 2.0), xs, np.full(200, DT))
    shifted = run(OneEuroFilter(0.5, 2.0), xs + t, np.full(200, DT))
    np.testing.assert_allclose(shifted, plain + t, rtol=0, atol=TOL_TRANSLATION)


def test_per_component_filtering_is_not_rotation_equivariant(
    signal: Helper, run: Helper, rotation: Helper
) -> None:
    """One cutoff from the derivative's norm is what buys equivariance: filtering x and y with
    separate scalar 1€ filters (β > 0) breaks it by many orders of magnitude more than ours.
    """
    rng = np.random.default_rng(3)
    xs = signal(rng, 300, 2)
    rot = rotation(0.7)
    dts = np.full(300, DT)

    def per_component(samples: NDArray[np.float64]) -> NDArray[np.float64]:
        fx, fy = OneEuroFilter(0.5, 2.0), OneEuroFilter(0.5, 2.0)
        return np.array([[fx.filter(float(a), DT), fy.filter(float(b), DT)] for a, b in samples])

    ours_error = np.abs(
        run(OneEuroFilter(0.5, 2.0), xs @ rot.T, dts)
        - run(OneEuroFilter(0.5, 2.0), xs, dts) @ rot.T
    ).max()
    theirs_error = np.abs(per_component(xs @ rot.T) - per_component(xs) @ rot.T).max()
    assert ours_error <= TOL_EQUIVARIANT
    assert theirs_error > NOT_EQUIVARIANT_FACTOR * max(ours_error, np.finfo(float).eps)


@pytest.mark.parametrize(
    ("make", "name"),
    [
        (lambda v: OneEuroFilter(min_cutoff=v), "min_cutoff"),
        (lambda v: OneEuroFilter(d_cutoff=v), "d_cutoff"),
        (lambda v: ExponentialMovingAverage(cutoff=v), "cutoff"),
    ],
)
@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_cutoffs_must_be_positive_and_finite(make: object, name: str, bad: float) -> None:
    """A cutoff that is not a finite frequency > 0 Hz is refused, naming the parameter."""
    with pytest.raises(ValueError, match=rf"^{name}: expected a finite frequency > 0 Hz"):
        make(bad)  # type: ignore[operator]


@pytest.mark.parametrize("bad", [-0.1, math.nan, -math.inf, math.inf])
def test_beta_must_be_non_negative_and_finite(bad: float) -> None:
    """β must be finite and >= 0; the error names it."""
    with pytest.raises(ValueError, match=r"^beta: expected a finite number >= 0"):
        OneEuroFilter(beta=bad)


def test_filter_rows_is_filter_bit_for_bit() -> None:
    """Law: ``filter_rows`` (the shortcut a world's perceived gravity takes every step) gives what
    ``filter`` gives, to the last bit and with the same state after: on rows that all started, on
    a first sample, with a NaN row, and with a dt that is not valid (both hold)."""
    rng = np.random.default_rng(5)
    short, generic = OneEuroFilter(2.0, 0.05, 1.0), OneEuroFilter(2.0, 0.05, 1.0)
    for step in range(200):
        x = rng.normal(size=(40, 2)) * 10.0 + 9.81
        if step % 17 == 3:
            x[7] = np.nan
        dt = 0.0 if step % 23 == 5 else 1.0 / 120.0
        a, b = short.filter_rows(x, dt), generic.filter(x, dt)
        assert a.tobytes() == b.tobytes(), step
        assert short.value is not None and generic.value is not None
        assert short.value.tobytes() == generic.value.tobytes(), step
