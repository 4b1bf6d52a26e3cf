"""The joints between two bodies (or a body and the fixed world), tagged by ``kind``."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from playground.level.values import Damping, Finite, Force, Name, NonNegative, Stiffness, Table, Vec

STATIC = "static"
"""The body name joints use for the fixed world."""


class _Joint(Table):
    a: Name = Field(description="First body (or 'static').")
    b: Name = Field(description="Second body (or 'static').")
    max_force: Force | None = Field(default=None, description="N; default unlimited.")
    collide: bool = Field(default=False, description="Let the two bodies collide.")


class Pivot(_Joint):
    """The bodies turn about a shared world point (m)."""

    kind: Literal["pivot"]
    anchor: Vec


class Pin(_Joint):
    """A rigid rod between two world points (m) at setup."""

    kind: Literal["pin"]
    anchor_a: Vec
    anchor_b: Vec


class Spring(_Joint):
    """A damped spring between two world points (m) at setup."""

    kind: Literal["spring"]
    anchor_a: Vec
    anchor_b: Vec
    stiffness: Stiffness = Field(description="N/m.")
    damping: Damping = Field(default=0.0, description="N·s/m.")
    rest_length: NonNegative | None = Field(
        default=None, description="m; default: the setup distance."
    )


class RotarySpring(_Joint):
    """A damped torsion spring between the bodies' angles."""

    kind: Literal["rotary_spring"]
    stiffness: Stiffness = Field(description="N·m/rad.")
    damping: Damping = Field(default=0.0, description="N·m·s/rad.")
    rest_angle: Finite = 0.0


class RotaryLimit(_Joint):
    """Keeps the relative angle b − a within [min, max] rad."""

    kind: Literal["rotary_limit"]
    min: Finite
    max: Finite


Joint = Annotated[Pivot | Pin | Spring | RotarySpring | RotaryLimit, Field(discriminator="kind")]
