"""The tracked bodies: one interface (:class:`TrackedBodies`) for the two ways of serving them, and
the set (:class:`TrackedSet`) that keeps who is tracked and which way serves them.

The scalar implementation (:class:`~playground.forces.scalar.ScalarBodies`) reads each body's
attributes and computes in plain floats: cheapest for few bodies. The batch implementation
(:class:`~playground.forces.batch.BatchBodies`) reads every body at once with ``pymunk.batch``
and computes on numpy arrays: cheapest for many. Both give the same readings; the set hands the
state from one to the other when the plan changes, so a run has one answer whichever served it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Literal, Protocol

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground.forces.batch import BatchBodies
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.scalar.bodies import SCALAR_MAX_BODIES, ScalarBodies
from playground.gravity import Perception
from playground.vec import Vec

__all__ = [
    "SCALAR_MAX_BODIES",
    "FieldForces",
    "FieldOnBodies",
    "Settings",
    "TrackedBodies",
    "TrackedSet",
]

FieldForces = Callable[
    [NDArray[np.uintp], NDArray[np.float64]],
    tuple[NDArray[np.intp] | slice, NDArray[np.float64]],
]
"""A field that varies in space, at the bodies of one batch read: given the read's body ids and
their (x, y) rows (m), the rows that are named dynamic bodies (their indices, or a slice when
they are one run) and the field's force (N) on each. The batch implementation takes this form."""

FieldOnBodies = Mapping[pymunk.Body, Vec]
"""A field's force (N) on each body it acts on this step. The scalar implementation takes this
form."""

UpAt = Callable[[pymunk.Body], Vec]
"""A body's up (unit vector) until it has felt a reading strong enough to define one."""


class Settings(Protocol):
    """What the tracked bodies read of their owner's settings when they are built (see
    :class:`~playground.world.WorldConfig`): the contact split, the sleep time (s; ∞: bodies
    never sleep) and the perception; the step's length, substeps and damping come with each
    step."""

    @property
    def contact_split(self) -> bool: ...
    @property
    def sleep_time(self) -> float: ...
    @property
    def perception(self) -> Perception: ...


class TrackedBodies(Protocol):
    """One way of serving the tracked bodies through a step of the space.

    The physics stage calls :meth:`before_step` once, then for each substep
    :meth:`before_substep` (from the second on), ``space.step`` and :meth:`after_substep`; the
    FORCES stage calls :meth:`finish` and the FILTER stage :meth:`filter`. The readers read rows
    (a body's row: :meth:`TrackedSet.row_of`) and change nothing.
    """

    kind: Literal["scalar", "batch"]
    """Which implementation this is, for benchmarks and tests (nothing else asks)."""

    takes_field_by_body: bool
    """Whether :meth:`before_step` takes a field's force as :data:`FieldOnBodies` (else as
    :data:`FieldForces`)."""

    def before_step(self, field: FieldForces | FieldOnBodies | None, substeps: int) -> None:
        """Add a field's force (N) to the bodies, and read the velocities and forces about to
        be integrated."""

    def before_substep(self) -> None:
        """Write the forces again before a substep after the first (pymunk clears them)."""

    def after_substep(self, *, last: bool, stamp: int, rescaled: bool) -> None:
        """Read the velocities after a substep (``stamp`` counts the space's steps, 1 for its
        first; ``rescaled``: Chipmunk rescaled its warm starts for a new substep length)."""

    def finish(
        self,
        *,
        dt: float,
        substeps: int,
        damping: float,
        space_gravity: Vec,
        ledger: ForceLedger,
    ) -> None:
        """The step's readings by reverse integration (``dt`` s, ``space_gravity`` m/s²)."""

    def filter(self, dt: float, up_at: UpAt) -> None:
        """Perceived gravity after :meth:`finish` (``dt`` s): −specific force, filtered."""

    def reading(self, row: int) -> BodyForces:
        """The last readings of a row as plain values."""

    def perceived_gravity(self, row: int) -> Vec:
        """The filtered perceived gravity of a row, m/s²."""

    def perceived_up(self, row: int) -> Vec:
        """The held unit up of a row."""

    def perceived_up_and_gravity(self, row: int) -> tuple[Vec, Vec]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of a row in one call."""

    def runaway(self, bound: float) -> tuple[int, int, float] | None:
        """The first engine force component (column 0: x, 1: y) that is not finite or beyond
        ±``bound`` (N), as (body id, column, value), or None."""

    def table(self) -> TrackedReadings:
        """Every row's readings as arrays (copies)."""


