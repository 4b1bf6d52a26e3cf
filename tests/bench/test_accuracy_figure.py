"""The accuracy figure (:mod:`playground.bench.accuracy_figure`): it is written, and the
configurations it marks as the front are the ones no other beats on both error and cost."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.bench.accuracy import Result
from playground.bench.accuracy_figure import accuracy_figure
from playground.bench.sweep_rows import configurations


def test_the_figure_marks_the_undominated_configurations(
    rows: list[Result], tmp_path: Path
) -> None:
    pytest.importorskip("matplotlib")
    path = tmp_path / "img" / "accuracy.png"
    front = accuracy_figure(rows, path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    configs = configurations(rows)
    assert front and set(front) <= set(configs)
    for c in front:
        assert not any(o.cost_ms < c.cost_ms and o.error < c.error for o in configs)
    assert [c.cost_ms for c in front] == sorted(c.cost_ms for c in front)
