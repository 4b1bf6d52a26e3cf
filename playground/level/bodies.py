"""The bodies of a level: props (dynamic), movers (kinematic) and actors (controlled)."""

from __future__ import annotations

import dataclasses
import math
from typing import Annotated, Any, Literal

from pydantic import Field, Strict, field_validator

from playground import intents, limits
from playground.level.derive import Derived
from playground.level.errors import suggest
from playground.level.paths import Path_
from playground.level.shapes import Shape
from playground.level.values import (
    PLAIN,
    Finite,
    Mass,
    Moment,
    Name,
    Speed,
    Table,
    TurnRate,
    Vec,
)


class Prop(Table):
    """A dynamic body: mass (kg) spread over its shapes by area."""

    name: Name
    position: Vec
    mass: Mass
    shapes: list[Shape] = Field(min_length=1)
    angle: Finite = 0.0
    velocity: Annotated[tuple[Speed, Speed], Strict(False)] = (0.0, 0.0)
    angular_velocity: TurnRate = 0.0
    moment: Moment | None = Field(default=None, description="kg·m²; default from the shapes.")


class MoverModel(Table):
    """A kinematic body (platform, elevator, room) driven along a path."""

    name: Name
    shapes: list[Shape] = Field(min_length=1)
    path: Path_


class Patrol(Derived):
    """Walk one way for half the ``period`` at move input ``speed``, then back."""

    __core__ = intents.Patrol


class Actor(Table):
    """A capsule controller (the player, an enemy): its parameters and where its intents come
    from (scripted ``inputs`` naming it, a ``patrol``, or nothing)."""

    name: Name
    position: Vec
    angle: Finite = 0.0
    velocity: Annotated[tuple[Speed, Speed], Strict(False)] = Field(
        default=(0.0, 0.0), description="Initial velocity, m/s."
    )
    angular_velocity: TurnRate = Field(default=0.0, description="Initial spin, rad/s.")
    controller: dict[str, float | bool] = Field(
        default_factory=dict, description="ControllerConfig fields (SI), e.g. mass = 70."
    )
    patrol: Patrol | None = None
    role: Literal["player", "enemy", "other"] | None = Field(
        default=None,
        description="How the view draws it and whether X nullifies it (enemy); default: player "
        "for the actor named player, other for the rest.",
    )

    @field_validator("controller")
    @classmethod
    def _config(cls, params: dict[str, float | bool]) -> dict[str, float | bool]:
        controller_config(params)
        return params


def controller_config(params: dict[str, float | bool]) -> Any:
    """Build a ``ControllerConfig`` from ``params``; ValueError naming a wrong key."""
    from playground.controller.config import ControllerConfig

    names = [f.name for f in dataclasses.fields(ControllerConfig)]
    for key in params:
        if key not in names:
            raise ValueError(f"unknown controller parameter {key!r}{suggest(key, names)}")
    for key, value in params.items():
        if isinstance(value, float) and not math.isfinite(value):
            raise ValueError(f"{key}: expected a finite number, got {value!r}")
        if isinstance(value, int | float) and not isinstance(value, bool):
            low, high = _controller_range(key)
            if not low <= value <= high:
                raise ValueError(f"{key}: expected a number in [{low:g}, {high:g}], got {value!r}")
    try:
        config: Any = ControllerConfig
        return config(**params)
    except (TypeError, ValueError) as exc:
        raise ValueError(str(exc)) from None


def _controller_range(key: str) -> tuple[float, float]:
    """The plausible range of a controller parameter, by its unit (see playground.limits); the
    controller's own checks (positive, below the hover's stability limit…) come after."""
    if key == "mass":
        return (limits.MIN_MASS, limits.MAX_MASS)
    if key.endswith(("_force", "_torque")):
        return (-limits.MAX_FORCE, limits.MAX_FORCE)
    if key.endswith("_frequency"):
        return (-limits.MAX_FREQUENCY, limits.MAX_FREQUENCY)
    if key.endswith(("_speed", "_spin")):
        return (-limits.MAX_SPEED, limits.MAX_SPEED)
    if key.endswith("length") or key in ("height", "radius", "ride_height"):
        return (-limits.MAX_LENGTH, limits.MAX_LENGTH)
    return (-PLAIN, PLAIN)