class TrackedSet:
    """The tracked bodies of one space, in rows (the order they were tracked), and the
    implementation that serves them (:attr:`active`), chosen by :meth:`plan`.

    ``replan`` is called when the set changes (the plan may choose again).
    """

    def __init__(self, space: pymunk.Space, config: Settings, replan: Callable[[], None]) -> None:
        self._replan = replan
        check_sleep = math.isfinite(config.sleep_time)
        self._batch = BatchBodies(space, config)
        self._scalar = ScalarBodies(
            space, contact_split=config.contact_split, check_sleep=check_sleep
        )
        self.active: TrackedBodies = self._batch
        """The implementation serving the tracked bodies in the coming steps."""
        self.bodies: list[pymunk.Body] = self._batch.solver.bodies
        """The tracked bodies in row order (the solver's list itself, kept in place: read it,
        do not change it)."""
        self.perceivers: set[int] = set()
        """Ids of the tracked bodies whose perceived gravity is filtered."""
        self.version = 0
        """Counts the changes of the rows (a body tracked or untracked): rows looked up at one
        version hold until the next."""

    def row_of(self, body: pymunk.Body, body_id: int | None = None) -> int | None:
        """The row of a tracked body, or None. ``body_id``: its ``body.id`` if the caller has
        it (reading it is a call into Chipmunk)."""
        return self._batch.solver.row_of(body, body_id)

    def perceived_block(
        self, rows: NDArray[np.intp]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The held unit up and the filtered perceived gravity (m/s²) of ``rows``, (k, 2) each:
        the values :meth:`TrackedBodies.perceived_up_and_gravity` gives row by row."""
        if self.active is self._batch:
            perceived = self._batch.perceived
            return perceived.up[rows], perceived.gravity[rows]
        table = self._scalar.rows
        picked = [table[i] for i in rows.tolist()]
        up = np.array([(r.ux, r.uy) for r in picked], dtype=np.float64).reshape(-1, 2)
        gravity = np.array([(r.gx, r.gy) for r in picked], dtype=np.float64).reshape(-1, 2)
        return up, gravity

    def configure(self, config: Settings) -> None:
        """Take new settings (contact split, sleeping; the rest is read every step)."""
        self._batch.configure(config)
        self._scalar.contact_split = config.contact_split
        self._scalar.check_sleep = math.isfinite(config.sleep_time)

    def tune(self, perception: Perception) -> None:
        """Re-tune the filter (1€ parameters, up threshold), keeping its state."""
        self._batch.perceived.tune(perception)
        self._scalar.threshold = perception.up_threshold

    def plan(self, max_bodies: int, plain_gravity: bool, substeps: int) -> None:
        """Serve the tracked bodies with the scalar implementation if they are at most
        ``max_bodies`` and ``plain_gravity`` (the gravity stage can hand its forces body by
        body), and with ``substeps`` > 1, the space holds at most ``max_bodies`` bodies (every
        body's force is written again before each substep); with the batch implementation
        otherwise."""
        scalar = (
            0 < len(self.bodies) <= max_bodies
            and (substeps == 1 or len(self._batch.space.bodies) <= max_bodies)
            and plain_gravity
        )
        if scalar == (self.active is self._scalar):
            return
        if scalar:
            self._scalar.load(self._batch.solver, self._batch.perceived)
            self.active = self._scalar
        else:
            self._scalar.store(self._batch.solver, self._batch.perceived)
            self.active = self._batch

    def _to_batch(self) -> None:
        """Hand the state back to the batch implementation before the rows change."""
        if self.active is self._scalar:
            self._scalar.store(self._batch.solver, self._batch.perceived)
            self.active = self._batch
            self._replan()

    def track(self, body: pymunk.Body, perceive: bool) -> None:
        """Recover ``body``'s engine forces every step; ``perceive`` also filters its gravity."""
        self._to_batch()
        self._batch.track(body)
        if perceive:
            self.perceivers.add(body.id)
        self.version += 1
        self._replan()

    def untrack(self, body: pymunk.Body) -> None:
        """Stop tracking ``body`` (the rows after it move up by one)."""
        self._to_batch()
        self._batch.untrack(body)
        self.perceivers.discard(body.id)
        self.version += 1
        self._replan()

    def refresh_masses(self) -> None:
        """A body's mass or moment changed."""
        self._batch.solver.refresh_masses()
        if self.active is self._scalar:
            self._scalar.refresh_masses()
