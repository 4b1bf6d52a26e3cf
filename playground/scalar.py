"""The scalar path: reverse integration and perceived gravity in plain floats, for few bodies.

Every numpy call costs about 1 µs and every ``pymunk.batch`` call about 5 µs whatever the body
count, so below :data:`SCALAR_MAX_BODIES` tracked bodies the vectorised
:class:`~playground.forces.solver.ForceSolver` and
:class:`~playground.perception.PerceivedGravity` cost more than the physics. This path reads each
tracked body's attributes, does the same arithmetic in the same order in Python floats and
filters with the same 1€ (and median-of-3) equations, so both paths give the same readings (to a
unit in the last place: magnitudes come from ``math.hypot`` here and from numpy's complex ``abs``
there).

The world switches between the paths at a plan change; the state moves with it
(:meth:`ScalarPath.load` and :meth:`ScalarPath.store`), so a run gives one answer whichever path
served each step.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pymunk

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import OneEuroFilter
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces
from playground.forces.solver import ForceSolver
from playground.perception import PerceivedGravity

__all__ = ["SCALAR_MAX_BODIES", "ScalarPath"]

SCALAR_MAX_BODIES = 20
"""Most tracked bodies the scalar path serves: the measured crossover. On a pile with every box
tracked and perceived, a step on the scalar path costs 0.13× the vectorised one at 1 body, 0.85×
at 16 and 1.1× at 24 (``playground bench overhead`` measures it again: docs/performance.md)."""

_NAN = math.nan

Vec = tuple[float, float]


class _Row:
    """One tracked body's per-step state and readings, in plain floats."""

    __slots__ = (
        "at",
        "ax",
        "ay",
        "body",
        "dxh",
        "dyh",
        "et",
        "ex",
        "ey",
        "ft",
        "fx",
        "fy",
        "gx",
        "gy",
        "i_dt",
        "inv_m",
        "locked",
        "m",
        "m_dt",
        "m_started",
        "moment",
        "px",
        "py",
        "s0",
        "s1",
        "s2",
        "seen",
        "sp",
        "st",
        "started",
        "sx",
        "sy",
        "ux",
        "uy",
        "v0w",
        "v0x",
        "v0y",
        "valid",
        "vw",
        "vx",
        "vy",
        "xh",
        "yh",
    )  # fmt: skip

    def __init__(self, body: pymunk.Body) -> None:
        self.body = body
        self.m = self.moment = self.inv_m = self.m_dt = self.i_dt = 0.0
        self.locked = False
        self.v0x = self.v0y = self.v0w = self.vx = self.vy = self.vw = 0.0
        self.fx = self.fy = self.ft = 0.0
        self.seen = self.valid = False
        # readings: engine (x, y, torque), support, specific, passive, applied
        self.ex = self.ey = self.et = 0.0
        self.sx = self.sy = self.st = 0.0
        self.sp = (0.0, 0.0)
        self.px = self.py = 0.0
        self.ax = self.ay = self.at = 0.0
        # filter: 1€ state (X̂, Ẋ̂), median-of-3 window, perceived gravity and up
        self.started = self.m_started = False
        self.xh = self.yh = self.dxh = self.dyh = 0.0
        self.s0 = self.s1 = self.s2 = (0.0, 0.0)
        self.gx = self.gy = 0.0
        self.ux = self.uy = _NAN


