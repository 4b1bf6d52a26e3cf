"""The force ledger and the reverse-integration force solver.

pymunk integrates each dynamic body's velocity as ``v ← v·d + (g + F/m)·h`` (``d = damping**h``)
and then solves contacts and joints by impulses. Knowing v before and after the step, the mass,
gravity and every force we applied, the impulse the engine applied is what is left over::

    J = m·(v₁ − d·v₀) − (m·g + F)·h          L = I·(ω₁ − d·ω₀) − T·h

and the **engine force** is J/dt. Summed over substeps, read for every tracked body at once with
``pymunk.batch`` and numpy. The **ledger** records the forces we apply by category, so that the
**support force** (engine + the forces that stand in for contacts: hover, drive, grip) and the
**specific force** (support / m: what an inner ear feels) come out right.

With the contact split on, the solver also sums each body's arbiter impulses (``total_impulse``):
the rest of the engine force is what joints did. That sum is only right when Chipmunk applied
what it reports, which it does not on a step where a contact is made again from an arbiter still
cached or where the warm start was rescaled (see :class:`ForceSolver`): such steps get no split
(NaN, ``split_valid`` False), never a wrong one.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

from playground._batch import lookup, read_arbiters

__all__ = ["BodyForces", "Category", "ForceLedger", "ForceSolver"]

Vec = tuple[float, float]


class Category(Enum):
    """Why a force was applied; the solver keeps a sum per category.

    PASSIVE: gravity and other fields. APPLIED: self-propulsion, scripted pushes — felt by nobody's
    inner ear by convention. SUPPORT: forces that stand in for contacts (a hover spring, a driving
    friction force, a grip) — they count in the support force.
    """

    PASSIVE = 0
    APPLIED = 1
    SUPPORT = 2


class _Entry:
    __slots__ = ("body", "fx", "fy", "parts", "torque")

    def __init__(self, body: pymunk.Body) -> None:
        self.body = body
        self.fx = 0.0
        self.fy = 0.0
        self.torque = 0.0
        self.parts = [0.0] * (2 * len(Category))


class ForceLedger:
    """Forces we put on bodies during one step, by body and category.

    Forces are world vectors (N) at world points (m); the torque about the centre of gravity
    follows. :meth:`flush` writes the totals to the bodies; it runs before every substep because
    pymunk clears forces after integrating. ``on_first`` is called when an empty ledger gets its
    first entry: a world uses it to know that its next step has forces to flush (a step with
    nothing to do takes a bare path that never looks at the ledger).

    >>> body = pymunk.Body(2.0, 1.0)
    >>> ledger = ForceLedger()
    >>> ledger.add(body, (3.0, 0.0), point=(0.0, 1.0), category=Category.SUPPORT)
    >>> ledger.flush()
    >>> body.force, body.torque
    (Vec2d(3.0, 0.0), -3.0)
    """

    __slots__ = ("_entries", "_on_first")

    def __init__(self, on_first: Callable[[], None] | None = None) -> None:
        # Keyed by the body object, not its id: ``body.id`` is a call into chipmunk (~0.5 µs)
        # and a controller adds several forces a step; the ids are read once, in items().
        self._entries: dict[pymunk.Body, _Entry] = {}
        self._on_first = on_first

    def _entry(self, body: pymunk.Body) -> _Entry:
        entry = self._entries.get(body)
        if entry is None:
            if not self._entries and self._on_first is not None:
                self._on_first()
            entry = self._entries[body] = _Entry(body)
        return entry

    def add(
        self,
        body: pymunk.Body,
        force: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Record ``force`` (N, world frame) on ``body`` at world ``point`` (m; default: its centre
        of gravity)."""
        fx, fy = float(force[0]), float(force[1])
        if not (math.isfinite(fx) and math.isfinite(fy)):
            raise ValueError(f"force: expected a finite 2-vector in newtons, got {force!r}")
        entry = self._entry(body)
        entry.fx += fx
        entry.fy += fy
        if point is not None:
            c = body.local_to_world(body.center_of_gravity)
            entry.torque += (point[0] - c.x) * fy - (point[1] - c.y) * fx
        i = 2 * category.value
        entry.parts[i] += fx
        entry.parts[i + 1] += fy

    def add_torque(self, body: pymunk.Body, torque: float, category: Category) -> None:
        """Record a pure torque (N·m)."""
        if not math.isfinite(torque):
            raise ValueError(f"torque: expected a finite number in N·m, got {torque!r}")
        self._entry(body).torque += float(torque)

    def flush(self) -> None:
        """Write each body's total force and torque (replacing what it had)."""
        for e in self._entries.values():
            e.body.force = (e.fx, e.fy)
            e.body.torque = e.torque

    def clear(self) -> None:
        self._entries.clear()

    def __len__(self) -> int:
        return len(self._entries)

    def items(self) -> list[tuple[int, list[float]]]:
        """(body id, per-category sums ``[px, py, ax, ay, sx, sy]``) of every body with forces."""
        return [(body.id, e.parts) for body, e in self._entries.items()]


