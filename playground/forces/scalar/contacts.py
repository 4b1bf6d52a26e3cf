"""The contact split of the scalar implementation: each tracked body's arbiter impulses in plain
floats.

The sums of the batch contact split (:class:`~playground.forces.contact_split.ContactSplit`), in
plain floats, read one of two ways. With a few bodies in the space per tracked row (and no
arbiter that may report an impulse not applied, below), every arbiter of the space is read in
one batch call (:class:`~playground._engine.arbiters.ArbiterValues`) and each row's terms are
found by a plan made again only when the arbiters' ids change: at ten tracked boxes a third of
the cost of the walk (:data:`ONE_READ_MIN_ROWS`, :data:`ONE_READ_BODIES_PER_ROW`). Each arbiter's
term is then worked out once for both its bodies, and on a step's first substep (the only one
with a single substep a step) the plan's rows are grouped by the signs of their terms, so a term
of body B is subtracted rather than negated and added: the same doubles, about half the Python
float operations of summing each body's terms apart (``benchmarks/step_instructions.py --pile 10
--split``). The first substep sets the sums rather than adding to them, so nothing zeroes the
rows before a step. Otherwise
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
from dataclasses import dataclass, field
from typing import Any

import pymunk

from playground._engine import raw
from playground._engine.arbiters import ArbiterValues
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
        self._plan = _Plan()
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
        """Add one substep's arbiter impulses to each row's sums (``jx, jy, jnx, jny``) and set
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
                r.jx = r.jy = r.jnx = r.jny = 0.0
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
                    self._marked.append(r)

    def _add_all(self, rows: list[Row], space: pymunk.Space, fresh: bool) -> None:
        """Add every row's terms from one read of every arbiter, as the walk adds them: a row's
        terms in the order of their values. Each arbiter's term for its body A is worked out
        once (J and its normal part); body B's is its negation, the values the walk reads from
        B's side (Chipmunk gives B −J and −n; their dot product is J·n, bit for bit).

        On a fresh row the order does not matter ((0 + x) + y = (0 + y) + x, bit for bit), and
        a term of body B is subtracted instead of negated and added (x − y is x + (−y)): the
        plan sorts the rows by their terms' signs, so no negation is made."""
        arbiters = self._arbiters
        arbiters.read(space)
        ids = arbiters.ids
        if ids is not self._plan_ids or rows is not self._plan_rows:
            self._plan = _plan(rows, ids)
            self._plan_ids, self._plan_rows = ids, rows
        terms = [
            (jx, jy, nx * (dot := jx * nx + jy * ny), ny * dot)
            for jx, jy, nx, ny in arbiters.values()
        ]
        plan = self._plan
        if fresh:
            for r, i in plan.a:
                jx, jy, jnx, jny = terms[i]
                r.jx = 0.0 + jx
                r.jy = 0.0 + jy
                r.jnx = 0.0 + jnx
                r.jny = 0.0 + jny
            for r, i in plan.b:
                jx, jy, jnx, jny = terms[i]
                r.jx = 0.0 - jx
                r.jy = 0.0 - jy
                r.jnx = 0.0 - jnx
                r.jny = 0.0 - jny
            for r, i, k in plan.aa:
                ax, ay, anx, any_ = terms[i]
                bx, by, bnx, bny = terms[k]
                r.jx = 0.0 + ax + bx
                r.jy = 0.0 + ay + by
                r.jnx = 0.0 + anx + bnx
                r.jny = 0.0 + any_ + bny
            for r, i, k in plan.ab:
                ax, ay, anx, any_ = terms[i]
                bx, by, bnx, bny = terms[k]
                r.jx = 0.0 + ax - bx
                r.jy = 0.0 + ay - by
                r.jnx = 0.0 + anx - bnx
                r.jny = 0.0 + any_ - bny
            for r, i, k in plan.bb:
                ax, ay, anx, any_ = terms[i]
                bx, by, bnx, bny = terms[k]
                r.jx = 0.0 - ax - bx
                r.jy = 0.0 - ay - by
                r.jnx = 0.0 - anx - bnx
                r.jny = 0.0 - any_ - bny
            for r in plan.idle:
                r.jx = r.jy = r.jnx = r.jny = 0.0
        else:
            terms += [(-jx, -jy, -jnx, -jny) for jx, jy, jnx, jny in terms]
            for r, k in plan.one:
                jx, jy, jnx, jny = terms[k]
                r.jx += jx
                r.jy += jy
                r.jnx += jnx
                r.jny += jny
            for r, k, k2 in plan.two:
                a, b = terms[k], terms[k2]
                if b < a:
                    a, b = b, a
                ax, ay, anx, any_ = a
                bx, by, bnx, bny = b
                r.jx = r.jx + ax + bx
                r.jy = r.jy + ay + by
                r.jnx = r.jnx + anx + bnx
                r.jny = r.jny + any_ + bny
        if not plan.many:
            return
        if fresh:
            terms += [(-jx, -jy, -jnx, -jny) for jx, jy, jnx, jny in terms]
        for r, found in plan.many:
            if fresh:
                r.jx = r.jy = r.jnx = r.jny = 0.0
            jx, jy, jnx, jny = r.jx, r.jy, r.jnx, r.jny
            for vx, vy, vnx, vny in sorted(terms[k] for k in found):
                jx += vx
                jy += vy
                jnx += vnx
                jny += vny
            r.jx, r.jy, r.jnx, r.jny = jx, jy, jnx, jny

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


