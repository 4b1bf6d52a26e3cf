"""Pictures out of the view: screenshots and animated GIFs, written whole or not at all.

Every output path is checked before anything runs (:func:`picture_path`, :func:`gif_path`), so a
typo costs a one-line error, not a finished run without its file. Files are written to a
temporary name beside the target and renamed into place: an interrupted or failed write never
leaves a half-written file under the name asked for.

>>> parse_size("640x360")
(640, 360)
>>> parse_size("0x360")
Traceback (most recent call last):
...
ValueError: --size: expected WIDTHxHEIGHT, each side 64 to 8192 px, got '0x360'
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

import pygame

from playground.view.draw import COLOURS

__all__ = [
    "GIF_FPS",
    "MAX_SIDE",
    "MIN_SIDE",
    "PICTURE_SUFFIXES",
    "GifWriter",
    "gif_path",
    "parse_size",
    "picture_path",
    "save_picture",
]

MIN_SIDE = 64  # px: below this the HUD cannot be read at all
MAX_SIDE = 8192  # px: past 8K a frame is ~200 MB of pixels; a typo, not a wish
PICTURE_SUFFIXES = (".png", ".bmp", ".tga", ".jpg", ".jpeg")  # what pygame.image.save writes
GIF_FPS = 20  # frames per second of an animated GIF: 50 ms per frame, a whole GIF delay unit
GIF_COLOURS = 64  # palette size of a GIF: the view's flat colours need few, and few keep it small


def parse_size(text: str) -> tuple[int, int]:
    """``"WxH"`` → (W, H) in px, each side in [MIN_SIDE, MAX_SIDE]; ValueError otherwise."""
    error = ValueError(
        f"--size: expected WIDTHxHEIGHT, each side {MIN_SIDE} to {MAX_SIDE} px, got {text!r}"
    )
    parts = text.lower().split("x")
    if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
        raise error
    w, h = int(parts[0]), int(parts[1])
    if not (MIN_SIDE <= w <= MAX_SIDE and MIN_SIDE <= h <= MAX_SIDE):
        raise error
    return (w, h)


def _folder(option: str, path: Path) -> None:
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise ValueError(f"{option}: folder {str(folder)!r} does not exist (for {str(path)!r})")


def picture_path(text: str, option: str = "--screenshot") -> Path:
    """A screenshot path: a known picture suffix in an existing folder; ValueError otherwise.

    >>> picture_path("shot.webp")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: --screenshot: 'shot.webp' has an unknown picture type; expected .png, ... or .jpeg
    """
    path = Path(text)
    if path.suffix.lower() not in PICTURE_SUFFIXES:
        known = ", ".join(PICTURE_SUFFIXES[:-1]) + " or " + PICTURE_SUFFIXES[-1]
        raise ValueError(f"{option}: {text!r} has an unknown picture type; expected {known}")
    _folder(option, path)
    return path


def gif_path(text: str, option: str = "--gif") -> Path:
    """An animated GIF path: ``.gif`` in an existing folder; ValueError otherwise.

    >>> gif_path("run.png")
    Traceback (most recent call last):
    ...
    ValueError: --gif: expected a file name ending in .gif, got 'run.png'
    """
    path = Path(text)
    if path.suffix.lower() != ".gif":
        raise ValueError(f"{option}: expected a file name ending in .gif, got {text!r}")
    _folder(option, path)
    return path


@contextlib.contextmanager
def _atomic(path: Path) -> Iterator[Path]:
    """A temporary path beside ``path`` (same suffix) that replaces it on success only."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}-", suffix=path.suffix, dir=path.parent)
    os.close(fd)
    # mkstemp makes the file private (0600); the finished file gets the usual permissions.
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)


def save_picture(surface: pygame.Surface, path: Path) -> Path:
    """Save ``surface`` to ``path`` (type from its suffix), whole or not at all."""
    with _atomic(path) as tmp:
        pygame.image.save(surface, str(tmp))
    return path


class GifWriter:
    """Collects frames of the view and writes them as one looping animated GIF (Pillow).

    ``every``: keep one drawn frame in ``every`` (at 60 drawn frames per second of simulated
    time and ``every = 3``, the GIF plays at 20 fps, in real time).

    >>> import pygame
    >>> gif = GifWriter(every=2)
    >>> for k in range(5):
    ...     gif.offer(pygame.Surface((8, 8)))
    >>> len(gif.frames)
    3
    """

    def __init__(self, every: int = 3, fps: int = GIF_FPS) -> None:
        if every < 1 or fps < 1:
            raise ValueError(f"every, fps: expected integers >= 1, got {every!r}, {fps!r}")
        self.every = every
        self.fps = fps
        self.frames: list[bytes] = []
        self.size: tuple[int, int] | None = None
        self._offered = 0

    def offer(self, surface: pygame.Surface) -> None:
        """Keep this frame if it is one in ``every`` (the first always is)."""
        if self._offered % self.every == 0:
            size = surface.get_size()
            if self.size is not None and size != self.size:
                raise ValueError(f"frame size {size} differs from the first frame's {self.size}")
            self.size = size
            self.frames.append(pygame.image.tobytes(surface, "RGB"))
        self._offered += 1

    def save(self, path: Path) -> Path:
        """Write the frames to ``path`` as a looping GIF, whole or not at all."""
        from PIL import Image

        if not self.frames or self.size is None:
            raise ValueError(f"{path}: no frames to write")
        rgbs = [Image.frombytes("RGB", self.size, data) for data in self.frames]
        # One palette for every frame: pixels that did not change keep their index, so the GIF
        # stores only what moved. It holds the view's own colours exactly (an arrow covers too few
        # pixels to win a place in an adaptive palette), the rest adapted to frames across the run.
        keep = sorted(set(COLOURS.values()))
        w, h = self.size
        picks = sorted({k * (len(rgbs) - 1) // 3 for k in range(4)})
        strip = Image.new("RGB", (w, h * len(picks)))
        for row, k in enumerate(picks):
            strip.paste(rgbs[k], (0, row * h))
        free = GIF_COLOURS - len(keep)
        adaptive = strip.quantize(free, method=Image.Quantize.MEDIANCUT).getpalette() or []
        colours = [c for rgb in keep for c in rgb] + adaptive[: 3 * free]
        colours += colours[:3] * (256 - len(colours) // 3)  # unused entries: a colour in use
        palette = Image.new("P", (1, 1))
        palette.putpalette(colours)
        images = [rgb.quantize(palette=palette, dither=Image.Dither.NONE) for rgb in rgbs]
        with _atomic(path) as tmp:
            images[0].save(
                tmp,
                format="GIF",
                save_all=True,
                append_images=images[1:],
                duration=round(1000 / self.fps),
                loop=0,
                optimize=True,
            )
        return path
