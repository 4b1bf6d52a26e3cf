"""The generated performance page (:mod:`playground.bench.performance_page`): ``bench overhead
--json`` turned into the page quotes the command and every goal, and the committed page is exactly
what the committed measurement generates."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from playground.bench import performance
from playground.bench.goals import GOALS
from playground.bench.measurement import GoalResult
from playground.bench.performance_page import goals_markdown, performance_doc
from playground.cli import main

ROOT = Path(__file__).resolve().parents[2]


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


def test_committed_page_is_generated_from_the_committed_measurement() -> None:
    """docs/performance.md is exactly what ``bench performance --from docs/performance.json``
    writes: nobody edited a number by hand, and the goals table is that run's."""
    data = json.loads((ROOT / "docs" / "performance.json").read_text(encoding="utf-8"))
    m = performance.from_dict(data, source="docs/performance.json")
    page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    assert page == performance_doc(m)
    assert {g.key for g in m.goals} == {g.key for g in GOALS}


@pytest.mark.parametrize(
    ("off_by", "verdict"), [(1.04, "missed by 1.04×"), (2.27, "missed by 2.3×")]
)
def test_a_near_miss_says_by_how_much(off_by: float, verdict: str) -> None:
    """A goal missed by a few per cent does not read "missed by 1.0×"."""
    goal = GoalResult("k", "a measure", "≤ 1", off_by, "measured", False, off_by, "why")
    assert f"| {verdict} |" in goals_markdown([goal])
