"""A level's gravity field: uniform, rotating, radial, or zones of those (tagged by ``kind``).

Each table's keys are the fields of its :mod:`playground.gravity` class (see
:mod:`playground.level.derive`).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import ConfigDict, Field

from playground import gravity
from playground.level.derive import Derived


class UniformGravity(Derived):
    """The same acceleration everywhere."""

    # A gravity table names its kind (the field is a tagged union); the default only serves the
    # level's own default field. The schema says so too.
    model_config = ConfigDict(json_schema_extra={"required": ["kind"]})
    __core__ = gravity.Uniform

    kind: Literal["uniform"] = "uniform"


class Turn(Derived):
    """A scheduled turn of a rotating room's gravity."""

    __core__ = gravity.Turn


class RotatingGravity(Derived):
    """Uniform gravity whose direction turns (from +x; −π/2 is down)."""

    __core__ = gravity.RotatingRoom

    kind: Literal["rotating"]


class RadialGravity(Derived):
    """Gravity toward a centre (a small planet)."""

    __core__ = gravity.Radial

    kind: Literal["radial"]


SimpleGravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity, Field(discriminator="kind")
]


class Zone(Derived):
    """A box with its own field."""

    __core__ = gravity.Zone

    field: SimpleGravity = Field(description="The zone's own field.")


class ZonesGravity(Derived):
    """A base field with regions that override it (first zone wins)."""

    __core__ = gravity.Zones

    kind: Literal["zones"]
    base: SimpleGravity = Field(
        default_factory=lambda: UniformGravity(), description="The field outside every zone."
    )


Gravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity | ZonesGravity, Field(discriminator="kind")
]
