"""The sweep one knob at a time (:mod:`playground.bench.accuracy_tables`): a table per knob that
was swept over at least two values, none for a knob that was not; bookkeeping scenes marked."""

from __future__ import annotations

from playground.bench.accuracy import Result
from playground.bench.accuracy_tables import accuracy_markdown

SECTIONS = (
    "### Error against dt",
    "### Error against solver iterations",
    "### Substeps at dt = 1/30 s",
    "### Force estimators",
    "### Filters",
)


def test_every_swept_knob_has_its_table(rows: list[Result]) -> None:
    text = accuracy_markdown(rows)
    for heading in SECTIONS:
        assert heading in text, heading
    assert "| rest (bookkeeping) |" in text


def test_a_knob_swept_at_one_value_has_no_table(rows: list[Result]) -> None:
    base = [r for r in rows if (r.dt, r.iterations) == (1 / 120, 10)]
    text = accuracy_markdown(base)
    assert "### Error against dt" not in text
    assert "### Error against solver iterations" not in text
    assert "### Force estimators" in text and "### Filters" in text
