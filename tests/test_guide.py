"""Laws of the settings guide (playground.bench.guide): knobs reach the scene, measures follow
the physics, costs are well formed, and the advice reads the runs."""

from __future__ import annotations

import math

import pytest

from playground.bench import guide
from playground.bench.guide import KNOBS, THRESHOLDS, Run

TOL_DRIFT_RATIO = 0.05
"""Relative: drift is a·τ·T for the drive's first-order lag, so doubling τ doubles it; the lag's
own settling and the step's rounding leave well under 5 %."""


def _knob(name: str) -> guide.Knob:
    return next(k for k in KNOBS if k.name == name)


def test_the_guide_moves_at_least_twelve_knobs_including_the_game_ones() -> None:
    """Law: ≥ 12 knobs, among them the probe, ride height, hover f and ζ, d_cutoff, slop and
    sleeping; every knob's default comes first."""
    names = {k.name for k in KNOBS}
    assert len(names) >= 12
    assert {
        "probe_radius", "probe_length", "ride_height", "hover_frequency", "hover_damping",
        "d_cutoff", "collision_slop", "sleep_time", "dt",
    } <= names  # fmt: skip
    assert all(len(k.values) >= 2 for k in KNOBS)


def test_drift_follows_the_drive_time_and_costs_are_well_formed() -> None:
    """Law: on the accelerating platform the drift is a·τ·T, so twice drive_time drifts twice as
    far (the controller knob reaches the level's actor); costs are positive and ordered."""
    runs = guide.run_scenario("platform", [(None, 0.0), (_knob("drive_time"), 0.1)])
    base, slow = runs
    assert base.knob == "defaults" and slow.knob == "drive_time"
    ratio = slow.measures["drift"] / base.measures["drift"]
    assert abs(ratio - 2.0) < TOL_DRIFT_RATIO * 2.0, ratio
    for r in runs:
        assert 0.0 < r.cost_lo <= r.cost_us <= r.cost_hi
        assert 0.0 < r.frame_share < 1.0


def test_every_kind_of_knob_reaches_the_scene() -> None:
    """Law: a settings, perception, controller and world knob each change the built scene."""
    from playground.level import find, load

    level = load(find("rest"))
    cases = [
        ("sleep_time", 0.5, lambda sc: sc.world.config.sleep_time),
        ("dt", 1 / 60, lambda sc: sc.world.config.dt),
        ("d_cutoff", 5.0, lambda sc: sc.world.config.perception.d_cutoff),
        ("probe_radius", 0.2, lambda sc: sc.controllers["player"].config.probe_radius),
    ]
    for name, value, read in cases:
        assert read(guide.build_with(level, _knob(name), value)) == value, name
        assert read(guide.build_with(level, None, 0.0)) != value, name


def test_hover_error_is_first_order_and_refused_beyond_the_limit() -> None:
    """Law: the hover's error against the continuous oscillator halves with dt, and a frequency
    beyond the stability limit is refused (reported as inf)."""
    coarse = guide.hover_error(5.0, 1.0, 1 / 60)
    fine = guide.hover_error(5.0, 1.0, 1 / 120)
    assert 1.8 < coarse / fine < 2.2
    assert math.isinf(guide.hover_error(40.0, 1.0, 1 / 30))


def _run(measures: dict[str, float], knob: str = "defaults", share_us: float = 100.0) -> Run:
    return Run("platform", knob, 0.0, measures, share_us, share_us, share_us, 1 / 120)


def test_advice_names_the_defaults_when_they_suffice_and_the_cheapest_fix_otherwise() -> None:
    """Law: the "if you want" row says "the defaults" when they are under the threshold, else the
    cheapest setting that is, else the best one tried."""
    limit = THRESHOLDS["drift"][0]
    ok = guide.advice([_run({"drift": 0.5 * limit})])
    assert "the defaults" in ok[0][1]
    fixed = guide.advice(
        [
            _run({"drift": 2 * limit}),
            _run({"drift": 0.5 * limit}, "drive_time", 300.0),
            _run({"drift": 0.4 * limit}, "dt", 900.0),
        ]
    )
    assert fixed[0][1].startswith("drive_time")
    none = guide.advice([_run({"drift": 3 * limit}), _run({"drift": 2 * limit}, "dt")])
    assert "no single knob" in none[0][1] and "dt" in none[0][1]


@pytest.mark.parametrize("tie", [0.0, 0.1])
def test_front_keeps_only_undominated_points(tie: float) -> None:
    """Law: no point of the front is dominated by another point."""
    pts = [(1.0, 9.0), (1.02, 8.0), (2.0, 5.0), (2.5, 6.0), (4.0, 1.0), (4.1, 1.0)]
    idx = guide.front(pts, tie)
    for i in idx:
        ci, mi = pts[i]
        assert not any(cj <= ci and mj < mi for cj, mj in pts if (cj, mj) != (ci, mi))
