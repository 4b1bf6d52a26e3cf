"""The simulation settings, the tracking and perception tables and the view hints of a level."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from playground import limits
from playground.gravity import perception
from playground.level.derive import Derived
from playground.level.values import Name, NonNegative, Positive, Table, Vec
from playground.world.config import WorldConfig


class Settings(Derived):
    """Simulation settings: the :class:`playground.WorldConfig` keys a level sets, and the run's
    length."""

    __core__ = WorldConfig
    __only__ = ("dt", "substeps", "iterations", "damping", "collision_slop", "contact_split")

    # Its own bounded type: an outer ``le`` does not narrow the ``le`` of an Annotated type.
    seconds: Annotated[float, Field(gt=0.0, le=limits.MAX_SECONDS, allow_inf_nan=False)] = Field(
        default=3.0,
        description="Length of a run (at most an hour, as `playground run` allows without --long).",
        json_schema_extra={"unit": "s"},
    )


class Perception(Derived):
    """How perceived gravity is filtered (see :class:`playground.Perception`)."""

    __core__ = perception.Perception


class Tracking(Table):
    """Which bodies the force solver tracks (actors always are) and how they are filtered."""

    bodies: list[Name] = Field(default_factory=list, description="Tracked prop names.")
    perceive: bool = Field(default=True, description="Filter perceived gravity for tracked bodies.")
    perception: Perception = Field(default_factory=lambda: Perception())


class View(Table):
    """Hints for the desktop view."""

    camera: Vec = Field(default=(0.0, 0.0), description="Camera centre at start, m.")
    pixels_per_metre: Positive = Field(default=50.0, le=10000.0, description="Zoom, px/m.")
    follow: Name | None = Field(
        default=None, description="Body the camera follows; default: the first actor, if any."
    )
    roll: bool = Field(default=False, description="Roll the camera with the followed body's up.")
    fixed: bool = Field(
        default=False,
        description="Keep the camera still at `camera` instead of following a body: for a "
        "level whose claim is motion, seen against the world's grid.",
    )
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
