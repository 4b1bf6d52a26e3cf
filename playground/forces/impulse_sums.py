"""Each tracked body's arbiter impulses summed over a step, from one read of every arbiter.

The contact split (:mod:`playground.forces.contact_split`) needs, per tracked body, the sum of
the impulses its arbiters applied to it (and of their parts along the contact normals). The
arbiters come in one batch read (:class:`~playground._engine.arbiters.ArbiterRows`); an arbiter
gives body A +J and body B −J. Chipmunk's arbiter order (and which body is A) follows memory
addresses, which differ between runs, so each body's terms of a substep are added in the order
of their values (jx, then jy, jnx, jny): two builds of a scene give bit-identical sums, and so
does the scalar implementation, which adds each body's terms in that order too
(:mod:`playground.forces.scalar.contacts`).

Which arbiter's terms go to which row is a *plan*, made again only when the read's ids change;
a substep then costs a fixed dozen numpy calls:

- a row with at most two terms in the substep takes them from an (N, 2) table (a missing term
  is a row of zeros): on a step's first substep its sum starts at +0.0 and two terms give the
  same sum in either order (x + y == y + x, and adding +0.0 or −0.0 to a sum that is never −0.0
  changes nothing), so they are added as they come; on a later substep the two are put in
  value order first;
- the rows with three or more terms (few: a body in a heap) are sorted in a table of their own.

>>> keys, key_row = np.array([7, 9], dtype=np.uintp), np.array([1, 0], dtype=np.intp)
>>> sums = ImpulseSums()
>>> sums.reset(keys, key_row)
>>> pairs = np.array([[9, 7], [7, 3]], dtype=np.uintp)  # 9 on 7; 7 on an untracked body 3
>>> values = np.array([[0.0, 2.0, 0.0, 1.0], [1.0, 1.0, 0.0, -1.0]])
>>> sums.begin()
>>> sums.add(pairs, values)
>>> sums.sums.tolist()  # row 0 is body 9, row 1 body 7: −J of the first arbiter + J of the second
[[0.0, 2.0, 0.0, 2.0], [1.0, -1.0, 0.0, -1.0]]
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from playground._engine.batch import lookup

__all__ = ["ImpulseSums"]


@dataclass(frozen=True, slots=True)
class _Plan:
    """Where each tracked row's terms are, in the (2M + 1, 4) table of one substep's terms:
    M arbiters' +J rows, their −J rows, then a row of zeros (a missing term).

    Attributes:
        first, second: (N,) table rows of the terms of each tracked row with at most two terms
            (two arrays: the gathers are then contiguous, several times cheaper for numpy to add
            than the strided halves of one (N, 2, 4) gather).
        heaped: the tracked rows with three or more terms; (R,).
        heap: (R, K) table rows of their terms, K the most any has (the rest: the zero row).
    """

    first: NDArray[np.intp]
    second: NDArray[np.intp]
    heaped: NDArray[np.intp]
    heap: NDArray[np.intp]


def _plan(
    pairs: NDArray[np.uintp], keys: NDArray[np.uintp], key_row: NDArray[np.intp], n: int
) -> _Plan:
    """The plan for arbiters between ``pairs`` of body ids, ``keys`` the sorted ids of the
    ``n`` tracked bodies and ``key_row`` the row of each."""
    m = len(pairs)
    hit_a = lookup(keys, pairs[:, 0])
    hit_b = lookup(keys, pairs[:, 1])
    on_a = np.flatnonzero(hit_a >= 0)
    on_b = np.flatnonzero(hit_b >= 0)
    term = np.concatenate([on_a, on_b + m])  # +J of an arbiter for its A, −J for its B
    row = np.concatenate([key_row[hit_a[on_a]], key_row[hit_b[on_b]]])
    order = np.argsort(row, kind="stable")
    term, row = term[order], row[order]
    count = np.bincount(row, minlength=n)
    start = np.cumsum(count) - count
    slot = np.arange(len(row)) - start[row]  # the term's place among its row's
    zero = 2 * m
    few = count[row] <= 2
    table = np.full((n, 2), zero, dtype=np.intp)
    table[row[few], slot[few]] = term[few]
    heaped = np.flatnonzero(count >= 3)
    heap = np.full((len(heaped), int(count.max(initial=0))), zero, dtype=np.intp)
    if len(heaped):
        place = np.empty(n, dtype=np.intp)
        place[heaped] = np.arange(len(heaped))
        many = ~few
        heap[place[row[many]], slot[many]] = term[many]
    return _Plan(table[:, 0].copy(), table[:, 1].copy(), heaped, heap)


def _pair_in_value_order(
    a: NDArray[np.float64], b: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(N, 4) terms ``a`` and ``b`` of each row, swapped where ``b`` comes first in the order of
    their values (jx, jy, jnx, jny, as Python compares tuples; a tie keeps ``a`` first)."""
    before = b[:, 3] < a[:, 3]
    for c in (2, 1, 0):
        before = (b[:, c] < a[:, c]) | ((b[:, c] == a[:, c]) & before)
    swap = before[:, None]
    return np.where(swap, b, a), np.where(swap, a, b)


