"""The contact split of the scalar implementation: each tracked body's arbiter impulses in plain
floats.

The sums of the batch contact split (:class:`~playground.forces.contact_split.ContactSplit`), in
plain floats, read one of two ways. With a few bodies in the space per tracked row (and no
arbiter that may report an impulse not applied, below), every arbiter of the space is read in
one batch call (:class:`~playground._engine.arbiters.ArbiterValues`) and each row's terms are
summed by a plan made again only when the arbiters' ids change
(:func:`~playground._engine.impulses.sum_impulses`: one C call for every row where its optional
helper was built, else Python floats, the same doubles): at ten tracked boxes a third of the
cost of the walk (:data:`ONE_READ_MIN_ROWS`, :data:`ONE_READ_BODIES_PER_ROW`). The first substep
sets the sums (a row's ``j``) rather than adding to them, so nothing zeroes the rows before a
step. Otherwise
each row's arbiters are walked with ``Body.each_arbiter``. Inside that callback Chipmunk
presents each arbiter from the body's side: ``total_impulse`` is the impulse the body received
and ``normal`` points away from it, so they are the batch implementation's +J, +n for body A and
−J, −n for body B, bit for bit (negation is exact). A body's impulses are summed in the order of
their values, as there, so both implementations give the same sums. The arbiters are walked
through Chipmunk's iterator and getters directly (:mod:`playground._engine.raw`: the same
doubles, without an ``Arbiter`` object and a ``Vec2d`` per read).

An arbiter that may report an impulse Chipmunk did not apply makes its bodies' split unknown for
the step, by the batch implementation's rule (:meth:`ContactSplit._stale`): a continuing contact
when the warm start was rescaled, and with ``collision_persistence`` > 1 a first contact from an
arbiter that may still have been cached. The pairs of recent substeps are kept for that rule, for
the tracked bodies' arbiters only (the only ones whose split is read).
"""

from __future__ import annotations

from collections import deque
from typing import Any

import pymunk

from playground._engine import raw
from playground._engine.arbiters import ArbiterValues
from playground._engine.impulses import Impulse, ImpulsePlan, sum_impulses
from playground.forces.scalar.row import Row

__all__ = ["ONE_READ_BODIES_PER_ROW", "ONE_READ_MIN_ROWS", "ContactSums"]

ONE_READ_MIN_ROWS = 2
"""Fewest tracked rows for one read of every arbiter in the space instead of a walk over each
row's arbiters. Measured with ``python benchmarks/split_pile.py --crossover`` (one read / walks,
every box tracked): 0.86× (blocks 0.63–1.30) at one box, 0.58× at two, 0.32× at ten; one row in
a space of ten boxes, 1.10×. At one row the two are even, so the walk keeps it."""

ONE_READ_BODIES_PER_ROW = 10
"""Most bodies in the space per tracked row for the one read: it reads every arbiter of the space
(about one a body in a pile), the walks only the tracked rows'. Same benchmark, untracked boxes:
ten boxes a row 0.64–0.80× at 2 to 8 rows, twenty a row 0.93–1.18×."""

_MASK = (1 << 64) - 1
"""Pair keys wrap at 64 bits, as the batch implementation's ``uint64`` keys do."""

_ZERO: Impulse = (0.0, 0.0, 0.0, 0.0)

Flags = tuple[bool, int, bool]
"""(first contact, pair key, the pair's ids fit the key's 32-bit halves) of an arbiter."""