@dataclass(frozen=True, slots=True)
class _Plan:
    """Which terms of a substep go to which row. A term is an index into the substep's terms:
    arbiter i's term for its body A is i, for its body B (the negation) M + i, M arbiters.

    Attributes:
        one, two: the rows with one term, two: (row, term) and (row, term, term), for a step's
            later substeps.
        many: the rows with three or more, each with its terms (any substep).
        a, b: the rows with one term, of an arbiter whose body A (B) is the row's: (row,
            arbiter), for a step's first substep.
        aa, ab, bb: the rows with two terms: (row, arbiter, arbiter), the row's body A of both,
            A of the first and B of the second, B of both; for a step's first substep.
        idle: the rows without a term.
    """

    one: list[tuple[Row, int]] = field(default_factory=list)
    two: list[tuple[Row, int, int]] = field(default_factory=list)
    many: list[tuple[Row, list[int]]] = field(default_factory=list)
    a: list[tuple[Row, int]] = field(default_factory=list)
    b: list[tuple[Row, int]] = field(default_factory=list)
    aa: list[tuple[Row, int, int]] = field(default_factory=list)
    ab: list[tuple[Row, int, int]] = field(default_factory=list)
    bb: list[tuple[Row, int, int]] = field(default_factory=list)
    idle: list[Row] = field(default_factory=list)


def _plan(rows: list[Row], ids: list[int]) -> _Plan:
    """Which arbiters' terms go to which row, for arbiters between ``ids`` (id_a, id_b, …)."""
    m = len(ids) // 2
    row_of = {raw.body_id(r.body): r for r in rows}
    terms: dict[int, list[int]] = {}
    for i in range(m):
        for body_id, term in ((ids[2 * i], i), (ids[2 * i + 1], m + i)):
            if body_id in row_of:
                terms.setdefault(body_id, []).append(term)
    plan = _Plan()
    for body_id, r in row_of.items():
        found = terms.get(body_id, [])
        if len(found) > 2:
            plan.many.append((r, found))
            continue
        if not found:
            plan.idle.append(r)
            continue
        on_a = sorted(found, key=lambda k: k >= m)  # A's terms first
        if len(on_a) == 1:
            plan.one.append((r, found[0]))
            (plan.a if on_a[0] < m else plan.b).append((r, on_a[0] % m))
        else:
            plan.two.append((r, found[0], found[1]))
            first, second = on_a
            pairs = plan.aa if second < m else plan.ab if first < m else plan.bb
            pairs.append((r, first % m, second % m))
    return plan
