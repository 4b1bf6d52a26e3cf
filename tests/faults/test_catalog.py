"""Laws of the catalogue of breaks: every break is declared by a shipped level, the seed sequences
and rooms declare two or more, the README lists them as the files do, and a level naming an
unknown break is refused with the valid names."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground import faults
from playground.level import SEED_SEQUENCES, LevelError, find, load, loads, shipped

ROOMS = ("spinning_ring", "rotating_room", "planet")
"""The artificial-gravity levels: they too must catch at least two breaks."""

MIN_CATCHES = 2
"""How many declared breaks a seed-sequence or room level must catch at least."""


def test_an_unknown_break_in_a_level_names_the_file_the_key_and_the_valid_names() -> None:
    with pytest.raises(LevelError) as info:
        loads(
            'title = "x"\ndescription = "y"\ncatches = ["hover_raection"]\n'
            "[[actors]]\nname = 'p'\nposition = [0, 1]\n"
            "[[expect]]\nbody = 'p'\nquantity = 'state'\nt = 1.0\nequals = 'airborne'\n",
            "bad.toml",
        )
    text = str(info.value)
    assert "bad.toml: catches.0: no break named 'hover_raection'" in text
    assert "did you mean 'hover_reaction'" in text
    assert all(name in text for name in faults.names())


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
