"""Laws of finding level files: shipped levels by name, any level by path."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.level import LevelError, find, load, shipped

LEVELS = Path(__file__).resolve().parents[2] / "levels"


def test_every_shipped_level_loads() -> None:
    """Each shipped level validates and has a title and a description."""
    levels = shipped()
    assert {"rest", "incline", "elevator"} <= set(levels)
    for path in levels.values():
        level = load(path)
        assert level.title and level.description and level.expect


def test_find_by_name_and_by_path() -> None:
    """LEVEL is a path or a shipped name; an unknown name lists the shipped ones."""
    assert find("rest") == find(str(LEVELS / "rest.toml")).resolve()
    with pytest.raises(LevelError, match="did you mean 'rest'"):
        find("rset")
