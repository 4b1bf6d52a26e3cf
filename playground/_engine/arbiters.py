"""Plumbing over ``pymunk.batch``: every arbiter of a space read at once, as numpy rows
(:class:`ArbiterRows`, for many bodies) or as Python lists (:class:`ArbiterValues`, for few).

``batch.get_space_arbiters`` walks the space's cached arbiters in C and packs the fields asked
for; it also makes its C argument (``ffi.new``) and reads its fields' flag value on every call,
which at ten bodies costs twice the walk itself. :class:`_Walk` makes them once and calls the
same C walk directly (pymunk's private ``lib``, as :mod:`playground._engine.raw` does;
``tests/_engine/test_arbiters.py`` checks both readers against ``get_space_arbiters``, bit for
bit). The id columns stay the same
array objects while the read's ids and first-contact flags are the same as the last read's (a
pile at rest keeps its arbiters, in the same order, step after step), so whatever is derived
from them (which tracked row each arbiter touches) is cached by checking them with ``is``, as
:class:`~playground._engine.batch.BodyRows` does for bodies.

>>> import pymunk
>>> space = pymunk.Space()
>>> space.gravity = (0.0, -10.0)
>>> space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
>>> box = pymunk.Body(2.0, 1.0)
>>> box.position = (0.0, 0.5)
>>> space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
>>> for _ in range(60):
...     space.step(0.01)
>>> rows = ArbiterRows()
>>> rows.read(space)
>>> ids = rows.pairs
>>> rows.read(space)
>>> rows.pairs is ids, len(ids), rows.first.tolist()
(True, 1, [False])
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from typing import Any

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray
from pymunk._chipmunk_cffi import ffi, lib

__all__ = ["ArbiterRows", "ArbiterValues"]

_A = batch.ArbiterFields
_FIELDS = _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.IS_FIRST_CONTACT | _A.NORMAL
"""Ints: id_a, id_b, first contact; floats: jx, jy, nx, ny (batch packs fields in flag order)."""

_VALUE_FIELDS = _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.NORMAL
"""Ints: id_a, id_b; floats: jx, jy, nx, ny."""

_each_cached_arbiter = lib.cpSpaceEachCachedArbiter
_batched = ffi.addressof(lib, "pmSpaceArbiterIteratorFuncBatched")
_unpack = ffi.unpack
_impulse_rows = struct.Struct("=4d").iter_unpack  # (jx, jy, nx, ny) in native doubles
_buffer = ffi.buffer
_INT_SIZE = ffi.sizeof("uintptr_t")
_FLOAT_SIZE = ffi.sizeof("cpFloat")


class _Walk:
    """``batch.get_space_arbiters`` with its arguments made once: :meth:`run` fills the int and
    float arrays, :meth:`ints` and :meth:`floats` give their bytes."""

    __slots__ = ("_buffer", "_data", "f", "i")

    def __init__(self, fields: batch.ArbiterFields) -> None:
        self._buffer = batch.Buffer()  # owns the two arrays, and frees them
        self.f = self._buffer._float_arr
        self.i = self._buffer._int_arr
        self._data = ffi.new("pmBatchedData *")
        self._data.fields = fields.value
        self._data.floatArray = self.f
        self._data.intArray = self.i

    def run(self, space: pymunk.Space) -> None:
        """Walk every arbiter of ``space`` now."""
        self.f.num = 0
        self.i.num = 0
        _each_cached_arbiter(space._space, _batched, self._data)

    def ints(self) -> bytes:
        """The ints of the last walk, as bytes (a copy)."""
        raw: bytes = _buffer(self.i.arr, _INT_SIZE * self.i.num)[:]
        return raw

    def floats(self) -> memoryview:
        """The floats of the last walk, valid until the next."""
        return memoryview(_buffer(self.f.arr, _FLOAT_SIZE * self.f.num))


class ArbiterRows:
    """The space's arbiters as rows, from the last :meth:`read`.

    Attributes:
        pairs: (id_a, id_b) of each arbiter's bodies; (M, 2), read-only, the same object while
            the ids and first-contact flags read are the same as the last read's.
        first: the arbiter's contacts were made this step (not warm-started); (M,), kept with
            :attr:`pairs`.
        values: jx, jy (``total_impulse``, N·s: the impulse applied to body A; body B received
            its negative), nx, ny (the normal, from A to B); (M, 4), a view valid until the next
            read.
    """

    __slots__ = ("_int_bytes", "_walk", "first", "pairs", "values")

    def __init__(self) -> None:
        self._walk = _Walk(_FIELDS)
        self._int_bytes = b""
        self.pairs: NDArray[np.uintp] = np.zeros((0, 2), dtype=np.uintp)
        self.first: NDArray[np.bool_] = np.zeros(0, dtype=bool)
        self.values: NDArray[np.float64] = np.zeros((0, 4))

    def read(self, space: pymunk.Space) -> None:
        """Read every arbiter of ``space`` now."""
        walk = self._walk
        walk.run(space)
        raw = walk.ints()
        if raw != self._int_bytes:
            self._int_bytes = raw
            ints = np.frombuffer(raw, dtype=np.uintp).reshape(-1, 3)
            self.pairs = ints[:, 0:2]
            self.first = ints[:, 2] != 0
        self.values = np.frombuffer(walk.floats(), dtype=np.float64).reshape(-1, 4)


class ArbiterValues:
    """The space's arbiters from the last :meth:`read` as Python values, for few bodies: the same
    walk as :class:`ArbiterRows` (without the first-contact flags), and no numpy call.

    Attributes:
        ids: id_a, id_b of each arbiter in turn (2·M ints); the same list object while the ids
            read are the same as the last read's.

    Their floats come from :meth:`values`.

    >>> import pymunk
    >>> space = pymunk.Space()
    >>> space.gravity = (0.0, -10.0)
    >>> space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
    >>> box = pymunk.Body(2.0, 1.0)
    >>> box.position = (0.0, 0.5)
    >>> space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
    >>> for _ in range(60):
    ...     space.step(0.01)
    >>> arbiters = ArbiterValues()
    >>> arbiters.read(space)
    >>> box.id in arbiters.ids, len(list(arbiters.values()))
    (True, 1)
    """

    __slots__ = ("_int_bytes", "_walk", "ids")

    def __init__(self) -> None:
        self._walk = _Walk(_VALUE_FIELDS)
        self._int_bytes = b""
        self.ids: list[int] = []

    def read(self, space: pymunk.Space) -> None:
        """Read every arbiter of ``space`` now."""
        walk = self._walk
        walk.run(space)
        raw = walk.ints()
        if raw != self._int_bytes:
            self._int_bytes = raw
            self.ids = _unpack(walk.i.arr, walk.i.num)

    def values(self) -> Iterator[tuple[float, float, float, float]]:
        """(jx, jy, nx, ny) of each arbiter of the last read, in turn: the impulse on body A
        (N·s) and the normal, from A to B. Unpacked from the walk's doubles by ``struct`` as
        they are iterated (no list, no Python loop); valid until the next read."""
        return _impulse_rows(self.floats())

    def floats(self) -> Any:
        """The doubles of the last read, jx, jy, nx, ny of each arbiter in turn (as
        :meth:`values` gives them): a buffer over the walk's own array, valid until the next
        read (:mod:`playground._engine.impulses` hands it to C)."""
        f = self._walk.f
        return _buffer(f.arr, _FLOAT_SIZE * f.num)
