"""The shared plumbing of the nearest-hit queries: a query's handle leads back to its
best-so-far list (where cffi refuses a callback: tests/_engine/test_raw.py)."""

from __future__ import annotations

import pymunk

from playground._engine.query import NearestQuery, from_handle


def test_the_handle_leads_to_the_best_so_far() -> None:
    best: list[object] = [1.0, None]
    query = NearestQuery(pymunk.Space(), pymunk.ShapeFilter(group=3), best)
    assert from_handle(query._data) is best
    assert query._filter_c[0].group == 3
