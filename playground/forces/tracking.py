"""Which row is which body: the tracked set behind the solver's per-body arrays.

The solver keeps one row per tracked body in arrays; a batch read of the space (``pymunk.batch``)
lists bodies by id in the engine's order. :class:`TrackedRows` keeps the tracked bodies, finds
a body's row by id, and maps the rows of a batch read to tracked rows, cached while the read's
ids do not change.

>>> space = pymunk.Space()
>>> a, b = pymunk.Body(1.0, 1.0), pymunk.Body(2.0, 1.0)
>>> space.add(a, b)
>>> rows = TrackedRows()
>>> rows.track(b), rows.track(a), rows.track(b)
(0, 1, 0)
>>> rows.row_of(a), rows.row_of(pymunk.Body(1.0, 1.0))
(1, None)
"""

from __future__ import annotations

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine.batch import lookup

__all__ = ["TrackedRows"]


class TrackedRows:
    """Tracked dynamic bodies, one row each in :attr:`bodies` order.

    A subclass that keeps per-row arrays grows and shrinks them in :meth:`_row_added` and
    :meth:`_row_removed`, and rebuilds what depends on the ids in :meth:`_rebuild_keys`, which
    runs lazily (check ``_keys_dirty`` before using the sorted ids).
    """

    def __init__(self) -> None:
        self.bodies: list[pymunk.Body] = []
        self._keys = np.zeros(0, dtype=np.uintp)  # sorted body ids
        self._key_row = np.zeros(0, dtype=np.intp)  # tracked index of each sorted id
        self._row_by_id: dict[int, int] = {}
        self._rows_cache: (
            tuple[NDArray[np.uintp], NDArray[np.intp], NDArray[np.intp], NDArray[np.intp] | None]
            | None
        ) = None
        self._keys_dirty = True

    def track(self, body: pymunk.Body) -> int:
        """Start tracking a dynamic body; returns its row. Idempotent."""
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError("track: only dynamic bodies have engine forces to recover")
        row = self.row_of(body)
        if row is not None:
            return row
        self.bodies.append(body)
        self._row_by_id[body.id] = len(self.bodies) - 1
        self._row_added()
        self._keys_dirty = True
        return len(self.bodies) - 1

    def untrack(self, body: pymunk.Body) -> None:
        """Stop tracking a body (rows after it move up by one)."""
        idx = self.row_of(body)
        if idx is None:
            return
        del self.bodies[idx]
        self._row_by_id = {b.id: i for i, b in enumerate(self.bodies)}
        self._row_removed(idx)
        self._keys_dirty = True

    def row_of(self, body: pymunk.Body, body_id: int | None = None) -> int | None:
        """The tracked row of a body, or None. ``body_id``: its ``body.id`` if the caller has it
        (reading it is a call into chipmunk)."""
        i = self._row_by_id.get(body.id if body_id is None else body_id)
        return i if i is not None and self.bodies[i] is body else None

    def _row_added(self) -> None:
        """A row was appended for a new body."""

    def _row_removed(self, row: int) -> None:
        """Row ``row`` was removed; the rows after it moved up by one."""

    def _rebuild_keys(self) -> None:
        """Sorted ids after the tracked set changed."""
        ids = np.array([b.id for b in self.bodies], dtype=np.uintp)
        self._row_by_id = {int(body_id): i for i, body_id in enumerate(ids)}
        self._rows_cache = None
        order = np.argsort(ids)
        self._keys = ids[order]
        self._key_row = order.astype(np.intp)
        self._keys_dirty = False

    def _rows(self, ids: NDArray[np.uintp]) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
        """(tracked index, row) pairs for the tracked bodies present in ``ids``.

        Row order only changes when bodies are added, removed, sleep or wake: reuse the last
        answer while ``ids`` is unchanged.
        """
        cache = self._rows_cache
        # A batch read hands the same ids array again while its ids are unchanged.
        if cache is not None and (cache[0] is ids or np.array_equal(cache[0], ids)):
            return cache[1], cache[2]
        hit = lookup(self._keys, ids)
        rows = np.nonzero(hit >= 0)[0]
        tracked = self._key_row[hit[rows]]
        full = None
        if len(tracked) == len(self.bodies):
            full = np.empty(len(tracked), dtype=np.intp)
            full[tracked] = rows
        self._rows_cache = (ids, tracked, rows, full)
        return tracked, rows

    def _order(self, ids: NDArray[np.uintp]) -> NDArray[np.intp] | None:
        """Rows of ``ids`` in tracked order when every tracked body is among them, else None."""
        self._rows(ids)
        assert self._rows_cache is not None
        return self._rows_cache[3]
