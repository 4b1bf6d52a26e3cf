"""pytest plugin: ``pytest levels/`` runs each level file and reports each expectation.

Registered by the ``pytest11`` entry point, so it works wherever playground is installed. A
``*.toml`` file is a level file when it lives in a directory called ``levels`` or matches one of
the ``levels_glob`` ini patterns (default ``levels/*.toml`` and ``*/levels/*.toml``). Each file
is built and run once, on its first item; each expectation is one test item whose failure
message is the check's detail.
A file that does not load is one failing item listing every problem.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from playground.level import Level, LevelError, load

__all__ = ["LevelFile", "LevelItem"]


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addini(
        "levels_glob",
        "glob patterns of level files collected by the playground plugin",
        type="args",
        default=["levels/*.toml", "*/levels/*.toml"],
    )


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> LevelFile | None:
    if file_path.suffix != ".toml":
        return None
    patterns = parent.config.getini("levels_glob")
    if file_path.parent.name == "levels" or any(file_path.match(p) for p in patterns):
        collected: LevelFile = LevelFile.from_parent(parent, path=file_path)
        return collected
    return None


class LevelFile(pytest.File):
    """One level file: built and run once, one item per expectation."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._results: dict[str, tuple[bool, str]] | None = None

    def collect(self) -> Iterator[pytest.Item]:
        try:
            level = load(self.path)
        except LevelError as exc:
            yield LevelItem.from_parent(self, name="load", check=None, error=str(exc))
            return
        from playground.expectations import check_names

        names = check_names(level)
        self.level = level
        for name in names:
            yield LevelItem.from_parent(self, name=name, check=name, error=None)

    def results(self) -> dict[str, tuple[bool, str]]:
        """Run the level once; every check's (passed, detail) by name."""
        if self._results is None:
            self._results = _run(self.level)
        return self._results


def _run(level: Level) -> dict[str, tuple[bool, str]]:
    from playground.expectations import watch
    from playground.scene import build

    scene = build(level)
    checks = watch(scene)
    scene.run(level.settings.seconds)
    return {r.name: (r.passed, r.detail) for r in checks.results()}


class LevelCheckError(Exception):
    """An expectation of a level did not hold."""


class LevelItem(pytest.Item):
    """One expectation of a level file (or the file's loading, if it does not load)."""

    def __init__(self, *, check: str | None, error: str | None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.check = check
        self.error = error

    def runtest(self) -> None:
        if self.error is not None:
            raise LevelCheckError(self.error)
        parent = self.parent
        assert isinstance(parent, LevelFile) and self.check is not None
        try:
            passed, detail = parent.results()[self.check]
        except LevelError as exc:
            raise LevelCheckError(str(exc)) from None
        if not passed:
            raise LevelCheckError(detail)

    def repr_failure(
        self,
        excinfo: pytest.ExceptionInfo[BaseException],
        style: Any = None,
    ) -> str:
        if isinstance(excinfo.value, LevelCheckError):
            return str(excinfo.value)
        return str(super().repr_failure(excinfo))

    def reportinfo(self) -> tuple[Path, int | None, str]:
        return self.path, None, f"{self.path.name}::{self.name}"
