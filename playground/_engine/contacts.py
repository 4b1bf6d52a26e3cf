"""Plumbing under pymunk's arbiters: the contacts of one body, read through Chipmunk's arbiter
iteration directly, for a controller's load and touch every step.

``body.each_arbiter(f)`` makes a handle, then for every contact an ``Arbiter`` and, on
``arb.total_impulse``, a ``Vec2d``; a caller adding up a load also makes a closure each call:
a cost paid every step even with no contact at all (docs/performance.md, contacts).
:class:`Contacts` passes Chipmunk callbacks of its
own, made once, that add the same terms in the same order (Chipmunk's arbiter list), so its
answers are those of :func:`load_by_pymunk` and :func:`touching_by_pymunk`, the same sums over
pymunk's public API (``tests/_engine/test_contacts.py`` compares them bit for bit).

The callbacks and the iteration are :mod:`playground._engine.raw`'s; where the platform refuses cffi
callbacks, :class:`Contacts` answers through the pymunk functions.

>>> import pymunk
>>> space = pymunk.Space()
>>> space.gravity = (0.0, -10.0)
>>> space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
>>> box = pymunk.Body(2.0, 1.0)
>>> box.position = (0.0, 0.5)
>>> space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
>>> for _ in range(60):
...     space.step(0.01)
>>> contacts = Contacts(box)
>>> contacts.touching(), round(contacts.load(0.0, -1.0, 0.01), 6)
(True, 20.0)
"""

from __future__ import annotations

from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi

from playground._engine import raw

__all__ = ["Contacts", "load_by_pymunk", "touching_by_pymunk"]

_each_arbiter = raw.each_arbiter
_impulse = raw.arbiter_impulse
_from_handle = ffi.from_handle


def _add_load(body: Any, arbiter: Any, data: Any) -> None:
    # acc = [load, ux, uy, h, touching]; the term is load_by_pymunk's, to the last bit.
    acc = _from_handle(data)
    jx, jy, _, _ = _impulse(arbiter)
    acc[0] += max(0.0, -(jx * acc[1] + jy * acc[2])) / acc[3]
    acc[4] = True


def _touch(body: Any, arbiter: Any, data: Any) -> None:
    _from_handle(data)[4] = True


_load_callback = raw.arbiter_callback(_add_load)
_touch_callback = raw.arbiter_callback(_touch)


def load_by_pymunk(body: pymunk.Body, ux: float, uy: float, h: float) -> float:
    """The force pressing on ``body`` along −(ux, uy) (a unit vector) through its contacts in
    the last step of ``h`` seconds, N: each contact's impulse on it, its part along −u if
    positive, over h, summed in pymunk's order. The reference :class:`Contacts` answers as."""
    load = 0.0

    def visit(arb: pymunk.Arbiter) -> None:
        nonlocal load
        # The body is the arbiter's first; total_impulse is the impulse on it.
        jx, jy = arb.total_impulse
        load += max(0.0, -(jx * ux + jy * uy)) / h

    body.each_arbiter(visit)
    return load


def touching_by_pymunk(body: pymunk.Body) -> bool:
    """Whether any contact touches ``body`` now (pymunk's public API)."""
    found = False

    def visit(arb: pymunk.Arbiter) -> None:
        nonlocal found
        found = True

    body.each_arbiter(visit)
    return found


class Contacts:
    """The contacts of one body (which must outlive this object)."""

    __slots__ = ("_acc", "_body", "_data", "_h")

    def __init__(self, body: pymunk.Body) -> None:
        self._body = body
        self._h = body._body
        self._acc: list[Any] = [0.0, 0.0, 0.0, 1.0, False]
        self._data = ffi.new_handle(self._acc)

    def load(self, ux: float, uy: float, h: float) -> float:
        """:func:`load_by_pymunk` of the body, N."""
        if _load_callback is None:
            return load_by_pymunk(self._body, ux, uy, h)
        acc = self._acc
        acc[0] = 0.0
        acc[1] = ux
        acc[2] = uy
        acc[3] = h
        _each_arbiter(self._h, _load_callback, self._data)
        return float(acc[0])

    def load_and_touching(self, ux: float, uy: float, h: float) -> tuple[float, bool]:
        """:meth:`load` and :meth:`touching` in one walk over the body's contacts."""
        if _load_callback is None:
            return load_by_pymunk(self._body, ux, uy, h), touching_by_pymunk(self._body)
        acc = self._acc
        acc[0] = 0.0
        acc[1] = ux
        acc[2] = uy
        acc[3] = h
        acc[4] = False
        _each_arbiter(self._h, _load_callback, self._data)
        return float(acc[0]), bool(acc[4])

    def touching(self) -> bool:
        """:func:`touching_by_pymunk` of the body."""
        if _touch_callback is None:
            return touching_by_pymunk(self._body)
        acc = self._acc
        acc[4] = False
        _each_arbiter(self._h, _touch_callback, self._data)
        return bool(acc[4])
