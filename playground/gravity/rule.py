"""Gravity rules: how one body departs from the field (a scale, optionally its own direction).

The rule's formula is written once, :func:`ruled`, for one body in plain floats and for columns
of bodies alike: :meth:`GravityRule.apply` (the controller, the gravity stage for one body), the
plain-float field (:mod:`playground.gravity.plain`) and :func:`apply_rules` (the vectorised stage)
all call it, so they agree bit for bit. Accelerations in m/s².
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, overload

import numpy as np
from numpy.typing import NDArray

from playground.gravity.field import Points
from playground.limits import MAX_GRAVITY_SCALE
from playground.params import bounded, unit
from playground.vec import Vec

__all__ = ["GravityRule", "apply_rules", "ruled"]

Column = NDArray[np.float64]
"""One component of many bodies' accelerations, m/s²."""


@overload
def ruled(gx: float, gy: float, scale: float, direction: Vec | None) -> Vec: ...


@overload
def ruled(
    gx: Column, gy: Column, scale: Column, direction: tuple[Column, Column] | None
) -> tuple[Column, Column]: ...


def ruled(gx: Any, gy: Any, scale: Any, direction: Any) -> Any:
    """The gravity (m/s²) of a body with a rule's ``scale`` and unit ``direction`` (None: the
    field's own) where the field is (gx, gy): ``scale · g``, or ``scale · |g| · direction``.
    Floats for one body, or numpy columns for many: the same operations in the same order.
    |g| is the C library's ``hypot`` both ways (``abs`` of a complex number is ``np.hypot``
    bit for bit; ``math.hypot`` is not).

    >>> ruled(0.0, -9.81, 0.5, None), ruled(3.0, -4.0, 2.0, (1.0, 0.0))
    ((0.0, -4.905), (10.0, 0.0))
    """
    if direction is None:
        return (gx * scale, gy * scale)
    norm = np.hypot(gx, gy) if isinstance(gx, np.ndarray) else abs(complex(gx, gy))
    mag = norm * scale
    return (direction[0] * mag, direction[1] * mag)


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

    def apply(self, gx: float, gy: float) -> Vec:
        """This rule's gravity where the field is (gx, gy), m/s² (:func:`ruled`).

        >>> GravityRule(scale=2.0, direction=(1.0, 0.0)).apply(3.0, -4.0)
        (10.0, 0.0)
        """
        return ruled(gx, gy, self.scale, self.direction)


def apply_rules(field_g: Points, scale: NDArray[np.float64], direction: Points) -> Points:
    """Per-body gravity from the field at each body and its rule, vectorised.

    ``direction`` rows are NaN where a body keeps the field's direction.
    """
    g: Points = np.empty_like(field_g)
    g[:, 0], g[:, 1] = ruled(field_g[:, 0], field_g[:, 1], scale, None)
    own = ~np.isnan(direction[:, 0])
    if own.any():
        field_own = field_g[own]
        g[own, 0], g[own, 1] = ruled(
            field_own[:, 0], field_own[:, 1], scale[own], (direction[own, 0], direction[own, 1])
        )
    return g
