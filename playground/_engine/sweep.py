"""Plumbing under pymunk's queries: the nearest solid shape a swept circle hits, found through
Chipmunk's segment query directly, for a controller's ground probe every step.

``space.segment_query`` calls back into Python for every hit and builds a ``SegmentQueryInfo``
and two ``Vec2d`` for each, then the caller walks the list. :class:`Sweep` passes Chipmunk a
callback of its own that keeps only the nearest non-sensor hit as plain floats (docs/performance.md,
row probe, has both costs). It visits the same hits in the same order and keeps the same one
(the strictly nearest, the first of equally near ones), so the answer is that of
:func:`nearest_by_pymunk`, the same walk over pymunk's public query (``tests/_engine/test_sweep.py``
compares them bit for bit). ``segment_query_first`` is not an answer: with a radius, pymunk
7.3.1's can return a farther shape (inside a 64-segment ring it reports a neighbouring chord's
end cap, normal 40° off, while the chord under the probe is 7 cm nearer).

:func:`nearest_each` runs many probes of one space (each with its own filter, a crowd's) in one
call: the same query and callback per probe, without a Python call of the probe's own between
them.

Like :mod:`playground._engine.raw` this reaches into pymunk's private ``_chipmunk_cffi`` (pymunk's
major version is pinned). Where the platform refuses a cffi callback (memory both writable and
executable), :class:`Sweep` answers through :func:`nearest_by_pymunk` instead.

>>> import pymunk
>>> space = pymunk.Space()
>>> floor = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0)
>>> space.add(floor)
>>> hit = Sweep(space, pymunk.ShapeFilter()).nearest(0.0, 1.0, 0.0, -1.0, 0.25)
>>> hit is not None and hit[0] is floor and hit[1:] == (0.0, 0.0, 0.0, 1.0)
True
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi, lib

from playground._engine.query import NearestQuery, from_handle, is_sensor, shape_data
from playground._engine.raw import c_callback

__all__ = [
    "Hit",
    "Sweep",
    "face_normal",
    "nearest_by_pymunk",
    "nearest_each",
    "nearest_where",
    "sharp",
]

Hit = tuple[pymunk.Shape, float, float, float, float]
"""The shape hit, the hit point (m) and the surface normal there (unit)."""

_query = lib.cpSpaceSegmentQuery


def _keep_nearest(shape: Any, point: Any, normal: Any, alpha: float, data: Any) -> None:
    # best = [alpha, shape, px, py, nx, ny]: strictly nearer only, so of equally near hits the
    # first wins (the walk in nearest_by_pymunk).
    best = from_handle(data)
    if alpha < best[0] and not is_sensor(shape):
        best[:] = alpha, shape, point.x, point.y, normal.x, normal.y


_callback = c_callback("cpSpaceSegmentQueryFunc", _keep_nearest)


def nearest_by_pymunk(
    space: pymunk.Space,
    start: tuple[float, float],
    end: tuple[float, float],
    radius: float,
    shape_filter: pymunk.ShapeFilter,
) -> Hit | None:
    """The nearest non-sensor shape hit by a circle of ``radius`` (m) swept from ``start`` to
    ``end`` (m), by pymunk's public query: the reference :class:`Sweep` answers as."""
    info: pymunk.SegmentQueryInfo | None = None
    for h in space.segment_query(start, end, radius, shape_filter):
        shape = h.shape
        if shape is not None and not shape.sensor and (info is None or h.alpha < info.alpha):
            info = h
    if info is None or info.shape is None:
        return None
    return (info.shape, info.point.x, info.point.y, info.normal.x, info.normal.y)


class Sweep(NearestQuery):
    """The nearest non-sensor shape a circle swept through ``space`` hits, among the shapes
    ``shape_filter`` lets through (a probe's filter, fixed: it is converted once)."""

    __slots__ = ()

    def __init__(self, space: pymunk.Space, shape_filter: pymunk.ShapeFilter) -> None:
        super().__init__(space, shape_filter, [math.inf, None, 0.0, 0.0, 0.0, 0.0])

    def nearest(self, x0: float, y0: float, x1: float, y1: float, radius: float) -> Hit | None:
        """The shape hit by a circle of ``radius`` (m) swept from (x0, y0) to (x1, y1) (m) that
        is nearest the start, with the hit point and normal; None if none is."""
        if _callback is None:
            return nearest_by_pymunk(self._space, (x0, y0), (x1, y1), radius, self._filter)
        best = self._best
        best[0] = math.inf
        best[1] = None
        _query(self._space_c, (x0, y0), (x1, y1), radius, self._filter_c[0], _callback, self._data)
        shape = best[1]
        if shape is None:
            return None
        best[1] = None
        return (from_handle(shape_data(shape)), best[2], best[3], best[4], best[5])


