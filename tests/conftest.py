"""Test-suite configuration: the ``slow`` tier.

Tests marked ``slow`` (the 5000-mutant fuzz, ten simulated minutes of standing still) are
deselected by default, so a developer's ``pytest -q`` stays quick. They run when

- the environment variable ``CI`` is set (``.ci/run`` sets ``CI=true``: CI runs everything), or
- a marker expression is given (``pytest -m slow`` runs only them, ``pytest -m "slow or not slow"``
  everything).
"""

from __future__ import annotations

import os

import pytest


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


pytest_plugins = ["pytester"]
