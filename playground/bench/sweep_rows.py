"""Reading the accuracy sweep's rows: the rows at given knobs, the scenes that only check the
bookkeeping, each configuration's mean error and cost, and the Pareto fronts of error against
cost.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass

from playground.bench.accuracy import Result
from playground.bench.markdown import dt_label
from playground.bench.scenes import SCENES, Knobs

__all__ = [
    "BASE",
    "BOOKKEEPING_ERROR",
    "ONE_PERCENT",
    "Config",
    "bookkeeping",
    "configurations",
    "knobs_of",
    "pareto",
    "pick",
    "scene_fronts",
]

ONE_PERCENT = 0.01
"""The error a reader calls "accurate": 1 % of the scene's force scale."""

BASE = Knobs()
"""The sweep's centre: every knob at its default (dt = 1/120 s, 1 substep, 10 iterations)."""


def knobs_of(r: Result) -> Knobs:
    """The knobs a row ran at."""
    return Knobs(dt=r.dt, substeps=r.substeps, iterations=r.iterations)


def pick(
    rows: Sequence[Result], knobs: Knobs, estimator: str = "reverse", filt: str = "none"
) -> dict[str, Result]:
    """The rows at ``knobs`` for one estimator and filter, by scene."""
    return {
        r.scene: r
        for r in rows
        if knobs_of(r) == knobs and r.estimator == estimator and r.filter == filt
    }


@dataclass(frozen=True, slots=True)
class Config:
    """One configuration across scenes: its mean error and its mean cost in ms of computing per
    simulated second (µs per step / dt: a smaller dt takes more steps), for the front."""

    label: str
    estimator: str
    error: float
    cost_ms: float


BOOKKEEPING_ERROR = ONE_PERCENT / 10
"""A scene whose median unfiltered reverse-integration error over the swept settings is below this
(a tenth of what a reader calls accurate) reads a constant force back almost exactly at any
setting: it checks the bookkeeping, and cannot rank settings."""


def bookkeeping(rows: Sequence[Result]) -> list[str]:
    """Scenes whose reading is a bookkeeping identity (see :data:`BOOKKEEPING_ERROR`).

    >>> r = Result("rest", 0.01, 1, 10, "reverse", "none", 1e-12, 0.0, 0.0, 5.0, 4.0, 1.25)
    >>> bookkeeping([r])
    ['rest']
    """
    out = []
    for scene in SCENES:
        errs = [
            r.error
            for r in rows
            if r.scene == scene and r.estimator == "reverse" and r.filter == "none"
        ]
        if errs and statistics.median(errs) < BOOKKEEPING_ERROR:
            out.append(scene)
    return out


def configurations(rows: Sequence[Result]) -> list[Config]:
    """Mean error and mean cost of each (knobs, estimator, filter) over the scenes it ran,
    bookkeeping scenes left out (they are ~0 for every setting and would only dilute the mean)."""
    groups: dict[tuple[Knobs, str, str], list[Result]] = {}
    skip = set(bookkeeping(rows))
    for r in rows:
        if r.scene in skip:
            continue
        groups.setdefault((knobs_of(r), r.estimator, r.filter), []).append(r)
    out = []
    for (k, est, filt), rs in groups.items():
        label = f"dt {dt_label(k.dt)}×{k.substeps}, {k.iterations} it, {est}, {filt}"
        out.append(
            Config(
                label,
                est,
                statistics.fmean(r.error for r in rs),
                statistics.fmean(r.cost_us / r.dt / 1000.0 for r in rs),
            )
        )
    return out


def pareto(points: Sequence[tuple[float, float]]) -> list[int]:
    """Indices of the (cost, error) points no other point beats on both, by rising cost.

    >>> pareto([(1.0, 5.0), (2.0, 3.0), (3.0, 4.0), (4.0, 1.0)])
    [0, 1, 3]
    """
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def scene_fronts(rows: Sequence[Result]) -> dict[str, list[Result]]:
    """Per scene that is not bookkeeping: its rows no other row of the scene beats on both error
    and cost per simulated second, cheapest first."""
    out = {}
    skip = set(bookkeeping(rows))
    for scene in SCENES:
        rs = [r for r in rows if r.scene == scene]
        if scene in skip or not rs:
            continue
        idx = pareto([(r.cost_us / r.dt / 1000.0, r.error) for r in rs])
        out[scene] = [rs[i] for i in idx]
    return out
