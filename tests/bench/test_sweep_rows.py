"""Reading the sweep's rows (:mod:`playground.bench.sweep_rows`): the Pareto front is not
dominated, and the bookkeeping scenes stay out of every configuration's mean."""

from __future__ import annotations

import pytest

from playground.bench.accuracy import Result
from playground.bench.sweep_rows import bookkeeping, configurations, pareto


def test_pareto_front_is_not_dominated(rows: list[Result]) -> None:
    """Law: no configuration is both cheaper and more accurate than one on the front."""
    configs = configurations(rows)
    pts = [(c.cost_ms, c.error) for c in configs]
    front = pareto(pts)
    assert front
    for i in front:
        assert not any(c < pts[i][0] and e < pts[i][1] for c, e in pts)


def test_bookkeeping_scenes_stay_out_of_the_means(rows: list[Result]) -> None:
    """Law: a scene that reads a constant back exactly (rest) is bookkeeping and no
    configuration's mean includes it; a scene with a real error (the stack) is not."""
    books = bookkeeping(rows)
    assert "rest" in books and "stack" not in books and "hover" not in books
    configs = configurations(rows)
    base = [c for c in configs if c.label.startswith("dt 1/120×1, 10 it, reverse, none")]
    (c,) = base
    real = [r.error for r in rows if r.scene in {"stack", "hover"} and r.iterations == 10
            and r.dt == 1 / 120 and r.estimator == "reverse" and r.filter == "none"]  # fmt: skip
    assert c.error == pytest.approx(sum(real) / len(real))
