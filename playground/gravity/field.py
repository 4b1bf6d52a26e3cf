"""Gravity fields: uniform, rotating rooms, radial planets and zones.

A field answers one question, vectorised: what acceleration (m/s²) does it give at these points at
time t? The world decides how to apply it: a field that is *uniform in space* becomes
``space.gravity`` (Chipmunk's C path, no per-step Python per body); anything else becomes one
vectorised force write per step. Per-body rules (scale, own direction) live in
:mod:`playground.gravity.rule`.

>>> field = Uniform((0.0, -9.81))
>>> field.at(np.zeros((2, 2)), t=0.0).tolist()
[[0.0, -9.81], [0.0, -9.81]]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from playground.limits import (
    MAX_ANGLE,
    MAX_ANGULAR_SPEED,
    MAX_COORDINATE,
    MAX_GRAVITY,
    MAX_LENGTH,
    MAX_TIME,
)
from playground.params import bounded, check, param
from playground.vec import Vec

__all__ = [
    "STANDARD_GRAVITY",
    "GravityField",
    "Points",
    "Radial",
    "RotatingRoom",
    "Turn",
    "Uniform",
    "Zone",
    "Zones",
]

STANDARD_GRAVITY = 9.81
"""Magnitude of Earth's surface gravity, m/s²."""

Points = NDArray[np.float64]


@runtime_checkable
class GravityField(Protocol):
    """What every field provides.

    ``uniform`` is True when the field is the same at every point (it may still change in time);
    the world then uses ``space.gravity`` instead of per-body forces.
    """

    @property
    def uniform(self) -> bool: ...

    def at(self, points: Points, t: float) -> Points:
        """Acceleration in m/s² at ``points`` (shape (N, 2), metres) at time ``t`` (s)."""
        ...


@dataclass(frozen=True, slots=True)
class Uniform:
    """The same acceleration everywhere and always.

    Default: Earth's gravity pointing to −y.
    """

    g: Vec = param(
        (0.0, -STANDARD_GRAVITY), doc="Acceleration.", unit="m/s²", ge=-MAX_GRAVITY, le=MAX_GRAVITY
    )

    def __post_init__(self) -> None:
        check(self)

    @property
    def uniform(self) -> bool:
        return True

    def at(self, points: Points, t: float) -> Points:
        return np.broadcast_to(np.asarray(self.g, dtype=np.float64), points.shape).copy()


@dataclass(frozen=True, slots=True)
class Turn:
    """A scheduled rotation of a room's gravity direction.

    The direction turns by ``angle`` (rad, counter-clockwise positive) between ``start`` and
    ``start + duration`` (s), following a smoothstep so the turn starts and ends at rest.
    ``duration = 0`` turns instantly. A flip is ``Turn(start, math.pi)``.
    """

    start: float = param(doc="When the turn starts.", unit="s", ge=0.0, le=MAX_TIME)
    angle: float = param(
        doc="How far it turns, CCW positive.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE
    )
    duration: float = param(
        0.0, doc="How long it takes (0: instantly).", unit="s", ge=0.0, le=MAX_TIME
    )

    def __post_init__(self) -> None:
        check(self)

    def progress(self, t: float) -> float:
        """Fraction of the turn done at time ``t`` (0 … 1), eased with a smoothstep.

        >>> Turn(1.0, math.pi, 2.0).progress(2.0)
        0.5
        """
        if t < self.start:
            return 0.0
        if self.duration == 0.0 or t >= self.start + self.duration:
            return 1.0
        s = (t - self.start) / self.duration
        return s * s * (3.0 - 2.0 * s)


@dataclass(frozen=True, slots=True)
class RotatingRoom:
    """Uniform gravity whose direction turns: at a constant rate, by scheduled turns, or both.

    The direction at time t is ``angle + rate·t + Σ turn.angle·turn.progress(t)``, measured from +x
    (so −π/2 is "down" on screen).

    >>> room = RotatingRoom(angle=-math.pi / 2, turns=(Turn(1.0, math.pi),))
    >>> [round(float(c), 6) for c in room.vector(2.0)]
    [0.0, 9.81]
    """

    magnitude: float = param(STANDARD_GRAVITY, doc="|g|.", unit="m/s²", ge=0.0, le=MAX_GRAVITY)
    angle: float = param(
        -math.pi / 2, doc="Direction at t = 0, from +x.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE
    )
    rate: float = param(
        0.0, doc="Constant turning rate.", unit="rad/s", ge=-MAX_ANGULAR_SPEED, le=MAX_ANGULAR_SPEED
    )
    turns: tuple[Turn, ...] = param((), doc="Scheduled turns and flips.")

    def __post_init__(self) -> None:
        check(self)

    @property
    def uniform(self) -> bool:
        return True

    def direction(self, t: float) -> float:
        """Direction of gravity at time ``t``, rad from +x."""
        return (
            self.angle + self.rate * t + sum(turn.angle * turn.progress(t) for turn in self.turns)
        )

    def vector(self, t: float) -> Vec:
        """Gravity at time ``t``, m/s²."""
        a = self.direction(t)
        return (self.magnitude * math.cos(a), self.magnitude * math.sin(a))

    def at(self, points: Points, t: float) -> Points:
        return np.broadcast_to(np.asarray(self.vector(t)), points.shape).copy()


