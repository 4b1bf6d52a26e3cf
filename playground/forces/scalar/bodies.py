"""The scalar implementation of the tracked bodies: reverse integration and perceived gravity in
plain floats, one body at a time, for few bodies.

Every numpy call and every ``pymunk.batch`` call has a fixed price whatever the body count
(docs/performance.md, rows numpy_call and batch_call), so below :data:`SCALAR_MAX_BODIES` tracked
bodies the batch implementation (:class:`~playground.forces.batch.BatchBodies`) costs more than
the physics. This one reads each tracked body's state (every row's velocities, and forces before
the step, in one call: :class:`~playground._engine.motion.Motions`), does the same arithmetic in
the same order in Python floats and filters with the same 1€ (and median-of-3) equations, so
both give the same readings (to a unit in the last place: magnitudes come from ``math.hypot``
here and from numpy's complex ``abs`` there). The contact split sums each body's arbiters
(:mod:`playground.forces.scalar.contacts`); a field that varies in space reaches the bodies as
forces computed in plain floats, body by body.

The tracked set (:class:`~playground.forces.tracked.TrackedSet`) switches between the two at a
plan change; the state moves with it (:meth:`ScalarBodies.load` and :meth:`ScalarBodies.store`,
see :mod:`playground.forces.scalar.handoff`), so a run gives one answer whichever served each
step.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Literal

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine import raw
from playground._engine.motion import Motions
from playground.filters.one_euro import OneEuroFilter
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.scalar import handoff
from playground.forces.scalar.contacts import ContactSums
from playground.forces.scalar.row import Row
from playground.forces.solver import ForceSolver
from playground.gravity import PerceivedGravity
from playground.vec import Vec

if TYPE_CHECKING:
    from playground.forces.tracked import FieldForces, FieldOnBodies

__all__ = ["SCALAR_MAX_BODIES", "ScalarBodies"]

SCALAR_MAX_BODIES = 28
"""Most tracked bodies the scalar implementation serves: the measured crossover, where a step
served in plain floats stops being cheaper than the batch one on a pile with every box tracked
and perceived. ``playground bench overhead`` measures it again; docs/performance.md ("Scalar or
batch") has the ratios."""

_NAN = math.nan
_hypot = math.hypot


class ScalarBodies:
    """The tracked bodies in plain floats, one :class:`Row` each (see
    :class:`~playground.forces.tracked.TrackedBodies`).

    ``contact_split`` and ``check_sleep`` mean what they mean for
    :class:`~playground.forces.solver.ForceSolver`; the rows come from the batch implementation's
    (:meth:`load`).

    >>> from playground.gravity import Perception
    >>> space = pymunk.Space()
    >>> body = pymunk.Body(2.0, 1.0)
    >>> space.add(body, pymunk.Circle(body, 0.5))
    >>> solver, perceived = ForceSolver(), PerceivedGravity(Perception())
    >>> _ = solver.track(body)
    >>> perceived.resize(np.array([-1]))
    >>> tracked = ScalarBodies(space)
    >>> tracked.load(solver, perceived)
    >>> tracked.before_step(None, 1)
    >>> space.step(0.01)
    >>> tracked.after_substep(last=True, stamp=1, rescaled=False)
    >>> tracked.finish(
    ...     dt=0.01, substeps=1, damping=1.0, space_gravity=(0.0, 0.0), ledger=ForceLedger()
    ... )
    >>> tracked.reading(0).engine, tracked.reading(0).valid  # free body: the engine did nothing
    ((0.0, 0.0), True)
    """

    kind: Literal["scalar", "batch"] = "scalar"
    takes_field_by_body = True

    def __init__(
        self, space: pymunk.Space, *, contact_split: bool = False, check_sleep: bool = False
    ) -> None:
        self.space = space
        self.contact_split = contact_split
        self.check_sleep = check_sleep
        self.threshold = 1.0
        """m/s²: below this |perceived gravity| a row's up holds (the perception's, at load)."""
        self.rows: list[Row] = []
        self._one_euro: OneEuroFilter | None = None
        self._median = False
        self._dt = _NAN
        self._field = False
        self._summed = 0
        self._held: list[tuple[pymunk.Body, pymunk.Vec2d, float]] = []
        self._contacts = ContactSums()
        self._motions = Motions([])  # the rows' bodies, read in one call
        # Whether a row may hold contact split readings (rows loaded, or split this step): only
        # then does a step without the split look for them to clear.
        self._split_held = False

    # -- hand-off with the batch implementation -------------------------------------------------

    def load(self, solver: ForceSolver, perceived: PerceivedGravity) -> None:
        """Take over the state of the batch implementation (at a plan change, not per step)."""
        self.rows, self._one_euro, self._median, history = handoff.load(solver, perceived)
        self._motions = Motions([r.body for r in self.rows])
        self.threshold = perceived.config.up_threshold
        self._split_held = True
        self._contacts.history = history
        self.refresh_masses()

    def store(self, solver: ForceSolver, perceived: PerceivedGravity) -> None:
        """Hand the state back to the batch implementation (at a plan change)."""
        handoff.store(self.rows, self._contacts.history, solver, perceived)

    def refresh_masses(self) -> None:
        """Re-read mass (kg) and moment (kg·m²) of every row (after a mass change)."""
        for r in self.rows:
            r.m = r.body.mass
            r.moment = r.body.moment
            r.locked = math.isinf(r.moment)
            r.inv_m = 1.0 / r.m
        self._dt = _NAN

    # -- per step (the order of ForceSolver's arithmetic, float by float) ----------------------

    def before_step(self, field: FieldForces | FieldOnBodies | None, substeps: int) -> None:
        """Add ``field``'s force (N) to each body it acts on, then read v₀, ω₀ and the forces
        about to be integrated from each row's body; with ``substeps`` > 1, keep every dynamic
        body's force to write again before each later substep."""
        assert field is None or not callable(field)
        if field is not None:
            _add_forces(field, sleeping=self.check_sleep)
        self._field = field is not None
        self._summed = 0
        for r, motion in zip(self.rows, self._motions.velocities_and_forces(), strict=True):
            r.v0x, r.v0y, r.v0w, r.fx, r.fy, r.ft = motion
            r.seen = True
            if field is not None:
                r.ffx, r.ffy = field.get(r.body, (0.0, 0.0))
        if substeps > 1:
            self._held = _forces_on(self.space)

    def before_substep(self) -> None:
        """Every dynamic body's force and torque of the step's start, written again."""
        for body, held_force, held_torque in self._held:
            body.force = held_force
            body.torque = held_torque

    def after_substep(self, *, last: bool, stamp: int, rescaled: bool) -> None:
        """Velocities after a substep (summed for the damping term unless it is the ``last``); a
        body asleep after any substep has no reading. With the contact split, its arbiter
        impulses (``stamp``, ``rescaled``: see :meth:`ForceSolver.after_substep`)."""
        check_sleep = self.check_sleep
        first_sum = self._summed == 0
        is_sleeping = raw.is_sleeping
        for r, (vx, vy, vw) in zip(self.rows, self._motions.velocities(), strict=True):
            r.vx, r.vy, r.vw = vx, vy, vw
            if not last:
                if first_sum:
                    r.qx, r.qy, r.qw = vx, vy, vw
                else:
                    r.qx += vx
                    r.qy += vy
                    r.qw += vw
            if check_sleep and is_sleeping(r.h):
                r.seen = False
        if not last:
            self._summed += 1
        if self.contact_split:
            self._contacts.accumulate(self.rows, self.space, stamp, rescaled, fresh=first_sum)

    def finish(
        self,
        *,
        dt: float,
        substeps: int,
        damping: float,
        space_gravity: Vec,
        ledger: ForceLedger,
    ) -> None:
        """The readings of this step (see :meth:`ForceSolver.finish`)."""
        if dt != self._dt:
            for r in self.rows:
                r.m_dt = r.m / dt
                r.i_dt = 0.0 if r.locked else r.moment / dt
            self._dt = dt
        d = damping ** (dt / substeps)
        k = 1.0 - d
        damped = d != 1.0
        summed = self._summed > 0
        gx, gy = space_gravity
        field = self._field
        parts = ledger.parts if len(ledger) else None
        split = self.contact_split
        for r in self.rows:
            if not r.seen:
                r.valid = False
                continue
            v0x, v0y, v0w = r.v0x, r.v0y, r.v0w
            dvx = r.vx - v0x
            dvy = r.vy - v0y
            dvw = r.vw - v0w
            if damped:
                if summed:
                    dvx += k * (v0x + r.qx)
                    dvy += k * (v0y + r.qy)
                    dvw += k * (v0w + r.qw)
                else:
                    dvx += k * v0x
                    dvy += k * v0y
                    dvw += k * v0w
            m, m_dt = r.m, r.m_dt
            fx, fy, ft = r.fx, r.fy, r.ft
            wx, wy = m * gx, m * gy
            ex = dvx * m_dt - fx - wx
            ey = dvy * m_dt - fy - wy
            et = 0.0 if r.locked else dvw * r.i_dt - ft - 0.0
            px, py = wx, wy
            ax, ay = fx, fy
            if field:
                px += r.ffx
                py += r.ffy
                ax -= r.ffx
                ay -= r.ffy
            sx, sy = ex, ey
            if parts is not None:
                p = parts(r.body)
                if p is not None:
                    px += p[0]
                    py += p[1]
                    sx += p[4]
                    sy += p[5]
                    ax -= p[0] + p[4]
                    ay -= p[1] + p[5]
            r.ex, r.ey, r.et = ex, ey, et
            r.px, r.py = px, py
            r.ax, r.ay, r.at = ax, ay, ft
            r.sx, r.sy, r.st = sx, sy, et
            inv_m = r.inv_m
            r.sp = (sx * inv_m, sy * inv_m)
            r.valid = True
            if split:
                # The contact split: contact, its normal part and the constraint's (N); NaN
                # where an arbiter may report an impulse not applied. A row not read this step
                # keeps its last values (the loop skipped it above).
                if r.unknown:
                    r.cx = r.cy = r.cnx = r.cny = r.kx = r.ky = _NAN
                    r.split = False
                else:
                    jx, jy, jnx, jny = r.j
                    cx = jx / dt
                    cy = jy / dt
                    r.cx = cx
                    r.cy = cy
                    r.cnx = jnx / dt
                    r.cny = jny / dt
                    r.kx = ex - cx
                    r.ky = ey - cy
                    r.split = True
        if split:
            self._split_held = True
        elif self._split_held:  # the split was just turned off: no row keeps its readings
            if any(r.split for r in self.rows):
                for r in self.rows:
                    r.cx = r.cy = r.cnx = r.cny = r.kx = r.ky = _NAN
                    r.split = False
            self._split_held = False

    def filter(self, dt: float, up_at: Callable[[pymunk.Body], Vec]) -> None:
        """Perceived gravity: −specific force through median-of-3 and 1€, and the up, held while
        |perceived gravity| < :attr:`threshold`; ``up_at`` gives a row's up until it has felt
        a strong enough reading (see :class:`~playground.gravity.PerceivedGravity`)."""
        threshold = self.threshold
        one = self._one_euro
        assert one is not None
        r_d = one._w_d * dt
        a_d = r_d / (1.0 + r_d)
        k_d = a_d / dt
        c_d = 1.0 - a_d
        w_beta = one._w_beta * dt
        w_min = one._w_min * dt
        median = self._median
        isfinite, hypot = math.isfinite, math.hypot
        for r in self.rows:
            if r.valid:
                sp = r.sp
                x, y = -sp[0], -sp[1]
                if median:
                    x, y = _median_step(r, x, y)
                if not r.started:
                    r.xh, r.yh, r.dxh, r.dyh = x, y, 0.0, 0.0
                    r.started = True
                else:
                    xh, yh = r.xh, r.yh
                    devx, devy = x - xh, y - yh
                    dx = devx * k_d + c_d * r.dxh
                    dy = devy * k_d + c_d * r.dyh
                    rr = hypot(dx, dy) * w_beta + w_min
                    alpha = rr / (rr + 1.0)
                    nx, ny = devx * alpha + xh, devy * alpha + yh
                    if isfinite(nx) and isfinite(ny):
                        r.xh, r.yh, r.dxh, r.dyh = nx, ny, dx, dy
            if r.started:
                ox, oy = r.xh, r.yh
                norm = hypot(ox, oy)
                r.gx, r.gy = ox, oy
                if norm >= threshold:
                    s = 1.0 / -norm
                    r.ux, r.uy = ox * s, oy * s
            if not isfinite(r.ux):
                r.ux, r.uy = up_at(r.body)

    # -- readings -------------------------------------------------------------------------------

    def runaway(self, bound: float) -> tuple[int, int, float] | None:
        """The first engine force component (column 0: x, 1: y) that is not finite or beyond
        ±``bound`` (N), as (body id, column, value), or None: what the batch implementation
        finds. (Chained comparisons, not ``abs``: the same test, NaN failing it, without a call
        per component.)"""
        low = -bound
        for r in self.rows:
            if not low <= r.ex <= bound:
                return r.body.id, 0, r.ex
            if not low <= r.ey <= bound:
                return r.body.id, 1, r.ey
        return None

    def perceived_gravity(self, row: int) -> Vec:
        """The filtered perceived gravity of a row, m/s²."""
        r = self.rows[row]
        return (r.gx, r.gy)

    def perceived_up(self, row: int) -> Vec:
        """The held unit up of a row."""
        r = self.rows[row]
        return (r.ux, r.uy)

    def perceived_up_and_gravity(self, row: int) -> tuple[Vec, Vec]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of a row in one call."""
        r = self.rows[row]
        return (r.ux, r.uy), (r.gx, r.gy)

    def table(self) -> TrackedReadings:
        """Every row's readings as arrays (the batch implementation's arrays, built anew)."""
        rows = self.rows
        return TrackedReadings(
            bodies=tuple(r.body for r in rows),
            valid=np.array([r.valid for r in rows], dtype=bool),
            engine=_pairs([(r.ex, r.ey) for r in rows]),
            engine_torque=np.array([r.et for r in rows], dtype=np.float64),
            support=_pairs([(r.sx, r.sy) for r in rows]),
            specific=_pairs([r.sp for r in rows]),
            passive=_pairs([(r.px, r.py) for r in rows]),
            applied=_pairs([(r.ax, r.ay) for r in rows]),
            contact=_pairs([(r.cx, r.cy) for r in rows]),
            contact_normal=_pairs([(r.cnx, r.cny) for r in rows]),
            constraint=_pairs([(r.kx, r.ky) for r in rows]),
            split_valid=np.array([r.split for r in rows], dtype=bool),
            perceived_gravity=_pairs([(r.gx, r.gy) for r in rows]),
            perceived_up=_pairs([(r.ux, r.uy) for r in rows]),
        )

    def reading(self, row: int) -> BodyForces:
        """The readings of a row as :meth:`ForceSolver.reading` gives them."""
        r = self.rows[row]
        return BodyForces(
            valid=r.valid,
            engine=(r.ex, r.ey),
            engine_torque=r.et,
            support=(r.sx, r.sy),
            specific=r.sp,
            passive=(r.px, r.py),
            applied=(r.ax, r.ay),
            contact=(r.cx, r.cy),
            contact_normal=(r.cnx, r.cny),
            contact_friction=(r.cx - r.cnx, r.cy - r.cny),
            constraint=(r.kx, r.ky),
            split_valid=r.split,
        )


def _pairs(values: list[Vec]) -> NDArray[np.float64]:
    """(x, y) values as an (N, 2) array (also when N is 0)."""
    return np.array(values, dtype=np.float64).reshape(-1, 2)


def _add_forces(forces: FieldOnBodies, *, sleeping: bool) -> None:
    """Add ``forces`` (N) to the forces the bodies have. With ``sleeping`` on, a body whose
    force and torque would be zero is left alone (setting a force restarts its idle clock), as
    the batch implementation does."""
    get_force, torque, set_force = raw.get_force, raw.torque, raw.set_force
    for body, (fx, fy) in forces.items():
        h = raw.handle(body)
        f = get_force(h)
        x, y = f.x + fx, f.y + fy
        if sleeping and x == 0.0 and y == 0.0 and torque(h) == 0.0:
            continue
        set_force(h, x, y)


def _forces_on(space: pymunk.Space) -> list[tuple[pymunk.Body, pymunk.Vec2d, float]]:
    """Every dynamic body with a force or torque now (N, N·m), to write again before each later
    substep (pymunk clears them after each): the others have none to re-apply, and writing
    one would restart a sleeping world's idle clock, as the batch implementation avoids too."""
    held = []
    for body in space.bodies:
        force, torque = body.force, body.torque
        if (force.x != 0.0 or force.y != 0.0 or torque != 0.0) and (
            body.body_type == pymunk.Body.DYNAMIC
        ):
            held.append((body, force, torque))
    return held


def _median_step(r: Row, x: float, y: float) -> tuple[float, float]:
    """Push (x, y) into the row's window and return the vector median (Median3's rule)."""
    if not r.m_started:
        r.s0 = r.s1 = r.s2 = (x, y)
        r.m_started = True
        return x, y
    a, b, c = r.s1, r.s2, (x, y)
    r.s0, r.s1, r.s2 = a, b, c
    ax, ay = a
    bx, by = b
    d_ab = _hypot(ax - bx, ay - by)
    d_bc = _hypot(bx - x, by - y)
    d_ac = _hypot(ax - x, ay - y)
    if d_ac >= d_ab and d_ac >= d_bc:
        return b
    if d_bc >= d_ab:
        return a
    return c
