"""The matrix: run each level clean and under each break it declares, and report which of its
checks caught the break (:class:`Outcome`, a :class:`Row` per level).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass

from playground.faults.catalog import BreakError, apply
from playground.level.document import Level

__all__ = ["Outcome", "Row", "matrix", "run"]


@dataclass(frozen=True, slots=True)
class Outcome:
    """One run of a level, clean (``fault`` None) or under a break.

    Attributes:
        level: the level's name.
        fault: the break applied, or None for the clean run.
        declared: the level declares the break in ``catches`` (True for the clean run).
        checks: how many checks the level has.
        failed: the names of the checks that failed.
        error: why the run could not be made (the break did not apply, or the run raised).
        seconds: wall-clock time of the run, s.
    """

    level: str
    fault: str | None
    declared: bool
    checks: int
    failed: tuple[str, ...]
    error: str | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """The clean run passes every check; a declared break is caught by at least one; an
        undeclared one only has to run."""
        if self.error is not None:
            return False
        if self.fault is None:
            return not self.failed
        return bool(self.failed) or not self.declared


@dataclass(frozen=True, slots=True)
class Row:
    """One level of the matrix: its clean run and one outcome per break tried."""

    level: str
    clean: Outcome
    breaks: tuple[Outcome, ...]

    @property
    def ok(self) -> bool:
        return self.clean.ok and all(o.ok for o in self.breaks)


def run(level: Level, name: str, fault: str | None = None) -> Outcome:
    """Build and run ``level`` (called ``name``) to its end, under the break ``fault`` if given,
    and say which checks failed."""
    from playground.scene import build
    from playground.scene.checks import watch

    declared = fault is None or fault in level.catches
    start = time.perf_counter()
    try:
        with apply(fault) if fault is not None else _nothing():
            scene = build(level)
            checks = watch(scene)
            scene.run(level.settings.seconds)
            results = checks.results()
    except BreakError as exc:
        return Outcome(name, fault, declared, len(level.expect), (), f"cannot apply: {exc}")
    except Exception as exc:  # a broken feature may raise anywhere: report it, keep going
        return Outcome(name, fault, declared, len(level.expect), (), f"{type(exc).__name__}: {exc}")
    failed = tuple(r.name for r in results if not r.passed)
    return Outcome(name, fault, declared, len(results), failed, seconds=time.perf_counter() - start)


@contextmanager
def _nothing() -> Iterator[None]:
    yield


def matrix(
    levels: Sequence[tuple[str, Level]],
    faults: Sequence[str] | None = None,
    progress: Callable[[str], None] | None = None,
) -> list[Row]:
    """Run each level clean and under each of its declared breaks (or under ``faults``, if
    given, declared or not); ``progress(label)`` is called before each run."""
    rows = []
    for name, level in levels:
        tried = list(level.catches) if faults is None else list(faults)
        if progress is not None:
            progress(f"{name} clean")
        clean = run(level, name)
        outcomes = []
        for fault in tried:
            if progress is not None:
                progress(f"{name} {fault}")
            outcomes.append(run(level, name, fault))
        rows.append(Row(name, clean, tuple(outcomes)))
    return rows
