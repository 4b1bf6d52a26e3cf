"""Members sharing a config: a crowd's config groups (:class:`Group`), the arrays it reads of
each member's config (:class:`ConfigArrays`) and the writer of a group's rows of the step's
arrays (:class:`Rows`)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from playground._engine.state import BodyState
from playground.controller.config import ControllerConfig

__all__ = ["ConfigArrays", "Group", "Rows"]

_BodyState: Any = BodyState  # called on arrays (typed for floats, written for both)


class Group:
    """Members sharing one config (equal configs: one group): their rows, a slice where they
    follow one another (one config for all: every row), which indexes a view, not a copy."""

    __slots__ = ("_gravity", "config", "cos_slope", "rows", "size")

    def __init__(self, config: ControllerConfig, rows: list[int]) -> None:
        self.config = config
        first, last = rows[0], rows[-1]
        self.rows: slice | NDArray[np.intp] = (
            slice(first, last + 1)
            if last - first + 1 == len(rows)
            else np.array(rows, dtype=np.intp)
        )
        self.size = len(rows)
        self.cos_slope = math.cos(config.max_slope)
        self._gravity: tuple[Any, ...] = (None,)

    def shared(self, body: Any, gravity: tuple[Any, Any]) -> tuple[Any, Any]:
        """The members' ``body`` and ``gravity`` (m/s²) for the laws, with the mass (kg) and
        each component of the gravity one float where every member of the group holds the
        same (to the bit): what follows from it alone the laws then work out once, not row by
        row. The gravity's arrays are made again when it changes: its floats are kept."""
        gx, gy = gravity
        if self._gravity[0] is not gx or self._gravity[1] is not gy:
            self._gravity = (gx, gy, (_one(gx, self.rows, gx), _one(gy, self.rows, gy)))
        m = _one(body.mass, self.rows, None)
        if m is not None:
            body = _BodyState(
                body.x, body.y, body.vx, body.vy, body.cos, body.sin, body.spin, m, body.moment
            )
        return body, self._gravity[2]


def _one(a: NDArray[np.float64], rows: slice | NDArray[np.intp], other: Any) -> Any:
    """The one value of ``a``'s ``rows`` as a float if they all hold it, bit for bit (0.0 is
    not -0.0), else ``other``."""
    values = a[rows]
    bits = values.view(np.int64)
    return float(values[0]) if (bits == bits[0]).all() else other


class ConfigArrays:
    """What the crowd's arrays read of each member's config: its lengths of
    :mod:`~playground.controller.stairs` (m; ``front`` is radius + probe_radius, the sum
    :func:`~playground.controller.stairs.ahead` looks ahead from), its hover frequency (Hz),
    the cosine of its steepest walkable slope, its max_lean (rad) and a sine short of its sine
    (a perceived up whose cross product with the field's up is smaller is surely within
    max_lean of it); made when the configs change, for the tread ahead and the lean of many
    members at once."""

    __slots__ = (
        "clearance", "cos_slope", "front", "hover_frequency", "max_lean", "reach", "ride_height",
        "surely_inside",
    )  # fmt: skip

    def __init__(self, configs: list[ControllerConfig]) -> None:
        self.ride_height = np.array([c.ride_height for c in configs])
        self.front = np.array([c.radius + c.probe_radius for c in configs])
        self.reach = np.array([c.ride_height - c.half_length for c in configs])
        self.clearance = np.array([c.ride_height - 0.5 * c.height for c in configs])
        self.hover_frequency = np.array([c.hover_frequency for c in configs])
        self.cos_slope = np.array([math.cos(c.max_slope) for c in configs])
        self.max_lean = np.array([c.max_lean for c in configs])
        self.surely_inside = np.array([math.sin(c.max_lean) * (1.0 - 1e-9) for c in configs])


class Rows:
    """Writes a config group's rows of the step's arrays into ``out`` (name → array, one
    element or row per member): with one group of every member its arrays themselves, else
    its rows of arrays of all members (zeros until filled)."""

    __slots__ = ("_n", "_out", "_whole")

    def __init__(self, out: dict[str, Any], n: int, groups: list[Group]) -> None:
        self._out = out
        self._n = n
        rows = groups[0].rows if len(groups) == 1 else None
        self._whole = isinstance(rows, slice) and rows == slice(0, n)

    def __call__(self, key: str, rows: slice | NDArray[np.intp], value: NDArray[Any]) -> None:
        if self._whole:
            self._out[key] = value
            return
        a = self._out.get(key)
        if a is None:
            a = self._out[key] = np.zeros((self._n, *value.shape[1:]), dtype=value.dtype)
        a[rows] = value[rows]
