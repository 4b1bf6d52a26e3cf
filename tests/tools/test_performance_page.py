"""The generated performance page (:mod:`tools.performance_page`): ``playground bench overhead
--json`` turned into the page by ``python -m tools performance --from`` quotes the command and
judges every goal, and the committed page is exactly what the committed measurement generates."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from playground.bench import performance
from playground.cli import main
from tools import cli, costs
from tools.goals import GOALS, GoalResult
from tools.performance_page import goals_markdown, performance_doc

ROOT = Path(__file__).resolve().parents[2]


def test_overhead_json_and_performance_page(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``bench overhead --quick --json`` prints the levels, piles and effects (no goals: they are
    the repository's); ``python -m tools performance --from`` turns that JSON into the page,
    quoting the command and judging each goal."""
    assert main(["bench", "overhead", "--quick", "--json", "--no-progress"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert "goals" not in data
    assert data["levels"][0]["level"] == "rest"
    assert data["effects"]
    source = tmp_path / "perf.json"
    source.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "performance.md"
    assert cli.main(["performance", "--from", str(source), "--out", str(out)]) == 0
    page = out.read_text(encoding="utf-8")
    assert "playground bench overhead --quick --json" in page
    for g in GOALS:
        # A quick run measures no crowd of 100 or 200 actors: their goals are left out.
        shown = not g.key.startswith("crowd_")
        assert (f"| {g.measure} | {g.text} |" in page) == shown


def test_committed_page_is_generated_from_the_committed_measurement() -> None:
    """docs/performance.md is exactly what ``python -m tools performance --from
    docs/performance.json`` writes, with docs/costs.json: nobody edited a number by hand."""
    data = json.loads((ROOT / "docs" / "performance.json").read_text(encoding="utf-8"))
    m = performance.from_dict(data, source="docs/performance.json")
    small = json.loads((ROOT / "docs" / "costs.json").read_text(encoding="utf-8"))
    rows = costs.from_dict(small, source="docs/costs.json")
    page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    assert page == performance_doc(m, (rows, small))


@pytest.mark.parametrize(
    ("off_by", "verdict"), [(1.04, "missed by 1.04×"), (2.27, "missed by 2.3×")]
)
def test_a_near_miss_says_by_how_much(off_by: float, verdict: str) -> None:
    """A goal missed by a few per cent does not read "missed by 1.0×"."""
    goal = GoalResult("k", "a measure", "≤ 1", off_by, "measured", False, off_by, "why")
    assert f"| {verdict} |" in goals_markdown([goal])


def test_performance_from_a_file_that_is_not_a_measurement(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``--from`` a JSON file without the measurement: one line naming the file and the key,
    exit 2, and no page written."""
    bad = tmp_path / "bad.json"
    bad.write_text("{}", encoding="utf-8")
    code = cli.main(["performance", "--from", str(bad), "--out", str(tmp_path / "p.md")])
    assert code == 2
    err = capsys.readouterr().err
    assert "bad.json" in err and "'levels'" in err
    assert not (tmp_path / "p.md").exists()
