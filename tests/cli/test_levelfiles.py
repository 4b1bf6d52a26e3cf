"""Laws of ``playground list``, ``check`` and ``schema`` (:mod:`playground.cli.levelfiles`): every
problem of a file reported with its key path, titles listed, a levels folder that loops listed."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from playground.cli import main
from playground.level import find, load


def test_check_reports_all_mistakes_and_exits_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """`playground check` on a broken file exits 1 and prints every problem's key path."""
    bad = tmp_path / "bad.toml"
    bad.write_text(
        'title = "x"\ndescription = "y"\n[settings]\ndtt = 1\niterations = "many"\n'
        '[[props]]\nname = "a"\nposition = [0]\nmass = 1\nshapes = []\n',
        encoding="utf-8",
    )
    assert main(["check", str(bad), "rest"]) == 1
    err = capsys.readouterr().err
    for path in ("settings.dtt", "settings.iterations", "props.0.position", "props.0.shapes"):
        assert path in err


def test_list_shows_titles(capsys: pytest.CaptureFixture[str]) -> None:
    """`playground list` prints each shipped level with its title."""
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "rest" in out and load(find("rest")).title in out


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
