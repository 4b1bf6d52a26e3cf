"""The batch implementation of the tracked bodies: every body read at once with ``pymunk.batch``,
the readings and the filter on numpy arrays, one row per tracked body.

Each numpy call costs about as much whatever the number of rows, so this serves many bodies
cheaply (the scalar implementation, :mod:`playground.forces.scalar`, serves few). One read before
the step serves the solver (:class:`~playground.forces.solver.ForceSolver`) and a field that
varies in space (its forces are added to the rows read and written back); with substeps, every
body's force is written again before each later substep, tracked or not.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Literal

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine.batch import BodyRows
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.solver import ForceSolver
from playground.gravity import PerceivedGravity
from playground.vec import Vec

if TYPE_CHECKING:
    from playground.forces.tracked import FieldForces, FieldOnBodies, Settings

__all__ = ["BatchBodies"]


class BatchBodies:
    """The tracked bodies on numpy arrays (see :class:`~playground.forces.tracked.TrackedBodies`):
    :attr:`solver` holds the rows and their readings, :attr:`perceived` their perceived gravity.

    >>> from playground.world import WorldConfig
    >>> space = pymunk.Space()
    >>> space.gravity = (0.0, -9.81)
    >>> body = pymunk.Body(2.0, 1.0)
    >>> space.add(body, pymunk.Circle(body, 0.5))
    >>> tracked = BatchBodies(space, WorldConfig())
    >>> tracked.track(body)
    >>> tracked.before_step(None, 1)
    >>> space.step(0.01)
    >>> tracked.after_substep(last=True, stamp=1, rescaled=False)
    >>> tracked.finish(
    ...     dt=0.01, substeps=1, damping=1.0, space_gravity=(0.0, -9.81), ledger=ForceLedger()
    ... )
    >>> tracked.reading(0).engine  # free fall: the engine did nothing
    (0.0, 0.0)
    """

    kind: Literal["scalar", "batch"] = "batch"
    takes_field_by_body = False

    def __init__(self, space: pymunk.Space, config: Settings) -> None:
        self.space = space
        self.solver = ForceSolver(
            contact_split=config.contact_split, check_sleep=math.isfinite(config.sleep_time)
        )
        self.perceived = PerceivedGravity(config.perception)
        self._rows = BodyRows()
        self._sleeping = math.isfinite(config.sleep_time)
        self._write = False  # whether a substep after the first writes the forces again
        self._all_valid: bool | None = None  # from the last finish, for the filter after it

    def configure(self, config: Settings) -> None:
        """Take new settings (contact split, sleeping)."""
        self.solver.contact_split = config.contact_split
        self._sleeping = math.isfinite(config.sleep_time)
        self.solver.check_sleep = self._sleeping

    def track(self, body: pymunk.Body) -> None:
        """Give ``body`` a row (no change if it has one)."""
        old = len(self.solver.bodies)
        self.solver.track(body)
        if len(self.solver.bodies) > old:
            self.perceived.resize(np.concatenate([np.arange(old), [-1]]).astype(np.intp))

    def untrack(self, body: pymunk.Body) -> None:
        """Drop ``body``'s row (the rows after it move up by one)."""
        row = self.solver.row_of(body)
        assert row is not None
        n = len(self.solver.bodies)
        self.solver.untrack(body)
        self.perceived.resize(np.delete(np.arange(n), row).astype(np.intp))

    # -- per step --------------------------------------------------------------------------------

    def before_step(self, field: FieldForces | FieldOnBodies | None, substeps: int) -> None:
        """One batch read of every body; a field's forces added to it and written back."""
        solver = self.solver
        self._write = False
        if field is not None and substeps == 1 and not solver.bodies and not solver.check_sleep:
            assert callable(field)
            self._field_only(field)
        elif field is not None or solver.bodies or substeps > 1:
            assert field is None or callable(field)
            rows = self._rows
            field_rows: NDArray[np.float64] | None = None
            if field is None:
                rows.read(self.space)
            else:
                # One read serves the field and the forces: positions come with the state.
                rows.read(self.space, positions=True)
                at, force = field(rows.ids, rows.positions)
                rows.state[at, 3:5] += force
                if solver.bodies:
                    # The solver tells the field's part of the force from the rest.
                    field_rows = np.zeros((len(rows.ids), 2))
                    field_rows[at] = force
            if field is not None or substeps > 1:
                # pymunk cleared every force after its last step: write them back only if one
                # is set.
                self._write = bool(rows.state[:, 3:6].any())
                if field is not None and self._write:
                    self._write_forces()
            if solver.bodies:
                solver.before_step(rows.ids, rows.flat, rows.width, field_rows)

    def before_substep(self) -> None:
        """Every body's force of the read before the step, written again (if one is set)."""
        if self._write:
            self._write_forces()

    def after_substep(self, *, last: bool, stamp: int, rescaled: bool) -> None:
        """Every tracked body's velocity, read in one batch call."""
        if self.solver.bodies:
            ids, vel = self._rows.read_velocities(self.space)
            self.solver.after_substep(
                self.space, ids, vel, last=last, stamp=stamp, rescaled=rescaled
            )

    def finish(
        self,
        *,
        dt: float,
        substeps: int,
        damping: float,
        space_gravity: Vec,
        ledger: ForceLedger,
    ) -> None:
        """The readings (see :meth:`ForceSolver.finish`)."""
        self._all_valid = self.solver.finish(
            dt=dt, substeps=substeps, damping=damping, space_gravity=space_gravity, ledger=ledger
        )

    def filter(self, dt: float, up_at: Callable[[pymunk.Body], Vec]) -> None:
        """Perceived gravity of every row; a row that has felt nothing yet gets ``up_at``."""
        # Whether every row has a reading, as finish found this step (None: look).
        all_valid, self._all_valid = self._all_valid, None
        perceived = self.perceived
        perceived.update(self.solver.specific, self.solver.valid, dt, all_valid=all_valid)
        if perceived.up_complete:
            return
        for row in np.nonzero(~np.isfinite(perceived.up).all(axis=1))[0]:
            perceived.up[row] = up_at(self.solver.bodies[row])

    def _field_only(self, field: FieldForces) -> None:
        """A field on untracked bodies in one substep without sleeping: positions and forces are
        all it reads, and the forces all it writes (the torques stay as they are)."""
        rows = self._rows
        forces, torques = rows.read_forces(self.space)
        at, force = field(rows.ids, rows.positions)
        forces[at] += force
        # pymunk cleared every force after its last step: write them only if one is set.
        if forces.any() or torques.any():
            rows.write_xy_forces(self.space, forces)

    def _write_forces(self) -> None:
        """Write the forces of the last read back, in one batch or per body if sleeping."""
        if self._sleeping:
            by_id = {b.id: b for b in self.space.bodies}
            for body_id, row in zip(self._rows.ids, self._rows.state, strict=True):
                body = by_id.get(int(body_id))
                # Setting a force wakes a body and restarts its idle clock: write only non-zero
                # forces (pymunk cleared the rest after the last substep).
                if (
                    body is not None
                    and body.body_type == pymunk.Body.DYNAMIC
                    and (row[3] != 0.0 or row[4] != 0.0 or row[5] != 0.0)
                ):
                    body.force = (row[3], row[4])
                    body.torque = row[5]
        else:
            self._rows.write_forces(self.space, self._rows.state[:, 3:6])

    # -- readings --------------------------------------------------------------------------------

    def reading(self, row: int) -> BodyForces:
        """The readings of a row as plain values."""
        return self.solver.reading(row)

    def perceived_gravity(self, row: int) -> Vec:
        """The filtered perceived gravity of a row, m/s²."""
        g = self.perceived.gravity[row]
        return (float(g[0]), float(g[1]))

    def perceived_up(self, row: int) -> Vec:
        """The held unit up of a row."""
        u = self.perceived.up[row]
        return (float(u[0]), float(u[1]))

    def perceived_up_and_gravity(self, row: int) -> tuple[Vec, Vec]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of a row in one call."""
        u = self.perceived.up[row]
        g = self.perceived.gravity[row]
        return (float(u[0]), float(u[1])), (float(g[0]), float(g[1]))

    def runaway(self, bound: float) -> tuple[int, int, float] | None:
        """The first engine force component (column 0: x, 1: y) that is not finite or beyond
        ±``bound`` (N), as (body id, column, value), or None: a quick pass over the contiguous
        readings (torques included) first, a closer look only when it fails."""
        solver = self.solver
        if solver.engine_within(bound):
            return None
        engine = solver.engine
        bad = ~(np.abs(engine) <= bound)  # NaN compares False
        if not bad.any():
            return None
        row, col = np.argwhere(bad)[0]
        return solver.bodies[row].id, int(col), float(engine[row, col])

    def table(self) -> TrackedReadings:
        """Every row's readings as arrays (copies)."""
        s, p = self.solver, self.perceived
        return TrackedReadings(
            bodies=tuple(s.bodies),
            valid=s.valid.copy(),
            engine=s.engine.copy(),
            engine_torque=s.engine_torque.copy(),
            support=s.support.copy(),
            specific=s.specific.copy(),
            passive=s.passive.copy(),
            applied=s.applied.copy(),
            contact=s.contact.copy(),
            contact_normal=s.contact_normal.copy(),
            constraint=s.constraint.copy(),
            split_valid=s.split_valid.copy(),
            perceived_gravity=p.gravity.copy(),
            perceived_up=p.up.copy(),
        )
