"""Plumbing shared by the nearest-hit queries through Chipmunk (:mod:`playground._engine.sweep`,
:mod:`playground._engine.reach`): the C side of a query, converted once (the ``cpSpace*``, the shape
filter, the best-so-far list a C callback fills, and its handle). The callbacks themselves are
made by :func:`playground._engine.raw.c_callback`.

>>> import pymunk
>>> query = NearestQuery(pymunk.Space(), pymunk.ShapeFilter(), [0.0, None])
>>> from_handle(query._data) is query._best
True
"""

from __future__ import annotations

from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

__all__ = ["NearestQuery", "from_handle", "is_sensor", "shape_data"]

is_sensor = lib.cpShapeGetSensor
shape_data = lib.cpShapeGetUserData
from_handle = ffi.from_handle


class NearestQuery:
    """A query of ``space`` among the shapes ``shape_filter`` lets through (a controller's
    filter, fixed: it is converted once), whose C callback keeps its best hit in ``best``."""

    __slots__ = ("_best", "_data", "_filter", "_filter_c", "_space", "_space_c")

    def __init__(
        self, space: pymunk.Space, shape_filter: pymunk.ShapeFilter, best: list[Any]
    ) -> None:
        self._space = space
        self._filter = shape_filter
        self._space_c = space._space
        self._filter_c = ffi.new("cpShapeFilter *", shape_filter)
        self._best = best
        self._data = ffi.new_handle(best)
