"""Kinematic movers: platforms, elevators and rooms that follow prescribed paths.

A path gives a pose (position in m, angle in rad) as a function of time. A :class:`Mover` drives a
kinematic body along it the way the engine wants (Box2D's ``b2Body_SetTargetTransform``): each step
it sets the velocity that reaches the target pose at the end of the step. It never teleports, so
bodies standing on a platform are carried by friction, not left behind.

>>> path = Sine(center=(0.0, 1.0), amplitude=(2.0, 0.0), frequency=0.5)
>>> path.pose(0.5)
((2.0, 1.0), 0.0)
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Literal, Protocol, runtime_checkable

import pymunk

from playground._engine import raw
from playground.limits import (
    MAX_ACCELERATION,
    MAX_ANGLE,
    MAX_ANGULAR_SPEED,
    MAX_COORDINATE,
    MAX_FREQUENCY,
    MAX_LENGTH,
    MAX_SPEED,
    MAX_TIME,
)
from playground.params import check, param, positive
from playground.vec import Vec

__all__ = ["Circle", "Elevator", "Mover", "Path", "Sine", "Spin", "Waypoints", "ring_room"]

Pose = tuple[Vec, float]


@runtime_checkable
class Path(Protocol):
    """A pose as a function of time: ``pose(t) -> ((x, y) m, angle rad)``."""

    def pose(self, t: float) -> Pose: ...


@dataclass(frozen=True, slots=True)
class Waypoints:
    """Through a list of points at a constant speed, linear or eased, looping or ping-pong.

    Eased legs average the same speed as straight ones. ``"loop"`` returns from the last point
    to the first; ``"pingpong"`` reverses; ``"once"`` stops at the last point. ``points`` (m),
    ``speed`` (m/s), ``angle`` (rad).

    >>> path = Waypoints(((0.0, 0.0), (2.0, 0.0)), speed=1.0, mode="pingpong")   # m, m/s
    >>> path.pose(3.0)                        # at 3 s: out 2 m and 1 m back; (m, m), rad
    ((1.0, 0.0), 0.0)
    """

    points: tuple[Vec, ...] = param(
        doc="The corners.", unit="m", min_items=2, ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    speed: float = param(1.0, doc="Travel speed along a leg.", unit="m/s", gt=0.0, le=MAX_SPEED)
    ease: bool = param(False, doc="Smoothstep each leg, so the mover stops at every corner.")
    mode: Literal["loop", "pingpong", "once"] = param(
        "pingpong", doc="At the last point: back to the first, reverse, or stop."
    )
    angle: float = param(
        0.0, doc="Constant angle of the body.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE
    )

    def __post_init__(self) -> None:
        check(self)

    def _legs(self) -> list[tuple[Vec, Vec]]:
        pts = list(self.points)
        if self.mode == "loop":
            pts.append(pts[0])
        elif self.mode == "pingpong":
            pts += pts[-2::-1]
        return list(itertools.pairwise(pts))

    def pose(self, t: float) -> Pose:
        legs = self._legs()
        times = [math.dist(a, b) / self.speed for a, b in legs]
        total = sum(times)
        if self.mode == "once":
            t = min(max(t, 0.0), total)
        elif total > 0.0:
            t = t % total
        for (a, b), dur in zip(legs, times, strict=True):
            if t <= dur and dur > 0.0:
                s = t / dur
                if self.ease:
                    s = s * s * (3.0 - 2.0 * s)
                return ((a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s), self.angle)
            t -= dur
        return (legs[-1][1], self.angle)


@dataclass(frozen=True, slots=True)
class Sine:
    """Oscillation ``center + amplitude·sin(2πf·t + phase)``.

    The amplitude is a vector: the direction of travel.
    """

    center: Vec = param(
        (0.0, 0.0), doc="Centre of the motion.", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    amplitude: Vec = param(
        (1.0, 0.0), doc="Amplitude and direction.", unit="m", ge=-MAX_LENGTH, le=MAX_LENGTH
    )
    frequency: float = param(0.25, doc="Frequency.", unit="Hz", gt=0.0, le=MAX_FREQUENCY)
    phase: float = param(0.0, doc="Phase.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE)
    angle: float = param(
        0.0, doc="Constant angle of the body.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE
    )

    def __post_init__(self) -> None:
        check(self)

    def pose(self, t: float) -> Pose:
        s = math.sin(2.0 * math.pi * self.frequency * t + self.phase)
        return (
            (self.center[0] + self.amplitude[0] * s, self.center[1] + self.amplitude[1] * s),
            self.angle,
        )


@dataclass(frozen=True, slots=True)
class Circle:
    """Around a circle of ``radius`` (m) about ``center`` (m), one turn per ``period`` (s).

    The body keeps its angle (a Ferris-wheel gondola) unless ``turn_with_path`` is set.
    """

    center: Vec = param(
        (0.0, 0.0), doc="Centre of the circle.", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    radius: float = param(1.0, doc="Radius.", unit="m", gt=0.0, le=MAX_LENGTH)
    period: float = param(
        4.0,
        doc="One turn (negative: clockwise).",
        unit="s",
        ge=-MAX_TIME,
        le=MAX_TIME,
        nonzero=True,
    )
    phase: float = param(0.0, doc="Angle at t = 0.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE)
    turn_with_path: bool = param(False, doc="Turn the body with the path.")

    def __post_init__(self) -> None:
        check(self)

    def pose(self, t: float) -> Pose:
        a = self.phase + 2.0 * math.pi * t / self.period
        pos = (
            self.center[0] + self.radius * math.cos(a),
            self.center[1] + self.radius * math.sin(a),
        )
        return (pos, a - self.phase if self.turn_with_path else 0.0)


@dataclass(frozen=True, slots=True)
class Spin:
    """Constant rotation about a fixed ``position`` (m) at ``rate`` (rad/s, CCW positive)."""

    position: Vec = param(
        (0.0, 0.0), doc="Fixed position.", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    rate: float = param(
        1.0,
        doc="Turning rate, CCW positive.",
        unit="rad/s",
        ge=-MAX_ANGULAR_SPEED,
        le=MAX_ANGULAR_SPEED,
    )
    angle: float = param(0.0, doc="Angle at t = 0.", unit="rad", ge=-MAX_ANGLE, le=MAX_ANGLE)

    def __post_init__(self) -> None:
        check(self)

    def pose(self, t: float) -> Pose:
        return (self.position, self.angle + self.rate * t)


@dataclass(frozen=True, slots=True)
class Elevator:
    """Rises along ``axis`` with a prescribed ``acceleration`` (m/s²) from rest.

    Waits at ``start`` until ``start_time`` (s), accelerates for ``duration`` (s), then cruises at
    the speed reached. ``p(t) = start + axis·½·a·τ²`` while accelerating.

    >>> Elevator(start=(0.0, 0.0), acceleration=2.0, start_time=1.0).pose(3.0)
    ((0.0, 4.0), 0.0)
    """

    start: Vec = param(
        (0.0, 0.0), doc="Where it waits.", unit="m", ge=-MAX_COORDINATE, le=MAX_COORDINATE
    )
    axis: Vec = param(
        (0.0, 1.0),
        doc="Direction of travel (any length).",
        nonzero=True,
        ge=-MAX_COORDINATE,
        le=MAX_COORDINATE,
    )
    acceleration: float = param(
        1.0, doc="Acceleration.", unit="m/s²", ge=-MAX_ACCELERATION, le=MAX_ACCELERATION
    )
    start_time: float = param(0.0, doc="When it starts.", unit="s", ge=-MAX_TIME, le=MAX_TIME)
    duration: float = param(
        math.inf,
        doc="How long it accelerates (default: forever).",
        unit="s",
        gt=0.0,
        le=MAX_TIME,
        inf=True,
    )

    def __post_init__(self) -> None:
        check(self)

    def distance(self, t: float) -> float:
        """Distance travelled along the axis at time ``t``, m."""
        tau = max(0.0, t - self.start_time)
        if tau <= self.duration:
            return 0.5 * self.acceleration * tau * tau
        d = self.duration
        return 0.5 * self.acceleration * d * d + self.acceleration * d * (tau - d)

    def pose(self, t: float) -> Pose:
        n = math.hypot(*self.axis)
        s = self.distance(t) / n
        return ((self.start[0] + self.axis[0] * s, self.start[1] + self.axis[1] * s), 0.0)


class Mover:
    """Drives one kinematic body along a path by velocity, never by teleporting.

    Each step, velocity = (target(t + dt) − position) / dt and angular velocity likewise, so the
    body reaches the path's pose exactly at the end of the step (kinematic bodies move by
    ``p += v·dt`` in pymunk, with or without substeps).

    >>> body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    >>> mover = Mover(body, Spin(rate=2.0))
    >>> mover.drive(t=0.0, dt=0.5)
    >>> body.angular_velocity
    2.0
    """

    __slots__ = ("_h", "body", "path")

    def __init__(self, body: pymunk.Body, path: Path) -> None:
        if body.body_type != pymunk.Body.KINEMATIC:
            raise ValueError("body: a mover drives a KINEMATIC body (got a dynamic or static one)")
        self.body = body
        self.path = path
        self._h = raw.handle(body)  # driven every step: through the C getters and setters

    def place(self, t: float) -> None:
        """Put the body at its pose at time ``t``: only before the first step (setup).

        Its shapes are re-indexed at once: Chipmunk caches where a shape is and refreshes that
        only when it steps, so a query before the first step (a player's ground probe) would find
        the shapes where the body was before it was placed.
        """
        (x, y), a = self.path.pose(t)
        self.body.position = (x, y)
        self.body.angle = a
        if self.body.space is not None:
            self.body.space.reindex_shapes_for_body(self.body)

    def drive(self, t: float, dt: float) -> None:
        """Set the velocity that brings the body from its pose now to the path's pose at t + dt."""
        (x, y), a = self.path.pose(t + dt)
        h = self._h
        px, py = raw.position(h)
        raw.set_velocity(h, (x - px) / dt, (y - py) / dt)
        raw.set_angular_velocity(h, (a - raw.angle(h)) / dt)


def ring_room(
    body: pymunk.Body,
    radius: float,
    *,
    segments: int = 48,
    thickness: float = 0.1,
    friction: float = 1.0,
) -> list[pymunk.Segment]:
    """A closed ring of ``segments`` segments (inner radius ``radius``, walls ``thickness`` thick,
    m) on ``body``, to add with it: ``world.add(name, body, *ring_room(body, radius))``.

    Spin the (kinematic) body with a :class:`Spin` mover to make a carnival ride: a body on the
    inner wall is carried round and feels ``v²/r`` outward.

    >>> ring = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    >>> len(ring_room(ring, 5.0, segments=12))
    12
    """
    positive("radius", radius)
    positive("thickness", thickness)
    if segments < 3:
        raise ValueError(f"segments: expected at least 3, got {segments}")
    # Chord midpoints are the closest points to the centre: put their inner faces at ``radius``.
    r = (radius + thickness) / math.cos(math.pi / segments)
    # Slightly longer chords so neighbouring segments overlap: no gaps to slip through.
    shapes = []
    for i in range(segments):
        a0 = 2.0 * math.pi * (i - 0.02) / segments
        a1 = 2.0 * math.pi * (i + 1.02) / segments
        seg = pymunk.Segment(
            body,
            (r * math.cos(a0), r * math.sin(a0)),
            (r * math.cos(a1), r * math.sin(a1)),
            thickness,
        )
        seg.friction = friction
        shapes.append(seg)
    return shapes
