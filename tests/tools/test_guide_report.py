"""The settings guide's report (:mod:`tools.guide_report`): the advice reads the runs,
and a front keeps only undominated points."""

from __future__ import annotations

import pytest

from tools.guide_report import advice, front, misses
from tools.guide_settings import THRESHOLDS, Run


def _run(measures: dict[str, float], knob: str = "defaults", share_us: float = 100.0) -> Run:
    return Run("platform", knob, 0.0, measures, share_us, share_us, share_us, 1 / 120)


def test_advice_names_the_defaults_when_they_suffice_and_the_cheapest_fix_otherwise() -> None:
    """Law: the "if you want" row says "the defaults" when they are under the threshold, else the
    cheapest setting that is, else the best one tried."""
    limit = THRESHOLDS["drift"][0]
    ok = advice([_run({"drift": 0.5 * limit})])
    assert "the defaults" in ok[0][1]
    fixed = advice(
        [
            _run({"drift": 2 * limit}),
            _run({"drift": 0.5 * limit}, "drive_time", 300.0),
            _run({"drift": 0.4 * limit}, "dt", 900.0),
        ]
    )
    assert fixed[0][1].startswith("the defaults miss") and "drive_time" in fixed[0][1]
    none = advice([_run({"drift": 3 * limit}), _run({"drift": 2 * limit}, "dt")])
    assert "no setting tried" in none[0][1] and "dt" in none[0][1]


def test_advice_and_misses_say_what_the_fix_breaks() -> None:
    """Law: where the defaults miss a threshold, the fix is named with the other measures it
    pushes over theirs (raising β cuts the ring's lag and shakes the platform's camera)."""
    up, shake = THRESHOLDS["ring up"][0], THRESHOLDS["shake"][0]
    runs = [
        Run("ring", "defaults", 0.0, {"ring up": 2 * up}, 100.0, 100.0, 100.0, 1 / 120),
        Run("platform", "defaults", 0.0, {"shake": 0.5 * shake}, 100.0, 100.0, 100.0, 1 / 120),
        Run("ring", "beta", 0.5, {"ring up": 0.5 * up}, 100.0, 100.0, 100.0, 1 / 120),
        Run("platform", "beta", 0.5, {"shake": 2 * shake}, 100.0, 100.0, 100.0, 1 / 120),
    ]
    (row,) = [y for x, y in advice(runs) if "spinning room" in x]
    assert "beta = 0.5" in row and "but shake" in row
    (line,) = misses(runs)
    assert "ring, ring up" in line and "at the price of shake" in line


@pytest.mark.parametrize("tie", [0.0, 0.1])
def test_front_keeps_only_undominated_points(tie: float) -> None:
    """Law: no point of the front is dominated by another point."""
    pts = [(1.0, 9.0), (1.02, 8.0), (2.0, 5.0), (2.5, 6.0), (4.0, 1.0), (4.1, 1.0)]
    idx = front(pts, tie)
    for i in idx:
        ci, mi = pts[i]
        assert not any(cj <= ci and mj < mi for cj, mj in pts if (cj, mj) != (ci, mi))
