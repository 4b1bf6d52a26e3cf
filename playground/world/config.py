"""The world's settings: :class:`WorldConfig`, frozen and checked when made.

>>> WorldConfig(substeps=2).dt
0.008333333333333333
>>> WorldConfig(dt=0.0)
Traceback (most recent call last):
...
ValueError: dt: expected a number in [0.0001, 0.1] s, got 0.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from playground.gravity import Perception
from playground.limits import MAX_DT, MAX_ITERATIONS, MAX_LENGTH, MAX_SUBSTEPS, MIN_DT
from playground.params import check, param

__all__ = ["WorldConfig"]


@dataclass(frozen=True, slots=True)
class WorldConfig:
    """Simulation settings, frozen; each field's doc, unit and bounds are declared with it.

    ``substeps``: every force and torque on a body when the step starts acts for the whole step,
    as over one ``space.step(dt)``: those applied through the world and those set straight on a
    pymunk body (``body.force``), tracked or not. pymunk clears forces after each ``space.step``,
    so the world re-applies them before each substep.

    ``collision_slop``: pymunk's default 0.1 is meant for pixels: in metres it lets a body sink
    10 cm into the floor. 5 mm is invisible at human scale and still large enough to keep resting
    contacts persistent (no jitter).

    ``sleep_time``: with sleeping on, the solver checks each tracked body for sleep (per-body
    Python) and forces are written per body rather than in one batch.

    ``guard``: off only to watch a blow-up on purpose; then :meth:`World.apply_force` takes any
    finite force.
    """

    dt: float = param(1.0 / 120.0, doc="Fixed step.", unit="s", ge=MIN_DT, le=MAX_DT)
    substeps: int = param(1, doc="space.step calls per step.", ge=1, le=MAX_SUBSTEPS)
    iterations: int = param(10, doc="Solver iterations per substep.", ge=1, le=MAX_ITERATIONS)
    damping: float = param(
        1.0, doc="Fraction of velocity kept per second (1: none).", gt=0.0, le=1.0
    )
    collision_slop: float = param(
        0.005, doc="Allowed overlap of shapes.", unit="m", ge=0.0, le=MAX_LENGTH
    )
    sleep_time: float = param(
        math.inf,
        doc="Idle time before bodies fall asleep (inf: never).",
        unit="s",
        gt=0.0,
        inf=True,
    )
    contact_split: bool = param(
        False,
        doc="Split engine forces into contact and constraint readings (a batch read of "
        "every arbiter per substep).",
    )
    timing: bool = param(
        False,
        doc="Time each stage (two perf_counter calls a stage; docs/performance.md, stage_timer).",
    )
    guard: bool = param(
        True, doc="Stop with RunawayError when a body goes non-finite or runs away."
    )
    perception: Perception = param(
        doc="How perceived gravity is filtered.", default_factory=Perception
    )

    def __post_init__(self) -> None:
        check(self)
