"""Hostile command lines: bounded run lengths, strict JSON, a level whose actor an event removes,
and a levels folder that contains itself."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from playground.cli import main
from playground.limits import MAX_SECONDS, MAX_TIME

REGRESSIONS = Path(__file__).parent / "regressions"


@pytest.mark.parametrize(
    ("argv", "bound"),
    [
        (["--seconds", "1e308"], MAX_SECONDS),
        (["--seconds", "1e15"], MAX_SECONDS),
        (["--seconds", str(MAX_SECONDS + 1)], MAX_SECONDS),
        (["--seconds", "nan"], MAX_SECONDS),
        (["--seconds", "-1"], MAX_SECONDS),
        (["--long", "--seconds", str(MAX_TIME + 1)], MAX_TIME),
    ],
)
def test_run_length_is_bounded(
    argv: list[str], bound: float, capsys: pytest.CaptureFixture[str]
) -> None:
    """Law: --seconds beyond MAX_SECONDS needs --long, and --long stops at MAX_TIME: one line on
    stderr and exit code 2, before anything runs."""
    assert main(["run", "rest", *argv]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"--seconds: expected a number of seconds in [0, {bound:g}]" in err


def test_run_json_is_strict_json(capsys: pytest.CaptureFixture[str]) -> None:
    """Law: ``run --json`` never prints NaN or Infinity, even before any reading exists."""

    def refuse(constant: str) -> None:
        raise AssertionError(f"not JSON: {constant}")

    for seconds in ("0", "0.05"):
        assert main(["run", "rest", "--json", "--seconds", seconds, "--no-progress"]) in (0, 1)
        report = json.loads(capsys.readouterr().out, parse_constant=refuse)
        assert report["level"] == "rest"


def test_an_actor_removed_by_an_event_runs_and_plays(tmp_path: Path) -> None:
    """Law: a level whose event removes its actor runs headless and plays in the view without a
    traceback (it used to raise KeyError: no body named 'player')."""
    level = REGRESSIONS / "remove_actor.toml"
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    for argv in (["run", str(level)], ["play", str(level), "--headless", "--frames", "30"]):
        done = subprocess.run(
            [sys.executable, "-m", "playground", *argv],
            capture_output=True,
            text=True,
            timeout=120,
            env=env,
            check=False,
        )
        assert done.returncode == 0, done.stderr[-2000:]
        assert "Traceback" not in done.stderr


def test_a_levels_folder_that_contains_itself_is_listed(tmp_path: Path) -> None:
    """Law: a PLAYGROUND_LEVELS folder with a symlink back to itself (and one to itself) lists
    its levels; nothing recurses."""
    folder = tmp_path / "levels"
    (folder / "sub").mkdir(parents=True)
    (folder / "sub" / "back").symlink_to(folder)
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    (folder / "mine.toml").write_text('title = "Mine"\ndescription = "Mine."\n', encoding="utf-8")
    env = {
        **os.environ,
        "PLAYGROUND_LEVELS": os.pathsep.join([str(folder), str(tmp_path / "loop")]),
    }
    done = subprocess.run(
        [sys.executable, "-m", "playground", "list"],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert "mine" in done.stdout and "Mine" in done.stdout
