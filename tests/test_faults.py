"""Laws of fault injection: breaks are reversible, named and real, and every level catches the
breaks it declares (the whole matrix, as `playground faults` runs it)."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from playground import controller, faults, movers, perception, world
from playground.cli import main
from playground.level import SEED_SEQUENCES, LevelError, find, load, loads, shipped
from playground.world import force_api, gravity_stage

ROOMS = ("spinning_ring", "rotating_room", "planet")
"""The artificial-gravity levels: they too must catch at least two breaks."""
MIN_CATCHES = 2
"""How many declared breaks a seed-sequence or room level must catch at least."""

PATCHED = (
    controller.Controller,
    controller.ControllerConfig,
    world.World,
    force_api.ForceAPI,
    gravity_stage.GravityStage,
    movers.Mover,
    movers.Spin,
    perception.PerceivedGravity,
)
"""The classes breaks patch."""


def _attributes() -> list[dict[str, object]]:
    return [dict(vars(cls)) for cls in PATCHED]


def test_the_matrix_is_green() -> None:
    """Every shipped level passes clean and fails under each break it declares; the level files
    are read, never written."""
    paths = shipped()
    before = {name: hashlib.sha256(p.read_bytes()).hexdigest() for name, p in paths.items()}
    rows = faults.matrix([(name, load(p)) for name, p in paths.items()])
    bad = [
        f"{o.level} / {o.fault or 'clean'}: {o.error or o.failed or 'no check failed'}"
        for row in rows
        for o in (row.clean, *row.breaks)
        if not o.ok
    ]
    assert not bad, "\n".join(bad)
    after = {name: hashlib.sha256(p.read_bytes()).hexdigest() for name, p in paths.items()}
    assert after == before


@pytest.mark.parametrize("name", faults.names())
def test_a_break_is_restored_on_exit_and_documented(name: str) -> None:
    """Entering and leaving a break leaves every patched class as it was, even after an
    exception inside; each break says what it breaks."""
    before = _attributes()
    with faults.apply(name):
        pass
    assert _attributes() == before
    with pytest.raises(RuntimeError), faults.apply(name):
        raise RuntimeError("inside the break")
    assert _attributes() == before
    assert len(faults.BREAKS[name].doc) > 20


def test_a_clean_run_after_a_broken_one_is_bit_for_bit_the_clean_run() -> None:
    """A break leaves nothing behind: the same level clean, before and after it, gives the same
    trajectory bit for bit."""
    from playground.scene import build

    level = load(find("seesaw"))

    def final() -> tuple[float, ...]:
        scene = build(level)
        scene.run(1.0)
        b = scene.world.body("player")
        return (b.position.x, b.position.y, b.angle, *scene.world.forces("plank").engine)

    clean = final()
    with faults.apply("hover_reaction"):
        broken = final()
    assert broken != clean
    assert final() == clean


def test_a_break_that_cannot_apply_says_which_and_why(monkeypatch: pytest.MonkeyPatch) -> None:
    """When the method a break patches is gone (a refactor renamed it), the run reports the break
    and the missing method instead of a verdict."""
    monkeypatch.delattr(controller.Controller, "_balance")
    outcome = faults.run(load(find("rest")), "rest", "balance_off")
    assert not outcome.ok
    assert outcome.error is not None
    assert "Controller._balance" in outcome.error and "cannot apply" in outcome.error


def test_a_declared_break_that_goes_uncaught_is_reported() -> None:
    """A level that declares a break its checks cannot see fails the matrix."""
    level = loads(
        'title = "x"\ndescription = "y"\ncatches = ["ring_spin_stopped"]\n'
        "[[geometry]]\nkind = 'segment'\na = [-5, 0]\nb = [5, 0]\n"
        "[[actors]]\nname = 'player'\nposition = [0, 0.95]\n"
        "[[expect]]\nbody = 'player'\nquantity = 'state'\nt = 1.0\nequals = 'grounded'\n"
    )
    (row,) = faults.matrix([("x", level)])
    assert row.clean.ok and not row.ok
    assert row.breaks[0].failed == () and row.breaks[0].declared


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
    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")
    rows = {
        cells[1].strip("` "): cells[-2].strip()
        for line in readme.splitlines()
        if line.startswith("| `") and len(cells := line.split("|")) == 6
    }
    for name, path in shipped().items():
        listed = rows[name]
        catches = load(path).catches
        assert listed == (", ".join(f"`{c}`" for c in catches) or "—"), name


def test_cli_faults_list_names_every_break_with_what_it_breaks(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["faults", "--list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == faults.names()
    assert all(faults.BREAKS[line.split()[0]].doc in line for line in lines)
