"""Level files: the TOML format as pydantic models, and loading with errors that say where.

A level is one TOML document: settings, gravity, static geometry, props, movers, joints, actors,
tracking, events, scripted inputs, expectations, view hints, a title and a description. Every
problem found while loading is reported at once as a :class:`LevelError` naming the file, the key
path and what was expected; an unknown key comes with the closest valid name. Quantities are SI
(m, kg, s, N, rad).

The package's modules, one concept each: the value types (:mod:`~playground.level.values`), the
tables (``settings``, ``gravity``, ``shapes``, ``paths``, ``joints``, ``bodies``, ``timeline``,
``expect``), the whole document and its schema (``document``), the errors (``errors``) and how
pydantic's are told (``explain``), the cross-references (``references``, ``expect_rules``),
loading (``loading``, ``salvage``) and where level files are (``files``).

>>> level = loads('title = "Tiny"\\ndescription = "A crate."\\n'
...               '[[props]]\\nname = "crate"\\nposition = [0, 1]\\nmass = 5\\n'
...               'shapes = [{kind = "box", size = [1, 1]}]\\n')
>>> level.props[0].mass, level.settings.dt
(5.0, 0.008333333333333333)
>>> loads('title = "x"\\ndescription = "y"\\n[settings]\\ndtt = 0.01\\n')
Traceback (most recent call last):
...
playground.level.errors.LevelError: <string>: settings.dtt: unknown key (did you mean 'dt'?)
"""

from __future__ import annotations

from playground.level.bodies import Actor, MoverModel, Patrol, Prop
from playground.level.document import SCHEMA_ID, Level, schema
from playground.level.errors import LevelError, Problem
from playground.level.expect import (
    CONTROLLER_QUANTITIES,
    FORCE_QUANTITIES,
    QUANTITIES,
    SCALAR_QUANTITIES,
    VECTOR_QUANTITIES,
    Expectation,
    Quantity,
    Reading,
)
from playground.level.files import (
    LEVELS_ENV,
    LEVELS_PACKAGE,
    SEED_SEQUENCES,
    find,
    levels_dirs,
    shipped,
)
from playground.level.gravity import (
    Gravity,
    RadialGravity,
    RotatingGravity,
    SimpleGravity,
    Turn,
    UniformGravity,
    Zone,
    ZonesGravity,
)
from playground.level.joints import (
    STATIC,
    Joint,
    Pin,
    Pivot,
    RotaryLimit,
    RotarySpring,
    Spring,
)
from playground.level.loading import load, loads, validate
from playground.level.paths import CirclePath, Elevator, Path_, Sine, Spin, Waypoints
from playground.level.settings import Perception, Settings, Tracking, View
from playground.level.shapes import Box, Capsule, CircleShape, Polygon, Ring, Segment, Shape
from playground.level.timeline import (
    BodyGravity,
    Event,
    FlipGravity,
    Impulse,
    Input,
    Nullify,
    Remove,
    RestoreGravity,
    SetGravity,
    Spawn,
)

__all__ = [
    "CONTROLLER_QUANTITIES",
    "FORCE_QUANTITIES",
    "LEVELS_ENV",
    "LEVELS_PACKAGE",
    "QUANTITIES",
    "SCALAR_QUANTITIES",
    "SCHEMA_ID",
    "SEED_SEQUENCES",
    "STATIC",
    "VECTOR_QUANTITIES",
    "Actor",
    "BodyGravity",
    "Box",
    "Capsule",
    "CirclePath",
    "CircleShape",
    "Elevator",
    "Event",
    "Expectation",
    "FlipGravity",
    "Gravity",
    "Impulse",
    "Input",
    "Joint",
    "Level",
    "LevelError",
    "MoverModel",
    "Nullify",
    "Path_",
    "Patrol",
    "Perception",
    "Pin",
    "Pivot",
    "Polygon",
    "Problem",
    "Prop",
    "Quantity",
    "RadialGravity",
    "Reading",
    "Remove",
    "RestoreGravity",
    "Ring",
    "RotaryLimit",
    "RotarySpring",
    "RotatingGravity",
    "Segment",
    "SetGravity",
    "Settings",
    "Shape",
    "SimpleGravity",
    "Sine",
    "Spawn",
    "Spin",
    "Spring",
    "Tracking",
    "Turn",
    "UniformGravity",
    "View",
    "Waypoints",
    "Zone",
    "ZonesGravity",
    "find",
    "levels_dirs",
    "load",
    "loads",
    "schema",
    "shipped",
    "validate",
]
