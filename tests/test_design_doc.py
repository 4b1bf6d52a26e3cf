"""Laws of the design notes (docs/design.md): the newcomer's map matches the code it maps.

The notes name, for every stage of :meth:`World.step`, the module that owns it; every module they
name exists, and nothing in the repository cites a design document that is not in it.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from playground.world import Stage

ROOT = Path(__file__).resolve().parent.parent
NOTES = ROOT / "docs" / "design.md"
STAGE_ROW = re.compile(r"^\| (\d) `(\w+)` \|[^|]*\| (.*) \|$", re.MULTILINE)
CITED_NOTE = re.compile(r"\b([A-Z][A-Z_]*\.md)\b")
"""An upper-case markdown file name cited in a text (a note such as the README)."""
MODULE = re.compile(r"`((?:\w+/)*_?\w+\.py)`|`(\w+/)`")


def stage_rows() -> dict[str, str]:
    """Stage name → the owner column of the stage table."""
    return {name: owner for _, name, owner in STAGE_ROW.findall(NOTES.read_text("utf-8"))}


def test_every_stage_of_the_step_has_a_row_in_order() -> None:
    """The table lists the stages of :class:`Stage`, numbered as the step runs them."""
    rows = STAGE_ROW.findall(NOTES.read_text("utf-8"))
    assert [(int(n), name) for n, name, _ in rows] == [(s.value, s.name) for s in Stage]


@pytest.mark.parametrize("stage", [s.name for s in Stage])
def test_each_stage_names_an_owner_module_that_exists(stage: str) -> None:
    """Every owner the table names is a module (or folder) of the package."""
    owners = [a or b for a, b in MODULE.findall(stage_rows()[stage])]
    assert owners, f"stage {stage} names no module"
    for owner in owners:
        assert (ROOT / "playground" / owner).exists(), f"{stage}: no playground/{owner}"


def test_every_markdown_file_cited_is_in_the_repository() -> None:
    """Code, tests, levels and docs cite only notes that are here (the design notes are
    docs/design.md): every upper-case markdown file they mention exists at the repository's root."""
    missing = set()
    for folder in ("playground", "tests", "docs", "levels", "benchmarks"):
        for path in (ROOT / folder).rglob("*"):
            if path.suffix in {".py", ".md", ".toml"}:
                for cited in CITED_NOTE.findall(path.read_text("utf-8")):
                    if not (ROOT / cited).is_file():
                        missing.add(f"{path.relative_to(ROOT)}: {cited}")
    for cited in CITED_NOTE.findall((ROOT / "README.md").read_text("utf-8")):
        if not (ROOT / cited).is_file():
            missing.add(f"README.md: {cited}")
    assert sorted(missing) == []
