"""Level files: the TOML format as pydantic models, and loading with errors that say where.

A level is one TOML document: settings, gravity, static geometry, props, movers, joints, actors,
tracking, events, scripted inputs, expectations, view hints, a title and a description. Every
problem found while loading is reported at once as a :class:`LevelError` naming the file, the key
path and what was expected; an unknown key comes with the closest valid name. Quantities are SI
(m, kg, s, N, rad).

>>> level = loads('title = "Tiny"\\ndescription = "A crate."\\n'
...               '[[props]]\\nname = "crate"\\nposition = [0, 1]\\nmass = 5\\n'
...               'shapes = [{kind = "box", size = [1, 1]}]\\n')
>>> level.props[0].mass, level.settings.dt
(5.0, 0.008333333333333333)
>>> loads('title = "x"\\ndescription = "y"\\n[settings]\\ndtt = 0.01\\n')
Traceback (most recent call last):
...
playground.level.LevelError: <string>: settings.dtt: unknown key (did you mean 'dt'?)
"""

from __future__ import annotations

import atexit
import copy
import dataclasses
import difflib
import functools
import importlib.resources
import json
import math
import os
import re
import shutil
import tempfile
import tomllib
import types
import typing
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Annotated, Any, Literal, Union

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    Strict,
    ValidationError,
    field_validator,
)

from playground import limits

__all__ = [
    "SEED_SEQUENCES",
    "Level",
    "LevelError",
    "Problem",
    "find",
    "levels_dirs",
    "load",
    "loads",
    "schema",
    "shipped",
]

# -- plain types ---------------------------------------------------------------------------------

# Every number is bounded (see playground.limits for each bound's reason). A plain number — a
# length, position, time, angle, rate, tolerance — lies within ±MAX_COORDINATE (1e5): larger is
# beyond any game-scale level, and sums and products of such numbers stay far from overflow.
# Quantities with a tighter plausible range (masses, speeds, gravities, forces, stiffnesses,
# frequencies, dt) say so where they are declared.
_PLAIN = limits.MAX_COORDINATE
Finite = Annotated[float, Field(ge=-_PLAIN, le=_PLAIN, allow_inf_nan=False)]
Positive = Annotated[float, Field(gt=0.0, le=_PLAIN, allow_inf_nan=False)]
NonNegative = Annotated[float, Field(ge=0.0, le=_PLAIN, allow_inf_nan=False)]
Unit = Annotated[float, Field(ge=-1.0, le=1.0, allow_inf_nan=False)]
# Tables are strict (no true -> 1.0, no "10" -> 10, as the JSON Schema says); a TOML array is a
# list, so fixed-length arrays are the one place a conversion (list -> tuple) is allowed.
Vec = Annotated[tuple[Finite, Finite], Strict(False)]


def _whole(value: object) -> object:
    """A float with no fraction is an integer (as in JSON Schema): 2.0 -> 2."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


Whole = Annotated[int, BeforeValidator(_whole)]
Mass = Annotated[float, Field(ge=limits.MIN_MASS, le=limits.MAX_MASS, allow_inf_nan=False)]
"""kg: see ``MIN_MASS`` and ``MAX_MASS`` (mass ratios with a 70 kg player)."""
Moment = Annotated[float, Field(ge=limits.MIN_MOMENT, le=limits.MAX_MOMENT, allow_inf_nan=False)]
"""kg·m²: 1/I must stay finite, m·L² of the largest body must fit."""
Speed = Annotated[float, Field(ge=-limits.MAX_SPEED, le=limits.MAX_SPEED, allow_inf_nan=False)]
"""m/s: faster bodies cross more than their own size per step and tunnel."""
TurnRate = Annotated[
    float, Field(ge=-limits.MAX_ANGULAR_SPEED, le=limits.MAX_ANGULAR_SPEED, allow_inf_nan=False)
]
"""rad/s: the same tunnelling argument at a metre-sized body's rim."""
Gravity_ = Annotated[
    float, Field(ge=-limits.MAX_GRAVITY, le=limits.MAX_GRAVITY, allow_inf_nan=False)
]
"""m/s²: at most 100 g, which the contacts and the hover spring still hold at 1/120 s."""
Force = Annotated[float, Field(gt=0.0, le=limits.MAX_FORCE, allow_inf_nan=False)]
"""N: keeps F·dt and every sum of forces finite."""
Stiffness = Annotated[float, Field(gt=0.0, le=limits.MAX_STIFFNESS, allow_inf_nan=False)]
"""N/m or N·m/rad; stability at the level's dt is checked when the level is built."""
Damping = Annotated[float, Field(ge=0.0, le=limits.MAX_STIFFNESS, allow_inf_nan=False)]
"""N·s/m or N·m·s/rad: bounded like a stiffness."""
Frequency = Annotated[float, Field(gt=0.0, le=limits.MAX_FREQUENCY, allow_inf_nan=False)]
"""Hz: above half the step rate a motion is not sampled at all."""
Name = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[A-Za-z_][A-Za-z0-9_\-]*$")]

SCHEMA_ID = (
    "https://github.com/pymunk-playground/pymunk-playground/raw/main/levels/level.schema.json"
)
"""The schema's ``$id``: where editors can fetch it (a level file names it in a ``#:schema``
first line, or the folder's own ``level.schema.json``)."""

STATIC = "static"
"""The body name joints use for the fixed world."""


