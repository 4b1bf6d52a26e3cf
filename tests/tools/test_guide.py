"""Laws of the settings guide's runner (:mod:`tools.guide`): measures follow the
physics, costs are well formed, and the hover's error against the exact oscillator is first order
and refused beyond the limit."""

from __future__ import annotations

import math

from tools import guide
from tools.guide_settings import COMBOS, KNOBS, Combo, Knob

TOL_DRIFT_RATIO = 0.05
"""Relative: drift is a·τ·T for the drive's first-order lag, so doubling τ doubles it; the lag's
own settling and the step's rounding leave well under 5 %."""


def _knob(name: str) -> Knob:
    return next(k for k in KNOBS if k.name == name)


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


def test_hover_error_is_first_order_and_refused_beyond_the_limit() -> None:
    """Law: the hover's error against the continuous oscillator halves with dt, and a frequency
    beyond the stability limit is refused (reported as inf)."""
    coarse = guide.hover_error(5.0, 1.0, 1 / 60)
    fine = guide.hover_error(5.0, 1.0, 1 / 120)
    assert 1.8 < coarse / fine < 2.2
    assert math.isinf(guide.hover_error(40.0, 1.0, 1 / 30))


def test_beta_buys_lag_with_shake_and_a_combination_moves_every_knob_it_names() -> None:
    """Law: raising β opens the 1€ cutoff on noise as on real turns, so the platform's camera
    shakes more (the jitter the lag measures cannot see); a combination of knobs is one run,
    labelled with all of them, and moves each (min_cutoff = 1 with β = 0 is steadier than either
    alone)."""
    steady = next(c for c in COMBOS if c.moves == (("min_cutoff", 1.0), ("beta", 0.0)))
    base, quick, calm, both = guide.run_scenario(
        "platform",
        [(None, 0.0), (_knob("beta"), 0.5), (_knob("beta"), 0.0), (steady, math.nan)],
    )
    assert quick.measures["shake"] > base.measures["shake"] > calm.measures["shake"]
    assert both.label == "min_cutoff = 1, beta = 0" and both.combined
    assert both.measures["shake"] < calm.measures["shake"]
    assert isinstance(steady, Combo)
