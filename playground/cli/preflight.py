"""Checks a command makes before its long work starts: output paths and optional dependencies.

Each failure is one line for the user (the CLI maps it to exit code 2), raised before a sweep or a
run rather than after it.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Sequence
from pathlib import Path

__all__ = ["UsageError", "needs", "writable"]


class UsageError(Exception):
    """Bad input or environment found by a command: the message is the whole story."""


def writable(
    option: str, path: str | Path, *, suffixes: Sequence[str] = (), force: bool = False
) -> Path:
    """``path`` if a file can be written there: its folder exists, it is not a folder, it ends in
    one of ``suffixes`` (any, if none are given), and nothing is there yet — not even a symlink,
    dangling or not — unless ``force``.

    >>> writable("--output", "/no/x.json")
    Traceback (most recent call last):
    ...
    playground.cli.preflight.UsageError: --output: folder /no does not exist (for /no/x.json)
    """
    p = Path(path)
    if suffixes and p.suffix.lower() not in suffixes:
        raise UsageError(f"{option}: expected a file ending in {' or '.join(suffixes)}, got {p}")
    if p.is_dir():
        raise UsageError(f"{option}: {p} is a folder; expected a file name")
    if not p.parent.is_dir():
        raise UsageError(f"{option}: folder {p.parent} does not exist (for {p})")
    if not force and (p.exists() or p.is_symlink()):
        raise UsageError(f"{option}: {p} already exists (use --force to overwrite)")
    return p


def needs(module: str, option: str) -> None:
    """Raise ``ModuleNotFoundError`` now if the optional ``module`` that ``option`` uses is
    missing (the CLI says which extra installs it)."""
    if importlib.util.find_spec(module) is None:
        raise ModuleNotFoundError(f"{option} needs {module}", name=module)
