"""The paths that drive a mover (a kinematic body), tagged by ``kind``.

Each table's keys are the fields of its :mod:`playground.movers` class (see
:mod:`playground.level.derive`).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from playground import movers
from playground.level.derive import Derived


class Waypoints(Derived):
    """Through a list of points at a constant speed."""

    __core__ = movers.Waypoints

    kind: Literal["waypoints"]


class Sine(Derived):
    """An oscillation about a centre."""

    __core__ = movers.Sine

    kind: Literal["sine"]


class CirclePath(Derived):
    """Around a circle."""

    __core__ = movers.Circle

    kind: Literal["circle"]


class Spin(Derived):
    """A constant rotation about a fixed position."""

    __core__ = movers.Spin

    kind: Literal["spin"]


class Elevator(Derived):
    """Rises along an axis with a prescribed acceleration from rest."""

    __core__ = movers.Elevator

    kind: Literal["elevator"]


Path_ = Annotated[Waypoints | Sine | CirclePath | Spin | Elevator, Field(discriminator="kind")]
