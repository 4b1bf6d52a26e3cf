"""The runtime guard: a world that goes non-finite or runs away stops with an error naming the body.

At the end of a step the world checks the force readings of its tracked bodies, and every
:data:`GUARD_EVERY` steps the position, velocity, angle and turning rate of every body, against the
runaway bounds of :mod:`playground.limits`. A value beyond them (or NaN, or ∞) raises
:class:`RunawayError` before readings, recordings or the view see it.

>>> import numpy as np
>>> rows = np.array([[0.0, 1.0, 0.0, 0.0, 0.0, 0.0], [2.0, np.nan, 0.0, 0.0, 0.0, 0.0]])
>>> first_bad(rows, STATE_BOUNDS)
(1, 1)
"""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

from playground.limits import RUNAWAY_FORCE, RUNAWAY_POSITION, RUNAWAY_SPEED

__all__ = [
    "FORCE_BOUNDS",
    "FORCE_COLUMNS",
    "GUARD_EVERY",
    "STATE_BOUNDS",
    "STATE_COLUMNS",
    "Runaway",
    "RunawayError",
    "first_bad",
    "state_runaway",
]

GUARD_EVERY = 256
"""Steps between checks of every body's state (about two seconds at 1/120 s): one batch read of
every body costs a fixed price close to a bare step of a small scene, so checked this rarely it
is lost in the noise even there (docs/performance.md, "The small costs", guard_check).
Tracked bodies' force readings are checked every step; a blow-up grows by orders of magnitude per
step, so a body that is not tracked is caught within this many steps, before anyone reads it (only
tracked bodies have readings and recordings, and the view clamps what it draws)."""

STATE_COLUMNS = (
    ("position", "x", "m"),
    ("position", "y", "m"),
    ("angle", "", "rad"),
    ("velocity", "x", "m/s"),
    ("velocity", "y", "m/s"),
    ("angular velocity", "", "rad/s"),
)
"""What each column of a state row is: quantity, component, unit."""

STATE_BOUNDS = np.array(
    [
        RUNAWAY_POSITION,
        RUNAWAY_POSITION,
        # An angle grows without bound while a body spins: only finiteness is checked.
        np.finfo(np.float64).max,
        RUNAWAY_SPEED,
        RUNAWAY_SPEED,
        RUNAWAY_SPEED,
    ]
)
"""Largest magnitude of each state column."""

FORCE_COLUMNS = (("engine force", "x", "N"), ("engine force", "y", "N"))
"""The force readings checked every step."""

FORCE_BOUNDS = np.array([RUNAWAY_FORCE, RUNAWAY_FORCE])

Runaway = tuple[int, tuple[str, str, str], float, float]
"""A value out of bounds: the body's id, its column (quantity, component, unit), value, bound."""

_F = batch.BodyFields
_STATE = _F.BODY_ID | _F.POSITION | _F.ANGLE | _F.VELOCITY | _F.ANGULAR_VELOCITY
"""The state read: x, y, angle, vx, vy, w per body (batch packs fields in this order)."""

_CAUSES = {
    "position": "the solver blew up (a joint anchored far from its bodies, a spring too stiff "
    "for dt, a huge mass ratio), or the body has been falling through empty space for a long time",
    "angle": "the solver blew up (see the velocity)",
    "velocity": "a force, impulse or spring far too strong for the body's mass at this dt, or a "
    "joint or contact fighting a huge mass ratio (lower dt, raise substeps, bring masses closer)",
    "angular velocity": "a torque, off-centre force or joint far too strong for the body's moment "
    "of inertia at this dt",
    "engine force": "a contact or joint holding against a huge mass ratio, bodies spawned inside "
    "each other pushed apart at once, or a spring too stiff for this dt",
}


class RunawayError(RuntimeError):
    """A body's state left the plausible ranges during a step.

    Attributes:
        body: the body's name (or a description of an unnamed one).
        step: the step that produced the value (1 is the first).
        time: simulated time at the end of that step, s.
        quantity: ``"position"``, ``"velocity"``, ``"engine force"``, …
        value: the offending component's value.
    """

    def __init__(
        self,
        body: str,
        step: int,
        time: float,
        column: tuple[str, str, str],
        value: float,
        bound: float,
    ) -> None:
        quantity, component, unit = column
        self.body = body
        self.step = step
        self.time = time
        self.quantity = quantity
        self.value = value
        what = f"{quantity} {component}".rstrip()
        if math.isfinite(value):
            problem = f"{value:.3g} {unit} is beyond the runaway bound ±{bound:g} {unit}"
        else:
            problem = f"is {value} (not finite)"
        super().__init__(
            f"step {step} (t = {time:.6g} s): {body}: {what} {problem}; "
            f"likely cause: {_CAUSES[quantity]}"
        )


def first_bad(rows: NDArray[np.float64], bounds: NDArray[np.float64]) -> tuple[int, int] | None:
    """The (row, column) of the first value that is not finite or beyond its column's bound."""
    ok = np.abs(rows) <= bounds  # NaN compares False
    if ok.all():
        return None
    row, col = np.argwhere(~ok)[0]
    return int(row), int(col)


def state_runaway(space: pymunk.Space, buffer: batch.Buffer) -> Runaway | None:
    """The first body of ``space`` whose position, angle or velocity is not finite or beyond
    :data:`STATE_BOUNDS`, or None (``buffer`` is reused for the read)."""
    buffer.clear()
    batch.get_space_bodies(space, _STATE, buffer)
    rows = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 6)
    bad = first_bad(rows, STATE_BOUNDS)
    if bad is None:
        return None
    row, col = bad
    body_id = int(np.frombuffer(buffer.int_buf(), dtype=np.uintp)[row])
    return body_id, STATE_COLUMNS[col], float(rows[row, col]), float(STATE_BOUNDS[col])
