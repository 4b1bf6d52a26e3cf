"""Laws of level validation against the JSON Schema: ``check`` is exactly as strict as the schema
on everything the schema can say, and reports reference errors beside structural ones."""

from __future__ import annotations

import copy
import json
import re
import tomllib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import jsonschema
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pydantic import ValidationError

from playground.cli import schema_text
from playground.level import Level, LevelError, loads, schema, shipped, validate

LEVELS = Path(__file__).resolve().parents[2] / "levels"
BASE = 'title = "x"\ndescription = "y"\n'
CRATE = (
    '[[props]]\nname = "crate"\nposition = [0, 1]\nmass = {mass}\n'
    'shapes = [{{kind = "box", size = [1, 1]}}]\n'
)

ACTOR = '[[actors]]\nname = "player"\nposition = [0, 1]\ncontroller = {{ mass = {mass} }}\n'


@pytest.mark.parametrize(
    ("text", "path"),
    [
        (CRATE.format(mass="true"), "props.0.mass"),
        (CRATE.format(mass='"10.0"'), "props.0.mass"),
        (CRATE.format(mass='"10"'), "props.0.mass"),
        (ACTOR.format(mass="true"), "actors.0.controller.mass"),
        (ACTOR.format(mass='"10"'), "actors.0.controller.mass"),
        ('[settings]\nseconds = "2"\n', "settings.seconds"),
        ("[settings]\nsubsteps = 2.5\n", "settings.substeps"),
        ("[settings]\ncontact_split = 1\n", "settings.contact_split"),
        ('[view]\ncamera = ["0", 0]\n', "view.camera.0"),
        ("[gravity]\ng = [0, -5]\n", "gravity"),
    ],
)
def test_check_refuses_what_the_schema_refuses(text: str, path: str) -> None:
    """A boolean or a string where a number belongs (and a number where a boolean belongs) is an
    error at its key path, as in the schema — never silently converted."""
    doc = tomllib.loads(BASE + text)
    assert not _schema_accepts(doc)
    with pytest.raises(LevelError) as info:
        validate(doc, "typed.toml")
    assert path in {p.path for p in info.value.problems}


def test_whole_floats_are_integers_as_in_the_schema() -> None:
    """``substeps = 2.0`` is an integer for JSON Schema, and so for ``check``."""
    doc = tomllib.loads(BASE + "[settings]\nsubsteps = 2.0\n")
    assert _schema_accepts(doc)
    assert validate(doc).settings.substeps == 2


def test_reference_errors_are_reported_beside_structural_errors() -> None:
    """An unknown body is reported even when another table of the file is malformed; a body
    whose own table is malformed is not reported as unknown."""
    text = (
        BASE
        + '[settings]\nseconds = "2"\n'
        + CRATE.format(mass="true")
        + '[[expect]]\nbody = "crate"\nquantity = "position"\ncomponent = "y"\nt = 1\nbelow = 2\n'
        + '[[expect]]\nbody = "crat"\nquantity = "angle"\nt = 1\nbelow = "x"\n'
        + '[[expect]]\nbody = "crat"\nquantity = "position"\ncomponent = "y"\nt = 1\nbelow = 2\n'
    )
    with pytest.raises(LevelError) as info:
        loads(text, "mixed.toml")
    messages = {p.path: p.message for p in info.value.problems}
    assert set(messages) == {"settings.seconds", "props.0.mass", "expect.1.below", "expect.2.body"}
    assert "no body named 'crat'" in messages["expect.2.body"]


# -- the property: the same random documents to `check` and to a JSON-schema validator ---------


def test_a_name_ending_in_a_newline_is_refused_by_both() -> None:
    """Names match their pattern to the end of the string: ``"crate\\n"`` is not a name, for the
    schema (ECMA-262 ``$``) and for ``check`` alike. Found by the property test below."""
    doc = tomllib.loads(BASE + CRATE.format(mass="10.0").replace('"crate"', '"crate\\n"'))
    assert doc["props"][0]["name"] == "crate\n"
    assert not _schema_accepts(doc)
    with pytest.raises(LevelError):
        validate(doc, "newline.toml")


def _ecma_pattern(
    validator: Any, pattern: str, instance: Any, _schema: dict[str, Any]
) -> Iterator[jsonschema.ValidationError]:
    """``pattern`` as JSON Schema defines it (ECMA-262, no multiline flag): ``$`` is the end of
    the string. Python's ``re`` lets ``$`` match before a final newline, so jsonschema's default
    would accept the name ``"A\\n"`` that editors and ``check`` refuse."""
    if validator.is_type(instance, "string") and not re.search(
        re.sub(r"(?<!\\)\$$", r"\\Z", pattern), instance
    ):
        yield jsonschema.ValidationError(f"{instance!r} does not match {pattern!r}")


