"""Laws of ``[[variants.unsupported]]`` (:mod:`playground.level.support`): a declaration covers
exactly the variants all its conditions hold for, never the level as written, and every key,
bound and check name it uses is checked at load, naming the file and the key."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.cli import EXIT_FAILED, EXIT_OK, main
from playground.level import LevelError, loads
from playground.level.support import declared, value_at
from playground.level.variants import parse_sets

# A crate falls freely from 10 m. Symplectic Euler (v += g·dt, then x += v·dt) puts it
# g·t·dt/2 below the exact fall after t s: 0.0204 m at 0.5 s and dt 1/120 s, 0.0409 m at
# 1/60 s. The check allows 0.03 m, so it holds at the level's 1/120 s and not at 1/60 s.
FALL = """title = "Fall"
description = "A crate in free fall."
[[props]]
name = "crate"
position = [0.0, 10.0]
mass = 10.0
shapes = [{ kind = "box", size = [1.0, 1.0] }]
[[expect]]
name = "falls g·t²/2"
body = "crate"
quantity = "position"
component = "y"
check = "at"
t = 0.5
equals = 8.77375
tolerance = 0.03
"""

COARSE = """
[[variants.unsupported]]
when = [{ key = "settings.dt", above = 0.01 }]
reason = "Euler's error g·t·dt/2 grows with the step: at 1/60 s it is 0.041 m, over 0.03 m"
"""


def test_a_declaration_covers_the_variants_all_its_conditions_hold_for() -> None:
    text = FALL + COARSE.replace(
        "above = 0.01 }]", 'above = 0.01 }, { key = "props.crate.mass", values = [10.0, 20] }]'
    )
    level = loads(text)
    assert declared(level) == ()
    for sets, covered in [
        (["settings.dt=0.016666666666666666"], True),
        (["settings.dt=0.016666666666666666", "props.crate.mass=20"], True),
        (["settings.dt=0.016666666666666666", "props.crate.mass=20.000000001"], True),
        (["settings.dt=0.016666666666666666", "props.crate.mass=20.001"], False),
        (["settings.dt=0.01"], False),  # `above` is strict
        (["settings.dt=0.004166666666666667"], False),
    ]:
        variant = loads(text, sets=parse_sets(sets))
        assert bool(declared(variant)) is covered, sets


def test_a_key_not_written_in_the_file_has_its_default() -> None:
    level = loads(FALL)
    assert value_at(level, "settings.substeps") == 1
    assert value_at(level, "props.0.mass") == value_at(level, "props.crate.mass") == 10.0


@pytest.mark.parametrize(
    ("declaration", "where", "message"),
    [
        (
            'when = [{ key = "settings.dtt", above = 0.01 }]',
            "variants.unsupported.0.when.0.key",
            "'settings.dtt' names no key of the level: settings has no key 'dtt' "
            "(did you mean 'dt'?)",
        ),
        (
            'when = [{ key = "props.crat.mass", above = 1.0 }]',
            "variants.unsupported.0.when.0.key",
            "props has no item named 'crat' (did you mean 'crate'?)",
        ),
        (
            'when = [{ key = "props.crate", above = 1.0 }]',
            "variants.unsupported.0.when.0.key",
            "props.crate is a table or an array, not a value",
        ),
        (
            'when = [{ key = "title", above = 1.0 }]',
            "variants.unsupported.0.when.0",
            "`above` and `below` bound a number; title is 'Fall', not a number",
        ),
        (
            'when = [{ key = "settings.dt" }]',
            "variants.unsupported.0.when.0",
            "a condition needs `values`, `above` or `below`",
        ),
        ("when = []", "variants.unsupported.0.when", "at least 1 item"),
        (
            'when = [{ key = "settings.dt", above = 0.01 }]\nchecks = ["falls g.t²/2"]',
            "variants.unsupported.0.checks.0",
            "no check named 'falls g.t²/2' (did you mean 'falls g·t²/2'?)",
        ),
        (
            'when = [{ key = "settings.dt", below = 0.01 }]',
            "variants.unsupported.0",
            "covers the level as written (its own settings)",
        ),
    ],
)
def test_a_bad_declaration_is_named_at_its_key(declaration: str, where: str, message: str) -> None:
    reason = "" if "reason" in declaration else '\nreason = "the physics"'
    text = FALL + f"[[variants.unsupported]]\n{declaration}{reason}\n"
    with pytest.raises(LevelError) as info:
        loads(text, "fall.toml")
    found = [str(p) for p in info.value.problems]
    assert any(p.startswith(f"{where}: ") and message in p for p in found), found
    assert str(info.value).startswith("fall.toml: ")


def test_check_names_are_judged_beside_a_broken_check() -> None:
    """An `at` check without its time is reported, and the declaration naming it still is."""
    text = FALL.replace("t = 0.5\n", "", 1) + COARSE + 'checks = ["falls"]\n'
    with pytest.raises(LevelError) as info:
        loads(text)
    found = [str(p) for p in info.value.problems]
    assert any(p.startswith("expect.0.t: ") for p in found), found
    named = "variants.unsupported.0.checks.0: no check named 'falls'"
    assert any(p.startswith(named) for p in found), found


def test_a_reason_is_required() -> None:
    text = FALL + '[[variants.unsupported]]\nwhen = [{ key = "settings.dt", above = 0.01 }]\n'
    with pytest.raises(LevelError, match=r"variants\.unsupported\.0\.reason: "):
        loads(text)


def test_the_variant_a_declaration_covers_loads_and_runs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Only the level as written may not be covered: the covered variant is checked and run
    (its check fails, as declared), and both say that the level declares it."""
    path = tmp_path / "fall.toml"
    path.write_text(FALL + COARSE, encoding="utf-8")
    assert main(["check", str(path)]) == EXIT_OK
    assert main(["run", str(path)]) == EXIT_OK
    assert "variants.unsupported" not in capsys.readouterr().out
    coarse = ["--set", "settings.dt=0.016666666666666666"]
    assert main(["check", str(path), *coarse]) == EXIT_OK
    assert main(["run", str(path), *coarse]) == EXIT_FAILED
    out = capsys.readouterr().out
    note = (
        "variants.unsupported.0 covers this variant (its checks may fail here): settings.dt > 0.01"
    )
    assert out.count(note) == 2


def test_check_names_the_file_and_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "fall.toml"
    path.write_text(FALL + COARSE.replace("settings.dt", "settings.td"), encoding="utf-8")
    assert main(["check", str(path)]) == EXIT_FAILED
    err = capsys.readouterr().err
    assert f"FAILED  {path}" in err
    assert "variants.unsupported.0.when.0.key: 'settings.td' names no key" in err
