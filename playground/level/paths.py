"""The paths that drive a mover (a kinematic body), tagged by ``kind``."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator

from playground import limits
from playground.level.values import Finite, Frequency, Positive, Speed, Table, TurnRate, Vec


class Waypoints(Table):
    kind: Literal["waypoints"]
    points: list[Vec] = Field(min_length=2)
    speed: Annotated[Speed, Field(gt=0.0)] = 1.0
    ease: bool = False
    mode: Literal["loop", "pingpong", "once"] = "pingpong"
    angle: Finite = 0.0


class Sine(Table):
    kind: Literal["sine"]
    center: Vec = (0.0, 0.0)
    amplitude: Vec = (1.0, 0.0)
    frequency: Frequency = 0.25
    phase: Finite = 0.0
    angle: Finite = 0.0


class CirclePath(Table):
    kind: Literal["circle"]
    center: Vec = (0.0, 0.0)
    radius: Positive = 1.0
    period: Finite = 4.0
    phase: Finite = 0.0
    turn_with_path: bool = False

    @field_validator("period")
    @classmethod
    def _nonzero(cls, v: float) -> float:
        if v == 0.0:
            raise ValueError("expected a non-zero period, s")
        return v


class Spin(Table):
    kind: Literal["spin"]
    position: Vec = (0.0, 0.0)
    rate: TurnRate = 1.0
    angle: Finite = 0.0


class Elevator(Table):
    kind: Literal["elevator"]
    start: Vec = (0.0, 0.0)
    axis: Vec = (0.0, 1.0)
    acceleration: Annotated[
        float, Field(ge=-limits.MAX_ACCELERATION, le=limits.MAX_ACCELERATION, allow_inf_nan=False)
    ] = 1.0
    start_time: Finite = 0.0
    duration: Positive | None = Field(default=None, description="s; default: accelerate forever.")

    @field_validator("axis")
    @classmethod
    def _nonzero(cls, v: tuple[float, float]) -> tuple[float, float]:
        if v == (0.0, 0.0):
            raise ValueError("expected a non-zero vector")
        return v


Path_ = Annotated[Waypoints | Sine | CirclePath | Spin | Elevator, Field(discriminator="kind")]
