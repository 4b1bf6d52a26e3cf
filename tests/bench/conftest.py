"""The benchmarks' tests share one small accuracy sweep (seconds, not minutes), run once."""

from __future__ import annotations

import pytest

from playground.bench.accuracy import Point, Result, sweep
from playground.bench.scenes import Knobs

POINTS = [
    Point("hover", Knobs(dt=1 / 30), "reverse"),
    Point("hover", Knobs(dt=1 / 120), "reverse"),
    Point("rest", Knobs(), "reverse"),
    Point("rest", Knobs(), "contact"),
    Point("rest", Knobs(), "finite-difference"),
    Point("stack", Knobs(iterations=2), "reverse"),
    Point("stack", Knobs(), "reverse"),
    Point("grip", Knobs(), "reverse"),
]


@pytest.fixture(scope="session")
def points() -> list[Point]:
    """The sweep's points: two dts of the hover, every estimator at rest, two iteration counts
    of the stack, the grip."""
    return list(POINTS)


@pytest.fixture(scope="session")
def rows() -> list[Result]:
    """The sweep of :func:`points`, one block each, in this process."""
    return sweep(POINTS, workers=0, progress=False, repeats=1)