def _in_value_order(terms: NDArray[np.float64]) -> NDArray[np.float64]:
    """(R, K, 4) terms with each row's K put in the order of their values (jx, jy, jnx, jny:
    the order of Python's tuples, as the scalar implementation sorts them)."""
    order = np.lexsort((terms[..., 3], terms[..., 2], terms[..., 1], terms[..., 0]), axis=-1)
    return np.take_along_axis(terms, order[..., None], axis=1)


class ImpulseSums:
    """Per tracked row, Σ over the step's substeps of its arbiters' impulses and their normal
    parts: :attr:`sums` columns jx, jy, jnx, jny (N·s), one row per tracked body."""

    __slots__ = ("_fresh", "_key_row", "_keys", "_plan", "_plan_of", "_table", "sums")

    def __init__(self) -> None:
        self._keys = np.zeros(0, dtype=np.uintp)
        self._key_row = np.zeros(0, dtype=np.intp)
        self.sums = np.zeros((0, 4))
        self._plan: _Plan | None = None
        self._plan_of: NDArray[np.uintp] | None = None  # the pairs array the plan was made for
        self._table = np.zeros((1, 4))  # one substep's terms: +J rows, −J rows, a zero row
        self._fresh = True  # no substep added since begin: every sum is +0.0

    def reset(self, keys: NDArray[np.uintp], key_row: NDArray[np.intp]) -> None:
        """A new tracked set: ``keys`` its sorted body ids, ``key_row`` the row of each."""
        self._keys = keys
        self._key_row = key_row
        self.sums = np.zeros((len(keys), 4))
        self._plan = self._plan_of = None
        self._fresh = True

    def begin(self) -> None:
        """Zero the sums before a step."""
        self.sums.fill(0.0)
        self._fresh = True

    def add(self, pairs: NDArray[np.uintp], values: NDArray[np.float64]) -> None:
        """Add one substep's arbiters: ``pairs`` (M, 2) body ids (an array kept while the ids
        do not change, as :class:`~playground._engine.arbiters.ArbiterRows` keeps it) and
        ``values`` (M, 4) rows jx, jy, nx, ny (the impulse on body A, N·s, and the normal)."""
        m = len(pairs)
        if self._plan is None or self._plan_of is not pairs:
            self._plan = _plan(pairs, self._keys, self._key_row, len(self._keys))
            self._plan_of = pairs
        plan = self._plan
        table = self._table
        if len(table) != 2 * m + 1:
            table = self._table = np.zeros((2 * m + 1, 4))
        plus = table[:m]
        np.copyto(plus, values)
        # The normal part of J, (J·n)·n: the same operations, in the same order, as the scalar
        # implementation's (jx·nx + jy·ny), then nx·dot and ny·dot.
        dot = plus[:, 0] * plus[:, 2]
        dot += plus[:, 1] * plus[:, 3]
        plus[:, 2] *= dot  # column by column: a third of the cost of plus[:, 2:4] *= dot[:, None]
        plus[:, 3] *= dot
        np.negative(plus, out=table[m : 2 * m])
        sums = self.sums
        a = np.take(table, plan.first, axis=0)
        b = np.take(table, plan.second, axis=0)
        if not self._fresh:
            a, b = _pair_in_value_order(a, b)
        sums += a
        sums += b
        if len(plan.heaped):
            heap = _in_value_order(np.take(table, plan.heap, axis=0))
            rows = plan.heaped
            for k in range(heap.shape[1]):
                sums[rows] += heap[:, k]
        self._fresh = False
