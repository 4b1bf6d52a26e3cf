"""The force ledger: the forces we put on bodies during a step, by body and by category.

A force's :class:`Category` says why it was applied; the solver keeps a sum per category, so that
the **support force** (engine + the forces that stand in for contacts: hover, drive, grip) and the
**specific force** (support / m: what an inner ear feels) come out right.

Forces on many bodies at once (a crowd of controllers) enter as one block of rows
(:class:`ForceRows`), numpy arrays; a row becomes an ordinary entry the moment anything else adds
to its body, so every body's sum is made of the same float additions in the same order as if
its row had been added by :meth:`ForceLedger.add_all`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from enum import Enum

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine import raw
from playground._engine.batch import ForceWrites
from playground.vec import Vec

__all__ = ["Category", "ForceLedger", "ForceRows", "RowBodies"]


class Category(Enum):
    """Why a force was applied; the solver keeps a sum per category.

    PASSIVE: gravity and other fields. APPLIED: self-propulsion, scripted pushes — felt by nobody's
    inner ear by convention. SUPPORT: forces that stand in for contacts (a hover spring, a driving
    friction force, a grip) — they count in the support force.
    """

    PASSIVE = 0
    APPLIED = 1
    SUPPORT = 2


_PARTS = 2 * len(Category)
"""(x, y) per category: the length of an entry's ``parts``."""


class _Entry:
    __slots__ = ("body", "fx", "fy", "h", "parts", "torque")

    def __init__(self, body: pymunk.Body) -> None:
        self.body = body
        self.h = raw.handle(body)  # written through the C setters the properties call
        self.fx = 0.0
        self.fy = 0.0
        self.torque = 0.0
        self.parts = [0.0] * _PARTS


class RowBodies:
    """The bodies of a block of rows, distinct, with their ids and each one's row: built once
    while a block's bodies stay the same (a crowd's batch members, step after step)."""

    __slots__ = ("bodies", "ids", "index", "writes")

    def __init__(self, bodies: list[pymunk.Body], ids: NDArray[np.uintp]) -> None:
        self.bodies = bodies
        self.ids = ids
        """Their ``body.id``."""
        self.index = {b: i for i, b in enumerate(bodies)}
        """Row of each body."""
        self.writes = ForceWrites()
        """Their forces written in one batch call (:meth:`ForceRows.flush`)."""


class ForceRows:
    """The forces on a block of bodies, one row each: what :meth:`ForceLedger.add_all` would
    have summed for each (its forces added to 0.0 in order, no point, then its torque), as
    arrays. The bodies have no entry in the ledger yet when the rows are added.

    Attributes:
        of: the bodies (:class:`RowBodies`).  force: (k, 2) total force, N.
        torque: (k,) torque, N·m.  parts: (k, 6) per-category sums ``[px, py, ax, ay, sx, sy]``,
        N.
    """

    __slots__ = ("active", "force", "of", "parts", "torque")

    def __init__(
        self,
        of: RowBodies,
        force: NDArray[np.float64],
        torque: NDArray[np.float64],
        parts: NDArray[np.float64],
    ) -> None:
        self.of = of
        self.force = force
        self.torque = torque
        self.parts = parts
        self.active = np.zeros(len(of.bodies), dtype=bool)
        """Which rows count as added already: a force added to the body of an active row adds
        to that row; the body of a row not yet active gets an entry of its own, and the row
        must be dropped (:meth:`ForceLedger.drop_row`) before the flush."""

    def flush(self, skip: NDArray[np.bool_] | None) -> None:
        """Write each row's force and torque to its body (rows ``skip`` left out): in one batch
        call while the space cannot sleep, else body by body."""
        of = self.of
        if not of.bodies:
            return
        space = of.bodies[0].space
        if space is not None and space.sleep_time_threshold == math.inf:
            if skip is None:
                of.writes.write(space, of.ids, self.force, self.torque)
            else:
                keep = ~skip
                ForceWrites().write(space, of.ids[keep], self.force[keep], self.torque[keep])
            return
        set_force, set_torque = raw.set_force, raw.set_torque
        fx, fy = self.force[:, 0].tolist(), self.force[:, 1].tolist()
        torque = self.torque.tolist()
        bodies = of.bodies
        rows = range(len(bodies)) if skip is None else np.flatnonzero(~skip).tolist()
        for i in rows:
            h = raw.handle(bodies[i])
            set_force(h, fx[i], fy[i])
            set_torque(h, torque[i])