@dataclass(frozen=True, slots=True)
class BodyForces:
    """One tracked body's readings after a step (plain values, SI).

    Attributes:
        valid: False when the body was not integrated through the whole step (asleep after one of
            its substeps, or absent from the space); the other fields then hold the last valid
            reading.
        engine: force the engine applied (contacts + joints), N.
        engine_torque: torque the engine applied, N·m.
        support: engine + our SUPPORT forces (hover, drive, grip), N.
        specific: support / m — what an accelerometer on the body reads, m/s².
        passive: gravity and fields on the body, N.
        applied: our APPLIED forces (self-propulsion, scripts), N.
        contact: sum of the body's arbiter impulses / dt, N (NaN unless ``split_valid``).
        contact_normal / contact_friction: the contact force's normal and tangential parts, N.
        constraint: engine − contact: what joints did, N (NaN unless ``split_valid``).
        split_valid: the contact split is on and known this step. It is unknown (the four
            fields above NaN) on a step where one of the body's arbiters reports an impulse the
            engine did not apply (see :class:`ForceSolver`).
    """

    valid: bool
    engine: Vec
    engine_torque: float
    support: Vec
    specific: Vec
    passive: Vec
    applied: Vec
    contact: Vec
    contact_normal: Vec
    contact_friction: Vec
    constraint: Vec
    split_valid: bool


def _vec(a: NDArray[np.float64]) -> Vec:
    return (float(a[0]), float(a[1]))


_READINGS = ("_engine3", "_support3", "_specific2", "_passive3", "_applied3")


