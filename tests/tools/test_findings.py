"""Where each knob stops paying (:mod:`tools.findings`), read off hand-made rows whose
answers are known: the stack's iterations, each scene's largest good dt, the hover's interpolated
1 % crossing, substeps against a smaller dt, finite differences against reverse integration."""

from __future__ import annotations

import math

import pytest

from playground.bench.accuracy import Result
from tools.findings import findings


def row(
    scene: str,
    error: float,
    *,
    dt: float = 1 / 120,
    substeps: int = 1,
    iterations: int = 10,
    estimator: str = "reverse",
    cost_us: float = 50.0,
) -> Result:
    return Result(scene, dt, substeps, iterations, estimator, "none", error, 0.0, 0.0,
                  cost_us, 5.0, cost_us / 5.0)  # fmt: skip


STACK = {1: 0.3, 2: 0.1, 4: 0.02, 10: 0.005, 20: 0.0009, 40: 0.00085}
"""The stack's error by iterations: under 1 % from 10, under 0.1 % from 20, flat past 20."""

HOVER = {1 / 30: 0.08, 1 / 60: 0.04, 1 / 120: 0.02, 1 / 240: 0.005, 1 / 480: 0.0025}
"""The hover's error by dt: under 1 % only at 1/240 and 1/480 (the iterations' rows at 1/120
repeat the 1/120 value)."""


INCLINE = {1 / 30: 0.005, 1 / 60: 0.02, 1 / 120: 0.005}
"""An incline good at 1/30 s but not at 1/60 s: its largest good dt is 1/120 s, from which every
smaller dt is good too."""


def rows() -> list[Result]:
    out = [row("stack", e, iterations=i) for i, e in STACK.items()]
    out += [row("hover", e, dt=dt) for dt, e in HOVER.items() if dt != 1 / 120]
    out += [row("hover", HOVER[1 / 120], iterations=i) for i in (1, 10)]
    out.append(row("hover", 0.03, dt=1 / 30, substeps=4, cost_us=80.0))
    out += [row("incline", e, dt=dt) for dt, e in INCLINE.items()]
    out.append(row("hover", 0.06, estimator="finite-difference"))
    out.append(row("stack", 0.01, estimator="finite-difference"))
    out.append(row("landing", 0.01))
    out.append(row("landing", 0.1, estimator="finite-difference"))
    return out


def test_the_stack_needs_its_iterations() -> None:
    f = findings(rows())
    assert (f.stack_iterations_1pct, f.stack_iterations_01pct) == (10, 20)
    assert f.stack_iterations == 20, "40 lowers the error by less than 10 %"
    assert f.stack_errors == tuple(STACK.items())
    assert f.plateau["stack"] == 20


def test_the_largest_good_dt_and_the_interpolated_crossing() -> None:
    f = findings(rows())
    assert f.hover_dt == 1 / 240
    assert f.dt_1pct["hover"] == 1 / 240
    assert f.dt_1pct["stack"] == 1 / 120, "its only swept dt, under 1 %"
    assert f.dt_1pct["incline"] == 1 / 120, "1/30 s is good, but 1/60 s is not"
    # log-log between (1/120, 2 %) and (1/240, 0.5 %): 1 % at half the log distance
    assert f.hover_dt_interpolated == pytest.approx(1 / 120 / 2**0.5, rel=1e-12)


def test_substeps_finite_differences_and_costs() -> None:
    f = findings(rows())
    assert f.substep_hover == (0.03, 0.02)
    assert f.substep_cost == pytest.approx((80.0 * 30 / 1000, 50.0 * 120 / 1000))
    # hover 3×, stack 2×: the landing's 10× (an impulse over a window, not a force) is left out
    assert f.fd_over_reverse == pytest.approx((0.06 / 0.02 + 0.01 / 0.005) / 2)
    assert (f.reverse_us, f.bare_us) == (50.0, 5.0)


def test_nothing_swept_reads_as_not_measured() -> None:
    f = findings([])
    assert (f.stack_iterations, f.stack_iterations_1pct, f.stack_errors) == (0, 0, ())
    assert math.isnan(f.hover_dt) and math.isnan(f.hover_dt_interpolated)
    assert f.dt_1pct == {} and f.plateau == {}
    assert all(math.isnan(v) for v in (*f.substep_hover, *f.substep_cost, f.fd_over_reverse))
