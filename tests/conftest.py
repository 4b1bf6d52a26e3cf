"""Test-suite configuration: the ``slow`` tier, and the one small accuracy sweep (seconds, not
minutes) that the benchmarks' tests (tests/bench) and the accuracy page's (tests/tools) share.

Tests marked ``slow`` (the 5000-mutant fuzz, ten simulated minutes of standing still) are
deselected by default, so a developer's ``pytest -q`` stays quick. They run when

- the environment variable ``CI`` is set (``.ci/run`` sets ``CI=true``: CI runs everything), or
- a marker expression is given (``pytest -m slow`` runs only them, ``pytest -m "slow or not slow"``
  everything).
"""

from __future__ import annotations

import os

import pytest

from playground.bench.accuracy import Point, Result, sweep
from playground.bench.scenes import Knobs


def run_slow(config: pytest.Config) -> bool:
    """Whether this session runs the ``slow`` tier (see the module docstring)."""
    return bool(os.environ.get("CI")) or bool(config.getoption("markexpr"))


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Deselect the ``slow`` tests unless :func:`run_slow` says this session runs them."""
    if run_slow(config):
        return
    slow = [item for item in items if item.get_closest_marker("slow") is not None]
    if slow:
        config.hook.pytest_deselected(items=slow)
        items[:] = [item for item in items if item.get_closest_marker("slow") is None]


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


pytest_plugins = ["pytester"]
