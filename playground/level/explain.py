"""Pydantic's validation errors told as level problems: the key path and what was expected."""

from __future__ import annotations

import json
import types
import typing
from collections.abc import Sequence
from typing import Annotated, Any, Union

from pydantic import BaseModel, ValidationError

from playground.level.document import Level
from playground.level.errors import Problem, suggest


def _unwrap(tp: Any) -> list[Any]:
    """The alternatives inside Annotated / Optional / Union."""
    origin = typing.get_origin(tp)
    if origin is Annotated:
        return _unwrap(typing.get_args(tp)[0])
    if origin is Union or origin is types.UnionType:
        return [alt for arg in typing.get_args(tp) for alt in _unwrap(arg)]
    return [tp]


def walk(
    loc: Sequence[int | str], root: type[BaseModel] = Level
) -> tuple[set[int], type[BaseModel] | None]:
    """Follow a pydantic error location through the models.

    Returns the positions of the discriminator tags pydantic put in the location (a key path has
    no such level; a key may be spelled like a tag, as ``impulse`` in an impulse event) and the
    model whose table sits at the end of it, if any.
    """
    tags: set[int] = set()
    current: list[Any] = [root]
    for position, key in enumerate(loc):
        nxt: list[Any] = []
        for tp in current:
            alts = _unwrap(tp)
            models = [a for a in alts if isinstance(a, type) and issubclass(a, BaseModel)]
            tagged = [
                m
                for m in models
                if "kind" in m.model_fields
                and typing.get_args(m.model_fields["kind"].annotation) == (key,)
            ]
            if len(models) > 1 and tagged:
                tags.add(position)
                nxt.extend(tagged)
                continue
            for alt in alts:
                origin = typing.get_origin(alt)
                if isinstance(alt, type) and issubclass(alt, BaseModel):
                    if isinstance(key, str) and key in alt.model_fields:
                        nxt.append(alt.model_fields[key].annotation)
                elif origin in (list, tuple) and isinstance(key, int):
                    nxt.extend(a for a in typing.get_args(alt) if a is not Ellipsis)
                elif origin is dict and isinstance(key, str):
                    nxt.append(typing.get_args(alt)[1])
        current = nxt
    for tp in current:
        for alt in _unwrap(tp):
            if isinstance(alt, type) and issubclass(alt, BaseModel):
                return tags, alt
    return tags, None


def _path(loc: Sequence[int | str], tags: set[int]) -> str:
    return ".".join(str(k) for i, k in enumerate(loc) if i not in tags)


_TYPE_WORDS = {
    "float_type": "a number",
    "float_parsing": "a number",
    "int_type": "an integer",
    "int_parsing": "an integer",
    "int_from_float": "an integer",
    "bool_type": "true or false",
    "bool_parsing": "true or false",
    "string_type": "a string",
    "list_type": "an array",
    "tuple_type": "an array",
    "dict_type": "a table",
    "model_type": "a table",
    "model_attributes_type": "a table",
    "finite_number": "a finite number",
}


def problems(exc: ValidationError, root: type[BaseModel] = Level) -> list[Problem]:
    """Each error of ``exc`` as a problem: its key path in ``root`` and what was expected."""
    out: list[Problem] = []
    for err in exc.errors(include_url=False):
        loc = tuple(err["loc"])
        tags, model = walk(loc[:-1], root)
        kind = err["type"]
        if kind == "extra_forbidden":
            key = str(loc[-1])
            options = list(model.model_fields) if model is not None else []
            message = f"unknown key{suggest(key, options)}"
        elif kind == "missing":
            message = "required key is missing"
        elif kind in _TYPE_WORDS:
            message = f"expected {_TYPE_WORDS[kind]}, got {_show(err.get('input'))}"
        elif kind == "union_tag_invalid":
            ctx = err.get("ctx", {})
            expected = str(ctx.get("expected_tags", ""))
            tag = str(ctx.get("tag", ""))
            names = [t.strip(" '") for t in expected.split(",")]
            message = f"kind {tag!r} is not one of {expected}{suggest(tag, names)}"
        elif kind == "union_tag_not_found":
            message = "a table with a 'kind' key is required"
        else:
            msg = str(err["msg"])
            msg = msg.removeprefix("Value error, ").replace("Input should be", "expected")
            message = f"{msg[0].lower()}{msg[1:]}, got {_show(err.get('input'))}"
        out.append(Problem(_path(loc, tags), message))
    return out


def _show(value: object) -> str:
    text = json.dumps(value, default=repr) if not isinstance(value, str) else repr(value)
    return text if len(text) <= 60 else text[:57] + "..."
