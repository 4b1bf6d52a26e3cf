"""Laws of ``check`` against ``run``: what check accepts, run runs; what run would refuse or
fail on, check refuses first, naming the file and the key (issue 23's defects, one case each)."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.cli import EXIT_FAILED, EXIT_OK, EXIT_USAGE, main

BASE = """title = "T"
description = "A crate, a lift and the floor."
[[geometry]]
kind = "segment"
a = [-10.0, 0.0]
b = [10.0, 0.0]
[[props]]
name = "crate"
position = [0.0, 0.5]
mass = 10.0
shapes = [{ kind = "box", size = [1.0, 1.0] }]
[[movers]]
name = "lift"
shapes = [{ kind = "box", size = [1.0, 0.2] }]
path = { kind = "elevator", start = [5.0, 1.0], acceleration = 1.0, start_time = 1.0 }
[[movers]]
name = "shuttle"
shapes = [{ kind = "box", size = [1.0, 0.2] }]
path = { kind = "elevator", start = [-5.0, 1.0], acceleration = 1.0, start_time = 1.0 }
"""

SPAWN = (
    '[[events]]\nkind = "spawn"\nt = 0.5\n'
    'prop = {{ name = "p", position = [2.0, 3.0], mass = {mass}, shapes = [{shape}] }}\n'
)
REMOVE = '[[events]]\nkind = "remove"\nt = {t}\nbody = "{body}"\n'
IMPULSE = '[[events]]\nkind = "impulse"\nt = {t}\nbody = "{body}"\nimpulse = [1.0, 0.0]\n'
PLAYER = '[[actors]]\nname = "player"\nposition = [-2.0, 0.95]\n'

CASES = {
    "joint kinematic-static": (
        '[[joints]]\nkind = "pivot"\na = "lift"\nb = "static"\nanchor = [5.0, 1.0]\n',
        "joints.0: a joint needs a dynamic body",
    ),
    "joint kinematic-kinematic": (
        '[[joints]]\nkind = "pin"\na = "lift"\nb = "shuttle"\n'
        "anchor_a = [5.0, 1.0]\nanchor_b = [-5.0, 1.0]\n",
        "joints.0: a joint needs a dynamic body",
    ),
    "joint to a spawned prop": (
        SPAWN.format(mass=1.0, shape='{ kind = "box", size = [1.0, 1.0] }')
        + '[[joints]]\nkind = "pivot"\na = "p"\nb = "static"\nanchor = [2.0, 3.0]\n',
        "joints.0.a: 'p' is spawned during the run",
    ),
    "event after removal": (
        REMOVE.format(t=1.0, body="crate") + IMPULSE.format(t=1.5, body="crate"),
        "events.1.body: 'crate' was removed at t = 1 s",
    ),
    "removed twice": (
        REMOVE.format(t=1.0, body="crate") + REMOVE.format(t=2.0, body="crate"),
        "events.1.body: 'crate' was removed",
    ),
    "event before spawn": (
        IMPULSE.format(t=0.2, body="p")
        + SPAWN.format(mass=1.0, shape='{ kind = "box", size = [1.0, 1.0] }'),
        "events.0.body: 'p' is spawned at t = 0.5 s, after this event",
    ),
    "removed before its spawn at the same time": (
        REMOVE.format(t=0.5, body="p")
        + SPAWN.format(mass=1.0, shape='{ kind = "box", size = [1.0, 1.0] }'),
        "events.0.body: 'p' is spawned at t = 0.5 s, by an event after this one",
    ),
    "nullify input on a removed body": (
        PLAYER + REMOVE.format(t=0.5, body="crate") + '[[inputs]]\nt = 1.0\nnullify = "crate"\n',
        "inputs.0.nullify: 'crate' was removed",
    ),
    "spawned prop with a tiny moment": (
        SPAWN.format(mass=1.0, shape='{ kind = "box", size = [1e-6, 1e-6] }'),
        "events.0.prop: p.moment: expected a number in [1e-09",
    ),
    "spawned prop with no area": (
        SPAWN.format(
            mass=1.0, shape='{ kind = "polygon", points = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]] }'
        ),
        "events.0.prop: p: its shapes have no area",
    ),
    "flip past the gravity bound": (
        '[gravity]\nkind = "uniform"\ng = [1000.0, -1000.0]\n'
        '[[events]]\nkind = "flip_gravity"\nt = 1.0\n',
        "events.0.angle: g[1]: expected a number in [-1000, 1000]",
    ),
    "body_gravity direction (0, 0)": (
        '[[events]]\nkind = "body_gravity"\nt = 1.0\nbody = "crate"\ndirection = [0.0, 0.0]\n',
        "events.0.direction: direction: expected a non-zero direction",
    ),
    "jump impulse past the bound": (
        '[[actors]]\nname = "player"\nposition = [-2.0, 0.95]\ncontroller = { mass = 1e6 }\n',
        "actors.0.controller.jump_speed: a jump of 1e+06 kg",
    ),
    "hands past the coordinate bound": (
        '[[actors]]\nname = "player"\nposition = [99999.0, 0.95]\n',
        "actors.0.position: its probe and hands reach",
    ),
    "always check on a body removed mid-window": (
        REMOVE.format(t=1.0, body="crate")
        + '[[expect]]\nbody = "crate"\nquantity = "position"\ncomponent = "y"\n'
        'check = "always"\nwindow = [0.5, 2.5]\nbelow = 5.0\n',
        "expect.0.body: 'crate' exists from t = 0 s to 1 s",
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_check_refuses_what_run_cannot_run(
    case: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Law: each level here passed ``check`` and then failed at ``run`` (a pymunk assertion, a
    KeyError, a ValueError mid-run, or a check that passes on a body that is gone). Now check
    refuses it, exit 1, naming the file and the key; run refuses it too, exit 2, one line."""
    extra, expected = CASES[case]
    path = tmp_path / "level.toml"
    path.write_text(BASE + extra, encoding="utf-8")
    assert main(["check", str(path)]) == EXIT_FAILED
    err = capsys.readouterr().err
    assert f"FAILED  {path}" in err
    assert expected in err
    assert main(["run", str(path)]) == EXIT_USAGE
    err = capsys.readouterr().err
    assert str(path) in err and "Traceback" not in err


