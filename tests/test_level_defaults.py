"""The level format restates the core's frozen configs as pydantic models (for path-bearing errors
and the JSON Schema); these laws keep the two from drifting apart: a key left out of a level file
means exactly what the core's default means."""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest

from playground import gravity, movers, perception, world
from playground import level as fmt

PAIRS: list[tuple[type[Any], type[Any], dict[str, str]]] = [
    (fmt.Settings, world.WorldConfig, {}),
    (fmt.Perception, perception.Perception, {}),
    (fmt.UniformGravity, gravity.Uniform, {}),
    (fmt.RotatingGravity, gravity.RotatingRoom, {}),
    (fmt.RadialGravity, gravity.Radial, {}),
    (fmt.Turn, gravity.Turn, {}),
    (fmt.Waypoints, movers.Waypoints, {}),
    (fmt.Sine, movers.Sine, {}),
    (fmt.CirclePath, movers.Circle, {}),
    (fmt.Spin, movers.Spin, {}),
    (fmt.Elevator, movers.Elevator, {}),
]


def _core_defaults(cls: type[Any]) -> dict[str, Any]:
    out = {}
    for f in dataclasses.fields(cls):
        if f.default is not dataclasses.MISSING:
            out[f.name] = f.default
        elif f.default_factory is not dataclasses.MISSING:
            out[f.name] = f.default_factory()
    return out


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    return bool(a == b)


@pytest.mark.parametrize(
    ("model", "core", "renamed"), PAIRS, ids=lambda p: getattr(p, "__name__", "")
)
def test_a_missing_key_means_the_core_default(
    model: type[Any], core: type[Any], renamed: dict[str, str]
) -> None:
    """Law: for every key the level model and the core config share, the model's default equals
    the core's (an Elevator's duration None in a file is the core's "forever", inf)."""
    core_defaults = _core_defaults(core)
    shared = [name for name in model.model_fields if renamed.get(name, name) in core_defaults]
    assert shared, f"{model.__name__} shares no field with {core.__name__}"
    for name in shared:
        field = model.model_fields[name]
        if field.is_required():
            continue
        default = field.get_default(call_default_factory=True)
        expected = core_defaults[renamed.get(name, name)]
        if model is fmt.Elevator and name == "duration":
            assert default is None and expected == float("inf")
            continue
        if model is fmt.Settings and name == "perception":
            continue
        assert _same(default, expected), f"{model.__name__}.{name}: {default!r} != {expected!r}"
