"""Reference problems of a document that does not validate, found in its valid part."""

from __future__ import annotations

import copy
from collections.abc import Iterator
from typing import Any

from pydantic import ValidationError

from playground.level.document import Level
from playground.level.errors import Problem
from playground.level.explain import walk
from playground.level.references import references

_SALVAGE_ROUNDS = 4
"""Passes that set invalid parts aside before giving up on reporting references too."""

Loc = tuple[int | str, ...]


def salvaged_references(data: object, exc: ValidationError) -> list[Problem]:
    """Reference problems of the document's valid part, reported beside its structural ones.

    Every invalid part is set aside: a list item (a prop, an expectation...) whole, a table key
    (it takes its default). The bodies named inside set-aside items are assumed to exist, and
    nothing is said about the set-aside parts. Empty if what remains still does not validate.
    """
    if not isinstance(data, dict):
        return []
    aside: set[Loc] = set()
    kept: dict[Loc, list[int]] = {}
    for _ in range(_SALVAGE_ROUNDS):
        aside |= {_aside(tuple(e["loc"]), e["type"], kept) for e in exc.errors()}
        doc, kept, assumed = _without(data, aside)
        try:
            level = Level.model_validate(doc)
        except ValidationError as again:
            exc = again
            continue
        except RecursionError:
            return []
        return [
            Problem(_renumber_path(p.path, kept), p.message)
            for p in references(level, frozenset(assumed))
        ]
    return []


def _aside(loc: Loc, kind: str, kept: dict[Loc, list[int]]) -> Loc:
    """What to set aside for an error at ``loc`` (pydantic's, in the numbering of the document
    whose lists ``kept`` thinned): its outermost list item, else the table key (the table itself
    when the key is missing), in the original document's numbering."""
    tags, _ = walk(loc)
    loc = _renumber(tuple(k for k in loc if k not in tags), kept)
    for i, key in enumerate(loc):
        if isinstance(key, int):
            return loc[: i + 1]
    return loc[:-1] if kind == "missing" else loc


def _without(data: dict[str, Any], aside: set[Loc]) -> tuple[Any, dict[Loc, list[int]], set[str]]:
    """A copy of ``data`` without the ``aside`` parts; for each thinned list the original index
    of every kept item; the body names found inside the removed items."""
    doc = copy.deepcopy(data)
    kept: dict[Loc, list[int]] = {}
    assumed: set[str] = set()
    for loc in sorted(aside, key=lambda k: (len(k), [str(x) for x in k]), reverse=True):
        if not loc:
            continue
        parent: Any = doc
        for key in loc[:-1]:
            try:
                parent = parent[key]
            except (KeyError, IndexError, TypeError):
                parent = None
                break
        last = loc[-1]
        if isinstance(parent, list) and isinstance(last, int) and last < len(parent):
            kept.setdefault(loc[:-1], list(range(len(parent))))
            assumed |= set(_names(parent[last]))
            parent[last] = _GONE
        elif isinstance(parent, dict) and last in parent:
            del parent[last]
    for where in list(kept):
        parent = doc
        try:
            for key in where:
                parent = parent[key]
        except (KeyError, IndexError, TypeError):
            del kept[where]  # inside a part set aside whole
            continue
        kept[where] = [i for i, item in zip(kept[where], parent, strict=True) if item is not _GONE]
        parent[:] = [item for item in parent if item is not _GONE]
    return doc, kept, assumed


_GONE = object()


def _names(item: object) -> Iterator[str]:
    """Every string under a ``name`` key inside ``item``."""
    if isinstance(item, dict):
        for key, value in item.items():
            if key == "name" and isinstance(value, str):
                yield value
            yield from _names(value)
    elif isinstance(item, list):
        for value in item:
            yield from _names(value)


def _renumber(loc: Loc, kept: dict[Loc, list[int]]) -> Loc:
    """``loc`` in the thinned document's numbering -> the original document's."""
    out: list[int | str] = []
    for key in loc:
        where = tuple(out)
        if isinstance(key, int) and where in kept and key < len(kept[where]):
            out.append(kept[where][key])
        else:
            out.append(key)
    return tuple(out)


def _renumber_path(path: str, kept: dict[Loc, list[int]]) -> str:
    loc = tuple(int(k) if k.isdigit() else k for k in path.split(".")) if path else ()
    return ".".join(str(k) for k in _renumber(loc, kept))
