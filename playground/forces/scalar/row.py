"""One tracked body's state in the scalar implementation, in plain floats.

A :class:`Row` holds what :class:`~playground.forces.solver.ForceSolver` and
:class:`~playground.gravity.PerceivedGravity` keep in one row of their arrays: the step's
inputs (v₀, ω₀, forces, the field's force), its readings (N, m/s²), the contact split's sums and
results, and the filter's state (median-of-3 window, 1€ estimate and derivative, held up).
"""

from __future__ import annotations

import math

import pymunk

from playground._engine import raw

__all__ = ["Row"]

_NAN = math.nan


class Row:
    """One tracked body's per-step state and readings, in plain floats."""

    __slots__ = (
        "at",
        "ax",
        "ay",
        "body",
        "cnx",
        "cny",
        "cx",
        "cy",
        "dxh",
        "dyh",
        "et",
        "ex",
        "ey",
        "ffx",
        "ffy",
        "ft",
        "fx",
        "fy",
        "gx",
        "gy",
        "h",
        "i_dt",
        "inv_m",
        "j",
        "kx",
        "ky",
        "locked",
        "m",
        "m_dt",
        "m_started",
        "moment",
        "px",
        "py",
        "qw",
        "qx",
        "qy",
        "s0",
        "s1",
        "s2",
        "seen",
        "sp",
        "split",
        "st",
        "started",
        "sx",
        "sy",
        "unknown",
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
        self.h = raw.handle(body)
        """The body's ``cpBody*``: its state is read through :mod:`playground._engine.raw`."""
        self.m = self.moment = self.inv_m = self.m_dt = self.i_dt = 0.0
        self.locked = False
        # inputs: v₀, ω₀, v, ω after the last substep, forces integrated, the field's part
        self.v0x = self.v0y = self.v0w = self.vx = self.vy = self.vw = 0.0
        self.qx = self.qy = self.qw = 0.0  # Σ v, ω over the substeps but the last
        self.fx = self.fy = self.ft = 0.0
        self.ffx = self.ffy = 0.0
        self.seen = self.valid = False
        # readings: engine (x, y, torque), support, specific, passive, applied
        self.ex = self.ey = self.et = 0.0
        self.sx = self.sy = self.st = 0.0
        self.sp = (0.0, 0.0)
        self.px = self.py = 0.0
        self.ax = self.ay = self.at = 0.0
        # contact split: this step's impulse sums (jx, jy, jnx, jny: Σ J and its normal parts,
        # N·s) and unknown flag; contact, its normal part and the constraint's (N), NaN until
        # known
        self.j = (0.0, 0.0, 0.0, 0.0)
        self.unknown = False
        self.cx = self.cy = self.cnx = self.cny = self.kx = self.ky = _NAN
        self.split = False
        # filter: 1€ state (X̂, Ẋ̂), median-of-3 window, perceived gravity and up
        self.started = self.m_started = False
        self.xh = self.yh = self.dxh = self.dyh = 0.0
        self.s0 = self.s1 = self.s2 = (0.0, 0.0)
        self.gx = self.gy = 0.0
        self.ux = self.uy = _NAN
