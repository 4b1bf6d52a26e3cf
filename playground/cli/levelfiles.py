"""The commands on level files: ``list`` the shipped levels, ``check`` files, print the ``schema``.

>>> from playground.cli import main
>>> main(["check", "incline"])
ok      incline: Incline
0
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from playground.cli.exits import EXIT_FAILED, EXIT_OK
from playground.cli.preflight import writable
from playground.level.document import Level, schema
from playground.level.errors import LevelError
from playground.level.files import find, shipped
from playground.level.loading import load, variant_source
from playground.level.variants import Setting, SettingError, parse_set

__all__ = [
    "add_set_option",
    "cmd_check",
    "cmd_list",
    "cmd_schema",
    "configure_check",
    "configure_list",
    "configure_schema",
    "declared_notes",
    "load_checked",
    "schema_text",
]


def cmd_list(args: argparse.Namespace) -> int:
    """Print the shipped levels with their titles."""
    levels = shipped()
    width = max((len(n) for n in levels), default=0)
    for name, path in levels.items():
        try:
            title = load(path).title
        except LevelError as exc:
            title = f"(invalid: {len(exc.problems)} problem(s); run playground check)"
        print(f"{name:<{width}}  {title}")
    return EXIT_OK


def load_checked(path: Path, sets: tuple[Setting, ...] = ()) -> Level:
    """The level file at ``path`` (a variant of it with ``sets``), its declared breaks also
    checked against the catalogue of faults (a :class:`LevelError` naming the file and each
    key; the level format alone knows no break names)."""
    level = load(path, sets)
    if level.catches:
        from playground.faults.catalog import catch_problems

        problems = catch_problems(level)
        if problems:
            raise LevelError(variant_source(str(path), sets), problems)
    return level


def declared_notes(level: Level) -> list[str]:
    """What ``check`` and ``run`` say of a variant its level declares it cannot support: each
    covering declaration's key path and reason."""
    from playground.level.support import matches

    return [
        f"variants.unsupported.{i} covers this variant (its checks may fail here): {u}"
        for i, u in matches(level)
    ]


def _setting(text: str) -> Setting:
    try:
        return parse_set(text)
    except SettingError as exc:
        raise argparse.ArgumentTypeError(exc.message) from None


def add_set_option(p: argparse.ArgumentParser) -> None:
    """The ``--set KEY.PATH=VALUE`` option of the commands that load levels (``args.sets``)."""
    p.add_argument(
        "--set",
        dest="sets",
        action="append",
        type=_setting,
        default=[],
        metavar="KEY.PATH=VALUE",
        help="a variant: set one key of the level (TOML value; repeatable), e.g. "
        "--set actors.player.controller.mass=140 --set settings.substeps=2",
    )


def cmd_check(args: argparse.Namespace) -> int:
    """Validate level files and build each scene, as ``run`` does; print every problem; exit 1
    if any file has one."""
    from playground.scene.scene import build

    failed = False
    sets = tuple(args.sets)
    for item in args.files:
        try:
            path = find(item)
            level = load_checked(path, sets)
            scene = build(level, variant_source(str(path), sets))
            print(f"ok      {item}: {level.title}")
            for line in declared_notes(level):
                print(f"note    {item}: {line}")
            note = _long_run(scene.world.space, level)
            if note:
                print(f"note    {item}: {note}")
        except LevelError as exc:
            failed = True
            where = f" (line {exc.line}, column {exc.column})" if exc.line is not None else ""
            print(f"FAILED  {exc.source}{where}: {len(exc.problems)} problem(s)", file=sys.stderr)
            for problem in exc.problems:
                print(f"  {problem}", file=sys.stderr)
    return EXIT_FAILED if failed else EXIT_OK


SECONDS_PER_BODY_STEP = 1e-6
"""s: about the least a step costs per body (docs/performance.md: the N = 1000 pile)."""
LONG_RUN_BODY_STEPS = 1e9
"""Bodies × steps above which ``check`` says a run will be long (a quarter of an hour or more at
:data:`SECONDS_PER_BODY_STEP`)."""


def _long_run(space: Any, level: Level) -> str:
    """A note when the level's run steps so many bodies so many times that it will be long."""
    bodies = max(1, len(space.bodies))
    steps = round(level.settings.seconds / level.settings.dt)
    work = bodies * steps
    if work <= LONG_RUN_BODY_STEPS:
        return ""
    minutes = work * SECONDS_PER_BODY_STEP / 60.0
    return (
        f"{bodies} bodies for {steps} steps ({work:.2g} body-steps): at a microsecond or more "
        f"per body and step, the run takes {minutes:.0f} minutes or more; shorten "
        "settings.seconds or use fewer bodies"
    )


def cmd_schema(args: argparse.Namespace) -> int:
    """Print the level JSON Schema, or write it to --output."""
    text = schema_text()
    if args.output is None:
        sys.stdout.write(text)
    else:
        writable("--output", args.output, force=args.force).write_text(text, encoding="utf-8")
    return EXIT_OK


def schema_text() -> str:
    """The JSON Schema as the committed ``levels/level.schema.json`` holds it."""
    return json.dumps(schema(), indent=2, ensure_ascii=False) + "\n"


def configure_list(p: argparse.ArgumentParser) -> None:
    p.set_defaults(func=cmd_list)


def configure_check(p: argparse.ArgumentParser) -> None:
    p.add_argument("files", nargs="+", metavar="FILE", help="level files or shipped names")
    add_set_option(p)
    p.set_defaults(func=cmd_check)


def configure_schema(p: argparse.ArgumentParser) -> None:
    p.add_argument("--output", "-o", metavar="FILE", help="write it to FILE instead")
    p.add_argument("--force", action="store_true", help="overwrite an existing --output file")
    p.set_defaults(func=cmd_schema)
