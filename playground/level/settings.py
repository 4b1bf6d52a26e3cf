"""The simulation settings, the tracking and perception tables and the view hints of a level."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from playground import limits
from playground.level.values import Frequency, Name, NonNegative, Positive, Table, Vec, Whole


class Settings(Table):
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


class Perception(Table):
    """How perceived gravity is filtered (see :class:`playground.Perception`)."""

    min_cutoff: Frequency = Field(default=2.0, description="1€ minimum cutoff, Hz.")
    beta: NonNegative = Field(default=0.05, description="1€ speed coefficient.")
    d_cutoff: Frequency = Field(default=1.0, description="1€ derivative cutoff, Hz.")
    spike_filter: bool = Field(default=True, description="Median-of-3 stage before the 1€ filter.")
    up_threshold: Positive = Field(default=1.0, description="Below this |g| (m/s²) up is held.")


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
