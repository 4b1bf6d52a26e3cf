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
PLAY_STARTUP = 5.0
"""s after ``play`` is inside ``main`` before it is surely stepping: it imports pygame and builds
its level first, which on a loaded 2-core machine (load 4–8) took more than 1 s (no replay
steps at 1 s, some at 2 s)."""
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


def _interrupt(args: list[str], cwd: Path, after: float = INTERRUPT_AFTER) -> tuple[int, str]:
    """Start the command, wait until it is inside ``main`` and ``after`` s more, press Ctrl-C
    (SIGINT)."""
    code, err, _ = _interrupt_timed(args, cwd, after)
    return code, err


def _interrupt_timed(
    args: list[str], cwd: Path, after: float = INTERRUPT_AFTER
) -> tuple[int, str, float]:
    """:func:`_interrupt`, and the seconds from Ctrl-C to the command's exit."""
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
        time.sleep(after)
        child.send_signal(signal.SIGINT)
        pressed = time.perf_counter()
        _, err = child.communicate(timeout=WAIT_READY)
        stopped = time.perf_counter() - pressed
    finally:
        child.kill()
        child.wait()
    return child.returncode, err, stopped


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
        PLAY_STARTUP,
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


def test_an_internal_error_is_one_line_exit_3_and_a_traceback_file(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """A bug inside a command (here ``list`` made to divide by zero) is one line on stderr saying
    it is an internal error and where the full traceback was written, exit 3 — never a traceback
    on the terminal, never exit 1 (which means a check failed)."""
    from playground.cli import EXIT_INTERNAL, levelfiles
    from playground.cli.exits import CRASH_DIR_ENV

    def broken(args: object) -> int:
        return 1 // 0

    monkeypatch.setattr(levelfiles, "cmd_list", broken)
    monkeypatch.setenv(CRASH_DIR_ENV, str(tmp_path))
    assert main(["list"]) == EXIT_INTERNAL
    line = _one_line(capsys.readouterr().err)
    assert "internal error (ZeroDivisionError" in line
    (written,) = tmp_path.glob("playground-crash-*.txt")
    assert str(written) in line
    text = written.read_text(encoding="utf-8")
    assert "Traceback" in text and "in broken" in text


def test_a_closed_pipe_ends_quietly(tmp_path: Path) -> None:
    """``playground list | head -1``: the reader goes away; the command ends with exit 0 and
    says nothing (no "Broken pipe", no "Exception ignored")."""
    read, write = os.pipe()
    os.close(read)
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    try:
        done = subprocess.run(
            [sys.executable, "-m", "playground", "list"],
            cwd=tmp_path,
            env=env,
            stdout=write,
            stderr=subprocess.PIPE,
            text=True,
            check=False,
        )
    finally:
        os.close(write)
    assert (done.returncode, done.stderr) == (EXIT_OK, "")


STOP_WITHIN = 5.0
"""s from Ctrl-C to the command's exit. Measured: 0.05-0.6 s on the commands below (before the
fix, ``bench accuracy`` took 30 s, waiting for every submitted sweep point, and ``bench docs``
lost the Ctrl-C inside a ground-probe callback); the bound leaves room for a loaded machine."""


@pytest.mark.parametrize(
    "args",
    # bench overhead runs the levels' controllers: their ground probe is a C callback.
    [["bench", "accuracy", "--no-progress"], ["bench", "overhead", "--no-progress"], ["faults"]],
    ids=lambda a: " ".join(a[:2]),
)
def test_ctrl_c_stops_a_long_command_at_once(args: list[str], tmp_path: Path) -> None:
    """Ctrl-C in the middle of a long command: "interrupted", exit 130, within
    :data:`STOP_WITHIN` — pending sweep points are cancelled and running ones stopped, and a
    Ctrl-C that lands inside one of the playground's own C callbacks is delivered just after."""
    code, err, stopped = _interrupt_timed(args, tmp_path)
    assert code == EXIT_INTERRUPTED, err
    assert "interrupted" in _one_line(err)
    assert stopped < STOP_WITHIN


FIFO_WAIT = 60.0
"""s before a command blocked on a FIFO counts as hung (each finishes in about a second)."""


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")
def test_a_fifo_named_like_a_level_is_not_read(tmp_path: Path) -> None:
    """A FIFO named ``*.toml`` in ``$PLAYGROUND_LEVELS`` (or named on the command line) is not a
    level: ``list`` and ``run`` do not block on it, ``check`` refuses it, exit 1, naming it."""
    os.mkfifo(tmp_path / "pipe.toml")
    env = {**os.environ, "PLAYGROUND_LEVELS": str(tmp_path)}
    for args in (["list"], ["run", "rest"], ["check", "pipe.toml"]):
        done = subprocess.run(
            [sys.executable, "-m", "playground", *args],
            cwd=tmp_path,
            env=env,
            capture_output=True,
            text=True,
            timeout=FIFO_WAIT,
            check=False,
        )
        if args[0] == "check":
            assert done.returncode == 1, done.stderr
            assert "pipe.toml" in done.stderr
        else:
            assert done.returncode == EXIT_OK, done.stderr
            assert "pipe" not in done.stdout
    from playground.level import LevelError, load

    with pytest.raises(LevelError, match="not a regular file"):
        load(tmp_path / "pipe.toml")


@pytest.mark.parametrize(
    "args",
    [
        ["play", "rest", "--headless", "--frames", "1", "--replay-out", "{out}.json"],
        ["play", "rest", "--headless", "--frames", "1", "--screenshot", "{out}.png"],
        ["schema", "-o", "{out}.json"],
        ["run", "rest", "--seconds", "0.1", "--record", "{out}.csv"],
    ],
    ids=["play --replay-out", "play --screenshot", "schema -o", "run --record"],
)
@pytest.mark.parametrize("there", ["a file", "a dangling symlink"])
def test_every_overwrite_needs_force(args: list[str], there: str, tmp_path: Path) -> None:
    """Law: no command writes over a file, or through a symlink (even a dangling one, whose
    target it would create), without ``--force``: one line naming ``--force``, exit 2, and
    nothing written; with ``--force`` it writes."""
    if args[0] == "play":
        pytest.importorskip("pygame")
    target = tmp_path / "target"
    suffix = Path(args[-1]).suffix
    out = tmp_path / f"out{suffix}"
    if there == "a file":
        out.write_text("precious", encoding="utf-8")
    else:
        out.symlink_to(target)
    line = [a.replace("{out}", str(tmp_path / "out")) for a in args]
    done = _cli(*line, cwd=tmp_path)
    assert done.returncode == EXIT_USAGE, done.stderr
    assert "--force" in _one_line(done.stderr)
    assert not target.exists()
    if there == "a file":
        assert out.read_text(encoding="utf-8") == "precious"
    done = _cli(*line, "--force", cwd=tmp_path)
    assert done.returncode in (EXIT_OK, 1), done.stderr
    assert out.stat().st_size > 0


def test_settings_seconds_are_bounded_alike_in_check_and_run(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Law: ``check`` refuses a ``settings.seconds`` that ``run`` would refuse (more than an
    hour), naming the file and the key — not ``--seconds``, a flag the user never gave."""
    from playground.cli import EXIT_FAILED

    path = tmp_path / "long.toml"
    path.write_text('title = "L"\ndescription = "d"\n[settings]\nseconds = 1e5\n', "utf-8")
    assert main(["check", str(path)]) == EXIT_FAILED
    err = capsys.readouterr().err
    assert str(path) in err and "settings.seconds: expected less than or equal to 3600" in err
    assert main(["run", str(path)]) == EXIT_USAGE
    err = capsys.readouterr().err
    assert "settings.seconds" in err and "--seconds" not in err
