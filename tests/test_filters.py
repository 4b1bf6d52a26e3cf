"""Laws of playground.filters: the 1€ filter against its reference, equivariance, guards, spikes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.typing import NDArray
from OneEuroFilter import OneEuroFilter as ReferenceOneEuro

from playground.filters import (
    ExponentialMovingAverage,
    Filter,
    FilterChain,
    Median3,
    OneEuroFilter,
)

# The reference and we evaluate the same formulas in a different order (it divides by
# 1/freq, we multiply by 2π·fc·Te): rounding differences of ~1e-15 per step, far below this.
TOL_REFERENCE = 1e-9
# OneEuroFilter(beta=0) and ExponentialMovingAverage evaluate the same α in different code.
TOL_EMA = 1e-12
# A rotation changes the norm of the derivative by a few ulps only; signals are O(1) to O(10).
TOL_EQUIVARIANT = 1e-12
# Translating by up to 10 units loses the low bits of O(1) signals: ~ulp(10) = 2e-15 per step.
TOL_TRANSLATION = 1e-11
# Different row counts can take different SIMD paths in numpy, which may round differently.
TOL_VECTORISED = 1e-12
# How many times our rotation error the per-component filter's error must at least be, for
# per-component filtering to count as clearly not equivariant (ours is at rounding level).
NOT_EQUIVARIANT_FACTOR = 1e6

DT = 1 / 60  # s, the physics step


def _signal(rng: np.random.Generator, n: int, k: int) -> NDArray[np.float64]:
    """n samples of k-vectors: a slow random walk plus a fast sine burst plus noise."""
    t = np.arange(n)[:, None] * DT
    walk = np.cumsum(rng.normal(0.0, 0.05, size=(n, k)), axis=0)
    burst = 3.0 * np.sin(2 * np.pi * rng.uniform(0.5, 3.0, size=k) * t + rng.uniform(0, 6, size=k))
    return walk + burst * (t > n * DT / 2) + rng.normal(0.0, 0.1, size=(n, k))


def _rotation(theta: float, k: int = 2) -> NDArray[np.float64]:
    """A rotation by theta (rad) in the first two axes of k-space."""
    r = np.eye(k)
    c, s = math.cos(theta), math.sin(theta)
    r[:2, :2] = [[c, -s], [s, c]]
    return r


def _run(f: Filter, xs: NDArray[np.float64], dts: NDArray[np.float64]) -> NDArray[np.float64]:
    """Feed samples xs[i] with periods dts[i]; stack the outputs."""
    return np.array([f.filter(x, float(dt)) for x, dt in zip(xs, dts, strict=True)])


PARAMS = [  # (min_cutoff Hz, beta 1/unit, d_cutoff Hz)
    (1.0, 0.0, 1.0),
    (1.0, 0.007, 1.0),
    (0.3, 0.5, 1.0),
    (2.5, 5.0, 0.4),
    (0.05, 40.0, 3.0),
]


# -- the reference ---------------------------------------------------------------------------


@pytest.mark.parametrize("params", PARAMS)
@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("variable_dt", [False, True])
def test_scalar_matches_reference(
    params: tuple[float, float, float], seed: int, variable_dt: bool
) -> None:
    """Scalar mode is the paper's filter: it matches the reference OneEuroFilter 0.2.1.

    The reference takes timestamps (and treats 0.0 as "none"), so they start at 1 s and our
    dt is the difference of the very timestamps it sees.
    """
    rng = np.random.default_rng(seed)
    n = 400
    xs = _signal(rng, n, 1)[:, 0]
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
def test_beta_zero_is_ema(seed: int) -> None:
    """With β = 0 the 1€ filter is the exponential moving average at min_cutoff."""
    rng = np.random.default_rng(seed)
    xs = _signal(rng, 300, 2).reshape(300, 1, 2) * [[1.0, 1.0], [2.0, -1.0], [0.5, 3.0]]
    dts = rng.uniform(0.004, 0.04, size=300)
    one_euro = _run(OneEuroFilter(min_cutoff=0.7, beta=0.0, d_cutoff=2.0), xs, dts)
    ema = _run(ExponentialMovingAverage(cutoff=0.7), xs, dts)
    np.testing.assert_allclose(one_euro, ema, rtol=0, atol=TOL_EMA)


# -- equivariance ----------------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(-math.pi, math.pi), seed=st.integers(0, 2**32 - 1))
def test_vector_mode_is_rotation_equivariant(theta: float, seed: int) -> None:
    """Rotating the input sequence rotates the output: filter(R·x) = R·filter(x)."""
    rng = np.random.default_rng(seed)
    xs = _signal(rng, 200, 2)
    rot = _rotation(theta)
    f, g = OneEuroFilter(0.5, 2.0, 1.0), OneEuroFilter(0.5, 2.0, 1.0)
    plain = _run(f, xs, np.full(200, DT))
    rotated = _run(g, xs @ rot.T, np.full(200, DT))
    np.testing.assert_allclose(rotated, plain @ rot.T, rtol=0, atol=TOL_EQUIVARIANT)


def test_three_vectors_are_rotation_equivariant() -> None:
    """The general k >= 3 layout shares the law: filter(R·x) = R·filter(x) in 3-D."""
    rng = np.random.default_rng(7)
    xs = _signal(rng, 200, 3)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    plain = _run(OneEuroFilter(0.5, 2.0), xs, np.full(200, DT))
    rotated = _run(OneEuroFilter(0.5, 2.0), xs @ q.T, np.full(200, DT))
    np.testing.assert_allclose(rotated, plain @ q.T, rtol=0, atol=TOL_EQUIVARIANT)


@settings(max_examples=40, deadline=None)
@given(
    shift=st.tuples(st.floats(-10, 10), st.floats(-10, 10)),
    seed=st.integers(0, 2**32 - 1),
)
def test_vector_mode_is_translation_equivariant(shift: tuple[float, float], seed: int) -> None:
    """Shifting the input sequence shifts the output: filter(x + t) = filter(x) + t."""
    rng = np.random.default_rng(seed)
    xs = _signal(rng, 200, 2)
    t = np.array(shift)
    plain = _run(OneEuroFilter(0.5, 2.0), xs, np.full(200, DT))
    shifted = _run(OneEuroFilter(0.5, 2.0), xs + t, np.full(200, DT))
    np.testing.assert_allclose(shifted, plain + t, rtol=0, atol=TOL_TRANSLATION)


def test_per_component_filtering_is_not_rotation_equivariant() -> None:
    """One cutoff from the derivative's norm is what buys equivariance: filtering x and y with
    separate scalar 1€ filters (β > 0) breaks it by many orders of magnitude more than ours.
    """
    rng = np.random.default_rng(3)
    xs = _signal(rng, 300, 2)
    rot = _rotation(0.7)
    dts = np.full(300, DT)

    def per_component(samples: NDArray[np.float64]) -> NDArray[np.float64]:
        fx, fy = OneEuroFilter(0.5, 2.0), OneEuroFilter(0.5, 2.0)
        return np.array([[fx.filter(float(a), DT), fy.filter(float(b), DT)] for a, b in samples])

    ours_error = np.abs(
        _run(OneEuroFilter(0.5, 2.0), xs @ rot.T, dts)
        - _run(OneEuroFilter(0.5, 2.0), xs, dts) @ rot.T
    ).max()
    theirs_error = np.abs(per_component(xs @ rot.T) - per_component(xs) @ rot.T).max()
    assert ours_error <= TOL_EQUIVARIANT
    assert theirs_error > NOT_EQUIVARIANT_FACTOR * max(ours_error, np.finfo(float).eps)


# -- basic laws ------------------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    c=st.floats(-1e6, 1e6),
    dt=st.floats(1e-4, 1.0),
    beta=st.floats(0.0, 100.0),
    n=st.integers(1, 50),
)
def test_constant_in_constant_out(c: float, dt: float, beta: float, n: int) -> None:
    """A constant input is returned exactly, from the first sample on.

    Exact equality is the law here, not luck: X̂ moves by α·(X − X̂), and X − X̂ is exactly 0.
    """
    f = OneEuroFilter(min_cutoff=1.0, beta=beta)
    assert all(f.filter(c, dt) == c for _ in range(n))
    g = OneEuroFilter(min_cutoff=1.0, beta=beta)
    row = np.array([[c, -c], [0.5 * c, 2.0]])
    for _ in range(n):
        np.testing.assert_array_equal(g.filter(row, dt), row)


@settings(max_examples=60, deadline=None)
@given(x=st.floats(allow_nan=False, allow_infinity=False), dt=st.floats(allow_nan=True))
def test_first_output_is_first_input(x: float, dt: float) -> None:
    """X̂_1 = X_1 exactly, whatever dt (the first sample needs none), for every filter."""
    for f in (OneEuroFilter(1.0, 3.0), ExponentialMovingAverage(), Median3()):
        assert f.filter(x, dt) == x
    chain = FilterChain(Median3(), OneEuroFilter(1.0, 3.0))
    np.testing.assert_array_equal(chain.filter([x, -x], dt), [x, -x])


def test_output_forms() -> None:
    """A float is a 1-vector and comes back a float; (k,) comes back (k,); (N, k) as (N, k)."""
    assert isinstance(OneEuroFilter().filter(1.0, DT), float)
    assert OneEuroFilter().filter([1.0, 2.0], DT).shape == (2,)
    assert OneEuroFilter().filter(np.zeros((4, 3)), DT).shape == (4, 3)
    f = OneEuroFilter()
    before = f.value
    assert before is None, "no output before the first sample"
    f.filter(2.0, DT)
    value = f.value
    assert value is not None and value.shape == (1, 1)


@pytest.mark.parametrize("k", [1, 2, 3])
def test_vectorised_rows_equal_separate_filters(k: int) -> None:
    """Filtering (N, k) rows at once equals N separate k-vector filters run one by one."""
    rng = np.random.default_rng(k)
    n_rows, n = 7, 150
    xs = np.stack([_signal(rng, n, k) for _ in range(n_rows)], axis=1)  # (n, N, k)
    dts = rng.uniform(0.004, 0.04, size=n)
    batch = _run(OneEuroFilter(0.8, 1.5, 1.2), xs, dts)
    for j in range(n_rows):
        alone = _run(OneEuroFilter(0.8, 1.5, 1.2), xs[:, j, :], dts)
        np.testing.assert_allclose(batch[:, j, :], alone, rtol=0, atol=TOL_VECTORISED)


def test_k1_rows_equal_scalar_filter() -> None:
    """For k = 1 the vector norm is |x|: (N, 1) rows are N scalar filters."""
    rng = np.random.default_rng(11)
    xs = _signal(rng, 200, 3)  # three scalar channels
    batch = _run(OneEuroFilter(0.8, 1.5), xs[:, :, None], np.full(200, DT))[:, :, 0]
    for j in range(3):
        f = OneEuroFilter(0.8, 1.5)
        alone = [f.filter(float(x), DT) for x in xs[:, j]]
        np.testing.assert_allclose(batch[:, j], alone, rtol=0, atol=TOL_VECTORISED)


def test_select_removes_adds_and_reorders_rows() -> None:
    """select() keeps each body's history: rows removed, added (-1) and reordered give the
    same outputs as one separate filter per body.
    """
    rng = np.random.default_rng(5)
    n = 90
    paths = {body: _signal(rng, n, 2) for body in "abcdefg"}
    # Which bodies are tracked, in row order, from a given step on.
    schedule = {0: list("abcde"), 30: list("eca"), 50: list("fcag"), 70: list("gb")}
    batch = OneEuroFilter(0.5, 2.0)
    separate: dict[str, OneEuroFilter] = {}
    rows: list[str] = []
    for i in range(n):
        if i in schedule:
            new_rows = schedule[i]
            if rows:
                batch.select(np.array([rows.index(b) if b in rows else -1 for b in new_rows]))
            for body in new_rows:
                if body not in rows:
                    separate[body] = OneEuroFilter(0.5, 2.0)  # a (re)appearing body starts over
            rows = new_rows
        out = batch.filter(np.array([paths[b][i] for b in rows]), DT)
        for j, body in enumerate(rows):
            expected = separate[body].filter(paths[body][i], DT)
            np.testing.assert_allclose(out[j], expected, rtol=0, atol=TOL_VECTORISED)


def test_select_new_rows_are_uninitialised() -> None:
    """A row added by select() outputs NaN in value until its first sample, which it returns."""
    f = OneEuroFilter(1.0, 1.0)
    f.filter([[1.0, 2.0]], DT)
    f.select(np.array([0, -1]))
    assert f.value is not None
    assert np.isnan(f.value[1]).all() and (f.value[0] == [1.0, 2.0]).all()
    out = f.filter([[1.0, 2.0], [5.0, 6.0]], DT)
    np.testing.assert_array_equal(out[1], [5.0, 6.0])


def test_row_count_is_fixed_without_select() -> None:
    """The first sample fixes (N, k); another shape is a ValueError until select() is called."""
    f = OneEuroFilter()
    f.filter(np.zeros((3, 2)), DT)
    with pytest.raises(ValueError, match="select"):
        f.filter(np.zeros((2, 2)), DT)
    with pytest.raises(ValueError, match="component"):
        f.filter(np.zeros((3, 3)), DT)
    f.select(np.array([0, 2]))
    assert f.filter(np.zeros((2, 2)), DT).shape == (2, 2)
    with pytest.raises(ValueError, match="rows"):
        f.select(np.array([0, 5]))
    with pytest.raises(ValueError, match="rows"):
        f.select(np.array([-2]))


def test_reset_forgets_everything() -> None:
    """After reset() the filter behaves as newly constructed, shape included."""
    rng = np.random.default_rng(2)
    xs = _signal(rng, 50, 2)
    f = OneEuroFilter(0.5, 2.0)
    _run(f, xs, np.full(50, DT))
    f.reset()
    assert f.value is None
    np.testing.assert_array_equal(
        _run(f, xs, np.full(50, DT)), _run(OneEuroFilter(0.5, 2.0), xs, np.full(50, DT))
    )
    f.reset()
    assert f.filter(np.ones((4, 3)), DT).shape == (4, 3)


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


# -- guards ----------------------------------------------------------------------------------


@pytest.mark.parametrize("bad_dt", [0.0, -DT, math.nan, math.inf, -math.inf])
def test_bad_dt_holds(bad_dt: float) -> None:
    """dt <= 0 or non-finite returns the previous output and leaves the state untouched: the
    rest of the sequence is as if that call never happened.
    """
    rng = np.random.default_rng(9)
    xs = _signal(rng, 60, 2)
    f, g = OneEuroFilter(0.5, 2.0), OneEuroFilter(0.5, 2.0)
    for i, x in enumerate(xs):
        if i == 20:
            before = f.value
            held = f.filter(x * 100.0, bad_dt)
            np.testing.assert_array_equal(held, before[0])  # type: ignore[index]
        np.testing.assert_array_equal(f.filter(x, DT), g.filter(x, DT))


_GOOD_DT = st.floats(1e-4, 0.1)
_BAD_DT = st.sampled_from([0.0, -0.01, math.nan, math.inf, -math.inf])
_GOOD_X = st.floats(-1e3, 1e3)
_BAD_X = st.sampled_from([math.nan, math.inf, -math.inf])
_EXTREME_X = st.sampled_from([1e308, -1e308, 1.7e308])


@settings(max_examples=150, deadline=None)
@given(
    data=st.data(),
    n_rows=st.integers(1, 4),
    n_steps=st.integers(1, 25),
    beta=st.sampled_from([0.0, 0.5, 50.0]),
)
def test_bad_samples_never_poison_state(
    data: st.DataObject, n_rows: int, n_steps: int, beta: float
) -> None:
    """Random NaN/inf components, extreme values and bad dts: each row behaves exactly like a
    separate filter fed only that row's finite samples (bad rows hold, good rows are unaffected,
    never-initialised rows output NaN), and the state stays finite, so a final good sample gives
    a finite output for every row.
    """
    f = OneEuroFilter(0.7, beta)
    alone = [OneEuroFilter(0.7, beta) for _ in range(n_rows)]
    component = st.one_of(_GOOD_X, _GOOD_X, _GOOD_X, _BAD_X, _EXTREME_X)
    for _ in range(n_steps):
        dt = data.draw(st.one_of(_GOOD_DT, _GOOD_DT, _BAD_DT))
        x = np.array(
            data.draw(st.lists(st.tuples(component, component), min_size=n_rows, max_size=n_rows))
        )
        out = f.filter(x, dt)
        for j in range(n_rows):
            if np.isfinite(x[j]).all():
                expected = alone[j].filter(x[j], dt)
            else:
                v = alone[j].value
                expected = np.full(2, np.nan) if v is None else v[0]
            np.testing.assert_allclose(out[j], expected, rtol=0, atol=TOL_VECTORISED)
            assert np.isfinite(out[j]).all() or np.isnan(out[j]).all()
    final = f.filter(np.ones((n_rows, 2)), 0.01)
    assert np.isfinite(final).all()


def test_uninitialised_row_with_bad_sample_outputs_nan_and_waits() -> None:
    """A never-initialised row given a non-finite sample stays uninitialised (NaN output); its
    next finite sample is its first, returned as is; the other rows proceed.
    """
    f = OneEuroFilter(1.0, 1.0)
    out = f.filter([[math.nan, 0.0], [1.0, 1.0]], DT)
    assert np.isnan(out[0]).all() and (out[1] == [1.0, 1.0]).all()
    out = f.filter([[7.0, 8.0], [1.0, 1.0]], DT)
    assert (out[0] == [7.0, 8.0]).all() and (out[1] == [1.0, 1.0]).all()
    assert math.isnan(OneEuroFilter().filter(math.inf, DT))


@pytest.mark.parametrize(
    "make",
    [
        lambda: OneEuroFilter(0.5, 2.0),
        ExponentialMovingAverage,
        Median3,
        lambda: FilterChain(Median3(), OneEuroFilter(0.5, 2.0)),
    ],
)
def test_non_finite_sample_is_skipped(make: object) -> None:
    """For every filter and the chain, a non-finite sample holds the output and the state:
    the rest of the sequence is as if that sample had never been given.
    """
    rng = np.random.default_rng(4)
    xs = _signal(rng, 40, 2)
    f, g = make(), make()  # type: ignore[operator]
    for i, x in enumerate(xs):
        if i in (10, 11, 25):
            before = f.value
            held = f.filter([math.inf, 0.0] if i == 10 else [math.nan, 1.0], DT)
            np.testing.assert_array_equal(held, before[0])
        np.testing.assert_array_equal(f.filter(x, DT), g.filter(x, DT))


# -- median of 3 and the chain -----------------------------------------------------------------


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
def test_median3_is_rotation_and_translation_equivariant(theta: float, seed: int) -> None:
    """The vector median picks the same sample in any frame: median(R·x + t) = R·median(x) + t."""
    rng = np.random.default_rng(seed)
    xs = rng.normal(size=(60, 5, 2)) * 3.0
    rot = _rotation(theta)
    t = rng.uniform(-5, 5, size=2)
    plain = _run(Median3(), xs, np.full(60, DT))
    moved = _run(Median3(), xs @ rot.T + t, np.full(60, DT))
    np.testing.assert_allclose(moved, plain @ rot.T + t, rtol=0, atol=TOL_TRANSLATION)


def test_median3_picks_one_of_the_samples() -> None:
    """The vector median minimises the summed distance to the other two samples, and is one of
    them (checked against a brute-force search over random triples).
    """
    rng = np.random.default_rng(8)
    xs = rng.normal(size=(30, 40, 2))
    out = _run(Median3(), xs, np.full(30, DT))
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


@settings(max_examples=50, deadline=None)
@given(height=st.floats(5.0, 1e6), at=st.integers(20, 100), seed=st.integers(0, 2**32 - 1))
def test_chain_peak_not_higher_than_one_euro_alone(height: float, at: int, seed: int) -> None:
    """Median3 before 1€ keeps a bounce spike out: the chain's peak stays within the clean
    signal's range and is never higher than the peak of 1€ alone, which lets the spike through.
    """
    rng = np.random.default_rng(seed)
    n = 150
    clean = np.sin(np.arange(n) * DT * 2 * np.pi) + rng.normal(0.0, 0.05, size=n)
    spiky = clean.copy()
    spiky[at] += height
    chain = FilterChain(Median3(), OneEuroFilter(1.0, 0.5))
    alone = OneEuroFilter(1.0, 0.5)
    chain_out = [chain.filter(float(x), DT) for x in spiky]
    alone_out = [alone.filter(float(x), DT) for x in spiky]
    assert max(chain_out) <= clean.max()
    assert max(chain_out) <= max(alone_out)


def test_chain_interface() -> None:
    """The chain shares the interface: select and reset reach every stage; value is the last's."""
    chain = FilterChain(Median3(), OneEuroFilter(1.0, 0.5))
    before = chain.value
    assert before is None, "no output before the first sample"
    chain.filter(np.array([[1.0, 2.0], [3.0, 4.0]]), DT)
    chain.select(np.array([1]))
    np.testing.assert_array_equal(chain.filter(np.array([[3.0, 4.0]]), DT), [[3.0, 4.0]])
    value = chain.value
    assert value is not None and value.shape == (1, 2)
    chain.reset()
    assert all(s.value is None for s in (chain, *chain.stages))
    with pytest.raises(ValueError, match="stages"):
        FilterChain()