class ForceSolver:
    """Engine forces of tracked dynamic bodies by reverse integration, vectorised over all.

    Per step the world calls :meth:`before_step` (reads v₀, ω₀ and the forces about to be
    integrated, straight from the engine), :meth:`after_substep` after each ``space.step`` and
    :meth:`finish`. Reading v₀ just before the step means every step — even the first after a body
    is added — has a reading; a body absent from either read, or asleep after any substep (not
    integrated in it), gets none and keeps its last values (``valid`` False).

    Results are arrays with one row per tracked body, in :attr:`bodies` order.

    **The contact split** sums ``Arbiter.total_impulse``: the impulses Chipmunk accumulated on the
    arbiter's contacts (``jnAcc``, ``jtAcc``). They are the impulses it applied, except in two
    cases read from its sources (``cpArbiter.c``, ``cpSpaceStep.c``):

    - *a contact made again while its arbiter is still cached.* An arbiter outlives its contact
      by ``space.collision_persistence`` steps. When the shapes touch again, ``cpArbiterUpdate``
      copies the accumulated impulses of the old contacts into the new ones, but the arbiter is
      a first contact, so ``cpArbiterApplyCachedImpulse`` does not apply them: the copied impulse
      is reported and never applied (on a box riding a platform that accelerates downward, one
      step in three read up to 5·m·g of "joint" force with no joint in the scene). The world
      sets ``collision_persistence`` to 1, so no arbiter outlives a step without contact; with a
      larger value, a first contact between two bodies that had an arbiter within that many
      steps (but not in the step before) makes the split of both unknown for the step.
    - *a warm start rescaled.* A continuing contact is warm-started with its accumulated impulse
      times h/h_prev when the substep length changes, while the accumulated impulse itself is
      not rescaled: on the first substep at a new length, bodies with a continuing contact get
      no split.

    Unknown means NaN with ``split_valid`` False — never a wrong number.
    """

    def __init__(self, *, contact_split: bool = False, check_sleep: bool = False) -> None:
        self.contact_split = contact_split
        self.check_sleep = check_sleep
        self.bodies: list[pymunk.Body] = []
        self._keys = np.zeros(0, dtype=np.uintp)  # sorted body ids
        self._row_by_id: dict[int, int] = {}
        self._rows_cache: (
            tuple[NDArray[np.uintp], NDArray[np.intp], NDArray[np.intp], NDArray[np.intp] | None]
            | None
        ) = None
        self._key_row = np.zeros(0, dtype=np.intp)  # tracked index of each sorted id
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
        self.contact = np.full((n, 2), np.nan)
        self.contact_normal = np.full((n, 2), np.nan)
        self.constraint = np.full((n, 2), np.nan)
        self.split_valid = np.zeros(n, dtype=bool)
        self._arb_buffer = batch.Buffer()
        # Body pairs with an arbiter in each recent substep: (substep stamp, sorted pair keys),
        # newest last, kept only while collision_persistence > 1.
        self._pairs: deque[tuple[int, NDArray[np.uint64]]] = deque()
        self._rebuild_keys()

    # -- membership -------------------------------------------------------------------------

    def track(self, body: pymunk.Body) -> int:
        """Start tracking a dynamic body; returns its row. Idempotent."""
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError("track: only dynamic bodies have engine forces to recover")
        row = self.row_of(body)
        if row is not None:
            return row
        self.bodies.append(body)
        self._row_by_id[body.id] = len(self.bodies) - 1
        for name in _READINGS:
            old = getattr(self, name)
            setattr(self, name, np.vstack([old, np.zeros((1, old.shape[1]))]))
        for name in ("contact", "contact_normal", "constraint"):
            setattr(self, name, np.vstack([getattr(self, name), np.full((1, 2), np.nan)]))
        self.valid = np.append(self.valid, False)
        self.split_valid = np.append(self.split_valid, False)
        self._keys_dirty = True
        return len(self.bodies) - 1

    def untrack(self, body: pymunk.Body) -> None:
        """Stop tracking a body (rows after it move up by one)."""
        idx = self.row_of(body)
        if idx is None:
            return
        del self.bodies[idx]
        self._row_by_id = {b.id: i for i, b in enumerate(self.bodies)}
        for name in (*_READINGS, "contact", "contact_normal", "constraint", "valid", "split_valid"):
            setattr(self, name, np.delete(getattr(self, name), idx, axis=0))
        self._keys_dirty = True

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
        ids = np.array([b.id for b in self.bodies], dtype=np.uintp)
        self._row_by_id = {int(body_id): i for i, body_id in enumerate(ids)}
        self._rows_cache = None
        order = np.argsort(ids)
        self._keys = ids[order]
        self._key_row = order.astype(np.intp)
        self.refresh_masses()
        n = len(self.bodies)
        self._vsum = np.zeros((n, 3))
        self._seen = np.zeros(n, dtype=bool)
        self._contact_j = np.zeros((n, 2))
        self._contact_jn = np.zeros((n, 2))
        self._split_unknown = np.zeros(n, dtype=bool)
        # The world may have stepped bare (nothing tracked) since the pairs were recorded.
        self._pairs.clear()
        self._keys_dirty = False

    def row_of(self, body: pymunk.Body, body_id: int | None = None) -> int | None:
        """The tracked row of a body, or None. ``body_id``: its ``body.id`` if the caller has it
        (reading it is a call into chipmunk)."""
        i = self._row_by_id.get(body.id if body_id is None else body_id)
        return i if i is not None and self.bodies[i] is body else None

    # -- per step -------------------------------------------------------------------------------

    def _rows(self, ids: NDArray[np.uintp]) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
        """(tracked index, row) pairs for the tracked bodies present in ``ids``.

        Row order only changes when bodies are added, removed, sleep or wake: reuse the last
        answer while ``ids`` is unchanged.
        """
        cache = self._rows_cache
        if cache is not None and np.array_equal(cache[0], ids):
            return cache[1], cache[2]
        hit = lookup(self._keys, ids)
        rows = np.nonzero(hit >= 0)[0]
        tracked = self._key_row[hit[rows]]
        full = None
        if len(tracked) == len(self.bodies):
            full = np.empty(len(tracked), dtype=np.intp)
            full[tracked] = rows
        self._rows_cache = (ids, tracked, rows, full)
        return tracked, rows

    def _order(self, ids: NDArray[np.uintp]) -> NDArray[np.intp] | None:
        """Rows of ``ids`` in tracked order when every tracked body is among them, else None."""
        self._rows(ids)
        assert self._rows_cache is not None
        return self._rows_cache[3]

    def before_step(
        self,
        ids: NDArray[np.uintp],
        state: NDArray[np.float64],
        field: NDArray[np.float64] | None = None,
    ) -> None:
        """Take v₀, ω₀ and the forces about to be integrated from a batch read.

        ``state`` columns: vx, vy, w, fx, fy, torque (see ``_batch.BodyRows``); ``field`` rows
        (N) are the per-body gravity forces included in those forces.
        """
        if self._keys_dirty:
            self._rebuild_keys()
        n = len(self.bodies)
        self._substeps_summed = 0
        if self.contact_split:
            self._contact_j.fill(0.0)
            self._contact_jn.fill(0.0)
            self._split_unknown.fill(False)
        order = self._order(ids)
        if order is not None:
            # Every tracked body is present (the usual case): one gather into tracked order;
            # v₀ and F are views of it.
            sub = np.take(state, order, axis=0)  # take: 3× cheaper than state[order]
            self._v0 = sub[:, 0:3]
            self._force = sub[:, 3:6]
            self._field = None if field is None else np.take(field, order, axis=0)
            self._seen.fill(True)
        else:
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
            sub = np.take(vel, order, axis=0)
        else:
            tracked, rows = self._rows(ids)
            present = np.zeros(len(self.bodies), dtype=bool)
            present[tracked] = True
            self._seen &= present
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
        if self.contact_split:
            self._accumulate_contacts(space, stamp, rescaled)

    def _accumulate_contacts(self, space: pymunk.Space, stamp: int, rescaled: bool) -> None:
        pairs, first, data = read_arbiters(space, self._arb_buffer)
        stale = self._stale(pairs, first, stamp, int(space.collision_persistence), rescaled)
        if stale is not None:
            for col in (0, 1):
                hit = lookup(self._keys, pairs[stale, col])
                self._split_unknown[self._key_row[hit[hit >= 0]]] = True
        if len(pairs) == 0:
            return
        j = data[:, 0:2]
        n = data[:, 2:4]
        jn = n * np.einsum("ij,ij->i", j, n)[:, None]
        rows, vals = [], []
        for col, sign in ((0, 1.0), (1, -1.0)):  # body A received +J, body B −J
            hit = lookup(self._keys, pairs[:, col])
            arb = np.nonzero(hit >= 0)[0]
            rows.append(self._key_row[hit[arb]])
            vals.append(sign * np.hstack([j[arb], jn[arb]]))
        idx = np.concatenate(rows)
        if len(idx) == 0:
            return
        v = np.vstack(vals)
        # Chipmunk's arbiter order (and which body is A) follows memory addresses, which differ
        # between runs: sum each body's impulses in an order set by their values, so that two
        # builds of a scene give bit-identical sums.
        order = np.lexsort((v[:, 3], v[:, 2], v[:, 1], v[:, 0], idx))
        np.add.at(self._contact_j, idx[order], v[order, 0:2])
        np.add.at(self._contact_jn, idx[order], v[order, 2:4])

    def _stale(
        self,
        pairs: NDArray[np.uintp],
        first: NDArray[np.bool_],
        stamp: int,
        persistence: int,
        rescaled: bool,
    ) -> NDArray[np.bool_] | None:
        """Which arbiters may report an impulse Chipmunk did not apply (None: none may).

        See the class docstring. A cached arbiter was last in contact between ``persistence`` and
        2 steps ago; when the recorded pairs do not cover those steps (recording just began, or
        a substep was not recorded), every first contact is suspect.
        """
        stale = ~first if rescaled and len(pairs) else None
        if persistence < 2:
            self._pairs.clear()
            return stale
        lo = np.minimum(pairs[:, 0], pairs[:, 1]).astype(np.uint64)
        hi = np.maximum(pairs[:, 0], pairs[:, 1]).astype(np.uint64)
        keys = (lo << np.uint64(32)) | hi
        history = self._pairs
        if history and history[-1][0] != stamp - 1:
            history.clear()  # a gap: the substeps in between were not seen
        if first.any():
            since = max(1, stamp - persistence)
            fits = not (hi >> np.uint64(32)).any()  # ids too large for a key: suspect all
            covered = fits and (stamp <= 1 or (bool(history) and history[0][0] <= since))
            old = [k for s, k in history if s <= stamp - 2]
            if not covered:
                cached = first
            elif old:
                cached = first & np.isin(keys, np.concatenate(old))
            else:
                cached = np.zeros_like(first)
            stale = cached if stale is None else stale | cached
        history.append((stamp, keys))
        while history[0][0] < stamp - persistence:
            history.popleft()
        return stale if stale is not None and stale.any() else None

    def finish(
        self,
        *,
        dt: float,
        substeps: int,
        damping: float,
        space_gravity: Vec,
        ledger: ForceLedger,
    ) -> None:
        """Compute the readings of this step.

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
        force = self._force.copy()  # contiguous from here on
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
        # (N, 2) and contiguous: the filter downstream is its only consumer.
        specific = np.multiply(support[:, 0:2], self._inv_m2)

        ok = self._seen
        if not ok.all():
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
            rows_ok = np.nonzero(ok)[0]
            self.contact[rows_ok] = self._contact_j[rows_ok] / dt
            self.contact_normal[rows_ok] = self._contact_jn[rows_ok] / dt
            self.constraint[rows_ok] = self.engine[rows_ok] - self.contact[rows_ok]
            self.split_valid[rows_ok] = True
            unknown = np.nonzero(ok & self._split_unknown)[0]
            if len(unknown):
                for name in ("contact", "contact_normal", "constraint"):
                    getattr(self, name)[unknown] = np.nan
                self.split_valid[unknown] = False
        elif self.split_valid.any():  # the split was just turned off
            for name in ("contact", "contact_normal", "constraint"):
                getattr(self, name).fill(np.nan)
            self.split_valid.fill(False)

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
