"""Laws of ``playground run`` (:mod:`playground.cli.running`): its report, exit codes, bounded run
lengths, strict JSON, recordings, and a progress bar on a terminal only."""

from __future__ import annotations

import fcntl
import json
import os
import pty
import struct
import subprocess
import sys
import termios
from pathlib import Path

import numpy as np
import pytest

from playground.cli import PROGRESS_MIN_STEPS, main
from playground.level import find, load
from playground.limits import MAX_SECONDS, MAX_TIME

REGRESSIONS = Path(__file__).parents[1] / "regressions"


TOL_SUPPORT_REL = 1e-6
"""The issue's acceptance bound for the idle player's support force against m·g."""
STANDARD_GRAVITY = 9.81
LONG_S = 2 * PROGRESS_MIN_STEPS * load(find("rest")).settings.dt
"""Simulated seconds of ``rest`` long enough for a bar (twice the threshold)."""


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
    from playground.scene import build
    from playground.scene.recording import recording

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


def _stderr(*args: str, tty: bool) -> str:
    """What ``playground ARGS`` writes on stderr, given a terminal or a pipe."""
    cmd = [sys.executable, "-m", "playground", *args]
    if not tty:
        done = subprocess.run(cmd, capture_output=True, text=True, check=True)
        return done.stderr
    leader, follower = pty.openpty()
    # A terminal of 24 x 80 characters (a fresh pty is 0 x 0, where tqdm draws nothing).
    fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
    child = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=follower)
    os.close(follower)
    chunks = []
    while True:
        try:
            data = os.read(leader, 65536)
        except OSError:  # EIO: the child closed its end
            break
        if not data:
            break
        chunks.append(data)
    os.close(leader)
    assert child.wait() == 0
    return b"".join(chunks).decode("utf-8", errors="replace")


def test_long_run_shows_a_bar_on_a_terminal_only() -> None:
    """``run`` of more than the threshold's steps draws a tqdm bar ("run: ... step") on a
    terminal; on a pipe, or with ``--no-progress``, stderr stays empty."""
    args = ["run", "rest", "--seconds", repr(LONG_S)]
    assert "run:" in _stderr(*args, tty=True)
    assert _stderr(*args, "--no-progress", tty=True).strip() == ""
    assert _stderr(*args, tty=False) == ""
