"""A level's gravity field: uniform, rotating, radial, or zones of those (tagged by ``kind``)."""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import ConfigDict, Field, Strict, field_validator

from playground import limits
from playground.gravity import STANDARD_GRAVITY
from playground.level.values import Finite, Gravity_, NonNegative, Positive, Table, TurnRate, Vec


class UniformGravity(Table):
    """The same acceleration everywhere (m/s²)."""

    # A gravity table names its kind (the field is a tagged union); the default only serves the
    # level's own default field. The schema says so too.
    model_config = ConfigDict(json_schema_extra={"required": ["kind"]})

    kind: Literal["uniform"] = "uniform"
    g: Annotated[tuple[Gravity_, Gravity_], Strict(False)] = (0.0, -STANDARD_GRAVITY)


class Turn(Table):
    """A scheduled turn of a rotating room's gravity, rad over s."""

    start: NonNegative
    angle: Finite
    duration: NonNegative = 0.0


class RotatingGravity(Table):
    """Uniform gravity whose direction turns (rad from +x; −π/2 is down)."""

    kind: Literal["rotating"]
    magnitude: Annotated[float, Field(ge=0.0, le=limits.MAX_GRAVITY)] = STANDARD_GRAVITY
    angle: Finite = -math.pi / 2
    rate: TurnRate = Field(default=0.0, description="Constant turning rate, rad/s.")
    turns: list[Turn] = Field(default_factory=list)


class RadialGravity(Table):
    """Gravity toward a centre (a small planet)."""

    kind: Literal["radial"]
    center: Vec = (0.0, 0.0)
    surface_gravity: Gravity_ = STANDARD_GRAVITY
    radius: Positive = 10.0
    softening: NonNegative = 0.5


SimpleGravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity, Field(discriminator="kind")
]


class Zone(Table):
    """A box (x0, y0, x1, y1), m, with its own field."""

    box: Annotated[tuple[Finite, Finite, Finite, Finite], Strict(False)]
    field: SimpleGravity

    @field_validator("box")
    @classmethod
    def _ordered(cls, box: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        if box[2] <= box[0] or box[3] <= box[1]:
            raise ValueError("expected (x0, y0, x1, y1) with x1 > x0 and y1 > y0")
        return box


class ZonesGravity(Table):
    """A base field with regions that override it (first zone wins)."""

    kind: Literal["zones"]
    base: SimpleGravity = Field(default_factory=lambda: UniformGravity())
    zones: list[Zone] = Field(default_factory=list)


Gravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity | ZonesGravity, Field(discriminator="kind")
]
