"""Laws of `playground faults`: it prints the matrix or its JSON, lists every break with what it
breaks, exits 1 on an uncaught break and 2 on an unknown name, listing the valid ones."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from playground import faults
from playground.cli import main
from playground.level import find, load


def test_cli_faults_prints_the_matrix(capsys: pytest.CaptureFixture[str]) -> None:
    """`playground faults LEVEL` lists the clean run and each declared break with the checks that
    caught it, and exits 0 when all are caught."""
    assert main(["faults", "rest"]) == 0
    out = capsys.readouterr().out
    assert "(clean)" in out
    for name in load(find("rest")).catches:
        assert f"{name}" in out
    assert "caught by" in out and "MISSED" not in out


def test_cli_faults_json(capsys: pytest.CaptureFixture[str]) -> None:
    """`--json` gives one object: per level its clean run and per break the checks that caught
    it; ``--break`` tries a break a level does not declare, which does not fail the run."""
    assert main(["faults", "rest", "--break", "ring_spin_stopped", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is True
    (level,) = report["levels"]
    assert level["level"] == "rest" and level["clean"]["passed"]
    (tried,) = level["breaks"]
    assert tried["break"] == "ring_spin_stopped"
    assert not tried["declared"] and not tried["caught"] and tried["ok"]


def test_cli_faults_exits_1_on_an_uncaught_break(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    level = tmp_path / "blind.toml"
    level.write_text(
        'title = "x"\ndescription = "y"\ncatches = ["ring_spin_stopped"]\n'
        "[[geometry]]\nkind = 'segment'\na = [-5, 0]\nb = [5, 0]\n"
        "[[actors]]\nname = 'player'\nposition = [0, 0.95]\n"
        "[[expect]]\nbody = 'player'\nquantity = 'state'\nt = 1.0\nequals = 'grounded'\n",
        encoding="utf-8",
    )
    assert main(["faults", str(level)]) == 1
    assert "MISSED" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "named"),
    [
        (["faults", "no_such_level"], "rest"),
        (["faults", "rest", "--break", "hover_raection"], "hover_reaction"),
    ],
)
def test_cli_faults_exits_2_on_an_unknown_name_listing_the_valid_ones(
    argv: list[str], named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert named in err


def test_cli_faults_list_names_every_break_with_what_it_breaks(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["faults", "--list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == faults.names()
    assert all(faults.BREAKS[line.split()[0]].doc in line for line in lines)
