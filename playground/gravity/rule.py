"""Gravity rules: how one body departs from the field (a scale, optionally its own direction).

The rule's formula lives here once (:meth:`GravityRule.apply` for one body in plain floats,
:func:`apply_rules` for rows of bodies); the controller, the scalar path and the gravity stage
all call it. Accelerations in m/s².
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from playground.gravity.field import Points
from playground.limits import MAX_GRAVITY_SCALE
from playground.params import bounded, unit
from playground.vec import Vec

__all__ = ["GravityRule", "apply_rules"]


@dataclass(frozen=True, slots=True)
class GravityRule:
    """How one body departs from the field: a scale, and optionally its own direction.

    The body's gravity is ``scale · field`` or, with a ``direction``,
    ``scale · |field| · direction`` (a unit vector). ``GravityRule(scale=0)`` nullifies gravity.

    >>> GravityRule(direction=(0.0, 2.0)).direction
    (0.0, 1.0)
    """

    scale: float = 1.0
    direction: Vec | None = None

    def __post_init__(self) -> None:
        bounded("scale", self.scale, MAX_GRAVITY_SCALE, "× the field")
        if self.direction is not None:
            object.__setattr__(self, "direction", unit("direction", self.direction))

    @property
    def is_default(self) -> bool:
        return self.scale == 1.0 and self.direction is None


def apply_rules(field_g: Points, scale: NDArray[np.float64], direction: Points) -> Points:
    """Per-body gravity from the field at each body and its rule, vectorised.

    ``direction`` rows are NaN where a body keeps the field's direction.
    """
    g = field_g * scale[:, None]
    own = ~np.isnan(direction[:, 0])
    if own.any():
        mag = np.hypot(field_g[own, 0], field_g[own, 1]) * scale[own]
        g[own] = direction[own] * mag[:, None]
    return g
