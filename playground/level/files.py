"""Where level files are: the shipped levels, extra folders, and finding a level by name."""

from __future__ import annotations

import atexit
import functools
import importlib.resources
import os
import shutil
import tempfile
from pathlib import Path

from playground.level.errors import LevelError, Problem, suggest

LEVELS_ENV = "PLAYGROUND_LEVELS"
"""Environment variable: extra directories of level files (os.pathsep separated)."""

LEVELS_PACKAGE = "playground.levels"
"""The package holding the shipped levels and their schema (the project's top-level ``levels/``
folder, mapped into the package when it is built)."""


def levels_dirs() -> list[Path]:
    """The extra level directories named in ``$PLAYGROUND_LEVELS`` that exist, in order."""
    dirs = [Path(d) for d in os.environ.get(LEVELS_ENV, "").split(os.pathsep) if d]
    return [d for d in dirs if d.is_dir()]


@functools.cache
def _packaged() -> dict[str, Path]:
    """The levels inside the package, as files on disk.

    ``importlib.resources`` finds them wherever the package was installed (a wheel, ``--user``,
    an editable install). A zip import has no files on disk: the levels are copied once, under
    their own names, into a temporary folder removed when the process exits.
    """
    root = importlib.resources.files(LEVELS_PACKAGE)
    items = sorted(
        (t for t in root.iterdir() if t.is_file() and t.name.endswith(".toml")),
        key=lambda t: t.name,
    )
    if all(isinstance(t, Path) for t in items):
        return {Path(str(t)).stem: Path(str(t)) for t in items}
    folder = Path(tempfile.mkdtemp(prefix="playground-levels-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    found: dict[str, Path] = {}
    for t in items:
        copy = folder / t.name
        copy.write_bytes(t.read_bytes())
        found[copy.stem] = copy
    return found


SEED_SEQUENCES = (
    "moving_platform",
    "seesaw",
    "flying_whale",
    "crusher",
    "gravity_flip",
    "null_enemy",
    "gravity_leap",
)
"""The shipped levels of the seven sequences the playground exists for (docs/design.md §1), in
that order: each must catch at least two breaks, and each has a GIF in the README."""


def shipped() -> dict[str, Path]:
    """Levels by name (file stem): those in ``$PLAYGROUND_LEVELS`` first, then the package's.

    >>> sorted(shipped())[:3]
    ['bounce', 'crowd', 'crusher']
    """
    found: dict[str, Path] = {}
    for d in levels_dirs():
        for f in sorted(d.glob("*.toml")):
            # Only regular files are levels: reading a FIFO named *.toml would block.
            if f.is_file():
                found.setdefault(f.stem, f)
    for name, path in _packaged().items():
        found.setdefault(name, path)
    return found


def find(level: str | os.PathLike[str]) -> Path:
    """A level file from a path or the name of a shipped level.

    >>> find("rest").name
    'rest.toml'
    """
    p = Path(level)
    if p.suffix == ".toml" or p.exists():
        if not p.is_file():
            raise LevelError(str(p), [Problem("", "no such level file")])
        return p
    levels = shipped()
    if str(level) in levels:
        return levels[str(level)]
    names = sorted(levels)
    raise LevelError(
        str(level),
        [
            Problem(
                "",
                f"not a file or a shipped level{suggest(str(level), names)} "
                f"(shipped: {', '.join(names) or 'none'})",
            )
        ],
    )
