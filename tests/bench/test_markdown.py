"""Markdown of the generated pages (:mod:`playground.bench.markdown`): a table's separator has a
cell per column, relative errors print as the pages print them."""

from __future__ import annotations

import math

import pytest

from playground.bench.markdown import dt_label, pct, table


def test_a_table_has_a_separator_cell_per_column() -> None:
    lines = table(["a", "b", "c"], [["1", "2", "3"], ["4", "5", "6"]]).splitlines()
    assert lines[1] == "|---|---|---|"
    assert lines[3] == "| 4 | 5 | 6 |"
    assert table(["x"], []) == "| x |\n|---|"


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (0.0, "0"),
        (0.00123, "0.12 %"),
        (0.0987, "9.9 %"),
        (0.35, "35 %"),
        (1.234, "123 %"),
        (math.nan, "–"),
    ],
)
def test_pct_prints_two_figures_below_ten_percent(value: float, text: str) -> None:
    assert pct(value) == text


def test_dt_label_is_a_fraction_of_a_second() -> None:
    assert [dt_label(dt) for dt in (1 / 30, 1 / 120, 1 / 480)] == ["1/30", "1/120", "1/480"]
