"""Variants: a level run with some of its keys set otherwise, without copying the file.

A *setting* is ``KEY.PATH=VALUE``, as ``playground run``, ``check`` and ``faults`` take it with
``--set`` (and the pytest plugin with ``--playground-set``). The key path is dotted, as a
level's problems are reported: a table's key by name, an array's item by its index or, for an
array of named tables (``actors``, ``props``, ``movers``), by its ``name``. The value is a TOML
value (``140``, ``0.25``, ``true``, ``[1.0, 2.0]``, ``"grounded"``); a word that is no TOML
value is taken as a string. Settings are applied to the parsed document *before* it is
validated, so a variant goes through the same level model, the same cross-references and the
same scene checks as the file itself: an unknown key or a bad value is a problem of the file,
named at its key, and a variant that ``check`` accepts, ``run`` runs.

>>> sets = parse_sets(["actors.player.controller.mass=140", "settings.substeps=2"])
>>> [str(s) for s in sets]
['actors.player.controller.mass=140', 'settings.substeps=2']
>>> data = {"settings": {"dt": 0.01}, "actors": [{"name": "player", "position": [0, 1]}]}
>>> out = apply(data, sets)
>>> out["actors"][0]["controller"], out["settings"]
({'mass': 140}, {'dt': 0.01, 'substeps': 2})
>>> data["settings"]                               # the document itself is left alone
{'dt': 0.01}
>>> try:
...     apply(data, parse_sets(["actors.enemy.controller.mass=1"]))
... except SettingError as exc:
...     print(exc.message)
actors has no item named 'enemy' (names: 'player'; or an index 0 … 0)
"""

from __future__ import annotations

import copy
import dataclasses
import tomllib
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from playground.level.errors import Problem, suggest

__all__ = ["Setting", "SettingError", "apply", "parse_set", "parse_sets"]


@dataclasses.dataclass(frozen=True, slots=True)
class Setting:
    """One key of a level set otherwise: its dotted key path and its value (a TOML value)."""

    path: str
    value: Any

    def __str__(self) -> str:
        return f"{self.path}={_toml(self.value)}"


class SettingError(ValueError):
    """A ``--set`` that cannot be read or that names no key of the level."""

    def __init__(self, setting: str, message: str) -> None:
        self.setting = setting
        self.message = message
        super().__init__(f"--set {setting}: {message}")

    def problem(self) -> Problem:
        """The error as a level problem (at the key path ``--set KEY=VALUE``)."""
        return Problem(f"--set {self.setting}", self.message)


def parse_set(text: str) -> Setting:
    """``KEY.PATH=VALUE`` as a :class:`Setting`; the value is read as TOML (a bare word that is
    not TOML is a string).

    >>> parse_set("settings.dt=0.004166666666666667").value
    0.004166666666666667
    >>> parse_set("expect.0.equals=grounded").value
    'grounded'
    """
    key, sep, raw = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise SettingError(text, "expected KEY.PATH=VALUE, e.g. settings.substeps=2")
    parts = key.split(".")
    if any(not p for p in parts):
        raise SettingError(text, f"{key!r} is not a dotted key path (an empty part)")
    raw = raw.strip()
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        if not raw:
            raise SettingError(text, "no value after '='") from None
        value = raw
    return Setting(key, value)


def parse_sets(texts: Iterable[str]) -> tuple[Setting, ...]:
    """Each ``KEY.PATH=VALUE`` as a :class:`Setting`, in order (a later one wins)."""
    return tuple(parse_set(t) for t in texts)


def apply(data: Mapping[str, Any], sets: Sequence[Setting]) -> dict[str, Any]:
    """A copy of the parsed document ``data`` with each setting applied, in order.

    A missing table on the way is made (``settings`` in a level without one, an actor's
    ``controller``); whether its keys are valid is the level model's to say, when the result
    is validated. Raises :class:`SettingError` for a path through something that is not a table
    or an array, or an array item that is not there.
    """
    out = copy.deepcopy(dict(data))
    for s in sets:
        _set(out, s)
    return out


def _set(doc: dict[str, Any], s: Setting) -> None:
    parts = s.path.split(".")
    node: Any = doc
    walked: list[str] = []
    for i, part in enumerate(parts):
        last = i == len(parts) - 1
        where = ".".join(walked) or "the level"
        if isinstance(node, dict):
            if last:
                node[part] = s.value
                return
            if part not in node:
                node[part] = {}
            node = node[part]
        elif isinstance(node, list):
            index = _index(node, part, where, s)
            if last:
                node[index] = s.value
                return
            node = node[index]
        else:
            raise SettingError(str(s), f"{where} is a value ({_toml(node)}), not a table")
        walked.append(part)


def _index(items: list[Any], part: str, where: str, s: Setting) -> int:
    """The position in an array of ``part``: an index, or the name of a named table."""
    if part.isdigit():
        index = int(part)
        if index >= len(items):
            raise SettingError(str(s), f"{where} has {len(items)} item(s): no index {index}")
        return index
    names = [item.get("name") for item in items if isinstance(item, dict)]
    for index, item in enumerate(items):
        if isinstance(item, dict) and item.get("name") == part:
            return index
    known = [str(n) for n in names if isinstance(n, str)]
    listed = f"names: {', '.join(map(repr, known))}; or " if known else ""
    span = f"an index 0 … {len(items) - 1}" if items else "it is empty"
    raise SettingError(
        str(s),
        f"{where} has no item named {part!r}{suggest(part, known)} ({listed}{span})",
    )


def _toml(value: Any) -> str:
    """A value as TOML writes it (for messages)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return repr(value)
