"""The errors of loading a level: each problem with its key path, all of them at once."""

from __future__ import annotations

import dataclasses
import difflib
from collections.abc import Sequence


@dataclasses.dataclass(frozen=True, slots=True)
class Problem:
    """One thing wrong with a level: where (dotted key path) and what."""

    path: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}" if self.path else self.message


class LevelError(Exception):
    """A level could not be loaded: every problem, each with its key path.

    ``line`` and ``column`` are set for TOML syntax errors.
    """

    def __init__(
        self,
        source: str,
        problems: Sequence[Problem],
        *,
        line: int | None = None,
        column: int | None = None,
    ) -> None:
        self.source = source
        self.problems = tuple(problems)
        self.line = line
        self.column = column
        super().__init__("\n".join(f"{source}: {p}" for p in self.problems))


def suggest(word: str, options: Sequence[str]) -> str:
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.5)
    return f" (did you mean {close[0]!r}?)" if close else ""
