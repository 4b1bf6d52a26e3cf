"""Plumbing under pymunk's queries: the nearest dynamic body within reach of a point, found
through Chipmunk's point query directly, for a controller's push every step.

``space.point_query`` calls back into Python for every shape within reach and builds a
``PointQueryInfo`` and two ``Vec2d`` for each, then the caller walks the list for the nearest
one it may push. :class:`Reach` passes Chipmunk a callback of its own that keeps only the
nearest eligible hit (not a sensor, on a dynamic body other than the ground) as plain floats.
It visits the same shapes in the same order and keeps the same one (the strictly nearest, the
first of equally near ones), so the answer is that of :func:`nearest_by_pymunk`, the same walk
over pymunk's public query (``tests/_engine/test_reach.py`` compares them bit for bit).

Like :mod:`playground._engine.sweep` this reaches into pymunk's private ``_chipmunk_cffi`` (pymunk's
major version is pinned). Where the platform refuses a cffi callback (memory both writable and
executable), :class:`Reach` answers through :func:`nearest_by_pymunk` instead.

>>> import pymunk
>>> space = pymunk.Space()
>>> box = pymunk.Body(1.0, 1.0)
>>> box.position = (1.0, 0.0)
>>> circle = pymunk.Circle(box, 0.5)
>>> space.add(box, circle)
>>> found = Reach(space, pymunk.ShapeFilter()).nearest(0.0, 0.0, 1.0, None)
>>> found is not None and found[0] is circle and found[1:] == (0.5, 0.0, 0.5)
True
"""

from __future__ import annotations

import math
from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

from playground._engine.query import NearestQuery, from_handle, is_sensor, shape_data
from playground._engine.raw import c_callback

__all__ = ["Found", "Reach", "nearest_by_pymunk"]

Found = tuple[pymunk.Shape, float, float, float]
"""The shape found, its point nearest the query point (m) and the distance to it (m)."""

_query = lib.cpSpacePointQuery
_body_of = lib.cpShapeGetBody
_body_type = lib.cpBodyGetType
_DYNAMIC = lib.CP_BODY_TYPE_DYNAMIC


def _keep_nearest(shape: Any, point: Any, distance: float, gradient: Any, data: Any) -> None:
    # best = [distance, shape, px, py, ground]: strictly nearer only, so of equally near hits
    # the first wins (the walk in nearest_by_pymunk).
    best = from_handle(data)
    if distance < best[0] and not is_sensor(shape):
        body = _body_of(shape)
        if body != best[4] and _body_type(body) == _DYNAMIC:
            best[:4] = distance, shape, point.x, point.y


_callback = c_callback("cpSpacePointQueryFunc", _keep_nearest)


def nearest_by_pymunk(
    space: pymunk.Space,
    point: tuple[float, float],
    reach: float,
    shape_filter: pymunk.ShapeFilter,
    ground: pymunk.Body | None,
    within: float = math.inf,
) -> Found | None:
    """The nearest non-sensor shape of a dynamic body other than ``ground`` within ``reach``
    (m) of ``point`` (m) and strictly nearer than ``within`` (m), by pymunk's public query: the
    reference :class:`Reach` answers as."""
    info: pymunk.PointQueryInfo | None = None
    for h in space.point_query(point, reach, shape_filter):
        shape = h.shape
        if (
            shape is None
            or shape.sensor
            or shape.body is None
            or shape.body is ground
            or shape.body.body_type != pymunk.Body.DYNAMIC
        ):
            continue
        if h.distance < (within if info is None else info.distance):
            info = h
    if info is None or info.shape is None:
        return None
    return (info.shape, info.point.x, info.point.y, info.distance)


class Reach(NearestQuery):
    """The nearest shape a controller may push within reach of a point of ``space``, among the
    shapes ``shape_filter`` lets through (a controller's filter, fixed: it is converted once)."""

    __slots__ = ()

    def __init__(self, space: pymunk.Space, shape_filter: pymunk.ShapeFilter) -> None:
        super().__init__(space, shape_filter, [math.inf, None, 0.0, 0.0, ffi.NULL])

    def nearest(
        self, x: float, y: float, reach: float, ground: pymunk.Body | None, within: float = math.inf
    ) -> Found | None:
        """The non-sensor shape of a dynamic body other than ``ground`` within ``reach`` (m) of
        (x, y) (m) that is nearest it and strictly nearer than ``within`` (m), with its nearest
        point and the distance; None if none is."""
        if _callback is None:
            return nearest_by_pymunk(self._space, (x, y), reach, self._filter, ground, within)
        best = self._best
        best[0] = within
        best[1] = None
        best[4] = ground._body if ground is not None else ffi.NULL
        _query(self._space_c, (x, y), reach, self._filter_c[0], _callback, self._data)
        shape = best[1]
        if shape is None:
            return None
        best[1] = None
        return (from_handle(shape_data(shape)), best[2], best[3], best[0])
