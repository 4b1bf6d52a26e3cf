"""Laws of the robustness matrix (:mod:`playground.scene.robustness`): a variant passes, is
declared, is stale or fails exactly as its level's checks and declarations say, and only the
player's mass is scaled."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.level import find, load
from playground.scene.robustness import VARIANTS, Variant, player, run

# A crate falls freely from 10 m; symplectic Euler leaves it g·t·dt/2 above the exact fall
# after t s (0.0204 m at 0.5 s and 1/120 s, 0.0409 m at 1/60 s), and the check allows 0.03 m.
# A second check (the crate falls at all) holds at every step.
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
[[expect]]
name = "falls"
body = "crate"
quantity = "position"
component = "y"
check = "at"
t = 0.5
below = 9.0
"""

COARSE = 60
FINE = 120


def _declared(when: str, checks: str = "") -> str:
    return (
        f"[[variants.unsupported]]\nwhen = [{when}]\n"
        f'reason = "Euler\'s error g·t·dt/2 grows with the step"\n{checks}'
    )


def _verdict(tmp_path: Path, text: str, rate: int, substeps: int = 1) -> str:
    path = tmp_path / "fall.toml"
    path.write_text(text, encoding="utf-8")
    return run(path, "fall", Variant(1.0, 1 / rate, substeps)).verdict


def test_an_undeclared_failure_fails_and_a_pass_passes(tmp_path: Path) -> None:
    assert _verdict(tmp_path, FALL, FINE) == "pass"
    assert _verdict(tmp_path, FALL, COARSE) == "fail"


def test_a_declared_failure_is_reported_as_declared(tmp_path: Path) -> None:
    text = FALL + _declared('{ key = "settings.dt", above = 0.01 }')
    assert _verdict(tmp_path, text, COARSE) == "declared"
    assert _verdict(tmp_path, text, FINE) == "pass"


def test_a_declaration_that_hides_a_pass_is_stale(tmp_path: Path) -> None:
    """Two substeps at 1/120 s pass: a declaration covering them is stale."""
    text = FALL + _declared('{ key = "settings.substeps", values = [2] }')
    assert _verdict(tmp_path, text, FINE, substeps=2) == "stale"


def test_a_declaration_excuses_only_the_checks_it_names(tmp_path: Path) -> None:
    coarse = '{ key = "settings.dt", above = 0.01 }'
    named = FALL + _declared(coarse, 'checks = ["falls g·t²/2"]\n')
    other = FALL + _declared(coarse, 'checks = ["falls"]\n')
    assert _verdict(tmp_path, named, COARSE) == "declared"
    assert _verdict(tmp_path, other, COARSE) == "fail"


def test_a_level_without_a_player_has_no_mass_axis(tmp_path: Path) -> None:
    path = tmp_path / "fall.toml"
    path.write_text(FALL, encoding="utf-8")
    assert player(load(path)) is None
    outcomes = [run(path, "fall", v) for v in VARIANTS if v.mass != 1.0][:2]
    assert [o.verdict for o in outcomes] == ["none", "none"]


@pytest.mark.parametrize("factor", [0.5, 2.0])
def test_only_the_players_mass_is_scaled(factor: float) -> None:
    """crusher has a second actor (``weak``) and two crates: they keep their masses."""
    level = load(find("crusher"))
    sets = Variant(factor, 1 / 120, 1).settings(level)
    assert sets is not None
    variant = load(find("crusher"), sets)
    masses = {a.name: a.controller.mass for a in variant.actors}
    assert masses == {"player": factor * 70.0, "weak": 70.0}
    assert [p.mass for p in variant.props] == [p.mass for p in level.props]
