"""The catalogue of breaks: :class:`Break`, the registry :data:`BREAKS` by name, :func:`apply` to
open one, and :func:`catch_problems` to check the breaks a level declares against it.

>>> "ring_spin_stopped" in names()
True
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, contextmanager
from dataclasses import dataclass

from playground.level.document import Level
from playground.level.errors import Problem, suggest

__all__ = [
    "BREAKS",
    "Break",
    "BreakError",
    "Patch",
    "apply",
    "catch_problems",
    "names",
    "register",
]

Patch = Callable[[], AbstractContextManager[None]]
"""A break: a context manager that breaks its feature while open."""


class BreakError(Exception):
    """A break could not be applied (the method or value it patches is gone or changed)."""


@dataclass(frozen=True, slots=True)
class Break:
    """One named break: ``patch()`` is a context manager that breaks the feature while open."""

    name: str
    patch: Patch

    @property
    def doc(self) -> str:
        """What it breaks: the first paragraph of its docstring, on one line."""
        text = inspect.getdoc(self.patch) or ""
        return " ".join(text.split("\n\n")[0].split())


BREAKS: dict[str, Break] = {}
"""Every break by name, in the order they are defined."""


def register(name: str) -> Callable[[Callable[[], Iterator[None]]], Patch]:
    def register(fn: Callable[[], Iterator[None]]) -> Patch:
        patch = contextmanager(fn)
        BREAKS[name] = Break(name, patch)
        return patch

    return register


def names() -> list[str]:
    """The names of every break, in registry order."""
    return list(BREAKS)


def catch_problems(level: Level) -> list[Problem]:
    """Each break ``level`` declares to catch that the catalogue does not hold, at its key
    (``catches.i``) with the valid names; the level format checks only that each is declared
    once."""
    valid = names()
    return [
        Problem(
            f"catches.{i}",
            f"no break named {name!r}{suggest(name, valid)} (valid: {', '.join(valid)})",
        )
        for i, name in enumerate(level.catches)
        if name not in BREAKS
    ]


def apply(name: str) -> AbstractContextManager[None]:
    """The context manager of the break ``name`` (KeyError listing the valid names)."""
    try:
        return BREAKS[name].patch()
    except KeyError:
        raise KeyError(f"no break named {name!r} (known: {', '.join(BREAKS)})") from None
