"""Laws of the design notes (docs/design.md): the newcomer's map matches the code it maps.

The notes name, for every stage of :meth:`World.step`, the module that owns it; every module they
name exists, and nothing in the repository cites a design document that is not in it.
"""

from __future__ import annotations

import re
import tomllib
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


MAP_ROW = re.compile(r"^\| [^|`]+ \| ((?:`[\w/.]+`(?:, )?)+) \|", re.MULTILINE)
"""A row of the newcomer's map: its layer's modules, each in backticks."""


def map_layers() -> list[set[str]]:
    """The newcomer's map (§6), top to bottom: each row's modules as dotted names."""
    section = NOTES.read_text("utf-8").split("## §6", 1)[1].split("## §7", 1)[0]
    rows = MAP_ROW.findall(section)
    return [
        {m.strip("`").removesuffix("/").removesuffix(".py") for m in row.split(", ")}
        for row in rows
    ]


def contract_layers() -> list[set[str]]:
    """The layers contract of pyproject.toml, top to bottom (optional layers unwrapped)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))
    (layers,) = [
        c["layers"] for c in config["tool"]["importlinter"]["contracts"] if c["type"] == "layers"
    ]
    return [{m.strip().strip("()") for m in layer.split("|")} for layer in layers]


def test_the_map_lists_the_layers_of_the_import_contract_in_order() -> None:
    """The newcomer's map is the contract that lint-imports checks: the same layers, the same
    modules in each, in the same order (so neither can change without the other)."""
    assert map_layers() == contract_layers()


def test_every_module_of_the_package_is_on_the_map() -> None:
    """Every package and top-level module of playground/ has its row, and every row names only
    what exists."""
    on_map = set().union(*map_layers())
    present = {
        p.stem if p.suffix == ".py" else p.name
        for p in (ROOT / "playground").iterdir()
        if (p.suffix == ".py" and p.stem != "__init__") or (p / "__init__.py").is_file()
    }
    assert on_map == present