def nearest_each(
    probes: Sequence[Sweep],
    x0: Sequence[float],
    y0: Sequence[float],
    x1: Sequence[float],
    y1: Sequence[float],
    radius: Sequence[float],
) -> list[Hit | None]:
    """``probes[i].nearest(x0[i], y0[i], x1[i], y1[i], radius[i])`` for each probe (m), in one
    call: the same answers, bit for bit (the same query and callback).

    >>> space = pymunk.Space()
    >>> floor = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0)
    >>> space.add(floor)
    >>> probe = Sweep(space, pymunk.ShapeFilter())
    >>> down, up = (0.0, 1.0, 0.0, -1.0, 0.25), (1.0, 1.0, 1.0, 2.0, 0.25)  # m
    >>> hits = nearest_each([probe, probe], *zip(down, up))
    >>> hits[0] == probe.nearest(*down), hits[1]
    (True, None)
    """
    if _callback is None or not probes:
        return [
            p.nearest(a, b, c, d, r)
            for p, a, b, c, d, r in zip(probes, x0, y0, x1, y1, radius, strict=True)
        ]
    best: list[Any] = [math.inf, None, 0.0, 0.0, 0.0, 0.0]
    data = ffi.new_handle(best)
    query, callback = _query, _callback
    # The Shape of each cpShape* hit, looked up once a call (a crowd's probes mostly hit one
    # floor); not kept across calls: a freed shape's memory may hold another shape later.
    shapes: dict[Any, pymunk.Shape] = {}
    out: list[Hit | None] = []
    append = out.append
    for p, a, b, c, d, r in zip(probes, x0, y0, x1, y1, radius, strict=True):
        best[0] = math.inf
        query(p._space_c, (a, b), (c, d), r, p._filter_c[0], callback, data)
        shape_c = best[1]
        if shape_c is None:
            append(None)
            continue
        best[1] = None
        shape = shapes.get(shape_c)
        if shape is None:
            shape = shapes[shape_c] = from_handle(shape_data(shape_c))
        append((shape, best[2], best[3], best[4], best[5]))
    return out


def nearest_where(
    space: pymunk.Space,
    start: tuple[float, float],
    end: tuple[float, float],
    radius: float,
    shape_filter: pymunk.ShapeFilter,
    keep: Callable[[pymunk.Shape], bool],
) -> Hit | None:
    """:func:`nearest_by_pymunk` among the shapes ``keep`` accepts: the slow path of a probe
    that must pass over a shape (a one-way platform seen from below), taken only then."""
    info: pymunk.SegmentQueryInfo | None = None
    for h in space.segment_query(start, end, radius, shape_filter):
        shape = h.shape
        if (
            shape is not None
            and not shape.sensor
            and (info is None or h.alpha < info.alpha)
            and keep(shape)
        ):
            info = h
    if info is None or info.shape is None:
        return None
    return (info.shape, info.point.x, info.point.y, info.normal.x, info.normal.y)


def sharp(shape: pymunk.Shape) -> bool:
    """The shape has sharp corners (a polygon or a segment of radius 0), where a swept circle's
    normal is the direction from the corner to the circle, not a face's normal.

    >>> sharp(pymunk.Poly.create_box(None, (1.0, 1.0))), sharp(pymunk.Circle(None, 1.0))
    (True, False)
    """
    if isinstance(shape, pymunk.Poly):
        return shape.radius == 0.0
    return isinstance(shape, pymunk.Segment) and shape.radius == 0.0


def face_normal(
    shape: pymunk.Shape, x: float, y: float, dx: float, dy: float
) -> tuple[float, float] | None:
    """The normal (unit) of the face of ``shape`` that a ray from (x, y) along (dx, dy) (m)
    meets first, or None if it meets none (pymunk's ``Shape.segment_query``, radius 0).

    >>> space = pymunk.Space()
    >>> box = pymunk.Poly.create_box(space.static_body, (1.0, 1.0))    # m: from -0.5 to 0.5
    >>> space.add(box)
    >>> face_normal(box, 0.5, 1.0, 0.0, -1.0)       # down onto its top face at the corner
    (0.0, 1.0)
    >>> face_normal(box, 2.0, 1.0, 0.0, -1.0) is None
    True
    """
    info = shape.segment_query((x, y), (x + dx, y + dy), 0.0)
    if info is None:
        return None
    return (info.normal.x, info.normal.y)
