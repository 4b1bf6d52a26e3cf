"""Moving the tracked bodies' state between the batch and the scalar implementation.

At a plan change (never per step) the world hands the state of
:class:`~playground.forces.solver.ForceSolver` and :class:`~playground.gravity.PerceivedGravity`
(readings, the contact split, the pairs of recent substeps, the filters' state) to the scalar
implementation's rows (:func:`load`), and back (:func:`store`), so a run gives one answer
whichever served each step.
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np
from numpy.typing import NDArray

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import OneEuroFilter
from playground.forces.scalar.row import Row
from playground.forces.solver import ForceSolver
from playground.gravity import PerceivedGravity

__all__ = ["Loaded", "load", "store"]

Loaded = tuple[list[Row], OneEuroFilter, bool, deque[tuple[int, frozenset[int]]]]
"""The rows, the 1€ stage, whether a median-of-3 stage runs before it, the recent pairs."""


def load(solver: ForceSolver, perceived: PerceivedGravity) -> Loaded:
    """The scalar implementation's state from the batch implementation's."""
    if solver._keys_dirty:
        solver._rebuild_keys()
    rows = []
    median, one_euro = _stages(perceived)
    for i, body in enumerate(solver.bodies):
        r = Row(body)
        r.ex, r.ey, r.et = (float(v) for v in solver._engine3[i])
        r.sx, r.sy, r.st = (float(v) for v in solver._support3[i])
        r.sp = (float(solver._specific2[i, 0]), float(solver._specific2[i, 1]))
        r.px, r.py = float(solver._passive3[i, 0]), float(solver._passive3[i, 1])
        r.ax, r.ay, r.at = (float(v) for v in solver._applied3[i])
        r.valid = bool(solver.valid[i])
        r.cx, r.cy = _xy(solver.contact[i])
        r.cnx, r.cny = _xy(solver.contact_normal[i])
        r.kx, r.ky = _xy(solver.constraint[i])
        r.split = bool(solver.split_valid[i])
        r.gx, r.gy = float(perceived.gravity[i, 0]), float(perceived.gravity[i, 1])
        r.ux, r.uy = float(perceived.up[i, 0]), float(perceived.up[i, 1])
        if one_euro._shape is not None and one_euro._init[i]:
            r.started = True
            r.xh, r.yh = _cxy(one_euro._xh[i])
            r.dxh, r.dyh = _cxy(one_euro._dxh[i])
        if median is not None and median._shape is not None and median._init[i]:
            r.m_started = True
            r.s0, r.s1, r.s2 = _cxy(median._s0[i]), _cxy(median._s1[i]), _cxy(median._s2[i])
        rows.append(r)
    history = deque(
        (stamp, frozenset(int(k) for k in keys)) for stamp, keys in solver._split._pairs
    )
    return rows, one_euro, median is not None, history


def store(
    rows: list[Row],
    history: deque[tuple[int, frozenset[int]]],
    solver: ForceSolver,
    perceived: PerceivedGravity,
) -> None:
    """Write the scalar implementation's state into the batch implementation's arrays."""
    solver._split._pairs = deque(
        (stamp, np.array(sorted(keys), dtype=np.uint64)) for stamp, keys in history
    )
    if not rows:
        return
    for i, r in enumerate(rows):
        solver._engine3[i] = (r.ex, r.ey, r.et)
        solver._support3[i] = (r.sx, r.sy, r.st)
        solver._specific2[i] = r.sp
        solver._passive3[i] = (r.px, r.py, 0.0)
        solver._applied3[i] = (r.ax, r.ay, r.at)
        solver.valid[i] = r.valid
        solver.contact[i] = (r.cx, r.cy)
        solver.contact_normal[i] = (r.cnx, r.cny)
        solver.constraint[i] = (r.kx, r.ky)
        solver.split_valid[i] = r.split
    if any(r.started for r in rows):
        _store_filters(rows, perceived)
    perceived.gravity = np.array([(r.gx, r.gy) for r in rows], dtype=float)
    perceived.up = np.array([(r.ux, r.uy) for r in rows], dtype=float)
    perceived.up_complete = all(math.isfinite(r.ux) for r in rows)


def _store_filters(rows: list[Row], perceived: PerceivedGravity) -> None:
    chain = perceived._filter
    shape = np.zeros((len(rows), 2))
    for stage in chain.stages if isinstance(chain, FilterChain) else (chain,):
        if not isinstance(stage, OneEuroFilter | Median3):
            continue
        if stage._shape is None:
            stage._fix_shape(shape)  # allocates every row, none started
        for i, r in enumerate(rows):
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


def _stages(perceived: PerceivedGravity) -> tuple[Median3 | None, OneEuroFilter]:
    """The filter's median-of-3 stage (if any) and its 1€ stage."""
    chain = perceived._filter
    stages = chain.stages if isinstance(chain, FilterChain) else (chain,)
    median = next((s for s in stages if isinstance(s, Median3)), None)
    one_euro = next(s for s in stages if isinstance(s, OneEuroFilter))
    return median, one_euro


def _xy(row: NDArray[np.float64]) -> tuple[float, float]:
    return float(row[0]), float(row[1])


def _cxy(z: complex) -> tuple[float, float]:
    return float(z.real), float(z.imag)
