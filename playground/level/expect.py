"""Expectations: the checks a level makes on its bodies' quantities, and the quantities."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, Strict, field_validator

from playground.level.values import Finite, Name, NonNegative, Table, Vec
from playground.quantities import CHECKED

QUANTITIES = tuple(q.name for q in CHECKED)
"""Every quantity an expectation reads (:mod:`playground.quantities`), in the order the schema
lists them."""
SCALAR_QUANTITIES = tuple(q.name for q in CHECKED if q.kind == "scalar")
"""Quantities that are numbers: angle (rad), angular velocity (rad/s), tilt (rad, 0..π)."""
VECTOR_QUANTITIES = tuple(q.name for q in CHECKED if q.kind == "vector")
"""Quantities that are (x, y) vectors; pick a ``component`` or compare the vector."""
FORCE_QUANTITIES = tuple(q.name for q in CHECKED if q.source == "solver")
"""Force readings of the solver, N; ``filtered = true`` gives the 1€-filtered reading."""
CONTROLLER_QUANTITIES = tuple(q.name for q in CHECKED if q.source == "controller")
"""An actor's own readings of the forces its controller put on it in the last step, N (the
grip: the joint's force the step before)."""

if TYPE_CHECKING:
    Quantity = str
else:
    # The names above, as the enum of the schema (a Literal of a tuple is a Literal of its items).
    Quantity = Literal[QUANTITIES]


class Reading(Table):
    """Another reading taken the same step: ``scale`` × ``body``'s ``quantity``."""

    body: Name
    quantity: Quantity
    scale: Finite = Field(default=1.0, description="Multiplies the reading (−1 flips it).")


class Expectation(Table):
    """A check on one body's quantity.

    ``check``: ``at`` time ``t``; ``always`` / ``eventually`` / ``mean`` over ``window`` (default
    the whole run); ``impulse``, a force's integral over the window (N·s: each step's reading,
    the step's mean force, times dt, over the steps after the window's start). Compare with
    ``equals`` (± ``tolerance`` + ``relative``·|equals|), or bound with ``above`` / ``below``; a
    state compares with ``equals`` or ``one_of``.

    The value compared is the quantity, minus the same quantity of ``relative_to``, minus the
    reading ``minus`` (another body's force, say), filtered if asked; then, with ``angle_to``,
    the angle between that vector and a fixed vector or another reading (its direction, rad).

    A force check may state its numbers in a body's own terms, so that it reads the same at any
    mass: with ``weights_of = "player"``, ``equals``, ``tolerance``, ``above`` and ``below``
    count weights m·g₀ of that body (``equals = [0.0, 1.0]``: one weight, straight up); with
    ``per_mass_of = "player"`` they are newtons per kilogram of it, an acceleration
    (``equals = [0.0, 10.81]``: m·(g + a) with g + a = 10.81 m/s²). An ``impulse`` counts
    weight-seconds, or N·s per kilogram, a speed (``equals = [0.0, 4.0]``: m·v with v = 4 m/s).
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
    check: Literal["at", "always", "eventually", "mean", "impulse"] = "at"
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
    weights_of: Name | None = Field(
        default=None,
        description="A force check's numbers (equals, tolerance, above, below) count weights "
        "of this body, m·g₀ with g₀ = 9.81 m/s² (the standard gravity the controller's budgets "
        "are in): the same check at any mass. Default: newtons.",
    )
    per_mass_of: Name | None = Field(
        default=None,
        description="A force check's numbers (equals, tolerance, above, below) are newtons per "
        "kilogram of this body, m/s² (m·(g + a) is g + a): the same check at any mass. "
        "Default: newtons.",
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