class _Model(BaseModel):
    """Every table of a level: unknown keys are errors, values are frozen."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


# -- settings ------------------------------------------------------------------------------------


class Settings(_Model):
    """Simulation settings (see :class:`playground.WorldConfig`)."""

    dt: float = Field(
        default=1.0 / 120.0,
        ge=limits.MIN_DT,
        le=limits.MAX_DT,
        allow_inf_nan=False,
        description="Fixed step, s (1e-4 … 0.1: see playground.limits).",
    )
    substeps: Whole = Field(default=1, ge=1, le=64, description="space.step calls per step.")
    iterations: Whole = Field(
        default=10, ge=1, le=1000, description="Solver iterations per substep."
    )
    damping: float = Field(
        default=1.0, gt=0.0, le=1.0, description="Fraction of velocity kept per second (1: none)."
    )
    collision_slop: NonNegative = Field(default=0.005, description="Allowed overlap, m.")
    contact_split: bool = Field(
        default=False, description="Split engine forces into contact and constraint readings."
    )
    seconds: Positive = Field(
        default=3.0, le=limits.MAX_SECONDS, description="Length of a run, s (at most an hour)."
    )


class Perception(_Model):
    """How perceived gravity is filtered (see :class:`playground.Perception`)."""

    min_cutoff: Frequency = Field(default=2.0, description="1€ minimum cutoff, Hz.")
    beta: NonNegative = Field(default=0.05, description="1€ speed coefficient.")
    d_cutoff: Frequency = Field(default=1.0, description="1€ derivative cutoff, Hz.")
    spike_filter: bool = Field(default=True, description="Median-of-3 stage before the 1€ filter.")
    up_threshold: Positive = Field(default=1.0, description="Below this |g| (m/s²) up is held.")


class Tracking(_Model):
    """Which bodies the force solver tracks (actors always are) and how they are filtered."""

    bodies: list[Name] = Field(default_factory=list, description="Tracked prop names.")
    perceive: bool = Field(default=True, description="Filter perceived gravity for tracked bodies.")
    perception: Perception = Field(default_factory=lambda: Perception())


class View(_Model):
    """Hints for the desktop view."""

    camera: Vec = Field(default=(0.0, 0.0), description="Camera centre at start, m.")
    pixels_per_metre: Positive = Field(default=50.0, le=10000.0, description="Zoom, px/m.")
    follow: Name | None = Field(
        default=None, description="Body the camera follows; default: the first actor, if any."
    )
    roll: bool = Field(default=False, description="Roll the camera with the followed body's up.")
    overlays: list[Literal["vectors", "contacts", "joints", "reactions", "perceived"]] | None = (
        Field(
            default=None,
            description="Overlays on at start (the compass is always on); default: vectors only.",
        )
    )
    moment: NonNegative | None = Field(
        default=None,
        description="Simulated time, s, of the moment that shows the level's claim best "
        "(its screenshot and its view test).",
    )


# -- gravity -------------------------------------------------------------------------------------


class UniformGravity(_Model):
    """The same acceleration everywhere (m/s²)."""

    # A gravity table names its kind (the field is a tagged union); the default only serves the
    # level's own default field. The schema says so too.
    model_config = ConfigDict(json_schema_extra={"required": ["kind"]})

    kind: Literal["uniform"] = "uniform"
    g: Annotated[tuple[Gravity_, Gravity_], Strict(False)] = (0.0, -9.81)


class Turn(_Model):
    """A scheduled turn of a rotating room's gravity, rad over s."""

    start: NonNegative
    angle: Finite
    duration: NonNegative = 0.0


class RotatingGravity(_Model):
    """Uniform gravity whose direction turns (rad from +x; −π/2 is down)."""

    kind: Literal["rotating"]
    magnitude: Annotated[float, Field(ge=0.0, le=limits.MAX_GRAVITY)] = 9.81
    angle: Finite = -math.pi / 2
    rate: TurnRate = Field(default=0.0, description="Constant turning rate, rad/s.")
    turns: list[Turn] = Field(default_factory=list)


class RadialGravity(_Model):
    """Gravity toward a centre (a small planet)."""

    kind: Literal["radial"]
    center: Vec = (0.0, 0.0)
    surface_gravity: Gravity_ = 9.81
    radius: Positive = 10.0
    softening: NonNegative = 0.5


SimpleGravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity, Field(discriminator="kind")
]


