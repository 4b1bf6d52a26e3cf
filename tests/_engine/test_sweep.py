"""The sweep through Chipmunk's query answers as pymunk's public query walked for the nearest
solid hit, bit for bit: the same shape (of equally near ones, the first), point and normal."""

from __future__ import annotations

import math
import os
import random
import struct
from unittest import mock

import numpy as np
import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import sweep
from playground._engine.sweep import NO_HIT, Hits, Sweep, Sweeps, nearest_by_pymunk, nearest_each

RING_SEGMENTS = 64
"""A ring of chords, where pymunk's segment_query_first picks a farther chord's end cap."""
RING_RADIUS = 3.5
"""The ring's radius, m."""


def _bits(hit: sweep.Hit | None) -> tuple[int, bytes] | None:
    """The hit's shape (by identity) and its floats' IEEE 754 bytes."""
    if hit is None:
        return None
    return id(hit[0]), struct.pack("4d", *hit[1:])


def _rows(hits: Hits) -> list[tuple[int, bytes] | None]:
    """:func:`_bits` of each query's hit in ``hits``."""
    out: list[tuple[int, bytes] | None] = []
    for k, j in enumerate(hits.shape.tolist()):
        if j == NO_HIT:
            out.append(None)
            continue
        floats = (hits.x[k], hits.y[k], hits.nx[k], hits.ny[k])
        out.append((id(hits.shapes[j]), struct.pack("4d", *floats)))
    return out


def _ring(space: pymunk.Space) -> None:
    """A ring of RING_SEGMENTS chords of radius RING_RADIUS around the origin."""
    step = 2 * math.pi / RING_SEGMENTS
    for i in range(RING_SEGMENTS):
        a = (RING_RADIUS * math.cos(i * step), RING_RADIUS * math.sin(i * step))
        b = (RING_RADIUS * math.cos((i + 1) * step), RING_RADIUS * math.sin((i + 1) * step))
        space.add(pymunk.Segment(space.static_body, a, b, 0.1))


def _scene(seed: int) -> tuple[pymunk.Space, pymunk.ShapeFilter]:
    """Shapes of every kind around the origin: twins (equally near), sensors, a ring, one shape
    of the probing group (which the filter leaves out), and a few of category HIDDEN (which
    HIDING's mask leaves out)."""
    rng = random.Random(seed)
    space = pymunk.Space()
    static = space.static_body
    for _ in range(6):
        a = (rng.uniform(-3, 3), rng.uniform(-3, 3))
        b = (rng.uniform(-3, 3), rng.uniform(-3, 3))
        r = rng.choice((0.0, 0.05, 0.2))
        twin = pymunk.Segment(static, a, b, r)
        space.add(pymunk.Segment(static, a, b, r), twin)
        twin.sensor = rng.random() < 0.3
    for _ in range(4):
        body = pymunk.Body(
            1.0, 1.0, body_type=rng.choice((pymunk.Body.DYNAMIC, pymunk.Body.KINEMATIC))
        )
        body.position = (rng.uniform(-3, 3), rng.uniform(-3, 3))
        body.angle = rng.uniform(-3, 3)
        shape: pymunk.Shape = rng.choice(
            (pymunk.Circle(body, 0.4), pymunk.Poly.create_box(body, (0.8, 0.3), 0.02))
        )
        shape.sensor = rng.random() < 0.2
        if rng.random() < 0.3:
            shape.filter = pymunk.ShapeFilter(categories=HIDDEN)
        space.add(body, shape)
    _ring(space)
    own = pymunk.Segment(static, (-1.0, 0.0), (1.0, 0.0), 0.1)
    own.filter = pymunk.ShapeFilter(group=7)
    space.add(own)
    return space, pymunk.ShapeFilter(group=7)


HIDDEN = 0b10
"""A category of some shapes of the scene."""
HIDING = pymunk.ShapeFilter(mask=pymunk.ShapeFilter.ALL_MASKS() ^ HIDDEN)
"""A filter that leaves out the shapes of category HIDDEN."""

