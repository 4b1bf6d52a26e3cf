"""Plumbing under pymunk's arbiters: the contacts of one body, read through Chipmunk's arbiter
iteration directly, for a controller's load and touch every step.

``body.each_arbiter(f)`` makes a handle, then for every contact an ``Arbiter`` and, on
``arb.total_impulse``, a ``Vec2d``; a caller adding up a load also makes a closure each call:
a cost paid every step even with no contact at all (docs/performance.md, contacts).
:class:`Contacts` passes Chipmunk callbacks of its
own, made once, that add the same terms in the same order (Chipmunk's arbiter list), so its
answers are those of :func:`load_by_pymunk` and :func:`touching_by_pymunk`, the same sums over
pymunk's public API (``tests/_engine/test_contacts.py`` compares them bit for bit).

An arbiter's impulse is the last substep's only. With substeps, :meth:`Contacts.gather` runs
after each substep but the last (``World.on_substep``) and adds each contact's impulse to the
step's sums, by contact (its pair of shapes); the next load adds the last substep's and reads
the step's mean force, Σ impulses / dt, as the force solver's readings are. With one substep
nothing is gathered and the load is the one impulse over dt, as it always was.

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
>>> for _ in range(120):                # settled at substeps of 0.005 s
...     space.step(0.005)
>>> space.step(0.005)                    # a step of 0.01 s as two substeps
>>> contacts.gather()
>>> space.step(0.005)
>>> round(contacts.load(0.0, -1.0, 0.01), 6)
20.0
"""

from __future__ import annotations

from collections.abc import Mapping, MutableMapping
from typing import Any

import pymunk
from pymunk._chipmunk_cffi import ffi

from playground._engine import raw

__all__ = ["Contacts", "gather_by_pymunk", "load_by_pymunk", "touching_by_pymunk"]

_each_arbiter = raw.each_arbiter
_impulse = raw.arbiter_impulse
_shape_key = raw.arbiter_shape_key
_from_handle = ffi.from_handle

Sums = dict[tuple[int, int], list[float]]
"""Each contact's impulse on the body over the earlier substeps of a step, N·s: [jx, jy] by
the addresses of its shapes (the body's first)."""


def _add_load(body: Any, arbiter: Any, data: Any) -> None:
    # acc = [load, ux, uy, h, touching]; the term is load_by_pymunk's, to the last bit.
    acc = _from_handle(data)
    jx, jy, _, _ = _impulse(arbiter)
    acc[0] += max(0.0, -(jx * acc[1] + jy * acc[2])) / acc[3]
    acc[4] = True


def _add_summed_load(body: Any, arbiter: Any, data: Any) -> None:
    # acc = [load, ux, uy, dt, touching, sums]: the contact's impulse over the step's substeps,
    # its earlier ones first; the term is load_by_pymunk's with ``earlier``, to the last bit.
    acc = _from_handle(data)
    jx, jy, _, _ = _impulse(arbiter)
    earlier = acc[5].pop(_shape_key(arbiter), None)
    if earlier is not None:
        jx = earlier[0] + jx
        jy = earlier[1] + jy
    acc[0] += max(0.0, -(jx * acc[1] + jy * acc[2])) / acc[3]
    acc[4] = True


def _gather(body: Any, arbiter: Any, data: Any) -> None:
    sums = _from_handle(data)
    jx, jy, _, _ = _impulse(arbiter)
    key = _shape_key(arbiter)
    total = sums.get(key)
    if total is None:
        sums[key] = [jx, jy]
    else:
        total[0] += jx
        total[1] += jy


def _touch(body: Any, arbiter: Any, data: Any) -> None:
    _from_handle(data)[4] = True


_load_callback = raw.arbiter_callback(_add_load)
_summed_load_callback = raw.arbiter_callback(_add_summed_load)
_gather_callback = raw.arbiter_callback(_gather)
_touch_callback = raw.arbiter_callback(_touch)


ShapeSums = MutableMapping[tuple[pymunk.Shape, pymunk.Shape], tuple[float, float]]
""":data:`Sums` of the pymunk functions: by the contact's shapes (the body's first)."""


