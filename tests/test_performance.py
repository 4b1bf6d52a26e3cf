"""Laws of the performance benchmark: its timer, its goals, its command and its generated page.

Speed itself is measured by ``playground bench overhead``, not asserted here: these tests check
what the benchmark reports and how, on one level and a small pile (seconds).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from playground.bench import performance
from playground.bench.blocks import Blocks, interleave
from playground.bench.performance import GOALS, LevelRow, PileRow, judge
from playground.bench.profiler import TOP_FUNCTIONS
from playground.cli import EXIT_USAGE, main

ROOT = Path(__file__).resolve().parents[1]


def test_interleave_alternates_and_prepares_every_b_block() -> None:
    """Law: blocks alternate which side goes first, and ``prepare_b`` runs (untimed) before
    every block of b, so b always starts from a fresh copy."""
    calls: list[str] = []
    t = interleave(
        lambda: calls.append("a"),
        lambda: calls.append("b"),
        repeats=4,
        steps=2,
        prepare_b=lambda: calls.append("p"),
    )
    assert len(t.a) == len(t.b) == 4
    # a first on even blocks, b first on odd ones
    assert "".join(calls) == "aa" + "pbb" + "pbb" + "aa" + "aa" + "pbb" + "pbb" + "aa"


def test_blocks_ratio_is_the_median_of_adjacent_pairs() -> None:
    """Law: the ratio is the median of a/b pair by pair (one disturbed block moves it not at
    all), ``best`` the fastest over the fastest, ``spread`` the extreme pair ratios."""
    t = Blocks(a=(2.0, 2.0, 50.0), b=(1.0, 1.0, 1.0))
    assert t.ratio == 2.0
    assert t.best == 2.0
    assert t.spread == (2.0, 50.0)


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
        PileRow("field", 1000, 1040.0, 1000.0, 1.04, 1.0, 1.1, 0.04),
        PileRow("no effect", 10, 11.0, 10.0, 1.1, 1.0, 1.2, 0.1),
    ]
    goals = {g.key: g for g in judge(levels, piles)}
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
    assert goals["field_1000"].met
    assert not goals["no_effect"].met


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


def test_overhead_json_and_performance_page(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``bench overhead --quick --json`` prints the goals, levels, piles and effects;
    ``bench performance --from`` turns that JSON into the page, quoting the command."""
    assert main(["bench", "overhead", "--quick", "--json", "--no-progress"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert [g["key"] for g in data["goals"]] == [g.key for g in GOALS]
    assert data["levels"][0]["level"] == "rest"
    assert data["effects"]
    source = tmp_path / "perf.json"
    source.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "performance.md"
    assert main(["bench", "performance", "--from", str(source), "--out", str(out)]) == 0
    page = out.read_text(encoding="utf-8")
    assert "playground bench overhead --quick --json" in page
    for g in GOALS:
        assert f"| {g.measure} | {g.text} |" in page


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


def test_committed_page_is_generated_from_the_committed_measurement() -> None:
    """docs/performance.md is exactly what ``bench performance --from docs/performance.json``
    writes: nobody edited a number by hand, and the goals table is that run's."""
    data = json.loads((ROOT / "docs" / "performance.json").read_text(encoding="utf-8"))
    m = performance.from_dict(data, source="docs/performance.json")
    page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    assert page == performance.performance_doc(m)
    assert {g.key for g in m.goals} == {g.key for g in GOALS}


def test_run_profile_prints_the_stages_and_the_top_functions(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """``playground run rest --profile``: after the checks, a row per stage that ran (with its
    calls: one per step) and the functions with the most own time, the world's among them."""
    assert main(["run", "rest", "--profile"]) == 0
    out = capsys.readouterr().out
    steps = re.search(r"(\d+) steps", out)
    assert steps is not None
    stages = out[out.index(f"stages over {steps[1]} steps") :]
    for stage in ("control", "physics", "forces", "filter"):
        assert re.search(rf"^{stage}\s+{steps[1]}\s", stages, re.MULTILINE), stage
    functions = out[out.index("top functions") :].splitlines()[3:]
    assert len(functions) == TOP_FUNCTIONS
    assert any("playground/" in line for line in functions)


def test_run_profile_json_holds_the_profile(capsys: pytest.CaptureFixture[str]) -> None:
    """With ``--json`` the profile is part of the one JSON object: stage shares sum to 1."""
    assert main(["run", "rest", "--profile", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    stages = {s["stage"]: s for s in report["profile"]["stages"]}
    assert stages["physics"]["calls"] == report["steps"]
    assert sum(s["share"] for s in stages.values()) == pytest.approx(1.0)
    assert len(report["profile"]["functions"]) == TOP_FUNCTIONS
