"""The seed sequences as short animated GIFs, for the README: ``playground gifs`` regenerates
them all with one command.

Each GIF is the level's scripted run from its start for its ``settings.seconds``, drawn off
screen at ``SIZE`` with the default window's field of view and the compact HUD (title, clock,
player state, legend, scope), kept at ``FPS`` frames per second, in real time.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from playground.level.files import SEED_SEQUENCES
from playground.view.app import App
from playground.view.capture import GifWriter
from playground.view.clock import HEADLESS_FRAME
from playground.view.launcher import init_headless, show_level

__all__ = ["FPS", "SEQUENCES", "SIZE", "make_gif", "make_gifs"]

SEQUENCES = SEED_SEQUENCES
"""The seven seed sequences, in the order the README tells them."""

SIZE = (640, 360)  # px: half the default window, small enough for a README
WINDOW_WIDTH = 1280  # px: the default window, whose field of view the GIFs keep
FPS = 20  # GIF frames per second: one drawn frame (1/60 s) in three
OUT = Path("docs/img/gifs")


def make_gif(level: str, path: Path, size: tuple[int, int] = SIZE) -> Path:
    """Write ``level``'s scripted run as an animated GIF to ``path``; returns it."""
    from playground.level.files import find
    from playground.level.loading import load

    seconds = load(find(level)).settings.seconds
    init_headless()
    app = App(show_level, level, size=size)
    app.compact = True
    # The level's zoom is chosen for the default window: keep its field of view.
    app.camera.zoom_by(size[0] / WINDOW_WIDTH)
    every = round(1.0 / (HEADLESS_FRAME * FPS))
    writer = GifWriter(every=every, fps=FPS)
    app.run_frames(round(seconds / HEADLESS_FRAME) + 1, each=writer)
    return writer.save(path)


def make_gifs(out: Path = OUT, levels: Sequence[str] | None = None) -> list[Path]:
    """Write one GIF per level (default: :data:`SEQUENCES`) into ``out`` (created if missing),
    named after the level."""
    out.mkdir(parents=True, exist_ok=True)
    return [make_gif(level, out / f"{level}.gif") for level in levels or SEQUENCES]
