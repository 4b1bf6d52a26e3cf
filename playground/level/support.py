"""Variants a level cannot support: its ``[[variants.unsupported]]`` tables, and which of them a
variant of the level matches.

A level is checked at its own settings, and the robustness matrix
(:mod:`playground.scene.robustness`) runs it at other player masses, steps and substeps as
variants (``--set``, :mod:`playground.level.variants`). Where the level's own physics does not
hold at some of them (a threshold a heavier player's weight crosses, a contact a coarser step
resolves otherwise) the level declares it, each declaration with the keys and values it covers
(all of its ``when`` conditions hold) and the physical reason:

>>> from playground.level import loads
>>> text = '''title = "t"
... description = "d"
... [[variants.unsupported]]
... when = [{ key = "settings.dt", above = 0.01 }]
... reason = "at a step over 10 ms the crate crosses its own size in one step and tunnels"
... '''
>>> level = loads(text)
>>> declared(level)                              # at its own step, 1/120 s: none
()
>>> from playground.level.variants import parse_sets
>>> coarse = loads(text, sets=parse_sets(["settings.dt=0.02"]))
>>> [u.reason[:30] for u in declared(coarse)]
['at a step over 10 ms the crate']

The level as written must not match one of its own declarations (its checks hold at its own
settings); ``playground check`` reports that, a key that names nothing, and a bound on a value
that is not a number, each at its key path.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from typing import Annotated, Any

from pydantic import BaseModel, Field, model_validator

from playground.level.errors import Problem, suggest
from playground.level.values import Finite, Table

__all__ = [
    "Condition",
    "Unsupported",
    "Variants",
    "declared",
    "matches",
    "own_problems",
    "support_problems",
    "value_at",
]

KeyPath = Annotated[
    str, Field(min_length=1, max_length=200, pattern=r"^[A-Za-z0-9_\-]+(\.[A-Za-z0-9_\-]+)*$")
]

REL_TOLERANCE = 1e-9
"""How close a number must be to one of a condition's ``values`` to be it, relative: a step
written as ``0.016666666666666666`` or computed as ``1 / 60`` is the same step, and no two
settings a level is run at differ by less."""


class Condition(Table):
    """One key of a variant and the values it covers: one of ``values``, and above ``above``
    and below ``below`` (each given bound holds)."""

    key: KeyPath = Field(
        description="Dotted key path of the level, as `--set` takes it "
        "(`actors.player.controller.mass`, `settings.dt`); a key not written in the file has "
        "its default."
    )
    values: list[bool | Finite | str] | None = Field(
        default=None, min_length=1, description="The values covered (a number within 1e-9)."
    )
    above: Finite | None = Field(default=None, description="Covers the numbers above this.")
    below: Finite | None = Field(default=None, description="Covers the numbers below this.")

    @model_validator(mode="after")
    def _something(self) -> Condition:
        if self.values is None and self.above is None and self.below is None:
            raise ValueError("a condition needs `values`, `above` or `below`")
        return self

    def holds(self, value: object) -> bool:
        """Whether ``value`` (the variant's value of :attr:`key`) is covered."""
        number = _number(value)
        if self.values is not None and not any(_same(value, v) for v in self.values):
            return False
        if self.above is not None and (number is None or not number > self.above):
            return False
        return not (self.below is not None and (number is None or not number < self.below))


class Unsupported(Table):
    """A variant of the level that its checks do not hold at, and why."""

    when: list[Condition] = Field(
        min_length=1, description="The variants covered: every condition holds."
    )
    reason: str = Field(
        min_length=1,
        description="The physics that does not hold there (what the docs explain), one "
        "sentence or a few.",
    )
    checks: list[str] | None = Field(
        default=None,
        min_length=1,
        description="The checks (by name, as reported) the reason is about; the level's other "
        "checks must still pass there. Default: any of them.",
    )

    def covers(self, level: BaseModel) -> bool:
        """Whether ``level`` (a variant of the level) is one this declaration covers."""
        return all(c.holds(value_at(level, c.key)) for c in self.when)

    def __str__(self) -> str:
        return f"{' and '.join(_describe(c) for c in self.when)}: {self.reason}"


class Variants(Table):
    """How the level behaves as a variant (run with `--set`, as the robustness matrix runs it)."""

    unsupported: list[Unsupported] = Field(
        default_factory=list,
        description="Variants the level's checks do not hold at, each with its physical reason: "
        "the robustness matrix reports them instead of failing, and fails one that passes "
        "(the declaration is stale).",
    )


def declared(level: Any) -> tuple[Unsupported, ...]:
    """The declarations of ``level`` (a validated level or variant) that cover it."""
    return tuple(u for u in level.variants.unsupported if u.covers(level))


def matches(level: Any) -> list[tuple[int, Unsupported]]:
    """:func:`declared`, each with its index in ``variants.unsupported``."""
    return [(i, u) for i, u in enumerate(level.variants.unsupported) if u.covers(level)]


class _Missing:
    """No value at a key path (the reason is in :attr:`problem`)."""

    def __init__(self, problem: str) -> None:
        self.problem = problem


def value_at(level: BaseModel, path: str) -> Any:
    """The value of the dotted key ``path`` in ``level`` (defaults included); an array item by
    its index or its ``name``. A path that names nothing gives a :class:`_Missing`, which no
    condition covers."""
    node: Any = level
    walked: list[str] = []
    for part in path.split("."):
        where = ".".join(walked) or "the level"
        if isinstance(node, BaseModel):
            fields = list(type(node).model_fields)
            if part not in fields:
                return _Missing(f"{where} has no key {part!r}{suggest(part, fields)}")
            node = getattr(node, part)
        elif isinstance(node, list | tuple):
            if part.isdigit():
                if int(part) >= len(node):
                    return _Missing(f"{where} has {len(node)} item(s): no index {part}")
                node = node[int(part)]
            else:
                names = [getattr(n, "name", None) for n in node]
                known = [n for n in names if isinstance(n, str)]
                if part not in known:
                    return _Missing(f"{where} has no item named {part!r}{suggest(part, known)}")
                node = node[known.index(part)]
        else:
            return _Missing(f"{where} is a value, not a table")
        walked.append(part)
    if isinstance(node, BaseModel | list):
        return _Missing(f"{path} is a table or an array, not a value")
    return node


def support_problems(
    level: Any, assumed: frozenset[str] = frozenset(), names: Sequence[str] = ()
) -> Iterator[Problem]:
    """Each condition's key names a value of the level, a bound is on a number, and each named
    check is one of ``names``, the level's checks (a key through a body in ``assumed``, left out
    of ``level`` as invalid, is not judged)."""
    for i, u in enumerate(level.variants.unsupported):
        for j, name in enumerate(u.checks or ()):
            if name not in names:
                listing = ", ".join(map(repr, names)) or "none"
                yield Problem(
                    f"variants.unsupported.{i}.checks.{j}",
                    f"no check named {name!r}{suggest(name, list(names))} (checks: {listing})",
                )
        for j, c in enumerate(u.when):
            at = f"variants.unsupported.{i}.when.{j}"
            if assumed & set(c.key.split(".")):
                continue
            value = value_at(level, c.key)
            if isinstance(value, _Missing):
                yield Problem(f"{at}.key", f"{c.key!r} names no key of the level: {value.problem}")
            elif (c.above is not None or c.below is not None) and _number(value) is None:
                yield Problem(
                    at, f"`above` and `below` bound a number; {c.key} is {value!r}, not a number"
                )


def own_problems(level: Any) -> Iterator[Problem]:
    """The level as written is covered by none of its declarations (its checks hold at its own
    settings; a declaration is for the variants)."""
    for i, _ in matches(level):
        yield Problem(
            f"variants.unsupported.{i}",
            "covers the level as written (its own settings); a level's checks hold at its own "
            "settings, a declaration covers variants of it only",
        )


def _number(value: object) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    return float(value)


def _same(value: object, wanted: object) -> bool:
    a, b = _number(value), _number(wanted)
    if a is not None and b is not None:
        return math.isclose(a, b, rel_tol=REL_TOLERANCE, abs_tol=0.0)
    return type(value) is type(wanted) and value == wanted


def _describe(c: Condition) -> str:
    parts = []
    if c.values is not None:
        shown = [f"{v:g}" if _number(v) is not None else repr(v) for v in c.values]
        parts.append(
            f"{c.key} in [{', '.join(shown)}]" if len(shown) > 1 else f"{c.key} = {shown[0]}"
        )
    if c.above is not None:
        parts.append(f"{c.key} > {c.above:g}")
    if c.below is not None:
        parts.append(f"{c.key} < {c.below:g}")
    return " and ".join(parts)
