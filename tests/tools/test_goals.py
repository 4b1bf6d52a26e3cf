"""The performance goals (:mod:`tools.goals`): each judged on the worst row it covers,
and a missed goal says why."""

from __future__ import annotations

import pytest

from playground.bench.measurement import CrowdRow, LevelRow, PileRow
from tools.goals import GOALS, judge


def _level(name: str, players: int, us: float, control: float) -> LevelRow:
    return LevelRow(name, 1 / 120, players, us, 1.0, us, us, us, (1 / 120) / (us * 1e-6),
                    {"control": control, "physics": 1.0}, scalar=True)  # fmt: skip


def test_goals_judge_the_worst_case_each_covers() -> None:
    """Law: a goal is judged on the worst row it covers (the slowest one-player level, the
    lowest real-time factor of any level, the costliest controller per actor, the larger piles'
    largest overhead), and ``off_by`` says by how much it is missed."""
    levels = [_level("a", 1, 20.0, 8.0), _level("b", 1, 30.0, 5.0), _level("c", 2, 50.0, 30.0)]
    piles = [
        PileRow("solver+1€", 10, 30.0, 10.0, 3.0, 2.9, 3.1, 2.0),
        PileRow("solver+1€", 1000, 1200.0, 1000.0, 1.2, 1.1, 1.3, 0.2),
        PileRow("solver+1€", 3000, 3150.0, 3000.0, 1.05, 1.0, 1.1, 0.05),
        PileRow("split on", 10, 45.0, 10.0, 4.5, 4.2, 4.9, 3.5),
        PileRow("split on", 1000, 1400.0, 1000.0, 1.4, 1.3, 1.5, 0.4),
        PileRow("field", 1000, 1040.0, 1000.0, 1.04, 1.0, 1.1, 0.04),
        PileRow("no effect", 10, 11.0, 10.0, 1.1, 1.0, 1.2, 0.1),
    ]
    crowds = [
        CrowdRow(10, 200.0, 5.0, 40.0, 38.0, 42.0, 20.0, 41.7, "scalar"),
        CrowdRow(100, 500.0, 50.0, 10.0, 9.0, 11.0, 5.0, 16.7, "batch"),
        CrowdRow(200, 700.0, 50.0, 14.0, 13.0, 15.0, 3.5, 11.9, "batch"),
    ]
    goals = {g.key: g for g in judge(levels, piles, crowds)}
    assert set(goals) == {g.key for g in GOALS}
    assert goals["one_player_us"].value == 30.0
    assert not goals["one_player_us"].met
    assert goals["one_player_us"].off_by == pytest.approx(30.0 / 25.0)
    assert goals["one_player_rt"].value == pytest.approx((1 / 120) / 30e-6)
    assert goals["every_level_rt"].value == pytest.approx((1 / 120) / 50e-6)
    assert goals["controller_us"].value == 15.0  # 30 µs for 2 actors
    assert goals["pile_10"].met and goals["pile_10"].why == ""
    assert goals["pile_large"].value == 0.2 and not goals["pile_large"].met
    assert goals["pile_large"].why  # a missed goal says why
    assert goals["split_10"].met and goals["split_1000"].met  # overheads 3.5× and 0.4×
    assert goals["field_1000"].met
    assert not goals["no_effect"].met
    # The crowd of 10 is not one the goals cover: the worst per actor is the crowd of 100's.
    assert goals["crowd_per_actor"].value == 5.0 and not goals["crowd_per_actor"].met
    assert goals["crowd_engine"].met and goals["crowd_rt"].met
    assert {g.key for g in judge(levels, piles)} == {g.key for g in GOALS} - {
        "crowd_per_actor", "crowd_engine", "crowd_rt",
    }  # fmt: skip
