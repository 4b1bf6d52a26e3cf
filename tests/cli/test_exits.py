"""Laws of the command line's errors: one line on stderr, a documented exit code, never a
traceback, and bad output paths refused before any long work starts."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from playground.cli import EXIT_INTERRUPTED, EXIT_OK, EXIT_USAGE, main
from playground.scene.recording import read

INTERRUPT_AFTER = 1.0
"""s after the command is inside ``main``: long enough to be in the middle of its work."""
WAIT_READY = 120.0
"""s to wait for the child to stop after Ctrl-C on a loaded machine before giving up."""


def _one_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert "Traceback" not in err
    return lines[0]


def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    return subprocess.run(
        [sys.executable, "-m", "playground", *args],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )


@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["run", "rest", "--record", "missing/out.csv"], "missing"),
        (["schema", "-o", "missing/level.schema.json"], "--output"),
        (["play", "rest", "--headless", "--replay-out", "missing/r.json"], "--replay-out"),
        (["play", "rest", "--headless", "--screenshot", "missing/shot.png"], "--screenshot"),
        (["play", "rest", "--headless", "--screenshot", "shot.txt"], "--screenshot"),
        (["bench", "overhead", "--quick", "--figure", "missing/o.png"], "--figure"),
        (["bench", "accuracy", "--quick", "--csv", "missing/a.csv"], "--csv"),
        (["run", "rset"], "did you mean 'rest'"),
        (["play", "rset", "--headless"], "did you mean 'rest'"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args: list[str], option: str, tmp_path: Path) -> None:
    """An output into a missing folder, a picture of an unknown type, an unknown level: one line
    naming the problem, exit 2, and nothing written."""
    done = _cli(*args, cwd=tmp_path)
    assert done.returncode == EXIT_USAGE, done.stderr
    assert option in _one_line(done.stderr)
    assert list(tmp_path.iterdir()) == []


def test_figure_without_matplotlib_fails_before_the_sweep(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """``bench accuracy|overhead --figure`` without matplotlib says which extra to install, exit 2,
    before the sweep runs (the sweep is replaced by a failure here)."""
    import playground.cli.bench as bench_cli

    def never(*args: object, **kwargs: object) -> None:
        raise AssertionError("the sweep ran before the figure's dependency was checked")

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setattr(bench_cli, "sweep", never)
    monkeypatch.setattr(bench_cli.overhead, "profile", never)
    for bench in ("accuracy", "overhead"):
        code = main(["bench", bench, "--quick", "--figure", str(tmp_path / "f.png")])
        assert code == EXIT_USAGE
        line = _one_line(capsys.readouterr().err)
        assert "pip install 'pymunk-playground[bench]'" in line


def test_missing_view_dependency_names_the_extra(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """``play`` without pygame-ce: one line naming the ``view`` extra, exit 2."""
    for name in [m for m in sys.modules if m == "pygame" or m.startswith("playground.view")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "pygame", None)
    assert main(["play", "rest", "--headless"]) == EXIT_USAGE
    line = _one_line(capsys.readouterr().err)
    assert "pip install 'pymunk-playground[view]'" in line


def test_existing_recording_is_kept_without_force(tmp_path: Path) -> None:
    """``run --record`` onto an existing file refuses (exit 2) and leaves it as it was;
    ``--force`` overwrites it."""
    out = tmp_path / "r.csv"
    out.write_text("precious", encoding="utf-8")
    done = _cli("run", "rest", "--record", str(out), cwd=tmp_path)
    assert done.returncode == EXIT_USAGE
    assert "--force" in _one_line(done.stderr)
    assert out.read_text(encoding="utf-8") == "precious"
    assert main(["run", "rest", "--record", str(out), "--force"]) == EXIT_OK
    assert len(read(out)["time"]) > 0


def _interrupt(args: list[str], cwd: Path) -> tuple[int, str]:
    """Start the command, wait until it is inside ``main``, press Ctrl-C (SIGINT)."""
    code = (
        "import signal, sys\n"
        "from playground.cli import main\n"
        # As in a terminal: a test runner may have started us with SIGINT ignored.
        "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
        "print('ready', flush=True)\n"
        f"sys.exit(main({args!r}))\n"
    )
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    child = subprocess.Popen(
        [sys.executable, "-c", code],
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert child.stdout is not None
        assert child.stdout.readline().strip() == "ready"
        time.sleep(INTERRUPT_AFTER)
        child.send_signal(signal.SIGINT)
        _, err = child.communicate(timeout=WAIT_READY)
    finally:
        child.kill()
        child.wait()
    return child.returncode, err


def test_ctrl_c_during_run_exits_130_and_keeps_the_recording(tmp_path: Path) -> None:
    """Ctrl-C during a long ``run --record``: "interrupted", exit 130, and the recording holds
    the steps run so far."""
    out = tmp_path / "cut.npz"
    code, err = _interrupt(["run", "sandbox", "--seconds", "3000", "--record", str(out)], tmp_path)
    assert code == EXIT_INTERRUPTED
    assert "interrupted" in _one_line(err)
    steps = len(read(out)["time"])
    assert steps > 0 and not out.with_name(out.name + ".partial").exists()


def test_ctrl_c_during_play_exits_130_and_keeps_the_replay(tmp_path: Path) -> None:
    """Ctrl-C during ``play`` (headless, many frames): "interrupted", exit 130, and the replay
    of the steps played so far is written."""
    pytest.importorskip("pygame")
    from playground.scene.replay import Replay

    out = tmp_path / "session.json"
    code, err = _interrupt(
        ["play", "sandbox", "--headless", "--frames", "1000000", "--replay-out", str(out)],
        tmp_path,
    )
    assert code == EXIT_INTERRUPTED
    assert "interrupted" in _one_line(err)
    assert Replay.load(out).steps > 0


def test_ctrl_c_inside_a_pymunk_callback_is_not_lost(capfd: pytest.CaptureFixture[str]) -> None:
    """A Ctrl-C that lands while Python runs inside a pymunk callback (called from C through
    cffi, which would print the KeyboardInterrupt and drop it) is delivered again just after:
    the command still stops, and no cffi traceback is printed."""
    import pymunk

    from playground.cli.exits import _interruptible

    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    box = pymunk.Body(1.0, 1.0)
    box.position = (0.0, 0.49)
    space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
    space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
    space.step(1.0 / 120.0)
    visited: list[bool] = []

    def visit(arbiter: pymunk.Arbiter) -> None:
        os.kill(os.getpid(), signal.SIGINT)
        visited.append(True)

    # As in a terminal: the test runner may have been started with SIGINT ignored.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt), _interruptible():
            box.each_arbiter(visit)
            assert visited == [True]
            time.sleep(INTERRUPT_AFTER)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert "Traceback" not in capfd.readouterr().err


def test_f12_says_where_the_screenshot_went(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """F12 in the view saves a PNG in the current folder and prints its full path, once."""
    pygame = pytest.importorskip("pygame")
    from playground.view.app import App
    from playground.view.launcher import init_headless, show_level

    monkeypatch.chdir(tmp_path)
    init_headless()
    app = App(show_level, "rest", size=(320, 240))
    app.run_frames(2)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_F12))
    (shot,) = tmp_path.glob("*.png")
    assert str(shot.resolve()) in _one_line(capsys.readouterr().err)
