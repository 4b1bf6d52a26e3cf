"""Laws of the tracked rows: a body's row by id, rows after a removal, batch rows mapped to rows."""

from __future__ import annotations

import numpy as np
import pymunk
import pytest

from playground.forces.tracking import TrackedRows


def space_with(n: int) -> tuple[pymunk.Space, list[pymunk.Body]]:
    space = pymunk.Space()
    bodies = [pymunk.Body(1.0, 1.0) for _ in range(n)]
    space.add(*bodies)
    return space, bodies


def test_rows_follow_tracking_order_and_move_up_on_removal() -> None:
    """Rows are given in tracking order, tracking twice is a no-op, and untracking a body moves
    the rows after it up by one; an untracked body has no row."""
    _, (a, b, c) = space_with(3)
    rows = TrackedRows()
    assert [rows.track(body) for body in (c, a, b, a)] == [0, 1, 2, 1]
    rows.untrack(a)
    assert rows.bodies == [c, b]
    assert (rows.row_of(c), rows.row_of(b), rows.row_of(a)) == (0, 1, None)
    rows.untrack(a)  # not tracked: nothing happens
    assert rows.bodies == [c, b]


def test_row_of_checks_the_body_not_only_its_id() -> None:
    """A body that is not tracked has no row even if the caller passes a tracked body's id."""
    _, (a, b) = space_with(2)
    rows = TrackedRows()
    rows.track(a)
    assert rows.row_of(a, a.id) == 0
    assert rows.row_of(b, a.id) is None


def test_only_dynamic_bodies_are_tracked() -> None:
    rows = TrackedRows()
    with pytest.raises(ValueError, match="only dynamic bodies"):
        rows.track(pymunk.Body(body_type=pymunk.Body.KINEMATIC))


def test_batch_rows_map_to_tracked_rows() -> None:
    """For ids in the engine's order, ``_rows`` gives (tracked row, batch row) of each tracked
    body present, and ``_order`` the batch rows in tracked order, or None when a tracked body is
    missing from the read."""
    _, (a, b, c, d) = space_with(4)
    rows = TrackedRows()
    for body in (c, a, d):
        rows.track(body)
    rows._rebuild_keys()
    ids = np.array([d.id, b.id, a.id, c.id], dtype=np.uintp)  # the engine's order
    tracked, batch_rows = rows._rows(ids)
    pairs = sorted(zip(tracked.tolist(), batch_rows.tolist(), strict=True))
    assert pairs == [(0, 3), (1, 2), (2, 0)]
    order = rows._order(ids)
    assert order is not None and order.tolist() == [3, 2, 0]
    without_a = np.array([d.id, b.id, c.id], dtype=np.uintp)
    assert rows._order(without_a) is None
    tracked, batch_rows = rows._rows(without_a)
    assert sorted(zip(tracked.tolist(), batch_rows.tolist(), strict=True)) == [(0, 2), (2, 0)]