class ContactSums:
    """Per-step arbiter impulse sums of the tracked rows, and the pairs of recent substeps.

    >>> space = pymunk.Space()
    >>> space.gravity, space.collision_persistence = (0.0, -10.0), 1
    >>> body = pymunk.Body(1.0, 1.0)
    >>> body.position = (0.0, 0.5)
    >>> floor = pymunk.Segment(space.static_body, (-1.0, 0.0), (1.0, 0.0), 0.0)
    >>> space.add(body, pymunk.Circle(body, 0.5), floor)
    >>> row, sums = Row(body), ContactSums()
    >>> for stamp in (1, 2, 3):  # falls for a step, is stopped, then rests
    ...     space.step(0.1)
    ...     sums.accumulate([row], space, stamp, rescaled=False, fresh=True)
    >>> row.j[1], row.j[2], row.unknown  # the floor holds the weight: 10 N for 0.1 s, all normal
    (1.0, 0.0, False)
    """

    __slots__ = (
        "_arbiters",
        "_flags",
        "_impulses",
        "_marked",
        "_pairs",
        "_plan",
        "_plan_ids",
        "_plan_rows",
        "_visit",
        "history",
    )

    def __init__(self) -> None:
        self.history: deque[tuple[int, frozenset[int]]] = deque()
        """(substep stamp, pair keys) of recent substeps, newest last, while persistence > 1."""
        # The body being read: its arbiters' impulses and flags, and whether pair keys are kept.
        self._impulses: list[Impulse] = []
        self._flags: list[Flags] = []
        self._pairs = False
        self._marked: list[Row] = []  # the rows set unknown since the step's first substep
        self._visit = raw.arbiter_callback(self._read)
        # The one read of every arbiter, and its plan: which arbiter's terms go to which row,
        # made again when the arbiters' ids or the rows change.
        self._arbiters = ArbiterValues()
        self._plan = ImpulsePlan([], [])
        self._plan_ids: list[int] | None = None
        self._plan_rows: list[Row] | None = None

    def accumulate(
        self,
        rows: list[Row],
        space: pymunk.Space,
        stamp: int,
        rescaled: bool,
        *,
        fresh: bool = False,
    ) -> None:
        """Add one substep's arbiter impulses to each row's sums (``j``) and set
        ``unknown`` on a row with an arbiter that may report an impulse not applied.

        ``stamp`` counts the space's steps (1 for its first); ``rescaled``: this substep's length
        differs from the one before it; ``fresh``: the step's first substep, whose terms start
        every row's sums at +0.0 and every ``unknown`` at False (the rows are not zeroed
        before).

        With at least :data:`ONE_READ_MIN_ROWS` rows and at most :data:`ONE_READ_BODIES_PER_ROW`
        bodies in the space per row, when no arbiter can report an impulse not applied (arbiters
        dropped at once, the warm start not rescaled), every arbiter of the space is read in one
        batch call instead of walking each row's: the same terms, added in the same order.
        """
        if fresh and self._marked:
            for r in self._marked:
                r.unknown = False
            self._marked.clear()
        persistence = raw.collision_persistence(raw.space_handle(space))
        n = len(rows)
        if (
            persistence < 2
            and not rescaled
            and n >= ONE_READ_MIN_ROWS
            and len(space.bodies) <= ONE_READ_BODIES_PER_ROW * n
        ):
            self.history.clear()  # as below: no pairs are kept with persistence < 2
            self._add_all(rows, space, fresh)
            return
        pairs = self._pairs = persistence >= 2
        found: list[tuple[Row, list[Flags]]] = []
        keys: set[int] = set()
        any_first = False
        fits = True
        each_arbiter, visit, null = raw.each_arbiter, self._visit, raw.NULL
        for r in rows:
            impulses: list[Impulse] = []
            flags: list[Flags] = []
            self._impulses, self._flags = impulses, flags
            if visit is not None:
                each_arbiter(r.h, visit, null)
            else:
                r.body.each_arbiter(self._read_arbiter)
            if fresh:
                r.j = _ZERO
            if not impulses:
                continue
            # Summed in the order of their values, as the batch implementation does.
            impulses.sort()
            jx, jy, jnx, jny = r.j
            for vx, vy, vnx, vny in impulses:
                jx += vx
                jy += vy
                jnx += vnx
                jny += vny
            r.j = (jx, jy, jnx, jny)
            for first, key, fit in flags:
                any_first = any_first or first
                keys.add(key)
                fits = fits and fit
            found.append((r, flags))
        if not found and not pairs:
            self.history.clear()  # no arbiter, no pair to remember
            return
        cached_all, old = self._cached(pairs, keys, stamp, persistence, any_first, fits)
        for r, flags in found:
            for first, key, _ in flags:
                if (rescaled and not first) or (first and (cached_all or key in old)):
                    r.unknown = True
                    self._marked.append(r)

    def _add_all(self, rows: list[Row], space: pymunk.Space, fresh: bool) -> None:
        """Add every row's terms from one read of every arbiter, as the walk adds them: a row's
        terms in the order of their values (:func:`~playground._engine.impulses.sum_impulses`,
        one C call where its helper was built). Body B's term of an arbiter is the negation of
        body A's, the values the walk reads from B's side (Chipmunk gives B −J and −n; their dot
        product is J·n, bit for bit)."""
        arbiters = self._arbiters
        arbiters.read(space)
        ids = arbiters.ids
        if ids is not self._plan_ids or rows is not self._plan_rows:
            self._plan = ImpulsePlan(ids, [raw.body_id(r.body) for r in rows])
            self._plan_ids, self._plan_rows = ids, rows
        previous = None if fresh else [r.j for r in rows]
        for r, j in zip(rows, sum_impulses(self._plan, arbiters, previous), strict=True):
            r.j = j

    def _cached(
        self,
        pairs: bool,
        keys: set[int],
        stamp: int,
        persistence: int,
        any_first: bool,
        fits: bool,
    ) -> tuple[bool, frozenset[int]]:
        """(every first contact may be from a cached arbiter, the pairs that may be cached)."""
        history = self.history
        if not pairs:
            history.clear()
            return False, frozenset()
        if history and history[-1][0] != stamp - 1:
            history.clear()  # a gap: the substeps in between were not seen
        cached_all, old = False, frozenset[int]()
        if any_first:
            since = max(1, stamp - persistence)
            covered = fits and (stamp <= 1 or (bool(history) and history[0][0] <= since))
            if not covered:
                cached_all = True
            else:
                old = frozenset(k for s, ks in history if s <= stamp - 2 for k in ks)
        history.append((stamp, frozenset(keys)))
        while history[0][0] < stamp - persistence:
            history.popleft()
        return cached_all, old

    def _read_arbiter(self, arb: pymunk.Arbiter) -> None:
        """:meth:`_read` from ``Body.each_arbiter`` (where cffi callbacks are refused)."""
        self._read(None, raw.arbiter_handle(arb), None)

    def _read(self, body: raw.Handle, arb: raw.ArbiterHandle, data: Any) -> None:
        """One arbiter, seen from the body whose arbiters are iterated (the C callback: reads
        plain values only); its pair key only while pairs are kept."""
        jx, jy, nx, ny = raw.arbiter_impulse(arb)
        dot = jx * nx + jy * ny
        self._impulses.append((jx, jy, nx * dot, ny * dot))
        key, fit = 0, True
        if self._pairs:
            ia, ib = raw.arbiter_body_ids(arb)
            lo, hi = (ia, ib) if ia <= ib else (ib, ia)
            key, fit = ((lo << 32) | hi) & _MASK, hi >> 32 == 0
        self._flags.append((raw.is_first_contact(arb) != 0, key, fit))
