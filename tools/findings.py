"""Where each knob of the accuracy sweep stops paying, read off its rows (:class:`Findings`):
the solver iterations the stack needs, the largest dt each scene tolerates at 1 %, the hover's
1 % crossing, substeps against a smaller dt, finite differences against reverse integration, and
the cost of a reading. Each threshold is read by a function of its own.
"""

from __future__ import annotations

import itertools
import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass, field

from playground.bench.accuracy import DTS, ITERATIONS, Result
from playground.bench.scenes import SCENES, Knobs
from playground.bench.sweep_rows import BASE, ONE_PERCENT, pick

__all__ = ["ROUND_OFF", "STOPS_PAYING", "Findings", "findings"]

STOPS_PAYING = 0.1
"""A knob stops paying once more of it lowers the error by less than 10 % (relative)."""

ROUND_OFF = 1e-6
"""Relative errors below this are round-off: a knob that only moves them has stopped paying."""


@dataclass(frozen=True, slots=True)
class Findings:
    """Where each knob stops paying, read off the sweep (NaN or 0 where not measured).

    Attributes:
        stack_iterations: iterations past which the stack's error falls by less than 10 %.
        stack_iterations_1pct: fewest iterations with the stack's error under 1 %.
        stack_errors: (iterations, error) of the stack at each swept iteration count.
        hover_dt: largest dt (s) with the hover oscillation's error under 1 %.
        hover_errors: (dt in s, error) of the hover at each swept dt.
        dt_1pct: per scene, the largest dt (s) with error under 1 % (NaN: none).
        substep_hover: hover error at dt 1/30 with 4 substeps, and at dt 1/120 with 1.
        substep_cost: cost of the same two, ms of computing per simulated second.
        fd_over_reverse: median over scenes of finite-difference error / reverse error.
        reverse_us, bare_us: median cost per step at the base knobs, µs.
        plateau: per scene, the iteration count past which its error falls by less than 10 %.
        hover_dt_interpolated: dt (s) where the hover error crosses 1 %, interpolated on the
            log-log line between the swept steps that bracket it.
        stack_iterations_01pct: fewest iterations with the stack's error under 0.1 %.
    """

    stack_iterations: int
    stack_iterations_1pct: int
    stack_errors: tuple[tuple[int, float], ...]
    hover_dt: float
    hover_errors: tuple[tuple[float, float], ...]
    dt_1pct: dict[str, float]
    substep_hover: tuple[float, float]
    substep_cost: tuple[float, float]
    fd_over_reverse: float
    reverse_us: float
    bare_us: float
    plateau: dict[str, int] = field(default_factory=dict)
    hover_dt_interpolated: float = math.nan
    stack_iterations_01pct: int = 0


def _stops_paying(values: Sequence[float]) -> int:
    """Index of the first value within :data:`STOPS_PAYING` of the best at or after it (or
    below :data:`ROUND_OFF`).

    >>> _stops_paying([0.3, 0.1, 0.095, 0.094]), _stops_paying([1e-3, 1e-9, 1e-15])
    (1, 1)
    """
    for i, v in enumerate(values):
        if v <= min(values[i:]) * (1.0 + STOPS_PAYING) or v < ROUND_OFF:
            return i
    return len(values) - 1


def _errors(
    rows: Sequence[Result], knobs: Sequence[tuple[float, Knobs]], scene: str
) -> list[tuple[float, float]]:
    """(knob value, error) of ``scene`` at each of ``knobs`` the sweep ran it at."""
    return [(v, r.error) for v, k in knobs if (r := pick(rows, k).get(scene)) is not None]


def _iterations(rows: Sequence[Result], scene: str) -> list[tuple[float, float]]:
    return _errors(rows, [(i, Knobs(iterations=i)) for i in ITERATIONS], scene)


def _first_under(errors: Sequence[tuple[float, float]], limit: float) -> int:
    """The first knob value whose error is under ``limit`` (0: none)."""
    return int(next((v for v, e in errors if e < limit), 0))


