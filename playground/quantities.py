"""Quantities: every reading of a body, named once — its name, SI unit, kind and where it comes
from, and what uses it.

A level's expectations check them (the level's ``quantity`` enum is :data:`CHECKED`), a recording
stores them (its columns are each quantity's :attr:`Quantity.columns`, in this table's order) and
``playground run --json`` reports them (:attr:`Quantity.report`). This is the vocabulary only:
reading a quantity needs a built scene (:mod:`playground.scene.readings`). Units are SI.

>>> QUANTITIES["support"].unit, QUANTITIES["support"].kind, QUANTITIES["support"].source
('N', 'vector', 'solver')
>>> [c for q in RECORDED for c in q.columns][:6]
['x', 'y', 'vx', 'vy', 'angle', 'engine_x']
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

__all__ = [
    "CHECKED",
    "QUANTITIES",
    "RECORDED",
    "REPORTED",
    "Kind",
    "Quantity",
    "Source",
    "Value",
]

Value = float | tuple[float, float] | str | None
"""A reading: a number, an (x, y) vector, a name (a state), or None (the body has none)."""

Kind = Literal["vector", "scalar", "text"]
Source = Literal["body", "scene", "solver", "perception", "controller"]
"""Where a reading comes from: the pymunk body; the scene (tilt, state); the force solver (the
body must be tracked); perception (tracked and perceived); the body's controller (an actor)."""


@dataclass(frozen=True, slots=True)
class Quantity:
    """One reading of a body.

    Attributes:
        name: the key a level, a recording and the report use.
        unit: its SI unit ("" for a name).
        kind: a vector (x, y), a scalar, or text.
        source: where it is read from (what the body must be for it to exist).
        doc: what it is.
        columns: its columns in a recording, in order; none: not recorded.
        report: where ``run --json`` puts it: "" at the body's top level, "force" in its
            ``force`` object; None: not reported.
        checked: whether a level's expectations may check it.
        split: it exists only where the engine's forces are split (``settings.contact_split``).
    """

    name: str
    unit: str
    kind: Kind
    source: Source
    doc: str
    columns: tuple[str, ...] = ()
    report: str | None = None
    checked: bool = True
    split: bool = False


def _xy(name: str) -> tuple[str, str]:
    return (f"{name}_x", f"{name}_y")


def _force(name: str, doc: str, *, recorded: bool = True, split: bool = False) -> Quantity:
    """A force reading of the solver, N, recorded and reported under ``force`` unless not."""
    return Quantity(
        name,
        "N",
        "vector",
        "solver",
        doc,
        columns=_xy(name) if recorded else (),
        report="force" if recorded else None,
        split=split,
    )


def _own(name: str, doc: str) -> Quantity:
    """An actor's own reading of the force its controller put on it in the last step, N."""
    return Quantity(name, "N", "vector", "controller", doc)


_TABLE = (
    Quantity("mass", "kg", "scalar", "body", "the body's mass", report="", checked=False),
    Quantity(
        "position",
        "m",
        "vector",
        "body",
        "the body's position (its origin), world frame",
        columns=("x", "y"),
        report="",
    ),
    Quantity(
        "velocity",
        "m/s",
        "vector",
        "body",
        "the body's velocity",
        columns=("vx", "vy"),
        report="",
    ),
    Quantity(
        "angle",
        "rad",
        "scalar",
        "body",
        "the body's angle, counter-clockwise",
        columns=("angle",),
        report="",
    ),
    Quantity(
        "angular_velocity",
        "rad/s",
        "scalar",
        "body",
        "the body's spin, counter-clockwise",
    ),
    Quantity("tilt", "rad", "scalar", "scene", "angle between the body's axis and its up, 0..π"),
    Quantity(
        "up",
        "",
        "vector",
        "scene",
        "the body's up (unit): its controller's, else its perceived one",
    ),
    _force("engine", "the engine's total force on the body (contacts and joints)"),
    _force("contact", "the contacts' force", split=True),
    _force("contact_normal", "the contacts' normal force", recorded=False, split=True),
    _force("contact_friction", "the contacts' friction force", recorded=False, split=True),
    _force("constraint", "the joints' force", split=True),
    _force(
        "support", "the engine's force plus the controller's support forces (hover, drive, grip)"
    ),
    Quantity(
        "support_filtered",
        "N",
        "vector",
        "perception",
        "the 1€-filtered support force, −m · perceived gravity",
        columns=_xy("support_filtered"),
        report="force",
        checked=False,
    ),
    Quantity(
        "perceived_gravity",
        "m/s²",
        "vector",
        "perception",
        "the gravity the body feels through its support (1€-filtered)",
        columns=_xy("perceived_gravity"),
        report="",
    ),
    _own("hover", "the hover spring's force"),
    _own("drive", "the drive's force along the ground"),
    _own("grip", "the grip joint's force (the step before)"),
    _own("push", "the push on the body in contact"),
    Quantity(
        "state",
        "",
        "text",
        "scene",
        "the controller's state (grounded, airborne, …); none for a body without one",
        columns=("state",),
        report="",
    ),
)

QUANTITIES: dict[str, Quantity] = {q.name: q for q in _TABLE}
"""Every quantity by name, in the table's order."""
CHECKED = tuple(q for q in _TABLE if q.checked)
"""What a level's expectations may check, in the order the schema lists them."""
RECORDED = tuple(q for q in _TABLE if q.columns)
"""What a recording stores, in its columns' order."""
REPORTED = tuple(q for q in _TABLE if q.report is not None)
"""What ``run --json`` reports for each tracked body, in its keys' order."""
