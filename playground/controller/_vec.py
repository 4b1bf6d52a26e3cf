"""Helpers on plane vectors (:data:`playground.vec.Vec`, plain float pairs), the controller's
currency: a Vec2d read from pymunk is copied into one at once (each read builds a new Vec2d).

>>> unit_or(3.0, 4.0, ZERO)
(0.6, 0.8)
>>> scaled((0.0, 2.0), 5.0)
(0.0, 5.0)
"""

from __future__ import annotations

import math

from playground.vec import Vec

__all__ = ["ZERO", "scaled", "unit_or"]

ZERO: Vec = (0.0, 0.0)


def unit_or(x: float, y: float, fallback: Vec) -> Vec:
    """(x, y) made unit length, or ``fallback`` if it has no length."""
    n = math.hypot(x, y)
    return (x / n, y / n) if n > 0.0 else fallback


def scaled(direction: Vec, magnitude: float) -> Vec:
    """``direction`` made unit length and scaled to ``magnitude`` (zero if it has no length)."""
    ux, uy = unit_or(direction[0], direction[1], ZERO)
    return (ux * magnitude, uy * magnitude)
