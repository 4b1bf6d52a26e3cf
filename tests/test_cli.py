"""Laws of the `playground` command: reports, exit codes, recordings and the pytest plugin."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from playground.cli import main
from playground.level import find, load

TOL_SUPPORT_REL = 1e-6
"""The issue's acceptance bound for the idle player's support force against m·g."""
STANDARD_GRAVITY = 9.81


def test_run_rest_json_reports_support_equal_to_weight(capsys: pytest.CaptureFixture[str]) -> None:
    """`playground run rest --json`: the player's support force is m·g (within 1e-6 relative)."""
    assert main(["run", "rest", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert {"level", "dt", "steps", "sim_seconds", "wall_seconds", "checks", "bodies"} <= set(
        report
    )
    player = report["bodies"]["player"]
    weight = player["mass"] * STANDARD_GRAVITY
    sx, sy = player["force"]["support"]
    assert abs(sx) <= TOL_SUPPORT_REL * weight
    assert abs(sy - weight) <= TOL_SUPPORT_REL * weight
    assert player["state"] == "grounded"
    assert all(c["passed"] for c in report["checks"])


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


def test_failing_check_exits_1(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A level whose expectation fails makes `run` exit 1 and says what happened and when."""
    text = find("incline").read_text(encoding="utf-8").replace("equals = 49.05", "equals = 40.0")
    level = tmp_path / "wrong.toml"
    level.write_text(text, encoding="utf-8")
    assert main(["run", str(level)]) == 1
    out = capsys.readouterr().out
    assert "FAIL" in out and "expected the mean over [0.5, 2] s to be 40 N" in out


@pytest.mark.parametrize("suffix", [".csv", ".npz"])
def test_recordings_are_bit_identical(tmp_path: Path, suffix: str) -> None:
    """Running the same level twice gives byte-identical recordings."""
    a, b = tmp_path / f"a{suffix}", tmp_path / f"b{suffix}"
    for path in (a, b):
        assert main(["run", "rest", "--record", str(path)]) == 0
    if suffix == ".csv":
        assert a.read_bytes() == b.read_bytes()
    else:
        da, db = np.load(a), np.load(b)
        assert sorted(da) == sorted(db)
        for key in da:
            assert np.array_equal(da[key], db[key])
        steps = round(load(find("rest")).settings.seconds / load(find("rest")).settings.dt)
        assert len(da["time"]) == steps


def test_interrupted_recording_is_readable(tmp_path: Path) -> None:
    """An interrupted run (KeyboardInterrupt) still leaves a complete recording."""
    from playground.recording import recording
    from playground.scene import build

    for suffix in (".csv", ".npz"):
        scene = build(load(find("rest")))
        path = tmp_path / f"cut{suffix}"
        with pytest.raises(KeyboardInterrupt), recording(scene, path):
            scene.run(0.25)
            raise KeyboardInterrupt
        if suffix == ".csv":
            assert len(path.read_text(encoding="utf-8").splitlines()) == 1 + 30
        else:
            assert len(np.load(path)["time"]) == 30


def test_plugin_collects_one_item_per_expectation() -> None:
    """`pytest levels/x.toml` collects one test per expectation of the level."""
    path = find("rest")
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "--collect-only",
            "-q",
            "-p",
            "no:cacheprovider",
            str(path),
        ],
        capture_output=True,
        text=True,
        check=False,
        cwd=path.parent,
    ).stdout
    items = [line for line in out.splitlines() if "::" in line]
    assert len(items) == len(load(path).expect)
