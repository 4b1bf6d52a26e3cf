"""What every chapter's simulations share (docs/chapters): the levels' gravity and step, loading
a shipped level, and recording a run as rows of numbers."""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import Any

import numpy as np
from numpy.typing import NDArray

from playground.gravity import STANDARD_GRAVITY
from playground.level.document import Level
from playground.scene import Scene
from playground.world.world import World

Array = NDArray[np.float64]

G = STANDARD_GRAVITY
"""Standard gravity of the levels, m/s² (short for the chapters' formulas)."""

DT = 1.0 / 120.0
"""The levels' step, s."""


@cache
def shipped_level(name: str) -> Level:
    """A shipped level, loaded and validated once per process.

    >>> shipped_level("bounce").settings.seconds > 0.0
    True
    """
    from playground.level.files import find
    from playground.level.loading import load

    return load(find(name))


def level_scene(name: str, **settings: Any) -> Scene:
    """Build a shipped level, optionally with some of its settings changed."""
    from playground.scene import build

    level = shipped_level(name)
    if settings:
        level = level.model_copy(update={"settings": level.settings.model_copy(update=settings)})
    return build(level)


def record(world: World, seconds: float, probe: Callable[[World], list[float]]) -> Array:
    """Step ``world`` for ``seconds`` and stack ``[t, *probe(world)]`` after every step.

    >>> rows = record(World(), 0.05, lambda w: [w.steps])
    >>> rows.shape, rows[-1].tolist() == [6 / 120, 6.0]
    ((6, 2), True)
    """
    rows: list[list[float]] = []
    for _ in range(round(seconds / world.config.dt)):
        world.step()
        rows.append([world.time, *probe(world)])
    return np.array(rows, dtype=np.float64)
