"""Laws of the pytest plugin: it collects a level named on the command line wherever it lives, and
a folder's TOML files only where the project opts in or the file declares itself a level."""

from __future__ import annotations

import subprocess
import sys

import pytest

from playground.level import find, load

pytest_plugins = ["pytester"]

NOT_A_LEVEL = '[tree]\nkind = "oak"\nheight = 12\n'
"""Another project's TOML file in a folder called ``levels``."""


def _level_text(*, directive: bool) -> str:
    """The shipped ``rest`` level, with or without its ``#:schema`` first line."""
    lines = find("rest").read_text(encoding="utf-8").splitlines(keepends=True)
    body = "".join(line for line in lines if not line.startswith("#:schema"))
    return ("#:schema ./level.schema.json\n" if directive else "") + body


def _checks() -> int:
    return len(load(find("rest")).expect)


def test_a_level_named_on_the_command_line_is_collected_anywhere(
    pytester: pytest.Pytester,
) -> None:
    """``pytest my_level.toml`` outside the repository runs its expectations, though the file is
    in no ``levels`` folder and the project has not opted in."""
    path = pytester.path / "elsewhere" / "my_level.toml"
    path.parent.mkdir()
    path.write_text(_level_text(directive=False), encoding="utf-8")
    result = pytester.runpytest("-p", "no:cacheprovider", str(path))
    result.assert_outcomes(passed=_checks())


def test_unrelated_levels_folder_is_left_alone(pytester: pytest.Pytester) -> None:
    """A project that has not opted in keeps its ``levels/*.toml`` to itself: nothing is
    collected from the folder or the whole project (pytest's "no tests ran", exit 5)."""
    levels = pytester.path / "levels"
    levels.mkdir()
    (levels / "forest.toml").write_text(NOT_A_LEVEL, encoding="utf-8")
    (levels / "rest.toml").write_text(_level_text(directive=False), encoding="utf-8")
    for args in ([], ["levels"]):
        result = pytester.runpytest("-p", "no:cacheprovider", *args)
        assert result.ret == pytest.ExitCode.NO_TESTS_COLLECTED


def test_a_project_opts_in_with_the_ini_option(pytester: pytest.Pytester) -> None:
    """``playground_levels = levels/*.toml`` in the project's ini collects exactly those files."""
    pytester.makeini("[pytest]\nplayground_levels = levels/*.toml\n")
    levels = pytester.path / "levels"
    levels.mkdir()
    (levels / "rest.toml").write_text(_level_text(directive=False), encoding="utf-8")
    (pytester.path / "other.toml").write_text(_level_text(directive=False), encoding="utf-8")
    result = pytester.runpytest("-p", "no:cacheprovider")
    result.assert_outcomes(passed=_checks())


def test_a_file_that_declares_itself_a_level_is_collected(pytester: pytest.Pytester) -> None:
    """A file whose first line is the ``#:schema`` directive naming the level schema is a level,
    in any folder, without an opt-in; its TOML neighbours are not."""
    folder = pytester.path / "stages"
    folder.mkdir()
    (folder / "mine.toml").write_text(_level_text(directive=True), encoding="utf-8")
    (folder / "config.toml").write_text(NOT_A_LEVEL, encoding="utf-8")
    result = pytester.runpytest("-p", "no:cacheprovider")
    result.assert_outcomes(passed=_checks())


def test_plugin_collects_one_item_per_expectation() -> None:
    """`pytest levels/x.toml` collects one test per expectation of the level."""
    path = find("rest")
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "--collect-only",
            "-q",
            "-p",
            "no:cacheprovider",
            str(path),
        ],
        capture_output=True,
        text=True,
        check=False,
        cwd=path.parent,
    ).stdout
    items = [line for line in out.splitlines() if "::" in line]
    assert len(items) == len(load(path).expect)


def test_playground_set_runs_every_level_as_a_variant(pytester: pytest.Pytester) -> None:
    """``--playground-set`` sets a key of every collected level, as ``playground run --set``
    does: ``rest`` (checks in the player's weights) passes at twice its mass and two substeps,
    and a bad value fails the level's load item naming the setting and the key."""
    path = pytester.path / "rest.toml"
    path.write_text(_level_text(directive=True), encoding="utf-8")
    mass, substeps = "actors.player.controller.mass=140", "settings.substeps=2"
    result = pytester.runpytest(
        "-p", "no:cacheprovider", "--playground-set", mass, "--playground-set", substeps
    )
    result.assert_outcomes(passed=_checks())
    bad = pytester.runpytest("-p", "no:cacheprovider", "--playground-set", "settings.substeps=0")
    bad.assert_outcomes(failed=1)
    bad.stdout.fnmatch_lines(["*rest.toml (with --set settings.substeps=0): settings.substeps:*"])
    unreadable = pytester.runpytest("-p", "no:cacheprovider", "--playground-set", "substeps")
    unreadable.stderr.fnmatch_lines(["*--playground-set: --set substeps: expected KEY.PATH=VALUE*"])
