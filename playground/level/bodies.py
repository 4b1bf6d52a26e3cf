"""The bodies of a level: props (dynamic), movers (kinematic) and actors (controlled)."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, Strict

from playground import intents
from playground.controller.config import ControllerConfig
from playground.level.derive import Derived
from playground.level.paths import Path_
from playground.level.shapes import Shape
from playground.level.values import (
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


class ControllerTable(Derived):
    """An actor's controller: body, sensing and force budgets (see
    :class:`playground.controller.ControllerConfig`); defaults fit a 70 kg, 1.8 m person."""

    __core__ = ControllerConfig


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
    controller: ControllerTable = Field(
        default_factory=lambda: ControllerTable(),
        description="The controller's parameters (every key optional).",
    )
    patrol: Patrol | None = None
    role: Literal["player", "enemy", "other"] | None = Field(
        default=None,
        description="How the view draws it and whether X nullifies it (enemy); default: player "
        "for the actor named player, other for the rest.",
    )