def test_the_base_level_is_fine(tmp_path: Path) -> None:
    """The level the cases add to is accepted and runs (so each refusal is the case's own)."""
    path = tmp_path / "level.toml"
    path.write_text(BASE, encoding="utf-8")
    assert main(["check", str(path)]) == EXIT_OK
    assert main(["run", str(path)]) == EXIT_OK


def test_a_build_refusal_names_the_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A problem only the built scene shows (a spring too stiff for the level's step) is
    reported under the file's name, not the level's title."""
    path = tmp_path / "stiff.toml"
    spring = (
        '[[joints]]\nkind = "spring"\na = "crate"\nb = "static"\n'
        "anchor_a = [0.0, 0.5]\nanchor_b = [0.0, 3.0]\nstiffness = 1e9\n"
    )
    path.write_text(BASE + spring, "utf-8")
    assert main(["check", str(path)]) == EXIT_FAILED
    err = capsys.readouterr().err
    assert f"FAILED  {path}" in err and "joints.0.stiffness" in err


def test_check_says_when_a_run_will_be_long(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A level that is valid but steps many bodies for very many steps (32 bodies for an hour
    at dt = 1e-4 s: 1.2e9 body-steps; the issue's 10 000 bodies for an hour would take ~17 h)
    passes check with a note saying so, not silently; the base level gets no note."""
    crates = "".join(
        f'[[props]]\nname = "c{k}"\nposition = [{k - 15}.0, 3.0]\nmass = 1.0\n'
        'shapes = [{ kind = "circle", radius = 0.3 }]\n'
        for k in range(29)
    )
    path = tmp_path / "long.toml"
    settings = 'description = "d"\n[settings]\nseconds = 3600.0\ndt = 0.0001'
    text = BASE.replace('description = "A crate, a lift and the floor."', settings)
    path.write_text(text + crates, "utf-8")
    assert main(["check", str(path)]) == EXIT_OK
    out = capsys.readouterr().out
    assert "note" in out and "body-steps" in out and "minutes or more" in out
    base = tmp_path / "base.toml"
    base.write_text(BASE, encoding="utf-8")
    assert main(["check", str(base)]) == EXIT_OK
    assert "note" not in capsys.readouterr().out