_COORD = st.floats(-3.2, 3.2, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(st.integers(0, 50), _COORD, _COORD, _COORD, _COORD, st.sampled_from((0.0, 0.05, 0.25)))
def test_the_sweep_answers_as_pymunks_query(
    seed: int, x0: float, y0: float, x1: float, y1: float, radius: float
) -> None:
    space, shape_filter = _scene(seed)
    fast = Sweep(space, shape_filter).nearest(x0, y0, x1, y1, radius)
    assert _bits(fast) == _bits(nearest_by_pymunk(space, (x0, y0), (x1, y1), radius, shape_filter))


_PROBE = st.tuples(_COORD, _COORD, _COORD, _COORD, st.sampled_from((0.0, 0.05, 0.25)))


@settings(max_examples=100, deadline=None)
@given(st.integers(0, 50), st.lists(_PROBE, max_size=12), st.data())
def test_many_probes_in_one_call_answer_as_each_alone(
    seed: int, probes: list[tuple[float, float, float, float, float]], data: st.DataObject
) -> None:
    """Law: nearest_each = each probe's own nearest = pymunk's query, bit for bit, whatever
    filter each probe has (its own group, or none)."""
    space, own = _scene(seed)
    filters = [data.draw(st.sampled_from((own, pymunk.ShapeFilter()))) for _ in probes]
    sweeps = [Sweep(space, f) for f in filters]
    x0, y0, x1, y1, radius = (list(c) for c in zip(*probes, strict=True)) if probes else ([],) * 5
    hits = nearest_each(sweeps, x0, y0, x1, y1, radius)
    assert len(hits) == len(probes)
    for hit, f, (a, b, c, d, r) in zip(hits, filters, probes, strict=True):
        assert _bits(hit) == _bits(nearest_by_pymunk(space, (a, b), (c, d), r, f))


def test_of_equally_near_shapes_the_first_wins_and_sensors_are_passed() -> None:
    space = pymunk.Space()
    first = pymunk.Segment(space.static_body, (-1.0, 0.0), (1.0, 0.0), 0.0)
    second = pymunk.Segment(space.static_body, (-1.0, 0.0), (1.0, 0.0), 0.0)
    sensor = pymunk.Segment(space.static_body, (-1.0, 0.5), (1.0, 0.5), 0.0)
    sensor.sensor = True
    space.add(first, second, sensor)
    ref = nearest_by_pymunk(space, (0.0, 1.0), (0.0, -1.0), 0.1, pymunk.ShapeFilter())
    hit = Sweep(space, pymunk.ShapeFilter()).nearest(0.0, 1.0, 0.0, -1.0, 0.1)
    assert ref is not None and hit is not None
    assert hit[0] is ref[0] and hit[0] is not sensor
    assert _bits(hit) == _bits(ref)


def test_inside_a_ring_the_nearest_chord_not_pymunks_first() -> None:
    space = pymunk.Space()
    _ring(space)
    radius = RING_RADIUS
    shape_filter = pymunk.ShapeFilter()
    th = 0.07  # a probe outward near a chord's end
    start = ((radius - 0.9) * math.cos(th), (radius - 0.9) * math.sin(th))
    end = ((radius + 0.5) * math.cos(th), (radius + 0.5) * math.sin(th))
    first = space.segment_query_first(start, end, 0.25, shape_filter)
    ref = nearest_by_pymunk(space, start, end, 0.25, shape_filter)
    hit = Sweep(space, shape_filter).nearest(*start, *end, 0.25)
    assert first is not None and ref is not None and first.shape is not ref[0]
    assert _bits(hit) == _bits(ref)


def test_without_cffi_callbacks_the_sweep_asks_pymunk(monkeypatch: pytest.MonkeyPatch) -> None:
    space, shape_filter = _scene(3)
    probe = Sweep(space, shape_filter)
    fast = probe.nearest(0.0, 3.0, 0.0, 3.6, 0.25)
    monkeypatch.setattr(sweep, "_callback", None)
    assert fast is not None and _bits(probe.nearest(0.0, 3.0, 0.0, 3.6, 0.25)) == _bits(fast)
    (many,) = nearest_each([probe], [0.0], [3.0], [0.0], [3.6], [0.25])
    assert _bits(many) == _bits(fast)


_FILTERS = st.sampled_from(("own", "none", "hiding"))


@settings(max_examples=150, deadline=None)
@given(
    st.integers(0, 50),
    st.integers(0, 50),
    st.lists(st.tuples(st.integers(0, 5), _PROBE), max_size=16),
    st.lists(_FILTERS, min_size=6, max_size=6),
)
def test_sweeps_compiled_and_by_callback_answer_as_pymunks_query(
    seed: int,
    other: int,
    queries: list[tuple[int, tuple[float, float, float, float, float]]],
    kinds: list[str],
) -> None:
    """Law: Sweeps.nearest gives, query by query, pymunk's public query's answer bit for bit,
    by the compiled helper and by the Python callback alike, and the same Hits (the same
    distinct shapes in the same order): six probes over two scenes, each probe with its own
    filter, queried in any order and any number of times, radius 0 (rays) among them."""
    scenes = [_scene(seed), _scene(other)]
    filters = [
        {"own": scenes[i % 2][1], "none": pymunk.ShapeFilter(), "hiding": HIDING}[kind]
        for i, kind in enumerate(kinds)
    ]
    probes = [Sweep(scenes[i % 2][0], f) for i, f in enumerate(filters)]
    rows = np.array([r for r, _ in queries], dtype=np.intp)
    x0, y0, x1, y1, radius = (
        (np.array(c, dtype=np.float64) for c in zip(*(q for _, q in queries), strict=True))
        if queries
        else (np.zeros(0),) * 5
    )
    sweeps = Sweeps(probes)
    hits = sweeps.nearest(rows, x0, y0, x1, y1, radius)
    with mock.patch.object(sweep, "_segment_queries", None):
        by_callback = sweeps.nearest(rows, x0, y0, x1, y1, radius)
    with (
        mock.patch.object(sweep, "_segment_queries", None),
        mock.patch.object(sweep, "_callback", None),
    ):
        by_pymunk = sweeps.nearest(rows, x0, y0, x1, y1, radius)
    expected = [
        _bits(nearest_by_pymunk(scenes[r % 2][0], (a, b), (c, d), rad, filters[r]))
        for r, (a, b, c, d, rad) in queries
    ]
    assert _rows(hits) == _rows(by_callback) == _rows(by_pymunk) == expected
    assert hits.shape.tolist() == by_callback.shape.tolist()
    assert [id(s) for s in hits.shapes] == [id(s) for s in by_callback.shapes]
    assert len({id(s) for s in hits.shapes}) == len(hits.shapes)


def test_sweeps_of_equally_near_shapes_the_first_and_no_sensor() -> None:
    """Twins under a sensor: every query keeps the twin Chipmunk visits first, as pymunk's walk
    does, and a query that meets only the sensor hits nothing (NaN floats)."""
    space = pymunk.Space()
    first = pymunk.Segment(space.static_body, (-1.0, 0.0), (1.0, 0.0), 0.0)
    second = pymunk.Segment(space.static_body, (-1.0, 0.0), (1.0, 0.0), 0.0)
    sensor = pymunk.Segment(space.static_body, (-1.0, 0.5), (1.0, 0.5), 0.0)
    sensor.sensor = True
    space.add(first, second, sensor)
    ref = nearest_by_pymunk(space, (0.0, 1.0), (0.0, -1.0), 0.0, pymunk.ShapeFilter())
    assert ref is not None and ref[0] in (first, second)
    probes = Sweeps([Sweep(space, pymunk.ShapeFilter())])
    rows = np.zeros(3, dtype=np.intp)
    hits = probes.nearest(rows, [0.0, 0.5, 0.0], [1.0, 1.0, 1.0], [0.0, 0.5, 0.0],
                          [-1.0, -1.0, 0.25], 0.0)  # fmt: skip
    assert hits.shapes == [ref[0]] and hits.shape.tolist() == [0, 0, NO_HIT]
    assert _rows(hits)[0] == _bits(ref)
    assert math.isnan(hits.x[2]) and math.isnan(hits.ny[2])


def test_sweeps_of_no_query_answer_empty_arrays() -> None:
    space, shape_filter = _scene(1)
    hits = Sweeps([Sweep(space, shape_filter)]).nearest(np.zeros(0, dtype=np.intp), *[[]] * 4, [])
    assert hits.shape.shape == hits.x.shape == (0,) and hits.shapes == []


@pytest.mark.skipif(sweep.QUERIES_BY != "compiled", reason="the compiled helper is not built")
def test_the_compiled_helper_refuses_what_it_cannot_read() -> None:
    """A row out of range, a wrong dtype or lengths that differ are errors, not reads of
    memory that is not there."""
    space, shape_filter = _scene(1)
    probes = Sweeps([Sweep(space, shape_filter)])
    one = np.zeros(1)
    with pytest.raises(IndexError, match="rows"):
        probes.nearest(np.array([1]), one, one, one, one, one)
    with pytest.raises(ValueError, match="x0"):
        probes.nearest(np.array([0]), np.zeros(2), one, one, one, one)
    with pytest.raises(TypeError, match="rows"):
        sweep._segment_queries(  # type: ignore[misc]
            sweep._QUERY_ADDRESS, sweep._SENSOR_ADDRESS, probes._spaces, probes._filters,
            np.zeros(1, dtype=np.float64), one, one, one, one, one,
            np.zeros(1, dtype=np.intp), np.zeros(1, dtype=np.uintp), np.zeros(4),
        )  # fmt: skip


@pytest.mark.skipif(os.environ.get("CI") != "true", reason="only CI (.ci/run) must build it")
def test_ci_runs_the_compiled_helper_not_the_fallback() -> None:
    """CI installs on a machine with a compiler and Python's headers: there the crowd's probes
    must run through the compiled helper, or CI would test only the fallback."""
    assert sweep.QUERIES_BY == "compiled"
