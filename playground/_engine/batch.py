"""Plumbing over ``pymunk.batch``: read and write every body's state as numpy rows.

Hazards measured on pymunk 7.3.1 (see docs/design.md §4): row order changes when bodies sleep, wake,
are added or removed, so rows are keyed by body id, never by position; ``space.static_body`` and
kinematic bodies appear as rows too; ``set_space_bodies`` writes to the wrong bodies while any body
is asleep, so :meth:`BodyRows.write_forces` must not be used when sleeping is enabled.
"""

from __future__ import annotations

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

_F = batch.BodyFields
_READ = _F.BODY_ID | _F.VELOCITY | _F.ANGULAR_VELOCITY | _F.FORCE | _F.TORQUE
_READ_ALL = _READ | _F.POSITION
"""A read with positions: x, y, then the state columns (batch packs fields in flag order)."""
_READ_FIELD = _F.BODY_ID | _F.POSITION | _F.FORCE | _F.TORQUE
"""What a field alone needs: x, y, fx, fy, torque (no velocities: nothing tracked)."""
_WRITE = _F.FORCE | _F.TORQUE


class BodyRows:
    """The space's bodies as rows: ids, velocity (m/s), angular velocity (rad/s), force (N), torque.

    ``state`` columns: vx, vy, w, fx, fy, torque.

    Rows are views of the batch buffers, valid until the next read of the same kind (the state
    and the velocities have a buffer each): whoever keeps rows past that copies them (the solver
    gathers them into tracked order). ``ids`` is a read-only array that stays the same object
    while the read's ids do not change (row order changes only when bodies are added, removed,
    sleep or wake), so a cache keyed by it is checked with ``is``.
    """

    __slots__ = (
        "_id_bytes",
        "_in",
        "_out",
        "_vel",
        "_vel_id_bytes",
        "_vel_ids",
        "_xy_at",
        "ids",
        "positions",
        "state",
        "width",
    )

    def __init__(self) -> None:
        self._in = batch.Buffer()
        self._vel = batch.Buffer()
        self._out = batch.Buffer()
        self._id_bytes = b""
        self.ids: NDArray[np.uintp] = np.zeros(0, dtype=np.uintp)
        self._vel_id_bytes = b""
        self._vel_ids = self.ids
        self.state: NDArray[np.float64] = np.zeros((0, 6))
        self.positions: NDArray[np.float64] = np.zeros((0, 2))
        """x, y (m) of each row, from the last read with ``positions``."""
        self.width = 6
        """Floats per row of the last :meth:`read` (8 with positions: x, y come first)."""
        self._xy_at = np.zeros((0, 2), dtype=np.intp)

    def _ids_of(self, buffer: batch.Buffer) -> NDArray[np.uintp]:
        """The ids of a state read into ``buffer``: the last array again if they are the same."""
        raw = bytes(buffer.int_buf())
        if raw != self._id_bytes:
            self._id_bytes = raw
            self.ids = np.frombuffer(raw, dtype=np.uintp)
        return self.ids

    def read(self, space: pymunk.Space, positions: bool = False) -> None:
        """Read every body, with its position too if ``positions``."""
        buffer = self._in
        buffer.clear()
        batch.get_space_bodies(space, _READ_ALL if positions else _READ, buffer)
        self._ids_of(buffer)
        floats = np.frombuffer(buffer.float_buf(), dtype=np.float64)
        if positions:
            rows = floats.reshape(-1, 8)
            self.positions = rows[:, 0:2]
            self.state = rows[:, 2:8]
            self.width = 8
        else:
            self.state = floats.reshape(-1, 6)
            self.width = 6

    @property
    def flat(self) -> NDArray[np.float64]:
        """The last :meth:`read` as one row of floats, :attr:`width` per body (for gathers)."""
        return np.frombuffer(self._in.float_buf(), dtype=np.float64)

    def read_velocities(self, space: pymunk.Space) -> tuple[NDArray[np.uintp], NDArray[np.float64]]:
        """Ids and (vx, vy, w) rows, read now (views, valid until the next call)."""
        buffer = self._vel
        buffer.clear()
        batch.get_space_bodies(space, _F.BODY_ID | _F.VELOCITY | _F.ANGULAR_VELOCITY, buffer)
        raw = bytes(buffer.int_buf())
        if raw == self._id_bytes:
            ids = self.ids  # the same order as the state read (the usual case)
        elif raw == self._vel_id_bytes:
            ids = self._vel_ids
        else:
            self._vel_id_bytes = raw
            ids = self._vel_ids = np.frombuffer(raw, dtype=np.uintp)
        return ids, np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 3)

    def read_forces(self, space: pymunk.Space) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Read every body's position (into :attr:`positions`), force and torque: the (fx, fy)
        rows as a contiguous copy (to add to and write with :meth:`write_xy_forces`) and the
        torques (a view). :attr:`state` is not read."""
        buffer = self._in
        buffer.clear()
        batch.get_space_bodies(space, _READ_FIELD, buffer)
        self._ids_of(buffer)
        rows = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 5)
        self.positions = rows[:, 0:2]
        m = len(rows)
        if self._xy_at.shape[0] != m:
            self._xy_at = np.arange(m)[:, None] * 5 + np.arange(2, 4)
        return np.take(rows.reshape(-1), self._xy_at), rows[:, 4]

    def write_xy_forces(self, space: pymunk.Space, forces: NDArray[np.float64]) -> None:
        """Write (fx, fy) rows (contiguous) in the order of the last read; torques stay.

        Only valid while no body sleeps and no body was added or removed since the read.
        """
        self._out.set_float_buf(forces.reshape(-1))
        self._out.set_int_buf(self.ids)
        batch.set_space_bodies(space, _F.FORCE, self._out)

    def write_forces(self, space: pymunk.Space, forces: NDArray[np.float64]) -> None:
        """Write (fx, fy, torque) rows in the order of the last :meth:`read`.

        Only valid while no body sleeps and no body was added or removed since the read.
        """
        data = np.ascontiguousarray(forces, dtype=np.float64).ravel()
        self._out.set_float_buf(data)
        self._out.set_int_buf(self.ids)
        batch.set_space_bodies(space, _WRITE, self._out)


def as_run(rows: NDArray[np.intp]) -> NDArray[np.intp] | slice:
    """``rows`` as a slice when they are one ascending run (``a, a + 1, …``), else as they are:
    the same rows, indexed without a gather (numpy takes a slice of a crowd's rows several times
    faster than the rows one by one). Built once while the rows stay the same.

    >>> as_run(np.array([3, 4, 5]))
    slice(3, 6, None)
    >>> as_run(np.array([3, 5])).tolist()
    [3, 5]
    """
    k = len(rows)
    if k == 0:
        return rows
    first = int(rows[0])
    if first < 0 or not np.array_equal(rows, np.arange(first, first + k)):
        return rows
    return slice(first, first + k)


def lookup(keys: NDArray[np.uintp], ids: NDArray[np.uintp]) -> NDArray[np.intp]:
    """Index of each of ``ids`` in the sorted array ``keys``, or −1 where absent.

    >>> lookup(np.array([3, 5, 9], dtype=np.uintp), np.array([5, 4, 9], dtype=np.uintp)).tolist()
    [1, -1, 2]
    """
    if len(keys) == 0:
        return np.full(len(ids), -1, dtype=np.intp)
    pos = np.searchsorted(keys, ids)
    pos_c = np.minimum(pos, len(keys) - 1)
    return np.where(keys[pos_c] == ids, pos_c, -1).astype(np.intp)


_POSES = _F.BODY_ID | _F.POSITION | _F.ANGLE | _F.VELOCITY | _F.ANGULAR_VELOCITY


class Poses:
    """The poses of a fixed list of bodies, read for every body of the space in one batch call
    and picked out by id: (k, 6) rows of x, y (m), angle (rad), vx, vy (m/s), angular velocity
    (rad/s), the very doubles the bodies' properties hold. Rows follow the list's order
    (``ids``), whatever order the space keeps its bodies in.

    >>> space = pymunk.Space()
    >>> body = pymunk.Body(1.0, 1.0)
    >>> body.position, body.velocity = (1.0, 2.0), (3.0, 4.0)
    >>> space.add(body, pymunk.Circle(body, 0.5))
    >>> Poses().read(space, np.array([body.id], dtype=np.uintp)).tolist()
    [[1.0, 2.0, 0.0, 3.0, 4.0, 0.0]]
    """

    __slots__ = ("_at", "_buffer", "_for", "_id_bytes")

    def __init__(self) -> None:
        self._buffer = batch.Buffer()
        self._id_bytes = b""
        self._for: NDArray[np.uintp] | None = None
        self._at = np.zeros(0, dtype=np.intp)

    def read(self, space: pymunk.Space, ids: NDArray[np.uintp]) -> NDArray[np.float64]:
        """The rows of the bodies ``ids`` (each in the space; KeyError for one that is not)."""
        buffer = self._buffer
        buffer.clear()
        batch.get_space_bodies(space, _POSES, buffer)
        raw = bytes(buffer.int_buf())
        if raw != self._id_bytes or self._for is not ids:
            order = np.frombuffer(raw, dtype=np.uintp)
            row = {int(b): i for i, b in enumerate(order.tolist())}
            self._at = np.array([row[int(b)] for b in ids.tolist()], dtype=np.intp)
            self._id_bytes = raw
            self._for = ids
        rows = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 6)
        return rows[self._at]


_TOUCHING = batch.ArbiterFields.BODY_A_ID | batch.ArbiterFields.BODY_B_ID


def touching_ids(space: pymunk.Space, buffer: batch.Buffer) -> NDArray[np.uintp]:
    """The ids of the bodies of every arbiter of the space (each body once per arbiter it has:
    a body absent has no contact), in one batch call."""
    buffer.clear()
    batch.get_space_arbiters(space, _TOUCHING, buffer)
    return np.frombuffer(buffer.int_buf(), dtype=np.uintp)


_FORCES = _F.BODY_ID | _F.FORCE | _F.TORQUE


class ForceWrites:
    """Set the force (N) and torque (N·m) of some bodies of a space in one batch read and one
    batch write, instead of two C calls a body: every other body of the space gets back the
    force and torque read from it. Only while no body of the space sleeps
    (``set_space_bodies`` then writes rows to the wrong bodies): a space whose
    ``sleep_time_threshold`` is infinite has none asleep.

    >>> space = pymunk.Space()
    >>> a, b = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    >>> space.add(a, b)
    >>> b.force, b.torque = (5.0, 6.0), 7.0
    >>> ids = np.array([a.id], dtype=np.uintp)
    >>> ForceWrites().write(space, ids, np.array([[1.0, 2.0]]), np.array([3.0]))
    >>> (tuple(a.force), a.torque), (tuple(b.force), b.torque)
    (((1.0, 2.0), 3.0), ((5.0, 6.0), 7.0))
    """

    __slots__ = ("_at", "_buffer", "_for", "_id_bytes")

    def __init__(self) -> None:
        self._buffer = batch.Buffer()
        self._id_bytes = b""
        self._for: NDArray[np.uintp] | None = None
        self._at: NDArray[np.intp] | slice = np.zeros(0, dtype=np.intp)

    def write(
        self,
        space: pymunk.Space,
        ids: NDArray[np.uintp],
        force: NDArray[np.float64],
        torque: NDArray[np.float64],
    ) -> None:
        """Set the bodies ``ids`` (distinct, each in the space; KeyError for one that is not)
        to the (k, 2) rows of ``force`` and the (k,) ``torque``."""
        buffer = self._buffer
        buffer.clear()
        batch.get_space_bodies(space, _FORCES, buffer)
        raw = bytes(buffer.int_buf())
        if raw != self._id_bytes or self._for is not ids:
            self._at = as_run(_rows_of(np.frombuffer(raw, dtype=np.uintp), ids))
            self._id_bytes = raw
            self._for = ids
        rows = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 3)
        at = self._at
        rows[at, 0:2] = force
        rows[at, 2] = torque
        batch.set_space_bodies(space, _F.FORCE | _F.TORQUE, buffer)


def _rows_of(order: NDArray[np.uintp], ids: NDArray[np.uintp]) -> NDArray[np.intp]:
    """The row of each of ``ids`` in ``order`` (KeyError for one absent)."""
    sorter = np.argsort(order)
    at = np.searchsorted(order, ids, sorter=sorter)
    at = np.minimum(at, len(order) - 1)
    rows = sorter[at] if len(order) else np.zeros(len(ids), dtype=np.intp)
    if len(ids) and (len(order) == 0 or (order[rows] != ids).any()):
        raise KeyError("a body is not in the space")
    return rows.astype(np.intp)