class ScalarPath:
    """Readings and perceived gravity of a few tracked bodies, one body at a time.

    >>> from playground.perception import Perception
    >>> space = pymunk.Space()
    >>> body = pymunk.Body(2.0, 1.0)
    >>> space.add(body, pymunk.Circle(body, 0.5))
    >>> solver, perceived = ForceSolver(), PerceivedGravity(Perception())
    >>> _ = solver.track(body)
    >>> perceived.resize(np.array([-1]))
    >>> path = ScalarPath()
    >>> path.load(solver, perceived)
    >>> path.before_step()
    >>> space.step(0.01)
    >>> path.after_substep(check_sleep=False)
    >>> path.finish(dt=0.01, damping=1.0, space_gravity=(0.0, 0.0), ledger=ForceLedger())
    >>> path.rows[0].ex, path.rows[0].valid  # free body: the engine did nothing
    (0.0, True)
    """

    def __init__(self) -> None:
        self.rows: list[_Row] = []
        self._one_euro: OneEuroFilter | None = None
        self._median = False
        self._weight_g: tuple[float, float] = (_NAN, _NAN)
        self._dt = _NAN

    # -- hand-off with the vectorised path ----------------------------------------------------

    def load(self, solver: ForceSolver, perceived: PerceivedGravity) -> None:
        """Take over the state of the vectorised path (at a plan change, not per step)."""
        if solver._keys_dirty:
            solver._rebuild_keys()
        self.rows = []
        chain = perceived._filter
        stages = chain.stages if isinstance(chain, FilterChain) else (chain,)
        median = next((s for s in stages if isinstance(s, Median3)), None)
        one_euro = next(s for s in stages if isinstance(s, OneEuroFilter))
        self._one_euro = one_euro
        self._median = median is not None
        for i, body in enumerate(solver.bodies):
            r = _Row(body)
            r.ex, r.ey, r.et = (float(v) for v in solver._engine3[i])
            r.sx, r.sy, r.st = (float(v) for v in solver._support3[i])
            r.sp = (float(solver._specific2[i, 0]), float(solver._specific2[i, 1]))
            r.px, r.py = float(solver._passive3[i, 0]), float(solver._passive3[i, 1])
            r.ax, r.ay, r.at = (float(v) for v in solver._applied3[i])
            r.valid = bool(solver.valid[i])
            r.gx, r.gy = float(perceived.gravity[i, 0]), float(perceived.gravity[i, 1])
            r.ux, r.uy = float(perceived.up[i, 0]), float(perceived.up[i, 1])
            if one_euro._shape is not None and one_euro._init[i]:
                r.started = True
                r.xh, r.yh = _xy(one_euro._xh[i])
                r.dxh, r.dyh = _xy(one_euro._dxh[i])
            if median is not None and median._shape is not None and median._init[i]:
                r.m_started = True
                r.s0, r.s1, r.s2 = _xy(median._s0[i]), _xy(median._s1[i]), _xy(median._s2[i])
            self.rows.append(r)
        self.refresh_masses()

    def store(self, solver: ForceSolver, perceived: PerceivedGravity) -> None:
        """Hand the state back to the vectorised path (at a plan change, or before a read of its
        arrays)."""
        n = len(self.rows)
        if n == 0:
            return
        for i, r in enumerate(self.rows):
            solver._engine3[i] = (r.ex, r.ey, r.et)
            solver._support3[i] = (r.sx, r.sy, r.st)
            solver._specific2[i] = r.sp
            solver._passive3[i] = (r.px, r.py, 0.0)
            solver._applied3[i] = (r.ax, r.ay, r.at)
            solver.valid[i] = r.valid
        if any(r.started for r in self.rows):
            chain = perceived._filter
            shape = np.zeros((n, 2))
            for stage in chain.stages if isinstance(chain, FilterChain) else (chain,):
                if not isinstance(stage, OneEuroFilter | Median3):
                    continue
                if stage._shape is None:
                    stage._fix_shape(shape)  # allocates every row, none started
                for i, r in enumerate(self.rows):
                    if isinstance(stage, OneEuroFilter) and r.started:
                        stage._xh[i] = complex(r.xh, r.yh)
                        stage._dxh[i] = complex(r.dxh, r.dyh)
                        stage._init[i] = True
                    elif isinstance(stage, Median3) and r.m_started:
                        stage._s0[i] = complex(*r.s0)
                        stage._s1[i] = complex(*r.s1)
                        stage._s2[i] = complex(*r.s2)
                        stage._init[i] = True
                stage._all_init = bool(stage._init.all())
        perceived.gravity = np.array([(r.gx, r.gy) for r in self.rows], dtype=float)
        perceived.up = np.array([(r.ux, r.uy) for r in self.rows], dtype=float)
        perceived.up_complete = all(math.isfinite(r.ux) for r in self.rows)

    def refresh_masses(self) -> None:
        """Re-read mass (kg) and moment (kg·m²) of every row (after a mass change)."""
        for r in self.rows:
            r.m = r.body.mass
            r.moment = r.body.moment
            r.locked = math.isinf(r.moment)
            r.inv_m = 1.0 / r.m
        self._dt = _NAN

    # -- per step (the order of ForceSolver's arithmetic, float by float) ----------------------

    def before_step(self) -> None:
        """v₀, ω₀ and the forces about to be integrated, read from each body."""
        for r in self.rows:
            b = r.body
            r.v0x, r.v0y = b.velocity
            r.v0w = b.angular_velocity
            r.fx, r.fy = b.force
            r.ft = b.torque
            r.seen = True

    def after_substep(self, *, check_sleep: bool) -> None:
        """Velocities after the (single) substep; a body asleep after it has no reading."""
        for r in self.rows:
            b = r.body
            r.vx, r.vy = b.velocity
            r.vw = b.angular_velocity
            if check_sleep and b.is_sleeping:
                r.seen = False

    def finish(
        self, *, dt: float, damping: float, space_gravity: tuple[float, float], ledger: ForceLedger
    ) -> None:
        """The readings of this step (see :meth:`ForceSolver.finish`; one substep)."""
        if dt != self._dt:
            for r in self.rows:
                r.m_dt = r.m / dt
                r.i_dt = 0.0 if r.locked else r.moment / dt
            self._dt = dt
        d = damping**dt
        gx, gy = space_gravity
        parts = {body_id: p for body_id, p in ledger.items()} if len(ledger) else None
        for r in self.rows:
            if not r.seen:
                r.valid = False
                continue
            dvx = r.vx - r.v0x
            dvy = r.vy - r.v0y
            dvw = r.vw - r.v0w
            if d != 1.0:
                k = 1.0 - d
                dvx += k * r.v0x
                dvy += k * r.v0y
                dvw += k * r.v0w
            wx, wy = r.m * gx, r.m * gy
            ex = dvx * r.m_dt - r.fx - wx
            ey = dvy * r.m_dt - r.fy - wy
            et = 0.0 if r.locked else dvw * r.i_dt - r.ft - 0.0
            px, py = wx, wy
            ax, ay, at = r.fx, r.fy, r.ft
            sx, sy, st = ex, ey, et
            if parts is not None:
                p = parts.get(r.body.id)
                if p is not None:
                    px += p[0]
                    py += p[1]
                    sx += p[4]
                    sy += p[5]
                    ax -= p[0] + p[4]
                    ay -= p[1] + p[5]
            r.ex, r.ey, r.et = ex, ey, et
            r.px, r.py = px, py
            r.ax, r.ay, r.at = ax, ay, at
            r.sx, r.sy, r.st = sx, sy, st
            r.sp = (sx * r.inv_m, sy * r.inv_m)
            r.valid = True

    def filter(self, dt: float, threshold: float, up_default: Callable[[pymunk.Body], Vec]) -> None:
        """Perceived gravity: −specific force through median-of-3 and 1€, and the up, held while
        |perceived gravity| < ``threshold`` (m/s²); ``up_default`` gives a row's up until it has
        felt a strong enough reading (see :class:`~playground.perception.PerceivedGravity`)."""
        one = self._one_euro
        assert one is not None
        r_d = one._w_d * dt
        a_d = r_d / (1.0 + r_d)
        k_d = a_d / dt
        c_d = 1.0 - a_d
        w_beta = one._w_beta * dt
        w_min = one._w_min * dt
        for r in self.rows:
            if r.valid:
                x, y = -r.sp[0], -r.sp[1]
                if self._median:
                    x, y = _median_step(r, x, y)
                if not r.started:
                    r.xh, r.yh, r.dxh, r.dyh = x, y, 0.0, 0.0
                    r.started = True
                else:
                    devx, devy = x - r.xh, y - r.yh
                    dx = devx * k_d + c_d * r.dxh
                    dy = devy * k_d + c_d * r.dyh
                    rr = math.hypot(dx, dy) * w_beta + w_min
                    alpha = rr / (rr + 1.0)
                    nx, ny = devx * alpha + r.xh, devy * alpha + r.yh
                    if math.isfinite(nx) and math.isfinite(ny):
                        r.xh, r.yh, r.dxh, r.dyh = nx, ny, dx, dy
            if not r.started:
                continue
            ox, oy = r.xh, r.yh
            norm = math.hypot(ox, oy)
            r.gx, r.gy = ox, oy
            if norm >= threshold:
                s = 1.0 / -norm
                r.ux, r.uy = ox * s, oy * s
        for r in self.rows:
            if not math.isfinite(r.ux):
                r.ux, r.uy = up_default(r.body)

    # -- readings -------------------------------------------------------------------------------

    def first_bad(self, bound: float) -> tuple[int, int] | None:
        """(row, column) of the first engine force component that is not finite or beyond
        ``bound`` (N), as :func:`playground.guard.first_bad` on the solver's engine rows."""
        for i, r in enumerate(self.rows):
            if not abs(r.ex) <= bound:
                return i, 0
            if not abs(r.ey) <= bound:
                return i, 1
        return None

    def engine(self, row: int) -> Vec:
        """The engine force of a row, N."""
        r = self.rows[row]
        return (r.ex, r.ey)

    def gravity(self, row: int) -> Vec:
        """The filtered perceived gravity of a row, m/s²."""
        r = self.rows[row]
        return (r.gx, r.gy)

    def up(self, row: int) -> Vec:
        """The held unit up of a row."""
        r = self.rows[row]
        return (r.ux, r.uy)

    def reading(self, row: int) -> BodyForces:
        """The readings of a row as :meth:`ForceSolver.reading` gives them (no contact split)."""
        r = self.rows[row]
        nan2 = (_NAN, _NAN)
        return BodyForces(
            valid=r.valid,
            engine=(r.ex, r.ey),
            engine_torque=r.et,
            support=(r.sx, r.sy),
            specific=r.sp,
            passive=(r.px, r.py),
            applied=(r.ax, r.ay),
            contact=nan2,
            contact_normal=nan2,
            contact_friction=nan2,
            constraint=nan2,
            split_valid=False,
        )


def _xy(z: complex) -> tuple[float, float]:
    return float(z.real), float(z.imag)


def _median_step(r: _Row, x: float, y: float) -> tuple[float, float]:
    """Push (x, y) into the row's window and return the vector median (Median3's rule)."""
    if not r.m_started:
        r.s0 = r.s1 = r.s2 = (x, y)
        r.m_started = True
        return x, y
    r.s0, r.s1, r.s2 = r.s1, r.s2, (x, y)
    a, b, c = r.s0, r.s1, r.s2
    d_ab = math.hypot(a[0] - b[0], a[1] - b[1])
    d_bc = math.hypot(b[0] - c[0], b[1] - c[1])
    d_ac = math.hypot(a[0] - c[0], a[1] - c[1])
    if d_ac >= d_ab and d_ac >= d_bc:
        return b
    if d_bc >= d_ab:
        return a
    return c
