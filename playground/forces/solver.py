"""The reverse-integration force solver: what the engine did to each tracked body in a step.

pymunk integrates each dynamic body's velocity as ``v ← v·d + (g + F/m)·h`` (``d = damping**h``)
and then solves contacts and joints by impulses. Knowing v before and after the step, the mass,
gravity and every force we applied, the impulse the engine applied is what is left over::

    J = m·(v₁ − d·v₀) − (m·g + F)·h          L = I·(ω₁ − d·ω₀) − T·h

and the **engine force** is J/dt. Summed over substeps, read for every tracked body at once with
``pymunk.batch`` and numpy. The ledger's categories (:mod:`playground.forces.ledger`) then give the
support, specific, passive and applied forces; the contact split
(:mod:`playground.forces.contact_split`) tells contacts from joints.
"""

from __future__ import annotations

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine.batch import as_run, lookup
from playground.forces.contact_split import ContactSplit
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces
from playground.forces.tracking import TrackedRows
from playground.vec import Vec

__all__ = ["ForceSolver"]


def _vec(a: NDArray[np.float64]) -> Vec:
    return (float(a[0]), float(a[1]))


_READINGS = ("_engine3", "_support3", "_specific2", "_passive3", "_applied3")


class ForceSolver(TrackedRows):
    """Engine forces of tracked dynamic bodies by reverse integration, vectorised over all.

    Per step the world calls :meth:`before_step` (reads v₀, ω₀ and the forces about to be
    integrated, straight from the engine), :meth:`after_substep` after each ``space.step`` and
    :meth:`finish`. Reading v₀ just before the step means every step — even the first after a body
    is added — has a reading; a body absent from either read, or asleep after any substep (not
    integrated in it), gets none and keeps its last values (``valid`` False).

    Results are arrays with one row per tracked body, in :attr:`bodies` order.

    With ``contact_split`` on, the engine force is split into what contacts did (the body's
    arbiter impulses, summed by :class:`~playground.forces.contact_split.ContactSplit`) and what
    joints did (the rest). A step whose arbiter impulses cannot be trusted gets NaN with
    ``split_valid`` False — never a wrong number.
    """

    def __init__(self, *, contact_split: bool = False, check_sleep: bool = False) -> None:
        self.contact_split = contact_split
        self.check_sleep = check_sleep
        super().__init__()
        self.mass = np.zeros(0)
        self.moment = np.zeros(0)
        n = 0
        self.valid = np.zeros(n, dtype=bool)
        # Readings in (N, 3) [x, y, angle] frames: whole contiguous arrays are an order of
        # magnitude cheaper for numpy than (N, 2) slices of them. The public (N, 2) arrays are
        # views (properties below).
        self._engine3 = np.zeros((n, 3))
        self._support3 = np.zeros((n, 3))
        self._specific2 = np.zeros((n, 2))
        self._passive3 = np.zeros((n, 3))
        self._applied3 = np.zeros((n, 3))
        self._split = ContactSplit()
        self._split_known = False  # the split ran since it was last forgotten
        self._all_seen = False  # every row was seen in every substep (else: look at _seen)
        self._rebuild_keys()

    # -- membership (see TrackedRows) --------------------------------------------------------

    def _row_added(self) -> None:
        for name in _READINGS:
            old = getattr(self, name)
            setattr(self, name, np.vstack([old, np.zeros((1, old.shape[1]))]))
        self.valid = np.append(self.valid, False)
        self._split.add_row()

    def _row_removed(self, row: int) -> None:
        for name in (*_READINGS, "valid"):
            setattr(self, name, np.delete(getattr(self, name), row, axis=0))
        self._split.remove_row(row)

    def refresh_masses(self) -> None:
        """Re-read mass (kg) and moment (kg·m²) of every tracked body (after a mass change)."""
        self.mass = np.array([b.mass for b in self.bodies], dtype=np.float64)
        self.moment = np.array([b.moment for b in self.bodies], dtype=np.float64)
        self._locked = np.isinf(self.moment)
        # [m, m, I] per row, I = 0 where rotation is locked (I = ∞: no torque reading).
        self._m3 = np.column_stack([self.mass, self.mass, np.where(self._locked, 0.0, self.moment)])
        self._any_locked = bool(self._locked.any())
        self._inv_m2 = np.column_stack([1.0 / self.mass, 1.0 / self.mass])
        self._scaled: tuple[float, NDArray[np.float64]] | None = None
        self._weight: tuple[Vec, NDArray[np.float64]] | None = None

    def _rebuild_keys(self) -> None:
        """Sorted ids, masses and per-step arrays after the tracked set changed (lazily)."""
        super()._rebuild_keys()
        self.refresh_masses()
        n = len(self.bodies)
        self._vsum = np.zeros((n, 3))
        self._seen = np.zeros(n, dtype=bool)
        self._xy = np.zeros((0, 2), dtype=np.intp)
        self._block_cache: (
            tuple[NDArray[np.uintp], NDArray[np.intp] | slice, NDArray[np.bool_] | None] | None
        ) = None
        self._split.reset(self._keys, self._key_row)
        self._gather_cache: dict[
            int, tuple[NDArray[np.intp], NDArray[np.intp], NDArray[np.intp]]
        ] = {}

    # -- per step -------------------------------------------------------------------------------

    def before_step(
        self,
        ids: NDArray[np.uintp],
        flat: NDArray[np.float64],
        width: int = 6,
        field: NDArray[np.float64] | None = None,
    ) -> None:
        """Take v₀, ω₀ and the forces about to be integrated from a batch read.

        ``flat`` holds ``width`` floats per row of ``ids``, the last six of them vx, vy, w, fx,
        fy, torque (see ``_batch.BodyRows``); ``field`` rows (N) are the per-body gravity forces
        included in those forces.
        """
        if self._keys_dirty:
            self._rebuild_keys()
        n = len(self.bodies)
        self._substeps_summed = 0
        if self.contact_split:
            self._split.begin()
        order = self._order(ids)
        if order is not None:
            # Every tracked body is present (the usual case): v₀ and F gathered straight into
            # tracked order as contiguous (N, 3) arrays, one flat take each.
            at_v, at_f = self._gathers(order, width)
            self._v0 = np.take(flat, at_v)
            self._force = np.take(flat, at_f)
            self._field = None if field is None else np.take(field, order, axis=0)
            self._seen.fill(True)
            self._all_seen = True
        else:
            state = flat.reshape(-1, width)[:, width - 6 :]
            tracked, rows = self._rows(ids)
            self._v0 = np.zeros((n, 3))
            self._force = np.zeros((n, 3))
            self._v0[tracked] = state[rows, 0:3]
            self._force[tracked] = state[rows, 3:6]
            self._field = None
            if field is not None:
                self._field = np.zeros((n, 2))
                self._field[tracked] = field[rows]
            self._seen.fill(False)
            self._seen[tracked] = True
            self._all_seen = False
        self._vlast = self._v0

    def after_substep(
        self,
        space: pymunk.Space,
        ids: NDArray[np.uintp],
        vel: NDArray[np.float64],
        last: bool,
        *,
        stamp: int = 0,
        rescaled: bool = False,
    ) -> None:
        """Accumulate one substep: velocities now (``vel`` rows vx, vy, w), contact impulses.

        ``stamp`` counts the space's steps (1 for its first); ``rescaled``: this substep's length
        differs from the one before it, so Chipmunk rescaled its warm starts.
        """
        order = self._order(ids)
        if order is not None:
            sub = np.take(vel.reshape(-1), self._gathers(order, 3)[0])
        else:
            tracked, rows = self._rows(ids)
            present = np.zeros(len(self.bodies), dtype=bool)
            present[tracked] = True
            self._seen &= present
            self._all_seen = False
            sub = self._vlast.copy()
            sub[tracked] = vel[rows]
        if not last:
            # Σ v_k over the substeps but the last, for the damping term (see finish()).
            if self._substeps_summed == 0:
                self._vsum[:] = sub
            else:
                self._vsum += sub
            self._substeps_summed += 1
        self._vlast = sub
        if self.check_sleep:
            # Asleep after a substep: not integrated in it (a body woken by a contact is
            # integrated in the substep that wakes it; one asleep for part of the step is not
            # integrated for the whole step, and its reading would be off by the gravity it
            # missed).
            self._seen &= np.array([not b.is_sleeping for b in self.bodies], dtype=bool)
            self._all_seen = False
        if self.contact_split:
            self._split.accumulate(space, stamp, rescaled)

    def _gathers(
        self, order: NDArray[np.intp], width: int
    ) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
        """Flat indices, (N, 3) each, of (vx, vy, w) and of the three columns after them for
        rows ``order`` of a read of ``width`` floats per row: a state read (``width`` 6, or 8
        with x, y first: vx … torque are its last six) or a velocities read (``width`` 3: the
        second array is then unused). Cached while the order stays the same."""
        cached = self._gather_cache.get(width)
        if cached is None or cached[0] is not order:
            first = width - 6 if width >= 6 else 0
            at_v = order[:, None] * width + np.arange(first, first + 3)
            cached = (order, at_v, at_v + 3)
            self._gather_cache[width] = cached
        return cached[1], cached[2]

    def finish(
        self,
        *,
        dt: float,
        substeps: int,
        damping: float,
        space_gravity: Vec,
        ledger: ForceLedger,
    ) -> bool:
        """Compute the readings of this step; return whether every row has one (:attr:`valid`
        all true).

        With n substeps of h = dt/n and per-substep velocity damping d = damping**h, summing the
        per-substep impulses telescopes to
        ``J = m·(v_n − v_0 + (1 − d)·Σ_{k<n} v_k) − (m·g + F)·dt``; the engine force is J/dt.
        The arithmetic runs on whole (N, 3) arrays — [x, y, angle] columns with [m, m, I] — so
        its cost is a dozen numpy calls whatever N is; the ledger's few entries are patched in.
        """
        d = damping ** (dt / substeps)
        dv = self._vlast - self._v0
        if d != 1.0:
            dv += (1.0 - d) * (self._v0 + self._vsum if self._substeps_summed else self._v0)
        force = self._force  # this step's own gather: "applied" from here on
        weights = self._weights3(space_gravity)
        # E = m·Δv/dt − F − m·g, columns [x, y, angle]
        engine = dv
        engine *= self._m3_over(dt)
        engine -= force
        engine -= weights
        if self._any_locked:
            engine[self._locked, 2] = 0.0
        passive = weights.copy()
        applied = force
        if self._field is not None:
            passive[:, 0:2] += self._field
            applied[:, 0:2] -= self._field
        support = engine.copy()
        # The ledger's forces are in F: those of PASSIVE and SUPPORT move out of "applied"; what
        # remains there is APPLIED plus whatever someone put on the body outside the ledger.
        row_by_id = self._row_by_id
        for body_id, p in ledger.items():  # usually far fewer entries than tracked bodies
            i = row_by_id.get(body_id)
            if i is not None:
                passive[i, 0] += p[0]
                passive[i, 1] += p[1]
                support[i, 0] += p[4]
                support[i, 1] += p[5]
                applied[i, 0] -= p[0] + p[4]
                applied[i, 1] -= p[1] + p[5]
        block = ledger.row_block()  # a crowd's forces, a row per body
        if block is not None and len(block[0]):
            ids, parts = block
            at, keep = self._block_rows(ids)
            if keep is not None:
                parts = parts[keep]
            # The same float operations as the loop above, row by row (each body once).
            passive[at, 0:2] += parts[:, 0:2]
            support[at, 0:2] += parts[:, 4:6]
            applied[at, 0:2] -= parts[:, 0:2] + parts[:, 4:6]
        # (N, 2) and contiguous: the filter downstream is its only consumer. Gathered, then
        # multiplied: half the cost of multiplying the (N, 2) slice of the (N, 3) rows.
        specific = np.take(support.reshape(-1), self._xy_index())
        specific *= self._inv_m2

        ok = self._seen
        all_valid = self._all_seen or bool(ok.all())
        if not all_valid:
            # Rows without a reading keep their last values.
            stale = ~ok
            for new, old in (
                (engine, self._engine3),
                (passive, self._passive3),
                (applied, self._applied3),
                (support, self._support3),
                (specific, self._specific2),
            ):
                new[stale] = old[stale]
        self._engine3, self._passive3, self._applied3 = engine, passive, applied
        self._support3, self._specific2 = support, specific
        self.valid = ok.copy()
        if self.contact_split:
            self._split.finish(ok, self.engine, dt)
            self._split_known = True
        elif self._split_known:  # the split was just turned off
            if self._split.valid.any():
                self._split.forget()
            self._split_known = False
        return all_valid

    def _block_rows(
        self, ids: NDArray[np.uintp]
    ) -> tuple[NDArray[np.intp] | slice, NDArray[np.bool_] | None]:
        """The tracked rows of those of a block's ``ids`` that are tracked (a slice when they
        are one run: a crowd tracked in the order it writes its rows) and which of the block's
        rows they are (None: all), cached while the block's ids are the same array (a crowd's,
        step after step)."""
        cached = self._block_cache
        if cached is None or cached[0] is not ids:
            pos = lookup(self._keys, ids)
            rows = np.where(pos >= 0, self._key_row[np.maximum(pos, 0)], -1).astype(np.intp)
            tracked = rows >= 0
            keep = None if tracked.all() else tracked
            cached = self._block_cache = (ids, as_run(rows if keep is None else rows[keep]), keep)
        return cached[1], cached[2]

    def _xy_index(self) -> NDArray[np.intp]:
        """Flat indices (N, 2) of the x, y columns of (N, 3) rows, cached while N stays."""
        n = len(self.bodies)
        if self._xy.shape[0] != n:
            self._xy = np.arange(n)[:, None] * 3 + np.arange(2)
        return self._xy

    def _m3_over(self, dt: float) -> NDArray[np.float64]:
        """[m, m, I] / dt, cached while dt and the masses stay the same."""
        if self._scaled is None or self._scaled[0] != dt:
            self._scaled = (dt, self._m3 / dt)
        return self._scaled[1]

    def _weights3(self, g: Vec) -> NDArray[np.float64]:
        """[m·gx, m·gy, 0] per row (N), cached while g and the masses stay the same."""
        if self._weight is None or self._weight[0] != g:
            self._weight = (g, self.mass[:, None] * np.array([g[0], g[1], 0.0]))
        return self._weight[1]

    def engine_within(self, bound: float) -> bool:
        """Whether every engine force and torque component is finite and within ±``bound``: a
        quick pass over the contiguous readings (NaN fails it) before a closer look."""
        engine = self._engine3
        return engine.size == 0 or bool(-bound <= engine.min() and engine.max() <= bound)

    # -- readings, one row per tracked body ------------------------------------------------------

    @property
    def engine(self) -> NDArray[np.float64]:
        """Force the engine applied (contacts + joints), N; (N, 2)."""
        return self._engine3[:, 0:2]

    @property
    def engine_torque(self) -> NDArray[np.float64]:
        """Torque the engine applied, N·m; (N,). Zero for rotation-locked bodies."""
        return self._engine3[:, 2]

    @property
    def support(self) -> NDArray[np.float64]:
        """Engine force + our SUPPORT forces, N; (N, 2)."""
        return self._support3[:, 0:2]

    @property
    def specific(self) -> NDArray[np.float64]:
        """Support / m, m/s²; (N, 2)."""
        return self._specific2

    @property
    def passive(self) -> NDArray[np.float64]:
        """Gravity, fields and our PASSIVE forces, N; (N, 2)."""
        return self._passive3[:, 0:2]

    @property
    def applied(self) -> NDArray[np.float64]:
        """Our APPLIED forces and any force put on the body outside the ledger, N; (N, 2)."""
        return self._applied3[:, 0:2]

    @property
    def contact(self) -> NDArray[np.float64]:
        """Σ arbiter impulses / dt, N; (N, 2), NaN unless :attr:`split_valid`."""
        return self._split.contact

    @property
    def contact_normal(self) -> NDArray[np.float64]:
        """The contact force's part along the contact normals, N; (N, 2)."""
        return self._split.contact_normal

    @property
    def constraint(self) -> NDArray[np.float64]:
        """Engine − contact: what joints did, N; (N, 2), NaN unless :attr:`split_valid`."""
        return self._split.constraint

    @property
    def split_valid(self) -> NDArray[np.bool_]:
        """Per row, the contact split is on and known this step; (N,)."""
        return self._split.valid

    def reading(self, row: int) -> BodyForces:
        """The readings of one tracked row as plain values."""
        return BodyForces(
            valid=bool(self.valid[row]),
            engine=_vec(self.engine[row]),
            engine_torque=float(self.engine_torque[row]),
            support=_vec(self.support[row]),
            specific=_vec(self.specific[row]),
            passive=_vec(self.passive[row]),
            applied=_vec(self.applied[row]),
            contact=_vec(self.contact[row]),
            contact_normal=_vec(self.contact_normal[row]),
            contact_friction=_vec(self.contact[row] - self.contact_normal[row]),
            constraint=_vec(self.constraint[row]),
            split_valid=bool(self.split_valid[row]),
        )
