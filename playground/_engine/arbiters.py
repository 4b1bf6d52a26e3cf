"""Plumbing over ``pymunk.batch``: every arbiter of a space read at once, as numpy rows.

One ``batch.get_space_arbiters`` call walks the space's cached arbiters in C and packs the
fields asked for; :class:`ArbiterRows` turns them into arrays. The id columns stay the same
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

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

__all__ = ["ArbiterRows"]

_A = batch.ArbiterFields
_FIELDS = _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.IS_FIRST_CONTACT | _A.NORMAL
"""Ints: id_a, id_b, first contact; floats: jx, jy, nx, ny (batch packs fields in flag order)."""


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

    __slots__ = ("_buffer", "_int_bytes", "first", "pairs", "values")

    def __init__(self) -> None:
        self._buffer = batch.Buffer()
        self._int_bytes = b""
        self.pairs: NDArray[np.uintp] = np.zeros((0, 2), dtype=np.uintp)
        self.first: NDArray[np.bool_] = np.zeros(0, dtype=bool)
        self.values: NDArray[np.float64] = np.zeros((0, 4))

    def read(self, space: pymunk.Space) -> None:
        """Read every arbiter of ``space`` now."""
        buffer = self._buffer
        buffer.clear()
        batch.get_space_arbiters(space, _FIELDS, buffer)
        raw = bytes(buffer.int_buf())
        if raw != self._int_bytes:
            self._int_bytes = raw
            ints = np.frombuffer(raw, dtype=np.uintp).reshape(-1, 3)
            self.pairs = ints[:, 0:2]
            self.first = ints[:, 2] != 0
        self.values = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 4)