VALIDATOR = jsonschema.validators.extend(
    jsonschema.Draft202012Validator, {"pattern": _ecma_pattern}
)(schema())
LEVEL_DOCS = [
    tomllib.loads(Path(p).read_text(encoding="utf-8")) for _, p in sorted(shipped().items())
]

# JSON has no NaN or infinity, so the schema cannot say "finite": those stay out of the documents.
SCALARS = (
    st.booleans()
    | st.integers(-3, 70)
    | st.integers(-(10**20), 10**20)
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.sampled_from([0.0, 1.0, 2.0, -1.0, 0.5, 64.0, 65.0, 1e-9, 1e9])
    | st.text(max_size=6)
    | st.sampled_from(["player", "box", "uniform", "at", "position", "x", "10.0", "", "a\n"])
)
VALUES = st.recursive(
    SCALARS,
    lambda children: (
        st.lists(children, max_size=3)
        | st.dictionaries(st.sampled_from(["kind", "name", "g", "size", "x"]), children, max_size=3)
    ),
    max_leaves=6,
)


def _schema_accepts(doc: object) -> bool:
    return VALIDATOR.is_valid(doc)


def _places(node: Any, here: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every key path inside a parsed document (tables and arrays)."""
    out = [here]
    if isinstance(node, dict):
        for key, value in node.items():
            out += _places(value, (*here, key))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            out += _places(value, (*here, i))
    return out


@st.composite
def mutated_levels(draw: st.DrawFn) -> dict[str, Any]:
    """A shipped level with one to three random edits: a value replaced, a key removed, a key
    added."""
    doc = copy.deepcopy(draw(st.sampled_from(LEVEL_DOCS)))
    for _ in range(draw(st.integers(1, 3))):
        places = [p for p in _places(doc) if p]
        place = draw(st.sampled_from(places))
        parent: Any = doc
        for key in place[:-1]:
            parent = parent[key]
        action = draw(st.sampled_from(["replace", "replace", "remove", "add"]))
        if action == "replace":
            parent[place[-1]] = draw(VALUES)
        elif action == "remove" and isinstance(parent, dict):
            del parent[place[-1]]
        elif isinstance(parent, dict):
            parent[draw(st.sampled_from(["bogus", "mass", "kind", "t"]))] = draw(VALUES)
    return doc


def _structural_errors(doc: dict[str, Any]) -> list[str]:
    """The model's errors that a JSON Schema can express: all but its own validators' errors
    (ordered boxes, non-zero vectors, controller parameters: the schema has no words for those)."""
    try:
        Level.model_validate(doc)
    except ValidationError as exc:
        return [f"{e['loc']}: {e['type']}" for e in exc.errors() if e["type"] != "value_error"]
    return []


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated_levels())
def test_check_and_the_schema_agree_on_random_documents(doc: dict[str, Any]) -> None:
    """Law: the schema accepts a document exactly when the level models find nothing structural
    wrong with it; so whatever the schema refuses, ``check`` refuses too."""
    accepted = _schema_accepts(doc)
    structural = _structural_errors(doc)
    assert accepted == (not structural), json.dumps(
        {"schema": [e.message for e in VALIDATOR.iter_errors(doc)][:3], "check": structural[:3]},
        default=repr,
    )
    if not accepted:
        with pytest.raises(LevelError):
            validate(doc, "random.toml")


def test_every_shipped_level_names_its_schema_for_editors() -> None:
    """Each shipped level's first line is the ``#:schema`` directive (Taplo, Even Better TOML),
    naming the schema file beside it; the schema has an ``$id``."""
    for name, path in shipped().items():
        first = Path(path).read_text(encoding="utf-8").splitlines()[0]
        assert first == "#:schema ./level.schema.json", name
        assert (Path(path).parent / "level.schema.json").is_file()
    assert schema()["$id"].endswith("/level.schema.json")


def test_committed_schema_is_up_to_date() -> None:
    """levels/level.schema.json is what the models export (run `playground schema -o ...`)."""
    committed = (LEVELS / "level.schema.json").read_text(encoding="utf-8")
    assert json.loads(committed) == json.loads(schema_text())