class ForceLedger:
    """Forces we put on bodies during one step, by body and category.

    Forces are world vectors (N) at world points (m); the torque about the centre of gravity
    follows. :meth:`flush` writes the totals to the bodies; it runs before every substep because
    pymunk clears forces after integrating. ``on_first`` is called when an empty ledger gets its
    first entry: a world uses it to know that its next step has forces to flush (a step with
    nothing to do takes a bare path that never looks at the ledger).

    >>> body = pymunk.Body(2.0, 1.0)
    >>> ledger = ForceLedger()
    >>> ledger.add(body, (3.0, 0.0), point=(0.0, 1.0), category=Category.SUPPORT)
    >>> ledger.flush()
    >>> body.force, body.torque
    (Vec2d(3.0, 0.0), -3.0)
    """

    __slots__ = ("_entries", "_folded", "_on_first", "_rows", "_spent")

    def __init__(self, on_first: Callable[[], None] | None = None) -> None:
        # Keyed by the body object, not its id: ``body.id`` is a call into chipmunk (many times
        # a dict lookup: docs/performance.md, body_key) and a controller adds several forces a
        # step; the ids are read once, in items().
        self._entries: dict[pymunk.Body, _Entry] = {}
        # The entries of the last step, emptied and used again for the same bodies (a controller
        # and a gravity rule put forces on the same bodies every step: no new entry to build).
        self._spent: dict[pymunk.Body, _Entry] = {}
        self._on_first = on_first
        # A block of rows (add_rows) and which of them became entries since (None: none did).
        self._rows: ForceRows | None = None
        self._folded: NDArray[np.bool_] | None = None

    def _entry(self, body: pymunk.Body) -> _Entry:
        entry = self._entries.get(body)
        if entry is None:
            if not self._entries and self._rows is None and self._on_first is not None:
                self._on_first()
            entry = self._spent.pop(body, None)
            if entry is None:
                entry = _Entry(body)
            else:
                entry.fx = entry.fy = entry.torque = 0.0
                entry.parts = [0.0] * _PARTS
            if self._rows is not None:
                self._fold(body, entry)
            self._entries[body] = entry
        return entry

    def _fold(self, body: pymunk.Body, entry: _Entry) -> None:
        """Start ``entry`` from ``body``'s row, if it has one: what comes after adds to it."""
        rows = self._rows
        assert rows is not None
        i = rows.of.index.get(body)
        if i is None or not rows.active[i]:
            return
        if self._folded is None:
            self._folded = np.zeros(len(rows.of.bodies), dtype=bool)
        self._folded[i] = True
        entry.fx, entry.fy = rows.force[i].tolist()
        entry.torque = float(rows.torque[i])
        entry.parts = rows.parts[i].tolist()

    def entry_bodies(self) -> list[pymunk.Body]:
        """The bodies with an entry (not a row) now."""
        return list(self._entries)

    def has(self, body: pymunk.Body) -> bool:
        """Whether ``body`` has an entry (not a row) in this step's ledger."""
        return body in self._entries

    def add_rows(self, rows: ForceRows) -> None:
        """Record a block of rows (one block a step; its bodies have no entry yet). The
        caller has checked that each value is finite."""
        assert self._rows is None, "one block of rows a step"
        if not self._entries and self._on_first is not None and len(rows.of.bodies):
            self._on_first()
        self._rows = rows
        self._folded = None

    def drop_row(self, body: pymunk.Body) -> None:
        """Leave ``body``'s row out (its forces went in otherwise)."""
        rows = self._rows
        i = None if rows is None else rows.of.index.get(body)
        if rows is None or i is None:
            return
        if self._folded is None:
            self._folded = np.zeros(len(rows.of.bodies), dtype=bool)
        self._folded[i] = True

    def row_block(self) -> tuple[NDArray[np.uintp], NDArray[np.float64]] | None:
        """The ids and per-category sums ``[px, py, ax, ay, sx, sy]`` (N) of the rows that are
        still rows (not entries: :meth:`items` has those), or None without rows."""
        rows = self._rows
        if rows is None:
            return None
        if self._folded is None:
            return rows.of.ids, rows.parts
        keep = ~self._folded
        return rows.of.ids[keep], rows.parts[keep]

    def add(
        self,
        body: pymunk.Body,
        force: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Record ``force`` (N, world frame) on ``body`` at world ``point`` (m; default: its centre
        of gravity)."""
        fx, fy = float(force[0]), float(force[1])
        if not (math.isfinite(fx) and math.isfinite(fy)):
            raise ValueError(f"force: expected a finite 2-vector in newtons, got {force!r}")
        entry = self._entry(body)
        entry.fx += fx
        entry.fy += fy
        if point is not None:
            cx, cy = raw.centre_of_gravity(entry.h)
            entry.torque += (point[0] - cx) * fy - (point[1] - cy) * fx
        # _value_, not value: a plain attribute, not a property (docs/performance.md, enum_value).
        i = 2 * category._value_
        entry.parts[i] += fx
        entry.parts[i + 1] += fy

    def add_all(
        self,
        body: pymunk.Body,
        forces: list[tuple[float, float, Category]],
        torque: float | None = None,
        point: Vec | None = None,
    ) -> None:
        """Record several forces (N, world frame, at world ``point``, m; default: the centre of
        gravity) on one body, in order, then a pure ``torque`` (N·m) if given: the same float
        additions, in the same order, as one :meth:`add` call each and one :meth:`add_torque`,
        without the per-call cost (a controller's forces on its own body, or their reactions on
        its ground, written once a step). The caller has checked that each is finite."""
        entry = self._entry(body)
        fx = entry.fx
        fy = entry.fy
        parts = entry.parts
        for x, y, category in forces:
            fx += x
            fy += y
            i = 2 * category._value_
            parts[i] += x
            parts[i + 1] += y
        entry.fx = fx
        entry.fy = fy
        if point is not None and forces:
            cx, cy = raw.centre_of_gravity(entry.h)
            lx, ly = point[0] - cx, point[1] - cy
            turn = entry.torque
            for x, y, _ in forces:
                turn += lx * y - ly * x
            entry.torque = turn
        if torque is not None:
            entry.torque += torque

    def add_torque(self, body: pymunk.Body, torque: float, category: Category) -> None:
        """Record a pure torque (N·m)."""
        if not math.isfinite(torque):
            raise ValueError(f"torque: expected a finite number in N·m, got {torque!r}")
        self._entry(body).torque += float(torque)

    def flush(self) -> None:
        """Write each body's total force and torque (replacing what it had)."""
        set_force, set_torque = raw.set_force, raw.set_torque
        for e in self._entries.values():
            set_force(e.h, e.fx, e.fy)
            set_torque(e.h, e.torque)
        if self._rows is not None:
            self._rows.flush(self._folded)

    def clear(self) -> None:
        """Forget every force (the step is over); the entries wait in ``_spent`` for one step."""
        self._spent = self._entries
        self._entries = {}
        self._rows = None
        self._folded = None

    def __len__(self) -> int:
        rows = self._rows
        if rows is None:
            return len(self._entries)
        folded = 0 if self._folded is None else int(self._folded.sum())
        return len(self._entries) + len(rows.of.bodies) - folded

    def parts(self, body: pymunk.Body) -> list[float] | None:
        """``body``'s per-category sums ``[px, py, ax, ay, sx, sy]`` (N), None if it has no
        forces (what :meth:`items` or :meth:`row_block` gives for it, without reading every
        body's id)."""
        entry = self._entries.get(body)
        if entry is not None:
            return entry.parts
        rows = self._rows
        if rows is not None:
            i = rows.of.index.get(body)
            if i is not None:
                parts: list[float] = rows.parts[i].tolist()
                return parts
        return None

    def items(self) -> list[tuple[int, list[float]]]:
        """(body id, per-category sums ``[px, py, ax, ay, sx, sy]``) of every body with an
        entry (the rows that stayed rows: :meth:`row_block`)."""
        return [(body.id, e.parts) for body, e in self._entries.items()]