def gather_by_pymunk(body: pymunk.Body, sums: ShapeSums) -> None:
    """Add each contact's impulse on ``body`` in the substep just run to ``sums`` (N·s, by its
    shapes), in pymunk's order. The reference :meth:`Contacts.gather` answers as."""

    def visit(arb: pymunk.Arbiter) -> None:
        jx, jy = arb.total_impulse
        key = arb.shapes
        total = sums.get(key)
        sums[key] = (jx, jy) if total is None else (total[0] + jx, total[1] + jy)

    body.each_arbiter(visit)


def load_by_pymunk(
    body: pymunk.Body,
    ux: float,
    uy: float,
    h: float,
    earlier: Mapping[tuple[pymunk.Shape, pymunk.Shape], tuple[float, float]] | None = None,
) -> float:
    """The force pressing on ``body`` along −(ux, uy) (a unit vector) through its contacts over
    the last ``h`` seconds, N: each contact's impulse on it (plus its ``earlier`` sum, from
    :func:`gather_by_pymunk`, if any), its part along −u if positive, over h, summed in
    pymunk's order, then the contacts of ``earlier`` that have ended, in theirs. The reference
    :class:`Contacts` answers as."""
    load = 0.0
    left = dict(earlier) if earlier else {}

    def visit(arb: pymunk.Arbiter) -> None:
        nonlocal load
        # The body is the arbiter's first; total_impulse is the impulse on it.
        jx, jy = arb.total_impulse
        before = left.pop(arb.shapes, None)
        if before is not None:
            jx = before[0] + jx
            jy = before[1] + jy
        load += max(0.0, -(jx * ux + jy * uy)) / h

    body.each_arbiter(visit)
    for jx, jy in left.values():
        load += max(0.0, -(jx * ux + jy * uy)) / h
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
    """The contacts of one body (which must outlive this object), and their impulses over the
    earlier substeps of the step (:meth:`gather`)."""

    __slots__ = ("_acc", "_body", "_data", "_h", "_sums", "_sums_data")

    def __init__(self, body: pymunk.Body) -> None:
        self._body = body
        self._h = body._body
        self._sums: Sums = {}
        self._sums_data = ffi.new_handle(self._sums)
        self._acc: list[Any] = [0.0, 0.0, 0.0, 1.0, False, self._sums]
        self._data = ffi.new_handle(self._acc)

    def gather(self) -> None:
        """Add the impulse each contact gave the body in the substep just run to the step's
        sums (:func:`gather_by_pymunk`): call it after each substep of a step but the last; the
        next :meth:`load` (or :meth:`load_and_touching`) reads them and starts them again."""
        if _gather_callback is None:
            self._body.each_arbiter(self._gather_arbiter)
            return
        _each_arbiter(self._h, _gather_callback, self._sums_data)

    def _gather_arbiter(self, arb: pymunk.Arbiter) -> None:
        _gather(None, raw.arbiter_handle(arb), self._sums_data)

    def load(self, ux: float, uy: float, h: float) -> float:
        """:func:`load_by_pymunk` of the body over the last ``h`` seconds (the step: the
        substeps gathered since the last load and the last one), N."""
        return self.load_and_touching(ux, uy, h)[0]

    def load_and_touching(self, ux: float, uy: float, h: float) -> tuple[float, bool]:
        """:meth:`load` and :meth:`touching` in one walk over the body's contacts."""
        acc = self._acc
        acc[0] = 0.0
        acc[1] = ux
        acc[2] = uy
        acc[3] = h
        acc[4] = False
        sums = self._sums
        if not sums:
            if _load_callback is None:
                self._body.each_arbiter(self._add_arbiter, _add_load)
            else:
                _each_arbiter(self._h, _load_callback, self._data)
            return float(acc[0]), bool(acc[4])
        if _summed_load_callback is None:
            self._body.each_arbiter(self._add_arbiter, _add_summed_load)
        else:
            _each_arbiter(self._h, _summed_load_callback, self._data)
        # The contacts that ended before the last substep.
        for jx, jy in sums.values():
            acc[0] += max(0.0, -(jx * ux + jy * uy)) / h
        sums.clear()
        return float(acc[0]), bool(acc[4])

    def _add_arbiter(self, arb: pymunk.Arbiter, add: Any) -> None:
        add(None, raw.arbiter_handle(arb), self._data)

    def touching(self) -> bool:
        """:func:`touching_by_pymunk` of the body."""
        if _touch_callback is None:
            return touching_by_pymunk(self._body)
        acc = self._acc
        acc[4] = False
        _each_arbiter(self._h, _touch_callback, self._data)
        return bool(acc[4])
