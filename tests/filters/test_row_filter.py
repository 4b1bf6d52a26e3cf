"""Laws every per-row filter shares: shapes, rows (vectorised, selected, reset) and the guards."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.typing import NDArray

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter

# Different row counts can take different SIMD paths in numpy, which may round differently.
TOL_VECTORISED = 1e-12

Helper = Callable[..., NDArray[np.float64]]
"""The type of the ``signal``, ``run`` and ``rotation`` fixtures (tests/filters/conftest.py)."""

DT = 1 / 60  # s, the physics step

_GOOD_DT = st.floats(1e-4, 0.1)
_BAD_DT = st.sampled_from([0.0, -0.01, math.nan, math.inf, -math.inf])
_GOOD_X = st.floats(-1e3, 1e3)
_BAD_X = st.sampled_from([math.nan, math.inf, -math.inf])
_EXTREME_X = st.sampled_from([1e308, -1e308, 1.7e308])


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
def test_vectorised_rows_equal_separate_filters(k: int, signal: Helper, run: Helper) -> None:
    """Filtering (N, k) rows at once equals N separate k-vector filters run one by one."""
    rng = np.random.default_rng(k)
    n_rows, n = 7, 150
    xs = np.stack([signal(rng, n, k) for _ in range(n_rows)], axis=1)  # (n, N, k)
    dts = rng.uniform(0.004, 0.04, size=n)
    batch = run(OneEuroFilter(0.8, 1.5, 1.2), xs, dts)
    for j in range(n_rows):
        alone = run(OneEuroFilter(0.8, 1.5, 1.2), xs[:, j, :], dts)
        np.testing.assert_allclose(batch[:, j, :], alone, rtol=0, atol=TOL_VECTORISED)


def test_k1_rows_equal_scalar_filter(signal: Helper, run: Helper) -> None:
    """For k = 1 the vector norm is |x|: (N, 1) rows are N scalar filters."""
    rng = np.random.default_rng(11)
    xs = signal(rng, 200, 3)  # three scalar channels
    batch = run(OneEuroFilter(0.8, 1.5), xs[:, :, None], np.full(200, DT))[:, :, 0]
    for j in range(3):
        f = OneEuroFilter(0.8, 1.5)
        alone = [f.filter(float(x), DT) for x in xs[:, j]]
        np.testing.assert_allclose(batch[:, j], alone, rtol=0, atol=TOL_VECTORISED)


def test_select_removes_adds_and_reorders_rows(signal: Helper) -> None:
    """select() keeps each body's history: rows removed, added (-1) and reordered give the
    same outputs as one separate filter per body.
    """
    rng = np.random.default_rng(5)
    n = 90
    paths = {body: signal(rng, n, 2) for body in "abcdefg"}
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


def test_reset_forgets_everything(signal: Helper, run: Helper) -> None:
    """After reset() the filter behaves as newly constructed, shape included."""
    rng = np.random.default_rng(2)
    xs = signal(rng, 50, 2)
    f = OneEuroFilter(0.5, 2.0)
    run(f, xs, np.full(50, DT))
    f.reset()
    assert f.value is None
    np.testing.assert_array_equal(
        run(f, xs, np.full(50, DT)), run(OneEuroFilter(0.5, 2.0), xs, np.full(50, DT))
    )
    f.reset()
    assert f.filter(np.ones((4, 3)), DT).shape == (4, 3)


@pytest.mark.parametrize("bad_dt", [0.0, -DT, math.nan, math.inf, -math.inf])
def test_bad_dt_holds(bad_dt: float, signal: Helper) -> None:
    """dt <= 0 or non-finite returns the previous output and leaves the state untouched: the
    rest of the sequence is as if that call never happened.
    """
    rng = np.random.default_rng(9)
    xs = signal(rng, 60, 2)
    f, g = OneEuroFilter(0.5, 2.0), OneEuroFilter(0.5, 2.0)
    for i, x in enumerate(xs):
        if i == 20:
            before = f.value
            held = f.filter(x * 100.0, bad_dt)
            np.testing.assert_array_equal(held, before[0])  # type: ignore[index]
        np.testing.assert_array_equal(f.filter(x, DT), g.filter(x, DT))


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
def test_non_finite_sample_is_skipped(make: object, signal: Helper) -> None:
    """For every filter and the chain, a non-finite sample holds the output and the state:
    the rest of the sequence is as if that sample had never been given.
    """
    rng = np.random.default_rng(4)
    xs = signal(rng, 40, 2)
    f, g = make(), make()  # type: ignore[operator]
    for i, x in enumerate(xs):
        if i in (10, 11, 25):
            before = f.value
            held = f.filter([math.inf, 0.0] if i == 10 else [math.nan, 1.0], DT)
            np.testing.assert_array_equal(held, before[0])
        np.testing.assert_array_equal(f.filter(x, DT), g.filter(x, DT))
