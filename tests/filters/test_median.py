"""Laws of the median of 3: spikes removed, warm-up, the vector median and its frame invariance."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.typing import NDArray

from playground.filters.median import Median3

# Rotating and translating by up to 5 units O(3) samples rounds their low bits: ~ulp(10) each.
TOL_FRAME = 1e-11

Helper = Callable[..., NDArray[np.float64]]
"""The type of the ``signal``, ``run`` and ``rotation`` fixtures (tests/filters/conftest.py)."""

DT = 1 / 60  # s, the physics step


@settings(max_examples=100, deadline=None)
@given(
    start=st.floats(-100, 100),
    slope=st.floats(-1, 1),
    at=st.integers(1, 19),  # a first sample has no past to be judged against
    height=st.floats(-1e300, 1e300),
)
def test_median3_removes_a_single_step_spike(
    start: float, slope: float, at: int, height: float
) -> None:
    """On a monotone ramp the median of 3 is the input one step late; a single-step spike of
    any height beyond the ramp's two-step change never reaches the output, which is always a
    non-spike sample from the last three steps.
    """
    n = 20
    ramp = start + slope * np.arange(n)
    m = Median3()
    late = [m.filter(float(x), DT) for x in ramp]
    np.testing.assert_array_equal(late, np.concatenate([ramp[:1], ramp[:-1]]))
    spiky = ramp.copy()
    spiky[at] += height
    # The law needs a spike beyond the ramp's two-step change, measured on the rounded values.
    if not abs(spiky[at] - ramp[at]) > 2 * np.abs(np.diff(ramp)).max():
        return
    m = Median3()
    out = [m.filter(float(x), DT) for x in spiky]
    for i, y in enumerate(out):
        window = [j for j in range(max(i - 2, 0), i + 1) if j != at]
        assert y in ramp[window]


def test_median3_warm_up_and_vector_spike() -> None:
    """Warm-up: output 1 is sample 1 and output 2 is sample 1 again (two samples tie to the
    older). A vector spike on a constant is removed completely.
    """
    m = Median3()
    base = np.array([1.0, -2.0])
    outs = [
        m.filter(x, DT)
        for x in (base, base + np.array([50.0, 80.0]), base, base, base - np.array([0, 1e9]), base)
    ]
    for y in outs:
        np.testing.assert_array_equal(y, base)


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(-math.pi, math.pi), seed=st.integers(0, 2**32 - 1))
def test_median3_is_rotation_and_translation_equivariant(
    theta: float, seed: int, run: Helper, rotation: Helper
) -> None:
    """The vector median picks the same sample in any frame: median(R·x + t) = R·median(x) + t."""
    rng = np.random.default_rng(seed)
    xs = rng.normal(size=(60, 5, 2)) * 3.0
    rot = rotation(theta)
    t = rng.uniform(-5, 5, size=2)
    plain = run(Median3(), xs, np.full(60, DT))
    moved = run(Median3(), xs @ rot.T + t, np.full(60, DT))
    np.testing.assert_allclose(moved, plain @ rot.T + t, rtol=0, atol=TOL_FRAME)


def test_median3_picks_one_of_the_samples(run: Helper) -> None:
    """The vector median minimises the summed distance to the other two samples, and is one of
    them (checked against a brute-force search over random triples).
    """
    rng = np.random.default_rng(8)
    xs = rng.normal(size=(30, 40, 2))
    out = run(Median3(), xs, np.full(30, DT))
    for i in range(2, 30):
        w = xs[i - 2 : i + 1]  # (3, rows, 2)
        cost = np.array(
            [
                np.linalg.norm(w[a] - w[(a + 1) % 3], axis=1)
                + np.linalg.norm(w[a] - w[(a + 2) % 3], axis=1)
                for a in range(3)
            ]
        )
        best = w[np.argmin(cost, axis=0), np.arange(40)]
        np.testing.assert_array_equal(out[i], best)
