"""Laws of the accuracy and overhead benchmarks, on small sizes (seconds, not minutes)."""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
from concurrent.futures import ThreadPoolExecutor
from dataclasses import fields
from pathlib import Path

import pytest

from playground.bench import overhead, report
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
from playground.bench.cli import configure
from playground.bench.scenes import SCENES, Knobs, build
from playground.filters import ExponentialMovingAverage, OneEuroFilter

TOL_EXACT_AT_REST = 1e-6
"""Relative error of reverse integration on a body at rest: the velocities do not change, so
only round-off remains (measured ≈ 1e-9 at dt = 1/30 s)."""

TOL_ESTIMATORS_AGREE = 1e-9
"""Reverse integration and the arbiter-impulse sum agree to round-off (docs/design.md §2: ~1e-12
relative on the force; the relative errors compared here are differences of such forces)."""

TOL_LAG = 1e-6
"""The EMA's ramp lag converges to τ = 1/(2π·fc) geometrically; after 1 s at 5 Hz the
remainder is below 1e-12 s, so 1e-6 s only absorbs round-off."""

POINTS = [
    Point("hover", Knobs(dt=1 / 30), "reverse"),
    Point("hover", Knobs(dt=1 / 120), "reverse"),
    Point("rest", Knobs(), "reverse"),
    Point("rest", Knobs(), "contact"),
    Point("rest", Knobs(), "finite-difference"),
    Point("stack", Knobs(iterations=2), "reverse"),
    Point("stack", Knobs(), "reverse"),
    Point("grip", Knobs(), "reverse"),
]


@pytest.fixture(scope="module")
def rows() -> list[Result]:
    return sweep(POINTS, workers=0, progress=False, repeats=1)


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


def test_every_point_gives_one_row_per_filter(rows: list[Result]) -> None:
    """Law: the sweep returns one row per point and filter, in the order of the points."""
    assert len(rows) == len(POINTS) * len(FILTERS)
    assert [r.scene for r in rows[:: len(FILTERS)]] == [p.scene for p in POINTS]
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


def test_any_executor_gives_the_same_errors(rows: list[Result]) -> None:
    """Law: same inputs, same trajectories: a thread pool reproduces the in-process errors."""
    with ThreadPoolExecutor(2) as pool:
        again = sweep(POINTS[:3], executor=pool, progress=False, repeats=1)
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


def test_csv_and_json_hold_every_row(rows: list[Result]) -> None:
    """Law: the CSV and JSON outputs round-trip every row and field."""
    names = [f.name for f in fields(Result)]
    table = list(csv.DictReader(io.StringIO(report.to_csv(rows))))
    assert len(table) == len(rows) and list(table[0]) == names
    data = json.loads(report.to_json(rows))
    assert len(data) == len(rows) and list(data[0]) == names


def test_pareto_front_is_not_dominated(rows: list[Result]) -> None:
    """Law: no configuration is both cheaper and more accurate than one on the front."""
    configs = report.configurations(rows)
    pts = [(c.cost_ms, c.error) for c in configs]
    front = report.pareto(pts)
    assert front
    for i in front:
        assert not any(c < pts[i][0] and e < pts[i][1] for c, e in pts)


def test_markdown_and_docs_are_written(rows: list[Result], tmp_path: Path) -> None:
    """Law: the report writes the doc, CSV, JSON (and the figure when matplotlib is there)."""
    pytest.importorskip("matplotlib")
    over = overhead.profile(sizes=(10,), repeats=1, settle_steps=1)
    written = report.write_docs(rows, over, tmp_path, seconds=(1.0, 1.0))
    assert (tmp_path / "img" / "accuracy.png").stat().st_size > 0
    assert (tmp_path / "img" / "accuracy_overhead.png").stat().st_size > 0
    assert {p.name for p in written} >= {"accuracy.md", "accuracy.csv", "accuracy_overhead.json"}
    text = (tmp_path / "accuracy.md").read_text(encoding="utf-8")
    assert report.COMMAND in text and "Pareto" in text
    assert "| scene |" in report.accuracy_markdown(rows)
    assert "## If you want X, set Y" in text


def test_the_settings_guide_goes_into_the_doc(rows: list[Result], tmp_path: Path) -> None:
    """Law: with the guide's runs, accuracy.md opens with the "if you want" table, has the
    guide's section, its figure and its fronts."""
    pytest.importorskip("matplotlib")
    from playground.bench import guide

    knob = next(k for k in guide.KNOBS if k.name == "drive_time")
    runs = guide.run_scenario("platform", [(None, 0.0), (knob, 0.025)])
    over = overhead.profile(sizes=(10,), repeats=1, settle_steps=1)
    hover = {(f, dt): 0.01 for f in guide.HOVER_FREQUENCIES for dt in guide.HOVER_DTS}
    report.write_docs(rows, over, tmp_path, seconds=(1.0, 1.0), guide=(runs, hover, 1.0))
    text = (tmp_path / "accuracy.md").read_text(encoding="utf-8")
    assert text.index("## If you want X, set Y") < text.index("## The settings guide")
    assert "accelerating platform" in text
    assert "**platform, drift**" in text
    assert (tmp_path / "img" / "guide.png").stat().st_size > 0


def test_bookkeeping_scenes_stay_out_of_the_means(rows: list[Result]) -> None:
    """Law: a scene that reads a constant back exactly (rest) is bookkeeping and no
    configuration's mean includes it; a scene with a real error (the stack) is not."""
    books = report.bookkeeping(rows)
    assert "rest" in books and "stack" not in books and "hover" not in books
    configs = report.configurations(rows)
    base = [c for c in configs if c.label.startswith("dt 1/120×1, 10 it, reverse, none")]
    (c,) = base
    real = [r.error for r in rows if r.scene in {"stack", "hover"} and r.iterations == 10
            and r.dt == 1 / 120 and r.estimator == "reverse" and r.filter == "none"]  # fmt: skip
    assert c.error == pytest.approx(sum(real) / len(real))


def test_cli_parses_both_subcommands() -> None:
    """Law: the bench parser accepts accuracy, overhead and docs with their options."""
    parser = argparse.ArgumentParser()
    configure(parser)
    args = parser.parse_args(["accuracy", "--quick", "--workers", "0", "--json"])
    assert (args.bench, args.quick, args.workers, args.json) == ("accuracy", True, 0, True)
    assert parser.parse_args(["overhead", "--quick"]).bench == "overhead"
    assert parser.parse_args(["docs"]).dir == Path("docs")


def test_overhead_quick_structure() -> None:
    """Law: the overhead profile has a bare baseline and every effect at every size."""
    rows = overhead.profile(sizes=(10, 30), repeats=1, settle_steps=5)
    effects = {r.effect for r in rows}
    assert set(overhead.EFFECTS) <= effects
    sizes = {r.bodies for r in rows}
    for n in sizes:
        assert {r.effect for r in rows if r.bodies == n} == effects
    for r in rows:
        assert r.us_per_step > 0.0 and r.bare_us > 0.0
        assert r.ratio > 0.0
    assert "| effect |" in overhead.overhead_markdown(rows)
