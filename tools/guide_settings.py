"""What the settings guide moves and what it measures: the knobs (:data:`KNOBS`, each with its
default first), what a player notices of each measure (:data:`THRESHOLDS`), and one scenario's run
at one setting (:class:`Run`).

>>> [k.name for k in KNOBS][:4]
['dt', 'substeps', 'iterations', 'collision_slop']
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["COMBOS", "FRAME", "KNOBS", "THRESHOLDS", "Combo", "Knob", "Run", "value_text"]

FRAME = 1.0 / 60.0
"""s: the display frame the cost is compared with (60 Hz)."""


@dataclass(frozen=True, slots=True)
class Knob:
    """One setting the guide moves: where it lives and the values tried (the default first).

    ``where`` is ``settings`` (the level's [settings]), ``perception`` ([tracking.perception]),
    ``controller`` (every actor's controller parameters) or ``world`` (the world's config after
    building: ``sleep_time``).
    """

    name: str
    where: str
    values: tuple[float | bool, ...]
    unit: str
    what: str


KNOBS: tuple[Knob, ...] = (
    Knob("dt", "settings", (1 / 120, 1 / 60, 1 / 240), "s", "the fixed step"),
    Knob("substeps", "settings", (1, 2, 4), "", "space.step calls per step"),
    Knob("iterations", "settings", (10, 4, 20), "", "solver iterations"),
    Knob("collision_slop", "settings", (0.005, 0.001, 0.02), "m", "allowed overlap"),
    Knob("sleep_time", "world", (math.inf, 0.5), "s", "idle time before a body sleeps"),
    Knob("min_cutoff", "perception", (2.0, 1.0, 5.0), "Hz", "1€ cutoff at rest"),
    Knob("beta", "perception", (0.05, 0.0, 0.5), "s²/m", "1€ speed coefficient"),
    Knob("d_cutoff", "perception", (1.0, 0.3, 5.0), "Hz", "1€ derivative cutoff"),
    Knob("spike_filter", "perception", (True, False), "", "median-of-3 before the 1€ filter"),
    Knob("hover_frequency", "controller", (5.0, 3.0, 8.0), "Hz", "hover spring"),
    Knob("hover_damping", "controller", (1.0, 0.5, 1.5), "", "hover damping ratio ζ"),
    Knob("ride_height", "controller", (0.95, 0.9, 1.0), "m", "centre above the ground"),
    Knob("probe_radius", "controller", (0.1, 0.05, 0.2), "m", "radius of the ground probe"),
    Knob("probe_length", "controller", (1.4, 1.2, 2.0), "m", "reach of the ground probe"),
    Knob("drive_time", "controller", (0.05, 0.025, 0.1), "s", "drive's time constant"),
)
"""The knobs, each with its default first."""


@dataclass(frozen=True, slots=True)
class Combo:
    """Several knobs of :data:`KNOBS` moved together from the defaults: (knob name, value) each."""

    moves: tuple[tuple[str, float | bool], ...]

    @property
    def name(self) -> str:
        """The setting as the tables print it: ``min_cutoff = 5, beta = 0.2``."""
        return ", ".join(f"{k} = {value_text(v)}" for k, v in self.moves)


COMBOS: tuple[Combo, ...] = (
    Combo((("min_cutoff", 1.0), ("beta", 0.0))),
    Combo((("min_cutoff", 1.0), ("beta", 0.2))),
    Combo((("min_cutoff", 1.0), ("beta", 0.5))),
    Combo((("min_cutoff", 5.0), ("beta", 0.2))),
    Combo((("spike_filter", False), ("beta", 0.2))),
    Combo((("dt", 1 / 240), ("beta", 0.2))),
)
"""Knobs moved together: the filter's two against each other (the camera's lag in the ring and
room against its shake on the platform), and β with the step or without the spike stage."""


THRESHOLDS: dict[str, tuple[float, str]] = {
    "drift": (1.0, "cm"),
    "shake": (10.0, "°/s"),
    "ring up": (2.0, "°"),
    "room up": (2.0, "°"),
    "landing tilt": (5.0, "°"),
    "penetration": (5.0, "mm"),
}
"""What a player notices, per measure: a centimetre of sliding on a platform; the camera rolling
back and forth by 10 °/s RMS where nothing turns (a sixth of a degree per 60 Hz frame; the
rotating room's real turn is 14 °/s); the camera's roll off by two degrees (the ring, the room); a
landing that tips the body by five degrees; feet five millimetres inside the floor (the
default slop is 5 mm: more is visible overlap). A setting is "good" below all of them."""


@dataclass(frozen=True, slots=True)
class Run:
    """One scenario run at one setting (one knob moved from the defaults, or a :class:`Combo`).

    Attributes:
        scenario: its name.  knob: the knob moved ("defaults" for none; a combination's
            :attr:`Combo.name`).  value: its value (NaN for a combination).
        measures: measure name → value, in the units of :data:`THRESHOLDS`.
        cost_us: µs per step, median over blocks.  cost_lo, cost_hi: 10th and 90th percentiles.
        dt: the step, s.
    """

    scenario: str
    knob: str
    value: float | bool
    measures: dict[str, float]
    cost_us: float
    cost_lo: float
    cost_hi: float
    dt: float

    @property
    def frame_share(self) -> float:
        """Cost as a fraction of a 60 Hz frame: µs per step × steps per frame / frame."""
        return self.cost_us * 1e-6 * (FRAME / self.dt) / FRAME

    @property
    def label(self) -> str:
        if self.knob == "defaults" or self.combined:
            return self.knob
        return f"{self.knob} = {value_text(self.value)}"

    @property
    def combined(self) -> bool:
        """The run moved several knobs together (a :class:`Combo`)."""
        return isinstance(self.value, float) and math.isnan(self.value)


def value_text(v: float | bool) -> str:
    """A knob value as the tables print it: on/off, never, 1/120, 0.05.

    >>> value_text(1 / 120), value_text(math.inf), value_text(False), value_text(0.05)
    ('1/120', 'never', 'off', '0.05')
    """
    if isinstance(v, bool):
        return "on" if v else "off"
    if math.isinf(v):
        return "never"
    if 0 < v < 0.02 and abs(1 / v - round(1 / v)) < 1e-6:
        return f"1/{round(1 / v)}"
    return f"{v:g}"