@dataclass(frozen=True, slots=True)
class Radial:
    """Gravity toward a centre, like a small planet, softened near the centre.

    ``g(r) = −g_surface·R²·r / (|r|² + ε²)^{3/2}``: equals ``g_surface`` at radius ``R`` (for ε ≪ R)
    and stays finite at the centre (Plummer softening). ``center`` (m), ``surface_gravity``
    (g_surface, m/s²), ``radius`` (R, m), ``softening`` (ε, m).

    >>> planet = Radial(center=(0.0, 0.0), surface_gravity=9.81, radius=10.0, softening=0.0)
    >>> points = np.array([[0.0, 10.0], [20.0, 0.0]])            # m: on the surface, 2 R out
    >>> planet.at(points, 0.0).round(4).tolist()                 # at t = 0 s; m/s²: g/4 at 2 R
    [[-0.0, -9.81], [-2.4525, -0.0]]
    """

    center: Vec = param(
        (0.0, 0.0), doc="The planet's centre.", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    surface_gravity: float = param(
        STANDARD_GRAVITY, doc="|g| at radius.", unit="m/s²", ge=-MAX_GRAVITY, le=MAX_GRAVITY
    )
    radius: float = param(10.0, doc="The planet's radius.", unit="m", gt=0.0, le=MAX_COORDINATE)
    softening: float = param(0.5, doc="Softening length ε.", unit="m", ge=0.0, le=MAX_LENGTH)

    def __post_init__(self) -> None:
        check(self)

    @property
    def uniform(self) -> bool:
        return False

    def at(self, points: Points, t: float) -> Points:
        # Column by column: numpy is several times slower at (N, 2) rows against a (2,) centre
        # or an (N, 1) scale than at whole columns, and the products and sums are the same.
        cx, cy = self.center
        rx = points[:, 0] - cx
        ry = points[:, 1] - cy
        d2 = rx * rx
        d2 += ry * ry
        d2 += self.softening**2
        gm = self.surface_gravity * self.radius**2
        denominator = d2 * np.sqrt(d2)
        if len(d2) and d2.min() > 0.0:
            scale = np.divide(-gm, denominator)
        else:
            # Zero at the exact centre of an unsoftened planet (no direction to pull in).
            scale = np.divide(-gm, denominator, out=np.zeros_like(d2), where=d2 > 0.0)
        out: Points = np.empty((len(d2), 2))
        np.multiply(rx, scale, out=out[:, 0])
        np.multiply(ry, scale, out=out[:, 1])
        return out


@dataclass(frozen=True, slots=True)
class Zone:
    """A region with its own field: an axis-aligned box ``(x0, y0, x1, y1)`` in metres."""

    box: tuple[float, float, float, float] = param(
        doc="(x0, y0, x1, y1).", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    field: GravityField = param(doc="The zone's own field.")

    def __post_init__(self) -> None:
        x0, y0, x1, y1 = self.box
        for i, v in enumerate(self.box):
            bounded(f"box[{i}]", v, MAX_COORDINATE, "m")
        if x1 <= x0 or y1 <= y0:
            raise ValueError(
                f"box: expected finite (x0, y0, x1, y1) with x1 > x0 and y1 > y0, got {self.box!r}"
            )

    def contains(self, points: Points) -> NDArray[np.bool_]:
        x0, y0, x1, y1 = self.box
        x, y = points[:, 0], points[:, 1]
        inside: NDArray[np.bool_] = (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
        return inside


@dataclass(frozen=True, slots=True)
class Zones:
    """A base field with regions that override it; the first zone containing a point wins.

    >>> zones = Zones(Uniform((0.0, -9.81)), (Zone((0.0, 0.0, 1.0, 1.0), Uniform((0.0, 9.81))),))
    >>> zones.at(np.array([[0.5, 0.5], [2.0, 0.5]]), 0.0).tolist()
    [[0.0, 9.81], [0.0, -9.81]]
    """

    base: GravityField = param(doc="The field outside every zone.", default_factory=Uniform)
    zones: tuple[Zone, ...] = param((), doc="Regions with their own field; the first wins.")

    @property
    def uniform(self) -> bool:
        return False

    def at(self, points: Points, t: float) -> Points:
        out = self.base.at(points, t)
        taken = np.zeros(len(points), dtype=bool)
        for zone in self.zones:
            inside = zone.contains(points) & ~taken
            if inside.any():
                out[inside] = zone.field.at(points[inside], t)
                taken |= inside
        return out
