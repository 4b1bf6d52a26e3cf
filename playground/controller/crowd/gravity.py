"""The gravity a crowd's members feel, on arrays: each member's field and the up against it, and
its magnitude, read again only when the field or a rule changed (:class:`Gravities`); and the
test of a perceived gravity too weak to give an up (:func:`below`)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from playground._engine.state import space_gravity
from playground.controller._vec import unit_or
from playground.controller.elementwise import ARRAYS
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["Gravities", "below"]


class Gravities:
    """Each member's gravity (m/s²), the unit up against it, whether it has any
    (:meth:`read`) and its magnitude (:meth:`weight_per_kg`)."""

    __slots__ = ("_g", "_g_norm", "_gravity_key")

    def __init__(self) -> None:
        self._gravity_key: tuple[int, float, float] | None = None
        self._g: tuple[Any, ...] = ()
        self._g_norm: tuple[Any, NDArray[np.float64]] = (None, np.zeros(0))

    def read(self, world: World, members: list[Controller]) -> tuple[Any, Any, Any, Any, Any]:
        """Each member's gravity (its rule on the uniform field), the unit up against it, and
        whether it has any: read again only when the field or a rule changed."""
        g = space_gravity(world.space)
        key = (world.gravity_version, g[0], g[1])
        if key != self._gravity_key or len(self._g[0]) != len(members):
            gs = [world.gravity_rule(c.name).apply(g[0], g[1]) for c in members]
            ups = [unit_or(-a, -b, (math.nan, math.nan)) for a, b in gs]
            self._g = (
                np.array([a for a, _ in gs]),
                np.array([b for _, b in gs]),
                np.array([u for u, _ in ups]),
                np.array([v for _, v in ups]),
                np.array([not math.isnan(u) for u, _ in ups]),
            )
            self._gravity_key = key
        return self._g

    def weight_per_kg(self) -> NDArray[np.float64]:
        """Each member's |g| (``math.hypot``, as its own step), m/s²: read again with the
        gravity (:meth:`read`)."""
        if self._g_norm[0] is not self._g:
            self._g_norm = (self._g, ARRAYS.hypot(self._g[0], self._g[1]))
        return self._g_norm[1]


def below(pg: NDArray[np.float64], threshold: float) -> NDArray[np.bool_]:
    """``math.hypot(gx, gy) < threshold`` row by row, to the last bit: the sum of squares
    decides all but the rows within 1e-12 of the threshold, which ``math.hypot`` does."""
    s = pg[:, 0] * pg[:, 0] + pg[:, 1] * pg[:, 1]
    lo, hi = (threshold * (1.0 - 1e-12)) ** 2, (threshold * (1.0 + 1e-12)) ** 2
    if len(s) and s.min() > hi:  # every row clear above it (the usual step); NaN is not
        return np.zeros(len(s), dtype=bool)
    below = s < lo
    for i in ((s >= lo) & (s <= hi)).nonzero()[0].tolist():  # near it (NaN is not)
        below[i] = math.hypot(pg[i, 0], pg[i, 1]) < threshold
    return below