class Zone(_Model):
    """A box (x0, y0, x1, y1), m, with its own field."""

    box: Annotated[tuple[Finite, Finite, Finite, Finite], Strict(False)]
    field: SimpleGravity

    @field_validator("box")
    @classmethod
    def _ordered(cls, box: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        if box[2] <= box[0] or box[3] <= box[1]:
            raise ValueError("expected (x0, y0, x1, y1) with x1 > x0 and y1 > y0")
        return box


class ZonesGravity(_Model):
    """A base field with regions that override it (first zone wins)."""

    kind: Literal["zones"]
    base: SimpleGravity = Field(default_factory=lambda: UniformGravity())
    zones: list[Zone] = Field(default_factory=list)


Gravity = Annotated[
    UniformGravity | RotatingGravity | RadialGravity | ZonesGravity, Field(discriminator="kind")
]

# -- shapes --------------------------------------------------------------------------------------


class _Surface(_Model):
    friction: NonNegative = Field(default=0.8, description="Coulomb friction coefficient.")
    elasticity: float = Field(default=0.0, ge=0.0, le=1.0, description="Restitution, 0..1.")


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

# -- bodies --------------------------------------------------------------------------------------


class Prop(_Model):
    """A dynamic body: mass (kg) spread over its shapes by area."""

    name: Name
    position: Vec
    mass: Mass
    shapes: list[Shape] = Field(min_length=1)
    angle: Finite = 0.0
    velocity: Annotated[tuple[Speed, Speed], Strict(False)] = (0.0, 0.0)
    angular_velocity: TurnRate = 0.0
    moment: Moment | None = Field(default=None, description="kg·m²; default from the shapes.")


class Waypoints(_Model):
    kind: Literal["waypoints"]
    points: list[Vec] = Field(min_length=2)
    speed: Annotated[Speed, Field(gt=0.0)] = 1.0
    ease: bool = False
    mode: Literal["loop", "pingpong", "once"] = "pingpong"
    angle: Finite = 0.0


class Sine(_Model):
    kind: Literal["sine"]
    center: Vec = (0.0, 0.0)
    amplitude: Vec = (1.0, 0.0)
    frequency: Frequency = 0.25
    phase: Finite = 0.0
    angle: Finite = 0.0


class CirclePath(_Model):
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


class Spin(_Model):
    kind: Literal["spin"]
    position: Vec = (0.0, 0.0)
    rate: TurnRate = 1.0
    angle: Finite = 0.0


class Elevator(_Model):
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


class MoverModel(_Model):
    """A kinematic body (platform, elevator, room) driven along a path."""

    name: Name
    shapes: list[Shape] = Field(min_length=1)
    path: Path_


class _Joint(_Model):
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


class Patrol(_Model):
    """Walk one way for half the ``period`` (s) at move input ``speed`` (0..1), then back."""

    speed: float = Field(default=0.5, ge=0.0, le=1.0, description="Move input, 0..1.")
    period: Positive = 4.0


class Actor(_Model):
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
        _controller_config(params)
        return params


def _controller_config(params: dict[str, float | bool]) -> Any:
    """Build a ``ControllerConfig`` from ``params``; ValueError naming a wrong key."""
    from playground.controller import ControllerConfig

    names = [f.name for f in dataclasses.fields(ControllerConfig)]
    for key in params:
        if key not in names:
            raise ValueError(f"unknown controller parameter {key!r}{_suggest(key, names)}")
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
    return (-_PLAIN, _PLAIN)


# -- timelines -----------------------------------------------------------------------------------


class Input(_Model):
    """From time ``t`` (s) on, ``actor`` holds this intent (until its next input)."""

    t: NonNegative
    actor: Name = "player"
    move: Unit = 0.0
    jump: bool = False
    grab: bool = False
    push: bool = False
    climb: Unit = 0.0
    gravity: Vec | None = Field(default=None, description="Own gravity direction (any length).")
    restore_gravity: bool = False
    nullify: Name | None = Field(default=None, description="Body whose gravity to nullify.")

    @field_validator("gravity")
    @classmethod
    def _direction(cls, v: tuple[float, float] | None) -> tuple[float, float] | None:
        if v is not None and v == (0.0, 0.0):
            raise ValueError("expected a non-zero direction")
        return v


Impulse_ = Annotated[
    float, Field(ge=-limits.MAX_IMPULSE, le=limits.MAX_IMPULSE, allow_inf_nan=False)
]
"""N·s: spread over one step of the smallest dt it stays within MAX_FORCE."""


class _Event(_Model):
    t: NonNegative = Field(description="When, s.")


class SetGravity(_Event):
    """Replace the field with uniform gravity ``g`` (m/s²)."""

    kind: Literal["set_gravity"]
    g: Annotated[tuple[Gravity_, Gravity_], Strict(False)]


class FlipGravity(_Event):
    """Turn a uniform field by ``angle`` rad (π: a flip), instantly."""

    kind: Literal["flip_gravity"]
    angle: Finite = math.pi


class Nullify(_Event):
    """Zero one body's gravity."""

    kind: Literal["nullify"]
    body: Name


class RestoreGravity(_Event):
    """Give a body the field's gravity back."""

    kind: Literal["restore_gravity"]
    body: Name


class BodyGravity(_Event):
    """Give a body its own gravity: ``scale`` × the field, along ``direction`` if given."""

    kind: Literal["body_gravity"]
    body: Name
    scale: Annotated[
        float,
        Field(ge=-limits.MAX_GRAVITY_SCALE, le=limits.MAX_GRAVITY_SCALE, allow_inf_nan=False),
    ] = 1.0
    direction: Vec | None = None


class Impulse(_Event):
    """A one-step impulse (N·s) on a body, at a world point (m) or its centre."""

    kind: Literal["impulse"]
    body: Name
    impulse: Annotated[tuple[Impulse_, Impulse_], Strict(False)]
    point: Vec | None = None


class Spawn(_Event):
    """Add a prop."""

    kind: Literal["spawn"]
    prop: Prop


class Remove(_Event):
    """Remove a body."""

    kind: Literal["remove"]
    body: Name


Event = Annotated[
    SetGravity | FlipGravity | Nullify | RestoreGravity | BodyGravity | Impulse | Spawn | Remove,
    Field(discriminator="kind"),
]

# -- expectations --------------------------------------------------------------------------------

VECTOR_QUANTITIES = (
    "position",
    "velocity",
    "engine",
    "contact",
    "contact_normal",
    "contact_friction",
    "constraint",
    "support",
    "perceived_gravity",
    "hover",
    "drive",
    "grip",
    "push",
)
"""Quantities that are (x, y) vectors; pick a ``component`` or compare the vector."""
SCALAR_QUANTITIES = ("angle", "angular_velocity", "tilt")
"""Quantities that are numbers: angle (rad), angular velocity (rad/s), tilt (rad, 0..π)."""
FORCE_QUANTITIES = (
    "engine",
    "contact",
    "contact_normal",
    "contact_friction",
    "constraint",
    "support",
)
"""Force readings of the solver, N; ``filtered = true`` gives the 1€-filtered reading."""
CONTROLLER_QUANTITIES = ("hover", "drive", "grip", "push")
"""An actor's own readings of the forces its controller put on it in the last step, N (the
grip: the joint's force the step before)."""

Quantity = Literal[
    "position",
    "velocity",
    "angle",
    "angular_velocity",
    "tilt",
    "state",
    "engine",
    "contact",
    "contact_normal",
    "contact_friction",
    "constraint",
    "support",
    "perceived_gravity",
    "hover",
    "drive",
    "grip",
    "push",
]


class Reading(_Model):
    """Another reading taken the same step: ``scale`` × ``body``'s ``quantity``."""

    body: Name
    quantity: Quantity
    scale: Finite = Field(default=1.0, description="Multiplies the reading (−1 flips it).")


class Expectation(_Model):
    """A check on one body's quantity.

    ``check``: ``at`` time ``t``; ``always`` / ``eventually`` / ``mean`` over ``window`` (default
    the whole run). Compare with ``equals`` (± ``tolerance`` + ``relative``·|equals|), or bound
    with ``above`` / ``below``; a state compares with ``equals`` or ``one_of``.

    The value compared is the quantity, minus the same quantity of ``relative_to``, minus the
    reading ``minus`` (another body's force, say), filtered if asked; then, with ``angle_to``,
    the angle between that vector and a fixed vector or another reading (its direction, rad).
    """

    name: str | None = Field(
        default=None, min_length=1, description="Default: made from the check."
    )
    body: Name
    quantity: Quantity
    component: Literal["x", "y", "norm"] | None = Field(
        default=None, description="For vectors: x, y or the length; none compares the vector."
    )
    filtered: bool = Field(default=False, description="1€-filtered force reading.")
    check: Literal["at", "always", "eventually", "mean"] = "at"
    t: NonNegative | None = Field(default=None, description="For check = 'at', s.")
    window: Annotated[tuple[NonNegative, NonNegative], Strict(False)] | None = Field(
        default=None, description="(start, end), s."
    )
    equals: Finite | Vec | str | None = None
    one_of: list[str] | None = None
    tolerance: NonNegative = Field(
        default=0.0, description="Absolute tolerance, in the quantity's unit."
    )
    relative: NonNegative = Field(default=0.0, description="Tolerance relative to |equals|.")
    above: Finite | None = None
    below: Finite | None = None
    relative_to: Name | None = Field(
        default=None, description="Subtract this body's same quantity (position, velocity…)."
    )
    change: bool = Field(
        default=False, description="Compare the change since the window's first step."
    )
    minus: Reading | None = Field(
        default=None,
        description="Subtract another reading (of any body, of the same kind) taken the same step.",
    )
    angle_to: Vec | Reading | None = Field(
        default=None,
        description="Check the angle (rad, 0..π) between the vector and this fixed vector or "
        "reading instead of the vector itself.",
    )

    @field_validator("window")
    @classmethod
    def _window(cls, w: tuple[float, float] | None) -> tuple[float, float] | None:
        if w is not None and w[1] < w[0]:
            raise ValueError("expected (start, end) with end >= start")
        return w


# -- the level -----------------------------------------------------------------------------------


class Level(_Model):
    """One level file."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        json_schema_extra={
            "$schema": "https://json-schema.org/draft/2020-12/schema",
            "$id": SCHEMA_ID,
        },
    )

    title: str = Field(min_length=1, max_length=80)
    description: str = Field(min_length=1, description="One paragraph: what the level shows.")
    settings: Settings = Field(default_factory=lambda: Settings())
    gravity: Gravity = Field(default_factory=lambda: UniformGravity())
    view: View = Field(default_factory=lambda: View())
    geometry: list[Shape] = Field(default_factory=list, description="Static shapes, world frame.")
    props: list[Prop] = Field(default_factory=list)
    movers: list[MoverModel] = Field(default_factory=list)
    joints: list[Joint] = Field(default_factory=list)
    actors: list[Actor] = Field(default_factory=list)
    tracking: Tracking = Field(default_factory=lambda: Tracking())
    events: list[Event] = Field(default_factory=list)
    inputs: list[Input] = Field(default_factory=list)
    expect: list[Expectation] = Field(default_factory=list)
    catches: list[Name] = Field(
        default_factory=list,
        description="Breaks (playground faults) its checks must catch, by name.",
    )

    def body_names(self) -> list[str]:
        """Every named body: props, movers, actors and spawned props."""
        spawned = [e.prop.name for e in self.events if isinstance(e, Spawn)]
        return [
            *(p.name for p in self.props),
            *(m.name for m in self.movers),
            *(a.name for a in self.actors),
            *spawned,
        ]

    def tracked(self) -> list[str]:
        """Bodies whose forces are read: actors and ``tracking.bodies``."""
        return [*(a.name for a in self.actors), *self.tracking.bodies]


# -- errors --------------------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True, slots=True)
class Problem:
    """One thing wrong with a level: where (dotted key path) and what."""

    path: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}" if self.path else self.message


class LevelError(Exception):
    """A level could not be loaded: every problem, each with its key path.

    ``line`` and ``column`` are set for TOML syntax errors.
    """

    def __init__(
        self,
        source: str,
        problems: Sequence[Problem],
        *,
        line: int | None = None,
        column: int | None = None,
    ) -> None:
        self.source = source
        self.problems = tuple(problems)
        self.line = line
        self.column = column
        super().__init__("\n".join(f"{source}: {p}" for p in self.problems))


def _suggest(word: str, options: Sequence[str]) -> str:
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.5)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _unwrap(tp: Any) -> list[Any]:
    """The alternatives inside Annotated / Optional / Union."""
    origin = typing.get_origin(tp)
    if origin is Annotated:
        return _unwrap(typing.get_args(tp)[0])
    if origin is Union or origin is types.UnionType:
        return [alt for arg in typing.get_args(tp) for alt in _unwrap(arg)]
    return [tp]


def _walk(loc: Sequence[int | str]) -> tuple[set[int], type[BaseModel] | None]:
    """Follow a pydantic error location through the models.

    Returns the positions of the discriminator tags pydantic put in the location (a key path has
    no such level; a key may be spelled like a tag, as ``impulse`` in an impulse event) and the
    model whose table sits at the end of it, if any.
    """
    tags: set[int] = set()
    current: list[Any] = [Level]
    for position, key in enumerate(loc):
        nxt: list[Any] = []
        for tp in current:
            alts = _unwrap(tp)
            models = [a for a in alts if isinstance(a, type) and issubclass(a, BaseModel)]
            tagged = [
                m
                for m in models
                if "kind" in m.model_fields
                and typing.get_args(m.model_fields["kind"].annotation) == (key,)
            ]
            if len(models) > 1 and tagged:
                tags.add(position)
                nxt.extend(tagged)
                continue
            for alt in alts:
                origin = typing.get_origin(alt)
                if isinstance(alt, type) and issubclass(alt, BaseModel):
                    if isinstance(key, str) and key in alt.model_fields:
                        nxt.append(alt.model_fields[key].annotation)
                elif origin in (list, tuple) and isinstance(key, int):
                    nxt.extend(a for a in typing.get_args(alt) if a is not Ellipsis)
                elif origin is dict and isinstance(key, str):
                    nxt.append(typing.get_args(alt)[1])
        current = nxt
    for tp in current:
        for alt in _unwrap(tp):
            if isinstance(alt, type) and issubclass(alt, BaseModel):
                return tags, alt
    return tags, None


def _path(loc: Sequence[int | str], tags: set[int]) -> str:
    return ".".join(str(k) for i, k in enumerate(loc) if i not in tags)


_TYPE_WORDS = {
    "float_type": "a number",
    "float_parsing": "a number",
    "int_type": "an integer",
    "int_parsing": "an integer",
    "int_from_float": "an integer",
    "bool_type": "true or false",
    "bool_parsing": "true or false",
    "string_type": "a string",
    "list_type": "an array",
    "tuple_type": "an array",
    "dict_type": "a table",
    "model_type": "a table",
    "model_attributes_type": "a table",
    "finite_number": "a finite number",
}


def _problems(exc: ValidationError) -> list[Problem]:
    out: list[Problem] = []
    for err in exc.errors(include_url=False):
        loc = tuple(err["loc"])
        tags, model = _walk(loc[:-1])
        kind = err["type"]
        if kind == "extra_forbidden":
            key = str(loc[-1])
            options = list(model.model_fields) if model is not None else []
            message = f"unknown key{_suggest(key, options)}"
        elif kind == "missing":
            message = "required key is missing"
        elif kind in _TYPE_WORDS:
            message = f"expected {_TYPE_WORDS[kind]}, got {_show(err.get('input'))}"
        elif kind == "union_tag_invalid":
            ctx = err.get("ctx", {})
            expected = str(ctx.get("expected_tags", ""))
            tag = str(ctx.get("tag", ""))
            names = [t.strip(" '") for t in expected.split(",")]
            message = f"kind {tag!r} is not one of {expected}{_suggest(tag, names)}"
        elif kind == "union_tag_not_found":
            message = "a table with a 'kind' key is required"
        else:
            msg = str(err["msg"])
            msg = msg.removeprefix("Value error, ").replace("Input should be", "expected")
            message = f"{msg[0].lower()}{msg[1:]}, got {_show(err.get('input'))}"
        out.append(Problem(_path(loc, tags), message))
    return out


def _show(value: object) -> str:
    text = json.dumps(value, default=repr) if not isinstance(value, str) else repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


# -- cross-references ----------------------------------------------------------------------------


def _references(level: Level, assumed: frozenset[str] = frozenset()) -> Iterator[Problem]:
    """Names that must exist, be unique, or be of the right kind.

    ``assumed`` are names of bodies left out of ``level`` because their tables are invalid
    (see :func:`validate`): references to them are not reported.
    """
    names = level.body_names()
    seen: set[str] = set()
    for name in names:
        if name == STATIC:
            yield Problem("", f"{STATIC!r} is reserved for the fixed world; rename the body")
        if name in seen:
            yield Problem("", f"body name {name!r} is used twice; names must be unique")
        seen.add(name)
    actors = [a.name for a in level.actors]
    tracked = level.tracked()
    dynamic = [*(p.name for p in level.props), *actors]
    dynamic += [e.prop.name for e in level.events if isinstance(e, Spawn)]

    def known(path: str, name: str, pool: Sequence[str], what: str) -> Iterator[Problem]:
        if name not in pool and name not in assumed:
            listing = ", ".join(pool) or "none"
            yield Problem(
                path, f"no {what} named {name!r}{_suggest(name, pool)} (known: {listing})"
            )

    for i, prop in enumerate(level.props):
        for j, shape in enumerate(prop.shapes):
            if isinstance(shape, Ring):
                yield Problem(f"props.{i}.shapes.{j}", "a ring belongs to a mover or geometry")
    for i, name in enumerate(level.tracking.bodies):
        yield from known(f"tracking.bodies.{i}", name, dynamic, "dynamic body")
    for i, joint in enumerate(level.joints):
        for end in ("a", "b"):
            yield from known(f"joints.{i}.{end}", getattr(joint, end), [*names, STATIC], "body")
        if joint.a == joint.b:
            yield Problem(f"joints.{i}", "a joint needs two different bodies")
    for i, inp in enumerate(level.inputs):
        yield from known(f"inputs.{i}.actor", inp.actor, actors, "actor")
        if inp.nullify is not None:
            yield from known(f"inputs.{i}.nullify", inp.nullify, dynamic, "dynamic body")
    for i, actor in enumerate(level.actors):
        if actor.patrol is not None and any(inp.actor == actor.name for inp in level.inputs):
            yield Problem(
                f"actors.{i}.patrol", "an actor has a patrol or scripted inputs, not both"
            )
    for i, event in enumerate(level.events):
        body = getattr(event, "body", None)
        if body is not None:
            pool = names if isinstance(event, Remove) else dynamic
            yield from known(f"events.{i}.body", body, pool, "body")
        if isinstance(event, FlipGravity) and not isinstance(level.gravity, UniformGravity):
            yield Problem(f"events.{i}", "flip_gravity turns a uniform field; use rotating turns")
    follow = level.view.follow
    if follow is not None and follow not in names and follow not in assumed:
        yield from known("view.follow", follow, names, "body")
    for i, exp in enumerate(level.expect):
        if exp.body in assumed or exp.relative_to in assumed:
            continue
        yield from _check_expectation(f"expect.{i}", exp, level, names, actors, tracked)
    yield from _check_catches(level)


def _check_catches(level: Level) -> Iterator[Problem]:
    """Every declared break exists, once; and there are checks to catch it."""
    if not level.catches:
        return
    from playground.faults import names as break_names

    valid = break_names()
    seen: set[str] = set()
    for i, name in enumerate(level.catches):
        if name not in valid:
            yield Problem(
                f"catches.{i}",
                f"no break named {name!r}{_suggest(name, valid)} (valid: {', '.join(valid)})",
            )
        elif name in seen:
            yield Problem(f"catches.{i}", f"break {name!r} is declared twice")
        seen.add(name)
    if not level.expect:
        yield Problem("catches", "a level without expectations cannot catch a break")


def _check_expectation(
    path: str,
    exp: Expectation,
    level: Level,
    names: Sequence[str],
    actors: Sequence[str],
    tracked: Sequence[str],
) -> Iterator[Problem]:
    if exp.body not in names:
        yield Problem(
            f"{path}.body", f"no body named {exp.body!r}{_suggest(exp.body, list(names))}"
        )
        return
    if exp.relative_to is not None:
        if exp.relative_to not in names:
            yield Problem(
                f"{path}.relative_to",
                f"no body named {exp.relative_to!r}{_suggest(exp.relative_to, list(names))}",
            )
        if exp.quantity not in ("position", "velocity", "angle", "angular_velocity"):
            yield Problem(
                f"{path}.relative_to",
                "only position, velocity, angle and angular_velocity are relative to a body",
            )
    if exp.change and (exp.check == "at" or exp.quantity == "state"):
        yield Problem(f"{path}.change", "change needs a window (always, eventually, mean)")
    q = exp.quantity
    seconds = level.settings.seconds
    if exp.check == "at":
        if exp.t is None:
            yield Problem(f"{path}.t", "check = 'at' needs a time t, s")
        elif exp.t > seconds:
            yield Problem(f"{path}.t", f"t = {exp.t} s is after the run's end ({seconds} s)")
        if exp.window is not None:
            yield Problem(f"{path}.window", "check = 'at' takes t, not a window")
    else:
        if exp.t is not None:
            yield Problem(f"{path}.t", f"check = {exp.check!r} takes a window, not t")
        if exp.window is not None and exp.window[1] > seconds:
            yield Problem(f"{path}.window", f"ends after the run's end ({seconds} s)")
    if q == "state":
        if exp.body not in actors:
            yield Problem(f"{path}.quantity", f"{exp.body!r} is not an actor: it has no state")
        if not isinstance(exp.equals, str) and exp.one_of is None:
            yield Problem(path, "a state check needs equals = 'state' or one_of = [...]")
        if exp.check == "mean":
            yield Problem(f"{path}.check", "a state has no mean")
        if exp.above is not None or exp.below is not None or exp.component is not None:
            yield Problem(path, "a state compares with equals or one_of only")
        return
    if isinstance(exp.equals, str) or exp.one_of is not None:
        yield Problem(f"{path}.equals", f"{q} is a number or vector, not a state name")
    if exp.equals is None and exp.above is None and exp.below is None:
        yield Problem(path, "nothing to compare: give equals, above or below")
    if exp.equals is not None and (exp.above is not None or exp.below is not None):
        yield Problem(path, "give equals (± tolerance) or above/below bounds, not both")
    if q in SCALAR_QUANTITIES and exp.component is not None:
        yield Problem(f"{path}.component", f"{q} is a number; it has no component")
    yield from _readable(path, exp.body, q, level, actors, tracked, filtered=exp.filtered)
    if exp.filtered and q not in FORCE_QUANTITIES:
        yield Problem(f"{path}.filtered", f"only force readings are filtered, not {q}")
    if exp.minus is not None:
        yield from _check_reading(f"{path}.minus", exp.minus, level, names, actors, tracked)
        if (exp.minus.quantity in VECTOR_QUANTITIES) != (q in VECTOR_QUANTITIES):
            yield Problem(
                f"{path}.minus.quantity",
                f"{exp.minus.quantity} and {q} are not both vectors or both numbers",
            )
    angle = exp.angle_to is not None
    if isinstance(exp.angle_to, Reading):
        ref = exp.angle_to
        yield from _check_reading(f"{path}.angle_to", ref, level, names, actors, tracked)
        if ref.quantity not in VECTOR_QUANTITIES:
            yield Problem(f"{path}.angle_to.quantity", f"{ref.quantity} is not a vector")
        if ref.scale == 0.0:
            yield Problem(f"{path}.angle_to.scale", "a zero vector has no direction")
    elif isinstance(exp.angle_to, tuple) and exp.angle_to == (0.0, 0.0):
        yield Problem(f"{path}.angle_to", "a zero vector has no direction")
    if angle:
        if q not in VECTOR_QUANTITIES:
            yield Problem(f"{path}.angle_to", f"{q} is a number: it has no direction")
        if exp.component is not None:
            yield Problem(f"{path}.component", "angle_to compares directions: no component")
        if exp.change:
            yield Problem(f"{path}.change", "angle_to compares directions, not changes")
    vector = q in VECTOR_QUANTITIES and exp.component is None and not angle
    if vector and (exp.above is not None or exp.below is not None):
        yield Problem(f"{path}.component", "bounds need a component: x, y or norm")
    if vector and isinstance(exp.equals, float | int):
        yield Problem(f"{path}.equals", f"{q} is a vector: give [x, y] or a component")
    if not vector and isinstance(exp.equals, tuple):
        yield Problem(f"{path}.equals", "expected a number for a component, angle or scalar")


def _check_reading(
    path: str,
    reading: Reading,
    level: Level,
    names: Sequence[str],
    actors: Sequence[str],
    tracked: Sequence[str],
) -> Iterator[Problem]:
    """Another reading an expectation refers to (``minus``, ``angle_to``)."""
    if reading.body not in names:
        yield Problem(
            f"{path}.body",
            f"no body named {reading.body!r}{_suggest(reading.body, list(names))}",
        )
        return
    if reading.quantity == "state":
        yield Problem(f"{path}.quantity", "a state is not a number or vector")
        return
    yield from _readable(path, reading.body, reading.quantity, level, actors, tracked)


def _readable(
    path: str,
    body: str,
    q: str,
    level: Level,
    actors: Sequence[str],
    tracked: Sequence[str],
    *,
    filtered: bool = False,
) -> Iterator[Problem]:
    """What a body needs for its quantity ``q`` to be read."""
    if q in (*FORCE_QUANTITIES, "perceived_gravity") and body not in tracked:
        yield Problem(f"{path}.body", f"{body!r} is not tracked; add it to tracking.bodies")
    if q in CONTROLLER_QUANTITIES and body not in actors:
        yield Problem(f"{path}.quantity", f"{body!r} is not an actor: it has no {q} reading")
    if (
        q in ("contact", "contact_normal", "contact_friction", "constraint")
        and not level.settings.contact_split
    ):
        yield Problem(f"{path}.quantity", f"{q} needs settings.contact_split = true")
    perceived = q == "perceived_gravity" or (q == "support" and filtered)
    if perceived and body not in actors and not level.tracking.perceive:
        yield Problem(f"{path}.quantity", "needs tracking.perceive = true")
    if q == "tilt" and body not in tracked:
        yield Problem(f"{path}.body", f"tilt needs an up: {body!r} must be an actor or tracked")


# -- loading -------------------------------------------------------------------------------------

_TOML_WHERE = re.compile(r"\(at line (\d+), column (\d+)\)")


def loads(text: str, source: str = "<string>") -> Level:
    """Parse and validate a level from TOML text; :class:`LevelError` lists every problem."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        where = _TOML_WHERE.search(str(exc))
        line, column = (int(where[1]), int(where[2])) if where else (None, None)
        raise LevelError(
            source, [Problem("", f"TOML syntax error: {exc}")], line=line, column=column
        ) from None
    except RecursionError:
        # tomllib parses nested arrays and inline tables recursively.
        raise LevelError(source, [_TOO_DEEP]) from None
    return validate(data, source)


_TOO_DEEP = Problem("", "document nested too deeply (no level nests more than a few tables)")


def validate(data: object, source: str = "<data>") -> Level:
    """Validate an already parsed document (a dict of TOML values)."""
    try:
        try:
            level = Level.model_validate(data)
        except ValidationError as exc:
            # Describing the error walks the document again (and may recurse as deep).
            raise LevelError(source, _problems(exc) + _salvaged_references(data, exc)) from None
    except RecursionError:
        raise LevelError(source, [_TOO_DEEP]) from None
    problems = list(_references(level))
    if problems:
        raise LevelError(source, problems)
    return level


_SALVAGE_ROUNDS = 4
"""Passes that set invalid parts aside before giving up on reporting references too."""

Loc = tuple[int | str, ...]


def _salvaged_references(data: object, exc: ValidationError) -> list[Problem]:
    """Reference problems of the document's valid part, reported beside its structural ones.

    Every invalid part is set aside: a list item (a prop, an expectation...) whole, a table key
    (it takes its default). The bodies named inside set-aside items are assumed to exist, and
    nothing is said about the set-aside parts. Empty if what remains still does not validate.
    """
    if not isinstance(data, dict):
        return []
    aside: set[Loc] = set()
    kept: dict[Loc, list[int]] = {}
    for _ in range(_SALVAGE_ROUNDS):
        aside |= {_aside(tuple(e["loc"]), e["type"], kept) for e in exc.errors()}
        doc, kept, assumed = _without(data, aside)
        try:
            level = Level.model_validate(doc)
        except ValidationError as again:
            exc = again
            continue
        except RecursionError:
            return []
        return [
            Problem(_renumber_path(p.path, kept), p.message)
            for p in _references(level, frozenset(assumed))
        ]
    return []


def _aside(loc: Loc, kind: str, kept: dict[Loc, list[int]]) -> Loc:
    """What to set aside for an error at ``loc`` (pydantic's, in the numbering of the document
    whose lists ``kept`` thinned): its outermost list item, else the table key (the table itself
    when the key is missing), in the original document's numbering."""
    tags, _ = _walk(loc)
    loc = _renumber(tuple(k for k in loc if k not in tags), kept)
    for i, key in enumerate(loc):
        if isinstance(key, int):
            return loc[: i + 1]
    return loc[:-1] if kind == "missing" else loc


def _without(data: dict[str, Any], aside: set[Loc]) -> tuple[Any, dict[Loc, list[int]], set[str]]:
    """A copy of ``data`` without the ``aside`` parts; for each thinned list the original index
    of every kept item; the body names found inside the removed items."""
    doc = copy.deepcopy(data)
    kept: dict[Loc, list[int]] = {}
    assumed: set[str] = set()
    for loc in sorted(aside, key=lambda k: (len(k), [str(x) for x in k]), reverse=True):
        if not loc:
            continue
        parent: Any = doc
        for key in loc[:-1]:
            try:
                parent = parent[key]
            except (KeyError, IndexError, TypeError):
                parent = None
                break
        last = loc[-1]
        if isinstance(parent, list) and isinstance(last, int) and last < len(parent):
            kept.setdefault(loc[:-1], list(range(len(parent))))
            assumed |= set(_names(parent[last]))
            parent[last] = _GONE
        elif isinstance(parent, dict) and last in parent:
            del parent[last]
    for where in list(kept):
        parent = doc
        try:
            for key in where:
                parent = parent[key]
        except (KeyError, IndexError, TypeError):
            del kept[where]  # inside a part set aside whole
            continue
        kept[where] = [i for i, item in zip(kept[where], parent, strict=True) if item is not _GONE]
        parent[:] = [item for item in parent if item is not _GONE]
    return doc, kept, assumed


_GONE = object()


def _names(item: object) -> Iterator[str]:
    """Every string under a ``name`` key inside ``item``."""
    if isinstance(item, dict):
        for key, value in item.items():
            if key == "name" and isinstance(value, str):
                yield value
            yield from _names(value)
    elif isinstance(item, list):
        for value in item:
            yield from _names(value)


def _renumber(loc: Loc, kept: dict[Loc, list[int]]) -> Loc:
    """``loc`` in the thinned document's numbering -> the original document's."""
    out: list[int | str] = []
    for key in loc:
        where = tuple(out)
        if isinstance(key, int) and where in kept and key < len(kept[where]):
            out.append(kept[where][key])
        else:
            out.append(key)
    return tuple(out)


def _renumber_path(path: str, kept: dict[Loc, list[int]]) -> str:
    loc = tuple(int(k) if k.isdigit() else k for k in path.split(".")) if path else ()
    return ".".join(str(k) for k in _renumber(loc, kept))


def load(path: str | os.PathLike[str]) -> Level:
    """Load a level file.

    >>> load(find("rest")).title
    'Rest'
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise LevelError(str(p), [Problem("", f"cannot read the file: {exc}")]) from None
    return loads(text, str(p))


# -- shipped levels ------------------------------------------------------------------------------

LEVELS_ENV = "PLAYGROUND_LEVELS"
"""Environment variable: extra directories of level files (os.pathsep separated)."""

LEVELS_PACKAGE = "playground.levels"
"""The package holding the shipped levels and their schema (the project's top-level ``levels/``
folder, mapped into the package when it is built)."""


def levels_dirs() -> list[Path]:
    """The extra level directories named in ``$PLAYGROUND_LEVELS`` that exist, in order."""
    dirs = [Path(d) for d in os.environ.get(LEVELS_ENV, "").split(os.pathsep) if d]
    return [d for d in dirs if d.is_dir()]


@functools.cache
def _packaged() -> dict[str, Path]:
    """The levels inside the package, as files on disk.

    ``importlib.resources`` finds them wherever the package was installed (a wheel, ``--user``,
    an editable install). A zip import has no files on disk: the levels are copied once, under
    their own names, into a temporary folder removed when the process exits.
    """
    root = importlib.resources.files(LEVELS_PACKAGE)
    items = sorted(
        (t for t in root.iterdir() if t.is_file() and t.name.endswith(".toml")),
        key=lambda t: t.name,
    )
    if all(isinstance(t, Path) for t in items):
        return {Path(str(t)).stem: Path(str(t)) for t in items}
    folder = Path(tempfile.mkdtemp(prefix="playground-levels-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    found: dict[str, Path] = {}
    for t in items:
        copy = folder / t.name
        copy.write_bytes(t.read_bytes())
        found[copy.stem] = copy
    return found


SEED_SEQUENCES = (
    "moving_platform",
    "seesaw",
    "flying_whale",
    "crusher",
    "gravity_flip",
    "null_enemy",
    "gravity_leap",
)
"""The shipped levels of the seven sequences the playground exists for (docs/design.md §1), in
that order: each must catch at least two breaks, and each has a GIF in the README."""


def shipped() -> dict[str, Path]:
    """Levels by name (file stem): those in ``$PLAYGROUND_LEVELS`` first, then the package's.

    >>> sorted(shipped())[:3]
    ['bounce', 'crusher', 'elevator']
    """
    found: dict[str, Path] = {}
    for d in levels_dirs():
        for f in sorted(d.glob("*.toml")):
            found.setdefault(f.stem, f)
    for name, path in _packaged().items():
        found.setdefault(name, path)
    return found


def find(level: str | os.PathLike[str]) -> Path:
    """A level file from a path or the name of a shipped level.

    >>> find("rest").name
    'rest.toml'
    """
    p = Path(level)
    if p.suffix == ".toml" or p.exists():
        if not p.is_file():
            raise LevelError(str(p), [Problem("", "no such level file")])
        return p
    levels = shipped()
    if str(level) in levels:
        return levels[str(level)]
    names = sorted(levels)
    raise LevelError(
        str(level),
        [
            Problem(
                "",
                f"not a file or a shipped level{_suggest(str(level), names)} "
                f"(shipped: {', '.join(names) or 'none'})",
            )
        ],
    )


def schema() -> dict[str, Any]:
    """The JSON Schema of a level file (what ``levels/level.schema.json`` holds)."""
    out = Level.model_json_schema()
    out["title"] = "playground level"
    return out
