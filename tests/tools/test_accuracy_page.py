"""The generated accuracy page (:mod:`tools.accuracy_page`): the doc, its data files and
figures are written, and the settings guide goes into it."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.bench import overhead
from playground.bench.accuracy import Result
from playground.bench.accuracy_tables import accuracy_markdown
from tools import accuracy_page as report


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
    assert "| scene |" in accuracy_markdown(rows)
    assert "## If you want X, set Y" in text


def test_the_settings_guide_goes_into_the_doc(rows: list[Result], tmp_path: Path) -> None:
    """Law: with the guide's runs, accuracy.md opens with the "if you want" table, has the
    guide's section, its figure and its fronts."""
    pytest.importorskip("matplotlib")
    from tools import guide
    from tools.guide_settings import KNOBS

    knob = next(k for k in KNOBS if k.name == "drive_time")
    runs = guide.run_scenario("platform", [(None, 0.0), (knob, 0.025)])
    over = overhead.profile(sizes=(10,), repeats=1, settle_steps=1)
    hover = {(f, dt): 0.01 for f in guide.HOVER_FREQUENCIES for dt in guide.HOVER_DTS}
    report.write_docs(rows, over, tmp_path, seconds=(1.0, 1.0), guide=(runs, hover, 1.0))
    text = (tmp_path / "accuracy.md").read_text(encoding="utf-8")
    assert text.index("## If you want X, set Y") < text.index("## The settings guide")
    assert "accelerating platform" in text
    assert "**platform, drift**" in text
    assert (tmp_path / "img" / "guide.png").stat().st_size > 0
