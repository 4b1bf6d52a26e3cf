"""Laws of the performance benchmark (:mod:`playground.bench.performance`): a level is timed
against its engine, and a file that is not a measurement is refused naming the file and the key.

Speed itself is measured by ``playground bench overhead``, not asserted here: these tests check
what the benchmark reports and how, on one level and a small pile (seconds).
"""

from __future__ import annotations

import pytest

from playground.bench import performance


def test_measure_times_a_level_against_its_engine() -> None:
    """Law: a level's row has the stages that ran and its step costs more than its engine's
    (it contains it); the real-time factor is dt over the step."""
    m = performance.measure(
        levels=("rest",),
        sizes=(10,),
        field_bodies=10,
        crossover=(1,),
        split_sizes=(10,),
        repeats=2,
    )
    (row,) = m.levels
    assert row.players == 1
    assert {"control", "physics", "forces", "filter"} <= set(row.stages)
    assert row.ratio > 1.0
    assert row.realtime == pytest.approx(row.dt / (row.level_us * 1e-6))
    kinds = {(r.kind, r.bodies) for r in m.piles}
    assert kinds == {
        ("solver+1€", 10),
        ("split off", 10),
        ("split on", 10),
        ("field", 10),
        ("no effect", 10),
        ("scalar/vector", 1),
    }


def test_from_dict_names_the_source_and_the_missing_key() -> None:
    """A JSON document without the measurement: a ValueError naming the file and the key."""
    with pytest.raises(ValueError, match=r"bad\.json: expected the key 'levels'"):
        performance.from_dict({}, source="bad.json")
