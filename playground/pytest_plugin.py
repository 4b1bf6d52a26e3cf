"""pytest plugin: ``pytest levels/`` runs each level file and reports each expectation.

Registered by the ``pytest11`` entry point, so it is active wherever playground is installed, and
it stays in its lane: a ``*.toml`` file is collected as a level only when

- it is named on the command line (``pytest path/to/any_level.toml``, wherever it lives);
- the project opts in: its ``playground_levels`` ini option lists glob patterns, relative to the
  rootdir, of its level files (this repository lists ``levels/*.toml``); or
- the file declares itself a playground level: its first line is a ``#:schema`` directive naming
  the level schema (``level.schema.json``), as every shipped level's is.

Any other TOML file (another project's ``levels/forest.toml``) is left alone. Each level is built
and run once, on its first item; each expectation is one test item whose failure message is the
check's detail. A file that does not load is one failing item listing every problem.

``--playground-set KEY.PATH=VALUE`` (repeatable) runs every collected level as a variant, each
key set as ``playground run --set`` sets it (:mod:`playground.level.variants`):
``pytest levels/ --playground-set settings.substeps=2``.
"""

from __future__ import annotations

import fnmatch
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from playground.level.document import SCHEMA_ID, Level
from playground.level.errors import LevelError
from playground.level.loading import load
from playground.level.variants import Setting, SettingError, parse_sets

__all__ = ["INI_OPTION", "SET_OPTION", "LevelFile", "LevelItem", "declares_level"]

INI_OPTION = "playground_levels"
"""The ini option a project uses to opt its level files in (glob patterns, rootdir-relative)."""

SCHEMA_NAME = SCHEMA_ID.rsplit("/", 1)[-1]
"""The schema's file name, which a level's ``#:schema`` directive ends with."""


SET_OPTION = "--playground-set"
"""The command-line option that runs every collected level as a variant (repeatable)."""


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        SET_OPTION,
        action="append",
        default=[],
        metavar="KEY.PATH=VALUE",
        help="run every collected level as a variant: set one key of it, as `playground run "
        "--set` does (TOML value; repeatable)",
    )
    parser.addini(
        INI_OPTION,
        "glob patterns (relative to the rootdir) of level files the playground plugin collects",
        type="args",
        default=[],
    )


def pytest_configure(config: pytest.Config) -> None:
    _sets(config)  # a setting that cannot be read is a usage error before anything is collected


def _sets(config: pytest.Config) -> tuple[Setting, ...]:
    """The ``--playground-set`` settings (a usage error if one cannot be read)."""
    try:
        return parse_sets(config.getoption(SET_OPTION) or [])
    except SettingError as exc:
        raise pytest.UsageError(f"{SET_OPTION}: {exc}") from None


def declares_level(path: Path) -> bool:
    """Whether the file's first line is a ``#:schema`` directive naming the level schema.

    >>> from playground.level import find
    >>> declares_level(find("rest"))
    True
    """
    try:
        with path.open(encoding="utf-8") as fh:
            first = fh.readline(4096).strip()
    except (OSError, UnicodeDecodeError):
        return False
    return first.startswith("#:schema") and first.removeprefix("#:schema").strip().endswith(
        SCHEMA_NAME
    )


def _opted_in(file_path: Path, config: pytest.Config) -> bool:
    patterns: list[str] = config.getini(INI_OPTION)
    if not patterns:
        return False
    try:
        relative = file_path.resolve().relative_to(config.rootpath.resolve()).as_posix()
    except ValueError:
        return False
    return any(fnmatch.fnmatch(relative, pattern) for pattern in patterns)


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> LevelFile | None:
    if file_path.suffix != ".toml":
        return None
    if (
        parent.session.isinitpath(file_path)
        or _opted_in(file_path, parent.config)
        or declares_level(file_path)
    ):
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
            level = load(self.path, _sets(self.config))
        except LevelError as exc:
            yield LevelItem.from_parent(self, name="load", check=None, error=str(exc))
            return
        from playground.scene.checks import check_names

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
    from playground.scene import build
    from playground.scene.checks import watch

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
