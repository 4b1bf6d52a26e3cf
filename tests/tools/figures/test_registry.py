"""Laws of the chapters' registries (:mod:`tools.figures.registry`): a number or a figure is
declared once, under one name."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tools.figures import registry
from tools.figures.registry import FIGURES, NUMBERS, figure, number


def test_a_declared_number_is_the_function_itself_under_its_name(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """``@number`` files the function under its own name and hands it back unchanged."""
    table: dict[str, registry.Number] = {}
    monkeypatch.setattr(registry, "NUMBERS", table)

    def ch0_answer() -> float:
        return 42.0

    assert number(ch0_answer) is ch0_answer
    assert table == {"ch0_answer": ch0_answer}


def test_a_declared_figure_is_filed_under_its_file_name(monkeypatch: pytest.MonkeyPatch) -> None:
    table: dict[str, registry.Figure] = {}
    monkeypatch.setattr(registry, "FIGURES", table)

    def draw(path: Path) -> Path:
        return path

    assert figure("00-nothing.png")(draw) is draw
    assert table == {"00-nothing.png": draw}


def test_a_name_declared_twice_is_refused_and_the_first_kept() -> None:
    """A second chapter computing a number under a name already taken would make a marker quote
    whichever module was imported last: refused, naming the name."""
    first_number, first_figure = NUMBERS["ch5_k"], FIGURES["05-floating-capsule.png"]

    def ch5_k() -> float:
        return 0.0

    with pytest.raises(ValueError, match="'ch5_k' is declared twice"):
        number(ch5_k)
    with pytest.raises(ValueError, match=re.escape("'05-floating-capsule.png' is declared twice")):
        figure("05-floating-capsule.png")(lambda path: path)
    assert NUMBERS["ch5_k"] is first_number
    assert FIGURES["05-floating-capsule.png"] is first_figure
