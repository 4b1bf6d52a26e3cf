"""Laws of progress bars: a long command shows one on a terminal, and none when stderr is not a
terminal or with ``--no-progress`` (so logs and pipes stay clean)."""

from __future__ import annotations

import fcntl
import os
import pty
import struct
import subprocess
import sys
import termios

from playground.cli import PROGRESS_MIN_STEPS
from playground.level import find, load

LONG_S = 2 * PROGRESS_MIN_STEPS * load(find("rest")).settings.dt
"""Simulated seconds of ``rest`` long enough for a bar (twice the threshold)."""


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
