"""The tread-ahead test of a crowd's walking members on arrays (:func:`may_step_up`): which of
them may find a tread to step up onto, and so run their own step."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from playground._engine.sweep import NO_HIT, Sweeps
from playground.controller import stairs
from playground.controller.crowd.groups import ConfigArrays
from playground.controller.elementwise import ARRAYS

__all__ = ["may_step_up"]

_COS_TREAD_PARALLEL = math.cos(stairs.TREAD_PARALLEL)


def may_step_up(
    sweeps: Sweeps,
    per_config: ConfigArrays,
    walking: NDArray[np.bool_],
    px: NDArray[np.float64],
    py: NDArray[np.float64],
    rvx: NDArray[np.float64],
    rvy: NDArray[np.float64],
    ux: NDArray[np.float64],
    uy: NDArray[np.float64],
    move: NDArray[np.float64],
    ground: NDArray[np.float64],
) -> NDArray[np.bool_]:
    """Which ``walking`` members (their probe found a walkable static ground, its hit point
    and normal in ``ground``'s first four rows; (rvx, rvy) their velocity relative to it,
    m/s) may find a tread ahead to step up onto (:func:`~playground.controller.stairs.
    step_up` not None): their own step runs. The ray and the tests are those of
    :func:`~playground.controller.stairs.ahead`, the same float operations on arrays, and
    the rays are cast in one call; a tread on a one-way platform counts as found (the
    platform may let the ray pass). ``sweeps`` casts the members' rays; ``per_config`` holds
    what the test reads of their configs."""
    k = per_config
    hx, hy, nx, ny = ground[0], ground[1], ground[2], ground[3]
    walk = walking & (nx * ux + ny * uy >= k.cos_slope)
    direction = np.sign(move)  # 1.0 or -1.0 where walking (move ≠ 0)
    speed = direction * ((rvx * ny) - (rvy * nx))
    tx, ty = direction * ny, -direction * nx
    d = k.front + ARRAYS.max(0.0, speed) * 0.5 / k.hover_frequency
    fx, fy = px - nx * k.ride_height, py - ny * k.ride_height
    ax, ay = fx + tx * d + nx * k.reach, fy + ty * d + ny * k.reach
    depth = (ax - hx) * nx + (ay - hy) * ny - k.clearance
    bx, by = ax - nx * depth, ay - ny * depth
    rows = (walk & (depth > 0.0)).nonzero()[0]
    may = np.zeros(len(walking), dtype=bool)
    if not len(rows):
        return may
    of = slice(None) if len(rows) == len(walking) else rows  # every row: a view
    treads = sweeps.nearest(rows, ax[of], ay[of], bx[of], by[of], 0.0)
    tread_of = treads.shape
    seen = tread_of != NO_HIT
    if not seen.any():
        return may
    r = rows[seen]
    sx, sy, mx, my = treads.point_normal[:, seen]
    no_body = np.array([s.body is None for s in treads.shapes], dtype=bool)
    hx, hy, nx, ny = hx[r], hy[r], nx[r], ny[r]
    no_step = (
        ((sx == bx[r]) & (sy == by[r]))
        | ((sx - hx) * nx + (sy - hy) * ny <= k.clearance[r])
        | (mx * nx + my * ny < _COS_TREAD_PARALLEL)
        | no_body[tread_of[seen]]
    )
    may[r] = ~no_step
    return may
