"""The level document: the top-level table that holds every other one, and its JSON Schema."""

from __future__ import annotations

from typing import Any

from pydantic import ConfigDict, Field

from playground.level.bodies import Actor, MoverModel, Prop
from playground.level.expect import Expectation
from playground.level.gravity import Gravity, UniformGravity
from playground.level.joints import Joint
from playground.level.settings import Settings, Tracking, View
from playground.level.shapes import Shape
from playground.level.support import Variants
from playground.level.timeline import Event, Input, Spawn
from playground.level.values import Name, Table

SCHEMA_ID = (
    "https://github.com/pymunk-playground/pymunk-playground/raw/main/levels/level.schema.json"
)
"""The schema's ``$id``: where editors can fetch it (a level file names it in a ``#:schema``
first line, or the folder's own ``level.schema.json``)."""


class Level(Table):
    """One level file."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        json_schema_extra={
            "$schema": "https://json-schema.org/draft/2020-12/schema",
            "$id": SCHEMA_ID,
        },
    )

    title: str = Field(min_length=1, max_length=80)
    description: str = Field(min_length=1, description="One paragraph: what the level shows.")
    settings: Settings = Field(default_factory=lambda: Settings())
    gravity: Gravity = Field(default_factory=lambda: UniformGravity())
    view: View = Field(default_factory=lambda: View())
    geometry: list[Shape] = Field(default_factory=list, description="Static shapes, world frame.")
    props: list[Prop] = Field(default_factory=list)
    movers: list[MoverModel] = Field(default_factory=list)
    joints: list[Joint] = Field(default_factory=list)
    actors: list[Actor] = Field(default_factory=list)
    tracking: Tracking = Field(default_factory=lambda: Tracking())
    events: list[Event] = Field(default_factory=list)
    inputs: list[Input] = Field(default_factory=list)
    expect: list[Expectation] = Field(default_factory=list)
    variants: Variants = Field(
        default_factory=lambda: Variants(),
        description="How the level runs as a variant: the variants it cannot support, and why.",
    )
    catches: list[Name] = Field(
        default_factory=list,
        description="Breaks (playground faults) its checks must catch, by name.",
    )

    def body_names(self) -> list[str]:
        """Every named body: props, movers, actors and spawned props."""
        spawned = [e.prop.name for e in self.events if isinstance(e, Spawn)]
        return [
            *(p.name for p in self.props),
            *(m.name for m in self.movers),
            *(a.name for a in self.actors),
            *spawned,
        ]

    def tracked(self) -> list[str]:
        """Bodies whose forces are read: actors and ``tracking.bodies``."""
        return [*(a.name for a in self.actors), *self.tracking.bodies]


def schema() -> dict[str, Any]:
    """The JSON Schema of a level file (what ``levels/level.schema.json`` holds)."""
    out = Level.model_json_schema()
    out["title"] = "playground level"
    return out
