"""The physics stage and the tracked bodies' stages: step the space, recover its forces, filter
what the bodies feel.

Three stages of the step live here. PHYSICS writes the ledger's forces, the field's forces and any
force set straight on a body before every substep (pymunk clears them after each), steps the
space and, after each substep but the last, calls the substep readers (what pymunk keeps only
for the substep just run, a contact's impulse, they add up for the step's mean); FORCES
recovers each tracked body's engine forces by reverse integration; FILTER turns them into
perceived gravity. The tracked bodies (:class:`~playground.forces.tracked.TrackedSet`) are
served by whichever implementation the world's plan chose; this stage calls them through their
one interface (:class:`~playground.forces.tracked.TrackedBodies`).
"""

from __future__ import annotations

from collections.abc import Callable

import pymunk

from playground._engine import raw
from playground.forces.ledger import ForceLedger
from playground.forces.tracked import FieldForces, FieldOnBodies, TrackedSet
from playground.vec import Vec
from playground.world.config import WorldConfig

__all__ = ["PhysicsStage"]


class PhysicsStage:
    """The space's substeps and the tracked bodies' solver and filter. ``replan`` is called when
    the tracked set changes; ``up_at`` gives a body's up until it feels a force."""

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
        self._up_at = up_at
        self.tracked = TrackedSet(space, config, replan)
        # space.step calls outside the bare step (which runs only with nothing tracked): the
        # stamps of the substeps for the contact split.
        self._space_steps = 0
        self.config = config
        self.substep_readers: list[Callable[[], None]] = []
        """Called after each substep of a step but the last (none with one substep); each
        reads the engine and changes nothing (``World.on_substep``)."""

    def configure(self, config: WorldConfig) -> None:
        """Take new settings (the world's config changed)."""
        self.config = config
        self.tracked.configure(config)

    # -- the stages ------------------------------------------------------------------------------

    def step(self, field: FieldForces | FieldOnBodies | None) -> None:
        """PHYSICS: write the forces, step the space ``config.substeps`` times, and feed each
        substep's velocities to the tracked bodies. ``field`` is the gravity stage's force on
        every body of a field that varies in space, in the form the tracked bodies take."""
        self.ledger.flush()
        cfg = self.config
        n = cfg.substeps
        h = cfg.dt / n
        tracked = self.tracked.active
        tracked.before_step(field, n)
        split = cfg.contact_split
        space, space_h = self.space, self._space_h
        readers = self.substep_readers
        for k in range(n):
            if k > 0:
                tracked.before_substep()
            # Chipmunk rescales warm starts by h / (its last step) when the length changes.
            rescaled = split and raw.current_time_step(space_h) != h
            space.step(h)
            self._space_steps += 1
            last = k == n - 1
            tracked.after_substep(last=last, stamp=self._space_steps, rescaled=rescaled)
            if not last:
                for read in readers:
                    read()

    def solve(self) -> None:
        """FORCES: reverse integration for the tracked bodies."""
        cfg = self.config
        self.tracked.active.finish(
            dt=cfg.dt,
            substeps=cfg.substeps,
            damping=cfg.damping,
            space_gravity=raw.gravity(self._space_h),
            ledger=self.ledger,
        )

    def filter(self) -> None:
        """FILTER: perceived gravity for the bodies that perceive."""
        self.tracked.active.filter(self.config.dt, self._up_at)
