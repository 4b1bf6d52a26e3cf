"""Loading a level: TOML text or a parsed document to a validated :class:`Level`."""

from __future__ import annotations

import os
import re
import stat
import tomllib
from collections.abc import Sequence
from pathlib import Path

from pydantic import ValidationError

from playground.level.document import Level
from playground.level.errors import LevelError, Problem
from playground.level.explain import problems
from playground.level.references import references
from playground.level.salvage import salvaged_references
from playground.level.support import own_problems
from playground.level.variants import Setting, SettingError, apply

_TOML_WHERE = re.compile(r"\(at line (\d+), column (\d+)\)")


def loads(text: str, source: str = "<string>", sets: Sequence[Setting] = ()) -> Level:
    """Parse and validate a level from TOML text, with the settings ``sets`` applied (a variant,
    see :mod:`playground.level.variants`); :class:`LevelError` lists every problem."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        where = _TOML_WHERE.search(str(exc))
        line, column = (int(where[1]), int(where[2])) if where else (None, None)
        raise LevelError(
            source, [Problem("", f"TOML syntax error: {exc}")], line=line, column=column
        ) from None
    except RecursionError:
        # tomllib parses nested arrays and inline tables recursively.
        raise LevelError(source, [_TOO_DEEP]) from None
    if not sets:
        level = validate(data, source)
        own = list(own_problems(level))
        if own:
            raise LevelError(source, own)
        return level
    label = variant_source(source, sets)
    try:
        data = apply(data, sets)
    except SettingError as exc:
        raise LevelError(label, [exc.problem()]) from None
    return validate(data, label)


def variant_source(source: str, sets: Sequence[Setting]) -> str:
    """What a variant's problems are reported under: the file and its settings.

    >>> from playground.level.variants import parse_sets
    >>> variant_source("rest.toml", parse_sets(["settings.substeps=2"]))
    'rest.toml (with --set settings.substeps=2)'
    """
    if not sets:
        return source
    return f"{source} (with {' '.join(f'--set {s}' for s in sets)})"


_TOO_DEEP = Problem("", "document nested too deeply (no level nests more than a few tables)")


def validate(data: object, source: str = "<data>") -> Level:
    """Validate an already parsed document (a dict of TOML values)."""
    try:
        try:
            level = Level.model_validate(data)
        except ValidationError as exc:
            # Describing the error walks the document again (and may recurse as deep).
            raise LevelError(source, problems(exc) + salvaged_references(data, exc)) from None
    except RecursionError:
        raise LevelError(source, [_TOO_DEEP]) from None
    found = list(references(level))
    if found:
        raise LevelError(source, found)
    return level


def load(path: str | os.PathLike[str], sets: Sequence[Setting] = ()) -> Level:
    """Load a level file (with the settings ``sets`` applied: a variant).

    >>> from playground.level.files import find
    >>> load(find("rest")).title
    'Rest'
    """
    p = Path(path)
    try:
        # Only a regular file is read (opening a FIFO would block until a writer comes).
        if not stat.S_ISREG(p.stat().st_mode):
            raise LevelError(str(p), [Problem("", "not a regular file; a level is a TOML file")])
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise LevelError(str(p), [Problem("", f"cannot read the file: {exc}")]) from None
    return loads(text, str(p), sets)
