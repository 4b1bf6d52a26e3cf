"""Laws of the accuracy sweep (:mod:`playground.bench.accuracy`) on a small sweep: one row per
point and filter, first-order dt, iterations that pay on a stack, exact readings at rest,
estimators that agree, filter lags, executors, plans and bad input."""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import pytest

from playground.bench.accuracy import (
    ESTIMATORS,
    FILTERS,
    Point,
    Result,
    filter_lag,
    measure,
    plan,
    sweep,
)
from playground.bench.scenes import SCENES, Knobs, build
from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter

TOL_EXACT_AT_REST = 1e-6
"""Relative error of reverse integration on a body at rest: the velocities do not change, so
only round-off remains (measured ≈ 1e-9 at dt = 1/30 s)."""

TOL_ESTIMATORS_AGREE = 1e-9
"""Reverse integration and the arbiter-impulse sum agree to round-off (docs/design.md §2: ~1e-12
relative on the force; the relative errors compared here are differences of such forces)."""

TOL_LAG = 1e-6
"""The EMA's ramp lag converges to τ = 1/(2π·fc) geometrically; after 1 s at 5 Hz the
remainder is below 1e-12 s, so 1e-6 s only absorbs round-off."""


def _one(rows: list[Result], scene: str, knobs: Knobs, estimator: str = "reverse") -> Result:
    (r,) = [
        r
        for r in rows
        if r.scene == scene
        and (r.dt, r.substeps, r.iterations) == (knobs.dt, knobs.substeps, knobs.iterations)
        and r.estimator == estimator
        and r.filter == "none"
    ]
    return r


def test_every_point_gives_one_row_per_filter(rows: list[Result], points: list[Point]) -> None:
    """Law: the sweep returns one row per point and filter, in the order of the points."""
    assert len(rows) == len(points) * len(FILTERS)
    assert [r.scene for r in rows[:: len(FILTERS)]] == [p.scene for p in points]
    assert [r.filter for r in rows[: len(FILTERS)]] == list(FILTERS)


def test_rows_are_well_formed(rows: list[Result]) -> None:
    """Law: errors are finite and >= 0, costs positive, ratio = cost / bare."""
    for r in rows:
        assert math.isfinite(r.error) and r.error >= 0.0
        assert r.cost_us > 0.0 and r.bare_us > 0.0
        assert math.isclose(r.ratio, r.cost_us / r.bare_us)
        assert r.lag >= 0.0


def test_hover_error_falls_with_smaller_dt(rows: list[Result]) -> None:
    """Law: the hover oscillation's error falls as dt shrinks (first-order integrator)."""
    coarse = _one(rows, "hover", Knobs(dt=1 / 30)).error
    fine = _one(rows, "hover", Knobs(dt=1 / 120)).error
    assert fine < coarse / 2.0


def test_stack_error_falls_with_more_iterations(rows: list[Result]) -> None:
    """Law: a heavy stack is read more accurately with more solver iterations."""
    assert _one(rows, "stack", Knobs()).error < _one(rows, "stack", Knobs(iterations=2)).error


def test_reverse_integration_is_exact_at_rest(rows: list[Result]) -> None:
    """Law: at rest, reverse integration returns m·g to round-off."""
    assert _one(rows, "rest", Knobs()).error < TOL_EXACT_AT_REST


def test_reverse_and_contact_estimators_agree(rows: list[Result]) -> None:
    """Law: on contacts alone, the arbiter-impulse sum equals reverse integration."""
    rev = _one(rows, "rest", Knobs()).error
    con = _one(rows, "rest", Knobs(), "contact").error
    assert abs(rev - con) < TOL_ESTIMATORS_AGREE


def test_ema_lag_is_its_time_constant() -> None:
    """Law: an EMA follows a ramp τ = 1/(2π·fc) late (exact for the discrete filter too)."""
    lag = filter_lag(lambda: ExponentialMovingAverage(cutoff=5.0), 1 / 120)
    assert abs(lag - 1.0 / (2.0 * math.pi * 5.0)) < TOL_LAG


def test_beta_shortens_the_lag() -> None:
    """Law: the 1€ filter's β raises the cutoff on a moving signal, so it lags less."""
    slow = filter_lag(lambda: OneEuroFilter(min_cutoff=1.0, beta=0.0), 1 / 120)
    fast = filter_lag(lambda: OneEuroFilter(min_cutoff=1.0, beta=0.5), 1 / 120)
    assert fast < slow
    assert filter_lag(None, 1 / 120) == 0.0


def test_any_executor_gives_the_same_errors(rows: list[Result], points: list[Point]) -> None:
    """Law: same inputs, same trajectories: a thread pool reproduces the in-process errors."""
    with ThreadPoolExecutor(2) as pool:
        again = sweep(points[:3], executor=pool, progress=False, repeats=1)
    assert [r.error for r in again] == [r.error for r in rows[: len(again)]]


def test_plans_cover_every_scene_and_estimator() -> None:
    """Law: both sweep sizes visit every scene; the default visits every estimator."""
    for size in ("quick", "default"):
        points = plan(size)  # type: ignore[arg-type]
        assert {p.scene for p in points} == set(SCENES)
    assert {p.estimator for p in plan("default")} == set(ESTIMATORS)
    with pytest.raises(ValueError, match="size"):
        plan("huge")  # type: ignore[arg-type]


def test_bad_input_is_named() -> None:
    """Law: an unknown scene, filter or estimator is refused with a message naming it."""
    with pytest.raises(ValueError, match="scene"):
        build("moon", Knobs())
    with pytest.raises(ValueError, match="filters"):
        measure(Point("rest", Knobs(), "reverse"), filters=("kalman",))
    with pytest.raises(ValueError, match="estimator"):
        measure(Point("rest", Knobs(), "psychic"))  # type: ignore[arg-type]
