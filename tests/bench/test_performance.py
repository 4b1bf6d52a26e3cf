"""Laws of the performance benchmark (:mod:`playground.bench.performance`): a level is timed
against its engine, and ``--from`` a file that is not a measurement is one line naming the file
and the key.

Speed itself is measured by ``playground bench overhead``, not asserted here: these tests check
what the benchmark reports and how, on one level and a small pile (seconds).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.bench import performance
from playground.cli import EXIT_USAGE, main


def test_measure_times_a_level_against_its_engine() -> None:
    """Law: a level's row has the stages that ran and its step costs more than its engine's
    (it contains it); the real-time factor is dt over the step."""
    m = performance.measure(
        levels=("rest",), sizes=(10,), field_bodies=10, crossover=(1,), repeats=2
    )
    (row,) = m.levels
    assert row.players == 1
    assert {"control", "physics", "forces", "filter"} <= set(row.stages)
    assert row.ratio > 1.0
    assert row.realtime == pytest.approx(row.dt / (row.level_us * 1e-6))
    kinds = {(r.kind, r.bodies) for r in m.piles}
    assert kinds == {("solver+1€", 10), ("field", 10), ("no effect", 10), ("scalar/vector", 1)}


def test_performance_from_a_file_that_is_not_a_measurement(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``--from`` a JSON file without the measurement: one line naming the file and the key."""
    bad = tmp_path / "bad.json"
    bad.write_text("{}", encoding="utf-8")
    code = main(["bench", "performance", "--from", str(bad), "--out", str(tmp_path / "p.md")])
    assert code == EXIT_USAGE
    err = capsys.readouterr().err
    assert "bad.json" in err and "'levels'" in err
    assert not (tmp_path / "p.md").exists()
