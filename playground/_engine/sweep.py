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

:class:`Sweeps` runs the probes of a crowd in one call and answers in arrays. Where the optional
compiled helper was built on install (:mod:`playground._engine._nearest`, a small C extension:
the same Chipmunk query with a C callback that keeps what the Python one keeps), no Python runs
between the queries; without a compiler it runs :func:`nearest_each`, the same answers.
:data:`QUERIES_BY` says which path serves.

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
from dataclasses import dataclass
from typing import Any, Final, Literal

import numpy as np
import pymunk
from numpy.typing import NDArray
from pymunk._chipmunk_cffi import ffi, lib

from playground._engine.query import NearestQuery, from_handle, is_sensor, shape_data
from playground._engine.raw import c_callback

__all__ = [
    "NO_HIT",
    "QUERIES_BY",
    "Hit",
    "Hits",
    "Sweep",
    "Sweeps",
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

# What the compiled helper declares of Chipmunk (playground/_engine/_nearest.c), as pymunk's cffi
# names it: the helper is used only if pymunk declares the very same, so a pymunk whose types
# differ falls back to the callback instead of calling through a wrong signature.
_DECLARED_IN_C: Final = (
    (
        "void(*)(struct cpSpace *, struct cpVect, struct cpVect, double, struct cpShapeFilter, "
        "void(*)(struct cpShape *, struct cpVect, struct cpVect, double, void *), void *)"
    ),
    "unsigned char(*)(struct cpShape *)",
    (("group", "uintptr_t"), ("categories", "unsigned int"), ("mask", "unsigned int")),
    (("x", "double"), ("y", "double")),
)


def _declared() -> tuple[Any, ...]:
    """pymunk's cffi declarations of what the compiled helper calls and passes."""
    return (
        ffi.typeof(lib.cpSpaceSegmentQuery).cname,
        ffi.typeof(lib.cpShapeGetSensor).cname,
        tuple((n, f.type.cname) for n, f in ffi.typeof("cpShapeFilter").fields),
        tuple((n, f.type.cname) for n, f in ffi.typeof("cpVect").fields),
    )


def _address(pointer: Any) -> int:
    """A cffi pointer (or a C function of pymunk's lib) as an int."""
    return int(ffi.cast("uintptr_t", pointer))


def _compiled_helper() -> Callable[..., int] | None:
    """The compiled helper's ``segment_queries``, if it was built and matches pymunk's
    declarations, else None."""
    try:
        from playground._engine import _nearest
    except ImportError:
        return None
    return _nearest.segment_queries if _declared() == _DECLARED_IN_C else None


_segment_queries = _compiled_helper()
_QUERY_ADDRESS = _address(ffi.addressof(lib, "cpSpaceSegmentQuery"))
_SENSOR_ADDRESS = _address(ffi.addressof(lib, "cpShapeGetSensor"))

QUERIES_BY: Final[Literal["compiled", "callback", "pymunk"]] = (
    "compiled"
    if _segment_queries is not None
    else "callback"
    if _callback is not None
    else "pymunk"
)
"""How :meth:`Sweeps.nearest` runs its queries, as the module was imported: ``"compiled"``
(the helper built on install, one C call for all), ``"callback"`` (:func:`nearest_each`: the
query with the Python callback, one Python call a query), ``"pymunk"`` (pymunk's public query,
where the platform refuses cffi callbacks). All three give the same answers, bit for bit."""


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


NO_HIT: Final = -1
""":attr:`Hits.shape` of a query that hit nothing."""


@dataclass(frozen=True, slots=True, eq=False)
class Hits:
    """The nearest hits of many queries, the k-th entry of each array the k-th query's."""

    shape: NDArray[np.intp]
    """Which shape the query hit, as an index into :attr:`shapes`; :data:`NO_HIT` if none."""
    shapes: list[pymunk.Shape]
    """The distinct shapes hit, each once, in the order first hit."""
    point_normal: NDArray[np.float64]
    """Four rows: the hit point's x and y (m) and the surface normal's x and y there (unit);
    NaN where nothing was hit."""

    @property
    def x(self) -> NDArray[np.float64]:
        """The hit point's x, m."""
        row: NDArray[np.float64] = self.point_normal[0]
        return row

    @property
    def y(self) -> NDArray[np.float64]:
        """The hit point's y, m."""
        row: NDArray[np.float64] = self.point_normal[1]
        return row

    @property
    def nx(self) -> NDArray[np.float64]:
        """The surface normal's x at the hit point (unit)."""
        row: NDArray[np.float64] = self.point_normal[2]
        return row

    @property
    def ny(self) -> NDArray[np.float64]:
        """The surface normal's y at the hit point (unit)."""
        row: NDArray[np.float64] = self.point_normal[3]
        return row


class Sweeps:
    """Many probes (:class:`Sweep`, each of its space and filter), queried in one call: a
    crowd's, made once while its members stay the same.

    >>> space = pymunk.Space()
    >>> floor = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0)
    >>> space.add(floor)
    >>> probes = Sweeps([Sweep(space, pymunk.ShapeFilter())] * 3)
    >>> rows = np.array([0, 2])                             # probes 0 and 2
    >>> hits = probes.nearest(rows, [0.0, 1.0], [1.0, 1.0], [0.0, 1.0], [-1.0, 2.0], 0.25)  # m
    >>> hits.shape.tolist(), hits.shapes == [floor], hits.x.tolist()[0], hits.ny.tolist()[0]
    ([0, -1], True, 0.0, 1.0)
    """

    __slots__ = ("_filters", "_probes", "_spaces")

    def __init__(self, probes: Sequence[Sweep]) -> None:
        self._probes = list(probes)
        # The C side of each probe, kept alive by the probe (its space and its filter).
        self._spaces = np.array([_address(p._space_c) for p in probes], dtype=np.uintp)
        self._filters = np.array([_address(p._filter_c) for p in probes], dtype=np.uintp)

    def __len__(self) -> int:
        return len(self._probes)

    def __getitem__(self, i: int) -> Sweep:
        """The ``i``-th probe."""
        return self._probes[i]

    def nearest(
        self,
        rows: NDArray[np.intp],
        x0: Any,
        y0: Any,
        x1: Any,
        y1: Any,
        radius: Any,
    ) -> Hits:
        """For each k, ``probes[rows[k]].nearest(x0[k], y0[k], x1[k], y1[k], radius[k])`` (m;
        ``radius`` may be one float for all), as :class:`Hits`: the same answers, bit for bit,
        whichever path serves (:data:`QUERIES_BY`)."""
        rows = np.ascontiguousarray(rows, dtype=np.intp)
        m = len(rows)
        x0, y0, x1, y1 = (np.ascontiguousarray(v, dtype=np.float64) for v in (x0, y0, x1, y1))
        if isinstance(radius, float | int):
            one, radius = float(radius), np.empty(m)
            radius.fill(one)  # np.full's own steps, without its Python wrapper
        radius = np.ascontiguousarray(radius, dtype=np.float64)
        which = np.empty(m, dtype=np.intp)
        points = np.empty((4, m))
        if _segment_queries is not None:
            found = np.empty(m, dtype=np.uintp)
            distinct = _segment_queries(
                _QUERY_ADDRESS, _SENSOR_ADDRESS, self._spaces, self._filters, rows,
                x0, y0, x1, y1, radius, which, found, points,
            )  # fmt: skip
            # The Shape of each cpShape* hit, looked up once a call; not kept across calls: a
            # freed shape's memory may hold another shape later.
            shapes = [
                from_handle(shape_data(ffi.cast("cpShape *", p))) for p in found[:distinct].tolist()
            ]
            return Hits(which, shapes, points)
        probes = self._probes
        hits = nearest_each(
            [probes[r] for r in rows.tolist()],
            x0.tolist(), y0.tolist(), x1.tolist(), y1.tolist(), radius.tolist(),
        )  # fmt: skip
        index: dict[pymunk.Shape, int] = {}
        for k, hit in enumerate(hits):
            if hit is None:
                which[k] = NO_HIT
                points[:, k] = math.nan
                continue
            which[k] = index.setdefault(hit[0], len(index))
            points[:, k] = hit[1:]
        return Hits(which, list(index), points)


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
