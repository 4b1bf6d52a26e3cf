"""The contact split of the scalar implementation: each tracked body's arbiter impulses in plain
floats.

The sums of the batch contact split (:class:`~playground.forces.contact_split.ContactSplit`),
read body by body with ``Body.each_arbiter`` instead of one batch read of every arbiter in the
space. Inside that callback Chipmunk presents each arbiter from the body's side:
``total_impulse`` is the impulse the body received and ``normal`` points away from it, so they
are the batch implementation's +J, +n for body A and −J, −n for body B, bit for bit (negation is
exact). A body's impulses are summed in the order of their values, as there, so both
implementations give the same sums. The arbiters are read through Chipmunk's iterator and
getters directly (:mod:`playground._engine.raw`: the same doubles, without an ``Arbiter`` object and
a ``Vec2d`` per read).

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
from playground.forces.scalar.row import Row

__all__ = ["ContactSums"]

_MASK = (1 << 64) - 1
"""Pair keys wrap at 64 bits, as the batch implementation's ``uint64`` keys do."""

Impulse = tuple[float, float, float, float]
"""(jx, jy, jnx, jny): an arbiter's impulse on the body and its normal part, N·s."""
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
    ...     row.jx = row.jy = row.jnx = row.jny = 0.0
    ...     sums.accumulate([row], space, stamp, rescaled=False)
    >>> row.jy, row.jnx, row.unknown  # the floor holds the weight: 10 N for 0.1 s, all normal
    (1.0, 0.0, False)
    """

    __slots__ = ("_flags", "_impulses", "_pairs", "_visit", "history")

    def __init__(self) -> None:
        self.history: deque[tuple[int, frozenset[int]]] = deque()
        """(substep stamp, pair keys) of recent substeps, newest last, while persistence > 1."""
        # The body being read: its arbiters' impulses and flags, and whether pair keys are kept.
        self._impulses: list[Impulse] = []
        self._flags: list[Flags] = []
        self._pairs = False
        self._visit = raw.arbiter_callback(self._read)

    def accumulate(self, rows: list[Row], space: pymunk.Space, stamp: int, rescaled: bool) -> None:
        """Add one substep's arbiter impulses to each row's sums (``jx, jy, jnx, jny``) and set
        ``unknown`` on a row with an arbiter that may report an impulse not applied.

        ``stamp`` counts the space's steps (1 for its first); ``rescaled``: this substep's length
        differs from the one before it.
        """
        persistence = raw.collision_persistence(raw.space_handle(space))
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
            if not impulses:
                continue
            # Summed in the order of their values, as the batch implementation does.
            impulses.sort()
            jx, jy, jnx, jny = r.jx, r.jy, r.jnx, r.jny
            for vx, vy, vnx, vny in impulses:
                jx += vx
                jy += vy
                jnx += vnx
                jny += vny
            r.jx, r.jy, r.jnx, r.jny = jx, jy, jnx, jny
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
