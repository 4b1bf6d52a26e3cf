"""Laws of the level loader: every problem is reported with its key path, never another error."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground.level import LevelError, loads, validate

LEVELS = Path(__file__).resolve().parents[2] / "levels"

MISTAKES = """
title = "Broken"
description = "Several mistakes at once."
[settings]
dtt = 0.01
substeps = 0
[[geometry]]
kind = "segmnt"
[[props]]
name = "crate"
position = [0, 1]
mass = -5
shapes = [{ kind = "box", size = [1, 1], frction = 1 }]
"""


def test_every_mistake_is_reported_with_its_key_path() -> None:
    """A file with several mistakes yields one problem per mistake, each at its key path."""
    with pytest.raises(LevelError) as info:
        loads(MISTAKES, "broken.toml")
    paths = {p.path for p in info.value.problems}
    assert {
        "settings.dtt",
        "settings.substeps",
        "geometry.0",
        "props.0.mass",
        "props.0.shapes.0.frction",
    } <= paths
    text = str(info.value)
    assert "broken.toml: settings.dtt: unknown key (did you mean 'dt'?)" in text
    assert "did you mean 'friction'?" in text
    assert "did you mean 'segment'?" in text


def test_toml_syntax_error_keeps_line_and_column() -> None:
    """A TOML syntax error says where it is."""
    with pytest.raises(LevelError) as info:
        loads('title = "x"\ndescription = \n', "bad.toml")
    assert (info.value.line, info.value.column) == (2, 15)
    assert "line 2, column 15" in str(info.value)


TOML_VALUES = st.recursive(
    st.none().map(lambda _: "")
    | st.booleans()
    | st.integers(-(10**30), 10**30)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=8),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=20,
)
KEYS = st.sampled_from(
    [
        "title",
        "description",
        "settings",
        "gravity",
        "view",
        "geometry",
        "props",
        "movers",
        "joints",
        "actors",
        "tracking",
        "events",
        "inputs",
        "expect",
        "kind",
        "name",
        "mass",
        "shapes",
        "position",
        "dt",
        "t",
        "body",
        "quantity",
        "controller",
        "bogus",
    ]
)
DOCUMENTS = st.dictionaries(KEYS, TOML_VALUES | st.dictionaries(KEYS, TOML_VALUES), max_size=8)


@settings(max_examples=300, deadline=None)
@given(DOCUMENTS)
def test_random_documents_raise_only_level_errors(doc: dict[str, object]) -> None:
    """Whatever the document, the loader returns a level or raises LevelError with a message."""
    try:
        validate(doc, "random.toml")
    except LevelError as exc:
        assert exc.problems and all(str(p) for p in exc.problems)


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_random_text_raises_only_level_errors(text: str) -> None:
    """Arbitrary text is either a level or a LevelError, never another exception."""
    try:
        loads(text)
    except LevelError as exc:
        assert str(exc)


@settings(max_examples=200, deadline=None)
@given(st.data())
def test_mutated_shipped_level_raises_only_level_errors(data: st.DataObject) -> None:
    """Replacing one value of a real level by random junk never escapes as another error."""
    import tomllib

    doc = tomllib.loads((LEVELS / "crusher.toml").read_text(encoding="utf-8"))
    section = data.draw(st.sampled_from(["settings", "actors", "props", "inputs", "expect"]))
    table = doc[section][0] if isinstance(doc[section], list) else doc[section]
    key = data.draw(st.sampled_from(sorted(table)))
    table[key] = data.draw(TOML_VALUES)
    try:
        validate(doc, "mutated.toml")
    except LevelError as exc:
        assert str(exc)


@pytest.mark.parametrize("opening", ["[", "{a = "])
def test_a_deeply_nested_document_is_a_level_error(opening: str) -> None:
    """Law: nesting deeper than Python's recursion limit gives LevelError, never RecursionError."""
    closing = "]" if opening == "[" else "}"
    depth = 50_000
    inner = "1" if opening != "[" else ""
    text = 'title = "x"\ndescription = "y"\nx = ' + opening * depth + inner + closing * depth
    with pytest.raises(LevelError, match="nested too deeply"):
        loads(text)
