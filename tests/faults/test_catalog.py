"""Laws of the catalogue of breaks: every break is declared by a shipped level, the seed sequences
and rooms declare two or more, the README lists them as the files do, and a level naming an
unknown break is refused with the valid names."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground import faults
from playground.cli import main
from playground.cli.exits import EXIT_FAILED, EXIT_USAGE
from playground.level import SEED_SEQUENCES, find, load, loads, shipped

ROOMS = ("spinning_ring", "rotating_room", "planet")
"""The artificial-gravity levels: they too must catch at least two breaks."""

MIN_CATCHES = 2
"""How many declared breaks a seed-sequence or room level must catch at least."""


UNKNOWN_BREAK = (
    'title = "x"\ndescription = "y"\ncatches = ["hover_reaction", "hover_raection"]\n'
    "[[actors]]\nname = 'p'\nposition = [0, 1]\n"
    "[[expect]]\nbody = 'p'\nquantity = 'state'\nt = 1.0\nequals = 'airborne'\n"
)
"""A level declaring a known break and a misspelt one (its second, ``catches.1``)."""


def test_an_unknown_break_is_named_at_its_key_with_the_valid_names() -> None:
    """The catalogue, not the level format, knows the break names: the level loads, and the
    catalogue refuses its unknown break at its key, suggesting the near name."""
    (problem,) = faults.catalog.catch_problems(loads(UNKNOWN_BREAK, "bad.toml"))
    text = str(problem)
    assert text.startswith("catches.1: no break named 'hover_raection'")
    assert "did you mean 'hover_reaction'" in text
    assert all(name in text for name in faults.names())


def test_check_refuses_an_unknown_break_naming_the_file_and_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(UNKNOWN_BREAK, encoding="utf-8")
    assert main(["check", str(bad)]) == EXIT_FAILED
    err = capsys.readouterr().err
    assert f"FAILED  {bad}: 1 problem(s)\n  catches.1: no break named 'hover_raection'" in err


def test_faults_refuses_an_unknown_break_naming_the_file_and_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(UNKNOWN_BREAK, encoding="utf-8")
    assert main(["faults", str(bad)]) == EXIT_USAGE
    assert f"{bad}: catches.1: no break named 'hover_raection'" in capsys.readouterr().err


def test_every_break_is_declared_by_a_level() -> None:
    """Each break is declared by at least one shipped level, so the green matrix shows each one
    is real: it changes a reading or a trajectory that a check sees."""
    declared = {b for p in shipped().values() for b in load(p).catches}
    assert set(faults.names()) <= declared, set(faults.names()) - declared


@pytest.mark.parametrize("name", [*SEED_SEQUENCES, *ROOMS])
def test_seed_sequences_and_rooms_catch_two_breaks(name: str) -> None:
    """The seed sequences and the artificial-gravity rooms each declare two breaks or more."""
    assert len(load(find(name)).catches) >= MIN_CATCHES


def test_the_readme_levels_table_lists_what_each_level_must_catch() -> None:
    """The README's levels table shows each shipped level's declared breaks, as the file has
    them."""
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text(encoding="utf-8")
    rows = {
        cells[1].strip("` "): cells[-2].strip()
        for line in readme.splitlines()
        if line.startswith("| `") and len(cells := line.split("|")) == 6
    }
    for name, path in shipped().items():
        listed = rows[name]
        catches = load(path).catches
        assert listed == (", ".join(f"`{c}`" for c in catches) or "—"), name
