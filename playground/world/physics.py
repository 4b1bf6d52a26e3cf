"""The physics stage and the readings of tracked bodies: step the space, recover its forces,
filter what the bodies feel.

Three stages of the step live here. PHYSICS writes the ledger's forces, the field's forces and any
force set straight on a body before every substep (pymunk clears them after each) and steps the
space; FORCES recovers each tracked body's engine forces by reverse integration; FILTER turns them
into perceived gravity. Few tracked bodies (and with substeps, few bodies), in a field uniform in
space or one the gravity stage evaluates body by body, are served by the scalar path in plain
floats (:mod:`playground.scalar`), contact split included; the rest by numpy and ``pymunk.batch``
(:class:`~playground.forces.solver.ForceSolver`, :class:`~playground.gravity.PerceivedGravity`).
Both paths give the same readings; the state moves with a switch.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine import raw
from playground._engine.batch import BodyRows
from playground.forces.ledger import ForceLedger
from playground.forces.solver import ForceSolver
from playground.gravity import PerceivedGravity
from playground.limits import RUNAWAY_FORCE
from playground.scalar.field import PlainField
from playground.scalar.path import FieldOnBodies, ScalarPath
from playground.vec import Vec
from playground.world.config import WorldConfig
from playground.world.gravity_stage import FieldForces
from playground.world.guard import FORCE_BOUNDS, FORCE_COLUMNS, Runaway, first_bad

__all__ = ["PhysicsStage"]


class PhysicsStage:
    """The space's substeps and the tracked bodies' solver and filter, on the scalar or the batch
    path. ``replan`` is called when the tracked set changes; ``up_at`` gives a body's up until it
    feels a force."""

    def __init__(
        self,
        space: pymunk.Space,
        config: WorldConfig,
        ledger: ForceLedger,
        replan: Callable[[], None],
        up_at: Callable[[pymunk.Body], Vec],
    ) -> None:
        self.space = space
        self._space_h = raw.space_handle(space)
        self.ledger = ledger
        self._replan = replan
        self._up_at = up_at
        self.solver = ForceSolver(
            contact_split=config.contact_split, check_sleep=math.isfinite(config.sleep_time)
        )
        self.perceived = PerceivedGravity(config.perception)
        self.perceivers: set[int] = set()
        """Ids of the tracked bodies whose perceived gravity is filtered."""
        # Few tracked bodies: the scalar path serves them in plain floats (see choose_path).
        self.scalar = ScalarPath(
            contact_split=config.contact_split, check_sleep=math.isfinite(config.sleep_time)
        )
        self.scalar_on = False
        self._scalar_synced = True
        self._rows = BodyRows()
        self._all_valid: bool | None = None  # from the last batch solve, for the filter after it
        # space.step calls outside the bare path (which runs only with nothing tracked): the
        # solver's substep stamps.
        self._space_steps = 0
        self.config = config
        self.configure(config)

    def configure(self, config: WorldConfig) -> None:
        """Take new settings (the world's config changed)."""
        self.config = config
        self.solver.contact_split = config.contact_split
        self.solver.check_sleep = math.isfinite(config.sleep_time)
        self.scalar.contact_split = config.contact_split
        self.scalar.check_sleep = self.solver.check_sleep

    # -- the path --------------------------------------------------------------------------------

    def choose_path(self, max_bodies: int, plain_gravity: bool) -> None:
        """Serve the tracked bodies on the scalar path if they are at most ``max_bodies`` and
        ``plain_gravity`` (the gravity stage can hand its forces body by body, see
        :meth:`GravityStage.plain_ready`), and with substeps, the space holds at most
        ``max_bodies`` bodies (every body's force is re-applied before each substep); on the
        batch path otherwise."""
        scalar = (
            0 < len(self.solver.bodies) <= max_bodies
            and (self.config.substeps == 1 or len(self.space.bodies) <= max_bodies)
            and plain_gravity
        )
        if scalar != self.scalar_on:
            if scalar:
                self.scalar.load(self.solver, self.perceived)
                self._scalar_synced = True
            else:
                self.sync()
            self.scalar_on = scalar

    def sync(self) -> None:
        """Copy the scalar path's readings into the solver and the filter (for their readers)."""
        if self.scalar_on and not self._scalar_synced:
            self.scalar.store(self.solver, self.perceived)
            self._scalar_synced = True

    def _leave_scalar(self) -> None:
        """Hand the scalar path's state back before the tracked set or the masses change."""
        if self.scalar_on:
            self.sync()
            self.scalar_on = False
            self._replan()

    # -- the tracked bodies ----------------------------------------------------------------------

    def track(self, body: pymunk.Body, perceive: bool) -> None:
        """Recover ``body``'s engine forces every step; ``perceive`` also filters its gravity."""
        self._leave_scalar()
        old = len(self.solver.bodies)
        self.solver.track(body)
        if len(self.solver.bodies) > old:
            self.perceived.resize(np.concatenate([np.arange(old), [-1]]).astype(np.intp))
        if perceive:
            self.perceivers.add(body.id)
        self._replan()

    def untrack(self, body: pymunk.Body) -> None:
        self._leave_scalar()
        row = self.solver.row_of(body)
        assert row is not None
        n = len(self.solver.bodies)
        self.solver.untrack(body)
        self.perceived.resize(np.delete(np.arange(n), row).astype(np.intp))
        self.perceivers.discard(body.id)
        self._replan()

    def refresh_masses(self) -> None:
        """A body's mass or moment changed."""
        self.solver.refresh_masses()
        if self.scalar_on:
            self.scalar.refresh_masses()

    def runaway(self) -> Runaway | None:
        """The first tracked reading that is not finite or beyond the runaway bound, or None."""
        if self.scalar_on:
            bad = self.scalar.first_bad(RUNAWAY_FORCE)
            if bad is None:
                return None
            row, col = bad
            value = self.scalar.engine(row)[col]
            return self.solver.bodies[row].id, FORCE_COLUMNS[col], value, RUNAWAY_FORCE
        if self.solver.engine_within(RUNAWAY_FORCE):
            return None
        bad = first_bad(self.solver.engine, FORCE_BOUNDS)
        if bad is None:
            return None
        row, col = bad
        value = float(self.solver.engine[row, col])
        return self.solver.bodies[row].id, FORCE_COLUMNS[col], value, float(FORCE_BOUNDS[col])

    # -- the stages ------------------------------------------------------------------------------

    def step(self, field: FieldForces | FieldOnBodies | None) -> None:
        """PHYSICS: write the forces, step the space ``config.substeps`` times, and feed each
        substep's velocities to the solver. ``field`` is the gravity stage's force on every body
        of a field that varies in space: batch rows, or body by body on the scalar path."""
        self.ledger.flush()
        if self.scalar_on:
            assert field is None or not callable(field)
            self._step_scalar(field)
            return
        cfg = self.config
        n = cfg.substeps
        h = cfg.dt / n
        # Forces set straight on a body (``body.force``) are re-applied with the ledger's before
        # every substep, tracked or not (see WorldConfig.substeps): with substeps, read them all.
        write = False  # whether a substep after the first must write the forces again
        if field is not None and n == 1 and not self.solver.bodies and not self.solver.check_sleep:
            assert callable(field)
            self._field_only(field)
        elif field is not None or self.solver.bodies or n > 1:
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
                if self.solver.bodies:
                    # The solver tells the field's part of the force from the rest.
                    field_rows = np.zeros((len(rows.ids), 2))
                    field_rows[at] = force
            if field is not None or n > 1:
                # pymunk cleared every force after its last step: write them back only if one
                # is set.
                write = bool(rows.state[:, 3:6].any())
                if field is not None and write:
                    self._write_forces()
            if self.solver.bodies:
                self.solver.before_step(rows.ids, rows.flat, rows.width, field_rows)
        for k in range(n):
            if k > 0 and write:
                self._write_forces()
            # Chipmunk rescales warm starts by h / (its last step) when the length changes.
            rescaled = self.config.contact_split and self.space.current_time_step != h
            self.space.step(h)
            self._space_steps += 1
            if self.solver.bodies:
                ids, vel = self._rows.read_velocities(self.space)
                self.solver.after_substep(
                    self.space,
                    ids,
                    vel,
                    last=k == n - 1,
                    stamp=self._space_steps,
                    rescaled=rescaled,
                )

    def _step_scalar(self, field: FieldOnBodies | None) -> None:
        """PHYSICS on the scalar path: the rows read before the step and after each substep. With
        substeps, every force on a body is written again before each later substep."""
        cfg = self.config
        n = cfg.substeps
        h = cfg.dt / n
        space, scalar = self.space, self.scalar
        if field is not None:
            PlainField.write(field, sleeping=self.solver.check_sleep)
        scalar.before_step(field)
        self._scalar_synced = False
        held = _forces_on(space) if n > 1 else []
        split = cfg.contact_split
        for k in range(n):
            if k > 0:
                for body, held_force, held_torque in held:
                    body.force = held_force
                    body.torque = held_torque
            # Chipmunk rescales warm starts by h / (its last step) when the length changes.
            rescaled = split and raw.current_time_step(self._space_h) != h
            space.step(h)
            self._space_steps += 1
            scalar.after_substep(space, last=k == n - 1, stamp=self._space_steps, rescaled=rescaled)

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
        """Write the forces of the last batch read back, in one batch or per body if sleeping."""
        if math.isfinite(self.config.sleep_time):
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

    def solve(self) -> None:
        """FORCES: reverse integration for the tracked bodies."""
        cfg = self.config
        if self.scalar_on:
            self.scalar.finish(
                dt=cfg.dt,
                damping=cfg.damping,
                space_gravity=raw.gravity(self._space_h),
                ledger=self.ledger,
                substeps=cfg.substeps,
            )
            return
        self._all_valid = self.solver.finish(
            dt=cfg.dt,
            substeps=cfg.substeps,
            damping=cfg.damping,
            space_gravity=raw.gravity(self._space_h),
            ledger=self.ledger,
        )

    def filter(self) -> None:
        """FILTER: perceived gravity for the bodies that perceive."""
        dt = self.config.dt
        if self.scalar_on:
            self.scalar.filter(dt, self.perceived.config.up_threshold, self._up_at)
            return
        # Whether every row has a reading, as the FORCES stage of this step found (None: look).
        all_valid, self._all_valid = self._all_valid, None
        self.perceived.update(self.solver.specific, self.solver.valid, dt, all_valid=all_valid)
        if self.perceived.up_complete:
            return
        # Until a body has felt anything, its up is against the gravity field at it.
        for row in np.nonzero(~np.isfinite(self.perceived.up).all(axis=1))[0]:
            self.perceived.up[row] = self._up_at(self.solver.bodies[row])


def _forces_on(space: pymunk.Space) -> list[tuple[pymunk.Body, pymunk.Vec2d, float]]:
    """Every dynamic body with a force or torque now (N, N·m), to write again before each later
    substep (pymunk clears them after each): the others have none to re-apply, and writing
    one would restart a sleeping world's idle clock, as the batch path avoids too."""
    held = []
    for body in space.bodies:
        force, torque = body.force, body.torque
        if (force.x != 0.0 or force.y != 0.0 or torque != 0.0) and (
            body.body_type == pymunk.Body.DYNAMIC
        ):
            held.append((body, force, torque))
    return held
