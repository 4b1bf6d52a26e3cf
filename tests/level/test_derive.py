"""Laws of the derived tables: each core config's fields are the level's keys, with the core's
doc, unit, bounds and default, strict as the schema says."""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest
from pydantic import BaseModel, ValidationError

from playground import gravity, intents, movers
from playground.controller.config import ControllerConfig
from playground.gravity import perception
from playground.level import schema
from playground.level.derive import _MODELS, to_core
from playground.params import SPEC, Spec
from playground.world.config import WorldConfig

CORE_CONFIGS = [
    WorldConfig,
    perception.Perception,
    gravity.Uniform,
    gravity.Turn,
    gravity.RotatingRoom,
    gravity.Radial,
    gravity.Zone,
    gravity.Zones,
    movers.Waypoints,
    movers.Sine,
    movers.Circle,
    movers.Spin,
    movers.Elevator,
    intents.Intent,
    intents.Patrol,
    ControllerConfig,
]
"""Every frozen config of the core that a level file sets."""

RUNTIME_ONLY = {"sleep_time", "timing", "guard", "perception"}
"""WorldConfig fields a level does not set: sleeping and stage timing are for programs, the guard
always runs for a level, and perception is the tracking table's."""

DEFS = schema()["$defs"]


def test_every_derived_table_is_in_the_level_schema() -> None:
    """The level's schema carries each derived table (the intent's keys as an input's)."""
    names = {_MODELS[core].__name__ for core in CORE_CONFIGS} - {"IntentTable"}
    assert names <= set(DEFS)
    assert set(_MODELS[intents.Intent].model_fields) < set(DEFS["Input"]["properties"])


def _shared(core: type[Any]) -> list[dataclasses.Field[Any]]:
    model = _MODELS[core]
    return [f for f in dataclasses.fields(core) if f.name in model.model_fields]


@pytest.mark.parametrize("core", CORE_CONFIGS, ids=lambda c: c.__name__)
def test_every_core_field_is_in_the_schema_with_its_doc_and_unit(core: type[Any]) -> None:
    """Law: each declared field of a core config is a key of its table in the JSON Schema, with
    the field's doc and unit (what an editor shows while completing it)."""
    model = _MODELS[core]
    properties = model.model_json_schema()["properties"]
    declared = {f.name for f in dataclasses.fields(core) if SPEC in f.metadata}
    left_out = declared - set(model.model_fields)
    assert left_out <= (RUNTIME_ONLY if core is WorldConfig else set()), left_out
    for f in _shared(core):
        spec: Spec = f.metadata[SPEC]
        prop = properties[f.name]
        assert prop["description"] == spec.doc, f.name
        if spec.unit:
            assert prop["unit"] == spec.unit, f.name


@pytest.mark.parametrize("core", CORE_CONFIGS, ids=lambda c: c.__name__)
def test_a_missing_key_means_the_core_default(core: type[Any]) -> None:
    """Law: a table with only its required keys builds the core object the core's defaults make
    (∞, which a file cannot write, is a key left out)."""
    samples: dict[type[Any], dict[str, Any]] = {
        gravity.Turn: {"start": 1.0, "angle": 0.5},
        gravity.Zone: {"box": (0.0, 0.0, 1.0, 1.0), "field": gravity.Uniform()},
        movers.Waypoints: {"points": ((0.0, 0.0), (1.0, 0.0))},
    }
    required = samples.get(core, {})
    model = _MODELS[core]
    data = {k: _table(v) for k, v in required.items()}
    if "kind" in model.model_fields and model.model_fields["kind"].is_required():
        data["kind"] = model.model_fields["kind"].annotation.__args__[0]
    assert to_core(model.model_validate(data)) == core(**required)


def _table(value: Any) -> Any:
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {"kind": "uniform", **dataclasses.asdict(value)}
    if isinstance(value, tuple) and value and isinstance(value[0], tuple):
        return [list(v) for v in value]
    return value


@pytest.mark.parametrize("bad", [True, "10", "10.0"])
def test_a_number_key_takes_no_boolean_and_no_string(bad: object) -> None:
    """Law: derived tables are strict: ``true`` is not 1.0 and ``"10"`` is not 10."""
    with pytest.raises(ValidationError):
        _MODELS[perception.Perception].model_validate({"min_cutoff": bad})
    with pytest.raises(ValidationError):
        _MODELS[WorldConfig].model_validate({"substeps": bad})


@pytest.mark.parametrize(
    ("core", "key", "value"),
    [
        (WorldConfig, "dt", 1.0),
        (WorldConfig, "substeps", 65),
        (perception.Perception, "min_cutoff", 0.0),
        (gravity.RotatingRoom, "magnitude", -1.0),
        (movers.Circle, "period", 0.0),
        (movers.Elevator, "axis", (0.0, 0.0)),
        (intents.Intent, "move", 1.5),
        (ControllerConfig, "hover_frequency", 0.0),
        (ControllerConfig, "mass", 1e7),
        (ControllerConfig, "radius", 1.0),
    ],
)
def test_the_level_refuses_what_the_core_refuses(core: type[Any], key: str, value: Any) -> None:
    """Law: a value outside a field's declared bounds is refused by the core config and by the
    level's table alike (one declaration, two readers)."""
    with pytest.raises(ValueError, match=key):
        core(**{key: value})
    model: type[BaseModel] = _MODELS[core]
    data: dict[str, Any] = {key: list(value) if isinstance(value, tuple) else value}
    if "kind" in model.model_fields:
        data["kind"] = model.model_fields["kind"].annotation.__args__[0]
    with pytest.raises(ValidationError):
        model.model_validate(data)
