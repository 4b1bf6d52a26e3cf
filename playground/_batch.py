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
_READ_POS = _F.BODY_ID | _F.POSITION
_READ_ALL = _READ | _F.POSITION
"""A read with positions: x, y, then the state columns (batch packs fields in flag order)."""
_WRITE = _F.FORCE | _F.TORQUE
_A = batch.ArbiterFields
_ARBITERS = _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.IS_FIRST_CONTACT | _A.NORMAL


class BodyRows:
    """The space's bodies as rows: ids, velocity (m/s), angular velocity (rad/s), force (N), torque.

    ``state`` columns: vx, vy, w, fx, fy, torque.
    """

    __slots__ = ("_in", "_out", "ids", "positions", "state")

    def __init__(self) -> None:
        self._in = batch.Buffer()
        self._out = batch.Buffer()
        self.ids: NDArray[np.uintp] = np.zeros(0, dtype=np.uintp)
        self.state: NDArray[np.float64] = np.zeros((0, 6))
        self.positions: NDArray[np.float64] = np.zeros((0, 2))
        """x, y (m) of each row, from the last read with ``positions``."""

    def read(self, space: pymunk.Space, positions: bool = False) -> None:
        """Read every body, with its position too if ``positions`` (copies: the batch buffer is
        reused)."""
        self._in.clear()
        batch.get_space_bodies(space, _READ_ALL if positions else _READ, self._in)
        self.ids = np.frombuffer(self._in.int_buf(), dtype=np.uintp).copy()
        floats = np.frombuffer(self._in.float_buf(), dtype=np.float64)
        if positions:
            rows = floats.reshape(-1, 8).copy()
            self.positions = rows[:, 0:2]
            self.state = rows[:, 2:8]
        else:
            self.state = floats.reshape(-1, 6).copy()

    def read_velocities(self, space: pymunk.Space) -> tuple[NDArray[np.uintp], NDArray[np.float64]]:
        """Ids and (vx, vy, w) rows, read now (copies)."""
        self._in.clear()
        batch.get_space_bodies(space, _F.BODY_ID | _F.VELOCITY | _F.ANGULAR_VELOCITY, self._in)
        ids = np.frombuffer(self._in.int_buf(), dtype=np.uintp).copy()
        return ids, np.frombuffer(self._in.float_buf(), dtype=np.float64).reshape(-1, 3).copy()

    def write_forces(self, space: pymunk.Space, forces: NDArray[np.float64]) -> None:
        """Write (fx, fy, torque) rows in the order of the last :meth:`read`.

        Only valid while no body sleeps and no body was added or removed since the read.
        """
        data = np.ascontiguousarray(forces, dtype=np.float64).ravel()
        self._out.set_float_buf(data)
        self._out.set_int_buf(self.ids)
        batch.set_space_bodies(space, _WRITE, self._out)


def read_positions(
    space: pymunk.Space, buffer: batch.Buffer
) -> tuple[NDArray[np.uintp], NDArray[np.float64]]:
    """Ids and (x, y) rows of every body (copies)."""
    buffer.clear()
    batch.get_space_bodies(space, _READ_POS, buffer)
    ids = np.frombuffer(buffer.int_buf(), dtype=np.uintp).copy()
    return ids, np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 2).copy()


def read_arbiters(
    space: pymunk.Space, buffer: batch.Buffer
) -> tuple[NDArray[np.uintp], NDArray[np.bool_], NDArray[np.float64]]:
    """Every arbiter as (id_a, id_b), its first-contact flag and (jx, jy, nx, ny) rows.

    ``total_impulse`` (N·s) is the impulse applied to body A; body B received its negative.
    The normal points from A to B. First contact: the arbiter's contacts were made this step
    (not warm-started).
    """
    buffer.clear()
    batch.get_space_arbiters(space, _ARBITERS, buffer)
    ints = np.frombuffer(buffer.int_buf(), dtype=np.uintp).reshape(-1, 3)
    floats = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 4).copy()
    return ints[:, 0:2].copy(), ints[:, 2] != 0, floats


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
