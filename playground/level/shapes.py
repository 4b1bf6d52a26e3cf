"""The collision shapes of bodies and static geometry (tagged by ``kind``), in m."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, Strict

from playground.level.values import Finite, NonNegative, Positive, Table, Vec, Whole


class _Surface(Table):
    friction: NonNegative = Field(default=0.8, description="Coulomb friction coefficient.")
    elasticity: float = Field(default=0.0, ge=0.0, le=1.0, description="Restitution, 0..1.")
    one_way: bool = Field(
        default=False,
        description="Solid only from its top, the +y side of its body's frame (world +y for "
        "geometry): bodies pass up through it and land on it (playground.world.one_way).",
    )


class Segment(_Surface):
    """A segment from a to b (m, in the body's frame; world frame for static geometry)."""

    kind: Literal["segment"]
    a: Vec
    b: Vec
    radius: NonNegative = 0.05


class Box(_Surface):
    """A box of size (w, h) m centred at ``center``, turned by ``angle`` rad."""

    kind: Literal["box"]
    size: Annotated[tuple[Positive, Positive], Strict(False)]
    center: Vec = (0.0, 0.0)
    angle: Finite = 0.0
    radius: NonNegative = 0.0


class Polygon(_Surface):
    """A convex polygon (its convex hull is used), vertices in m."""

    kind: Literal["polygon"]
    points: list[Vec] = Field(min_length=3, max_length=64)
    radius: NonNegative = 0.0


class CircleShape(_Surface):
    """A circle of ``radius`` m centred at ``center``."""

    kind: Literal["circle"]
    radius: Positive
    center: Vec = (0.0, 0.0)


class Capsule(_Surface):
    """A capsule along the local y axis: end-cap centres ``length`` m apart, ``radius`` m."""

    kind: Literal["capsule"]
    length: NonNegative
    radius: Positive
    center: Vec = (0.0, 0.0)


class Ring(_Surface):
    """A closed ring of thin segments, inner radius ``radius`` m, about the body's origin."""

    kind: Literal["ring"]
    radius: Positive
    segments: Whole = Field(default=48, ge=3, le=512)
    thickness: Positive = 0.1


Shape = Annotated[
    Segment | Box | Polygon | CircleShape | Capsule | Ring, Field(discriminator="kind")
]
