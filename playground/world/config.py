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
from dataclasses import dataclass, field

from playground._validate import finite, in_range
from playground.limits import MAX_DT, MIN_DT
from playground.perception import Perception

__all__ = ["WorldConfig"]


@dataclass(frozen=True, slots=True)
class WorldConfig:
    """Simulation settings, frozen.

    Attributes:
        dt: the fixed step, s, within [``MIN_DT``, ``MAX_DT``] of :mod:`playground.limits`.
        substeps: ``space.step`` calls per step (each of dt/substeps). Every force and torque
            on a body when the step starts acts for the whole step, as over one
            ``space.step(dt)``: those applied through the world and those set straight on a
            pymunk body (``body.force``), tracked or not. pymunk clears forces after each
            ``space.step``, so the world re-applies them before each substep.
        iterations: the contact/joint solver's iterations per substep.
        damping: fraction of velocity kept after one second (pymunk's convention; 1 = none).
        collision_slop: allowed overlap, m. pymunk's default 0.1 is meant for pixels: in metres
            it lets a body sink 10 cm into the floor. 5 mm is invisible at human scale and still
            large enough to keep resting contacts persistent (no jitter).
        sleep_time: idle time before bodies fall asleep, s (inf: never). With sleeping on, the
            solver checks each tracked body for sleep (per-body Python) and forces are written
            per body rather than in one batch.
        contact_split: also split engine forces into contacts and constraints (costs a batch
            read of every arbiter per substep).
        timing: time each stage (off by default: ``perf_counter`` calls cost ~1 µs a stage).
        guard: stop with :class:`~playground.guard.RunawayError` when a body goes non-finite or
            runs away (see :mod:`playground.guard`). Off only to watch a blow-up on purpose; then
            :meth:`World.apply_force` takes any finite force.
        perception: how perceived gravity is filtered.
    """

    dt: float = 1.0 / 120.0
    substeps: int = 1
    iterations: int = 10
    damping: float = 1.0
    collision_slop: float = 0.005
    sleep_time: float = math.inf
    contact_split: bool = False
    timing: bool = False
    guard: bool = True
    perception: Perception = field(default_factory=Perception)

    def __post_init__(self) -> None:
        in_range("dt", self.dt, MIN_DT, MAX_DT, "s")
        for name in ("substeps", "iterations"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise ValueError(f"{name}: expected an integer >= 1, got {value!r}")
        finite("damping", self.damping)
        if not 0.0 < self.damping <= 1.0:
            raise ValueError(f"damping: expected a number in (0, 1], got {self.damping!r}")
        finite("collision_slop", self.collision_slop)
        if self.collision_slop < 0.0:
            raise ValueError(
                f"collision_slop: expected a number >= 0 m, got {self.collision_slop!r}"
            )
        if not self.sleep_time > 0.0:
            raise ValueError(
                f"sleep_time: expected a number of seconds > 0, got {self.sleep_time!r}"
            )
