"""The demo in a real window: `playground play` opens an X11 window under Xvfb (a virtual screen),
runs its frames and saves what it drew; without any display it refuses with a hint, exit code 2.

The window test needs Debian's ``xvfb`` (``.ci/run`` installs it where it can); elsewhere it is
skipped and says why.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pygame
import pytest

WINDOW_TIMEOUT = 120.0
"""s: a 60-frame run takes ~5 s here; the margin covers a loaded CI machine."""

BACKGROUND_SHARE_MAX = 0.98
"""A drawn frame is not one flat colour: at most this share of pixels may be the most common one."""


def _play(args: list[str], env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    cmd = [sys.executable, "-m", "playground.cli", "play", *args]
    return subprocess.run(
        cmd, env=env, capture_output=True, text=True, timeout=WINDOW_TIMEOUT, check=False
    )


@pytest.mark.skipif(shutil.which("xvfb-run") is None, reason="Debian's xvfb is not installed")
def test_play_opens_a_real_window_and_draws_the_level(tmp_path: Path) -> None:
    """Law: under a real X server the windowed loop (not the headless one) runs to its frame
    count, exits 0 and leaves a screenshot that shows a scene, not an empty window."""
    shot = tmp_path / "window.png"
    env = {k: v for k, v in os.environ.items() if k not in ("SDL_VIDEODRIVER", "DISPLAY")}
    cmd = [
        "xvfb-run", "-a", "-s", "-screen 0 1280x800x24",
        sys.executable, "-m", "playground.cli",
        "play", "flying_whale", "--frames", "60", "--screenshot", str(shot),
    ]  # fmt: skip
    done = subprocess.run(
        cmd, env=env, capture_output=True, text=True, timeout=WINDOW_TIMEOUT, check=False
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert shot.exists(), done.stderr[-2000:]
    pygame.init()
    image = pygame.image.load(str(shot))
    pixels = pygame.surfarray.array2d(image).ravel()
    _, counts = np.unique(pixels, return_counts=True)
    assert counts.max() / pixels.size <= BACKGROUND_SHARE_MAX


def test_play_without_a_display_says_so_and_suggests_headless() -> None:
    """Law: with no display at all, plain `playground play` exits 2 with a hint to --headless,
    never a traceback."""
    env = {
        k: v
        for k, v in os.environ.items()
        if k not in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY")
    }
    done = _play(["rest"], env)
    assert done.returncode == 2
    assert "--headless" in done.stderr + done.stdout
    assert "Traceback" not in done.stderr