def _largest_good_dt(swept: Sequence[tuple[float, float]]) -> float:
    """The largest dt from which every smaller dt is also under 1 % (``swept``: largest dt
    first; NaN: none)."""
    good = math.nan
    for dt, error in reversed(swept):
        if error >= ONE_PERCENT:
            break
        good = dt
    return good


def _crossing(hover: Sequence[tuple[float, float]]) -> float:
    """dt (s) where the hover error crosses 1 %, interpolated on the log-log line between the
    swept steps that bracket it (NaN: it does not cross)."""
    crossing = math.nan
    for (dt0, e0), (dt1, e1) in itertools.pairwise(hover):
        if e0 >= ONE_PERCENT > e1 and e0 > 0 and e1 > 0:
            t = math.log(e0 / ONE_PERCENT) / math.log(e0 / e1)
            crossing = math.exp(math.log(dt0) + t * (math.log(dt1) - math.log(dt0)))
    return crossing


def _fd_over_reverse(rows: Sequence[Result]) -> float:
    """Median over scenes of finite-difference error / reverse error (the landing left out)."""
    base, fd = pick(rows, BASE), pick(rows, BASE, "finite-difference")
    ratios = [
        fd[s].error / base[s].error
        for s in fd
        if s in base and base[s].error > 0 and s != "landing"
    ]
    return statistics.median(ratios) if ratios else math.nan


def _hover_at(r: Result | None) -> tuple[float, float]:
    """The hover's error and its cost in ms of computing per simulated second (NaN: not run)."""
    if r is None:
        return math.nan, math.nan
    return r.error, r.cost_us / r.dt / 1000.0


def _substeps(rows: Sequence[Result]) -> tuple[tuple[float, float], tuple[float, float]]:
    """The hover's (errors, costs) at dt 1/30 s with 4 substeps and at dt 1/120 s with 1."""
    sub = _hover_at(pick(rows, Knobs(dt=1 / 30, substeps=4)).get("hover"))
    plain = _hover_at(pick(rows, BASE).get("hover"))
    return (sub[0], plain[0]), (sub[1], plain[1])


def findings(rows: Sequence[Result]) -> Findings:
    """Read the thresholds of :class:`Findings` off the sweep's rows."""
    stack = _iterations(rows, "stack")
    dts = sorted((dt for dt in DTS if pick(rows, Knobs(dt=dt))), reverse=True)
    by_dt = [(dt, Knobs(dt=dt)) for dt in dts]
    dt_1pct = {
        scene: _largest_good_dt(swept) for scene in SCENES if (swept := _errors(rows, by_dt, scene))
    }
    plateau = {
        scene: int(swept[_stops_paying([e for _, e in swept])][0])
        for scene in SCENES
        if (swept := _iterations(rows, scene))
    }
    hover = _errors(rows, by_dt, "hover")
    substep_hover, substep_cost = _substeps(rows)
    base = pick(rows, BASE)
    return Findings(
        plateau=plateau,
        hover_dt_interpolated=_crossing(hover),
        stack_iterations_01pct=_first_under(stack, ONE_PERCENT / 10),
        stack_iterations=int(stack[_stops_paying([e for _, e in stack])][0]) if stack else 0,
        stack_iterations_1pct=_first_under(stack, ONE_PERCENT),
        stack_errors=tuple((int(i), e) for i, e in stack),
        hover_dt=dt_1pct.get("hover", math.nan),
        hover_errors=tuple(hover),
        dt_1pct=dt_1pct,
        substep_hover=substep_hover,
        substep_cost=substep_cost,
        fd_over_reverse=_fd_over_reverse(rows),
        reverse_us=statistics.median(r.cost_us for r in base.values()) if base else math.nan,
        bare_us=statistics.median(r.bare_us for r in base.values()) if base else math.nan,
    )
