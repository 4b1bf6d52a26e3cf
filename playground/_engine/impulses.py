"""Plumbing under the scalar contact split: each tracked body's arbiter impulses summed from one
read of every arbiter of the space (:class:`~playground._engine.arbiters.ArbiterValues`).

An arbiter gives body A its impulse J and body B −J; a row's *terms* are, for each of its
arbiters, J (or −J) and its part along the normal, (J·n)·n, and its sums add them in the order
Python sorts their tuples (jx, jy, jnx, jny), as the batch contact split
(:mod:`playground.forces.impulse_sums`) and the walk over a body's arbiters
(:mod:`playground.forces.scalar.contacts`) do: every implementation gives the same doubles.
Which terms go to which row is an :class:`ImpulsePlan`, made again only when the read's ids
change.

Where the optional compiled helper was built on install (:mod:`playground._engine._impulses`, a
small C extension), :func:`sum_impulses` is one C call for every row; without it the same terms
are added in Python floats (:func:`sum_impulses_by_python`). Both give the same doubles
(``tests/_engine/test_impulses.py``); :data:`SUMS_BY` says which path serves.

>>> import pymunk
>>> from playground._engine.arbiters import ArbiterValues
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
>>> plan = ImpulsePlan(arbiters.ids, [box.id])
>>> [round(x, 6) for x in sum_impulses(plan, arbiters, None)[0]]  # 20 N for 0.01 s, all normal
[0.0, 0.2, 0.0, 0.2]
"""

from __future__ import annotations

import struct
from array import array
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Final, Literal

from playground._engine.arbiters import ArbiterValues

__all__ = ["SUMS_BY", "Impulse", "ImpulsePlan", "sum_impulses", "sum_impulses_by_python"]

Impulse = tuple[float, float, float, float]
"""(jx, jy, jnx, jny): impulses on a body and their parts along the contact normals, N·s."""

_ZERO: Final[Impulse] = (0.0, 0.0, 0.0, 0.0)

_INDEX: Final = next(c for c in "lq" if array(c).itemsize == struct.calcsize("n"))
"""The array typecode of C's ``Py_ssize_t``, the compiled helper's index."""


def _compiled() -> Callable[[Any, array[int], array[int], list[Impulse] | None], list[Impulse]]:
    from playground._engine import _impulses

    return _impulses.sums


try:
    _sums_c: Callable[..., list[Impulse]] | None = _compiled()
except ImportError:
    _sums_c = None

SUMS_BY: Final[Literal["compiled", "python"]] = "python" if _sums_c is None else "compiled"
"""How :func:`sum_impulses` runs, as the module was imported: ``"compiled"`` (the helper built
on install, one C call for every row) or ``"python"`` (:func:`sum_impulses_by_python`)."""


@dataclass(frozen=True, slots=True)
class _Groups:
    """The rows of :class:`ImpulsePlan` by their terms, for the Python sums. A term is an index
    into a read's terms: arbiter i's for its body A is i, for its body B (the negation) M + i.

    Attributes:
        one, two: the rows with one term, two: (row, term) and (row, term, term), for a step's
            later substeps.
        many: the rows with three or more, each with its terms (any substep).
        a, b: the rows with one term, of an arbiter whose body A (B) is the row's: (row,
            arbiter), for a step's first substep.
        aa, ab, bb: the rows with two terms: (row, arbiter, arbiter), the row's body A of both,
            A of the first and B of the second, B of both; for a step's first substep.
    """

    one: list[tuple[int, int]] = field(default_factory=list)
    two: list[tuple[int, int, int]] = field(default_factory=list)
    many: list[tuple[int, list[int]]] = field(default_factory=list)
    a: list[tuple[int, int]] = field(default_factory=list)
    b: list[tuple[int, int]] = field(default_factory=list)
    aa: list[tuple[int, int, int]] = field(default_factory=list)
    ab: list[tuple[int, int, int]] = field(default_factory=list)
    bb: list[tuple[int, int, int]] = field(default_factory=list)


class ImpulsePlan:
    """Which terms of a read go to which row, for arbiters between ``ids`` (id_a, id_b of each
    arbiter in turn, as :attr:`ArbiterValues.ids <playground._engine.arbiters.ArbiterValues>`)
    and rows of the bodies ``row_ids`` (``body.id``), in that order.

    Attributes:
        rows: the number of rows.
        starts, terms: row k's terms are ``terms[starts[k]:starts[k + 1]]`` (the compiled
            helper's form).
    """

    __slots__ = ("_groups", "rows", "starts", "terms")

    def __init__(self, ids: list[int], row_ids: list[int]) -> None:
        m = len(ids) // 2
        row_of = {body_id: k for k, body_id in enumerate(row_ids)}
        found: list[list[int]] = [[] for _ in row_ids]
        for i in range(m):
            for body_id, term in ((ids[2 * i], i), (ids[2 * i + 1], m + i)):
                k = row_of.get(body_id)
                if k is not None:
                    found[k].append(term)
        self.rows = len(row_ids)
        self.starts = array(_INDEX, [0])
        self.terms = array(_INDEX)
        groups = self._groups = _Groups()
        for k, terms in enumerate(found):
            self.terms.extend(terms)
            self.starts.append(len(self.terms))
            if len(terms) > 2:
                groups.many.append((k, terms))
            elif terms:
                on_a = sorted(terms, key=lambda t: t >= m)  # A's terms first
                if len(terms) == 1:
                    groups.one.append((k, terms[0]))
                    (groups.a if on_a[0] < m else groups.b).append((k, on_a[0] % m))
                else:
                    groups.two.append((k, terms[0], terms[1]))
                    first, second = on_a
                    pairs = groups.aa if second < m else groups.ab if first < m else groups.bb
                    pairs.append((k, first % m, second % m))


def sum_impulses(
    plan: ImpulsePlan, arbiters: ArbiterValues, previous: list[Impulse] | None
) -> list[Impulse]:
    """Each row's sums of the terms of ``arbiters``' last read (N·s), a new list: from +0.0
    (``previous`` None: a step's first substep) or added to ``previous`` (one tuple a row)."""
    if _sums_c is None:
        return sum_impulses_by_python(plan, arbiters, previous)
    return _sums_c(arbiters.floats(), plan.starts, plan.terms, previous)


def sum_impulses_by_python(
    plan: ImpulsePlan, arbiters: ArbiterValues, previous: list[Impulse] | None
) -> list[Impulse]:
    """:func:`sum_impulses` in Python floats: the reference the compiled helper answers as, and
    its path without it.

    Each arbiter's term for its body A is worked out once (J and its normal part); body B's is
    its negation. From +0.0 the order of two terms does not matter ((0 + x) + y = (0 + y) + x,
    bit for bit), and a term of body B is subtracted instead of negated and added (x − y is
    x + (−y)): the plan groups the rows by their terms' signs, so no negation is made."""
    terms = [
        (jx, jy, nx * (dot := jx * nx + jy * ny), ny * dot) for jx, jy, nx, ny in arbiters.values()
    ]
    groups = plan._groups
    if previous is None:
        out = [_ZERO] * plan.rows
        for k, i in groups.a:
            jx, jy, jnx, jny = terms[i]
            out[k] = (0.0 + jx, 0.0 + jy, 0.0 + jnx, 0.0 + jny)
        for k, i in groups.b:
            jx, jy, jnx, jny = terms[i]
            out[k] = (0.0 - jx, 0.0 - jy, 0.0 - jnx, 0.0 - jny)
        for k, i, i2 in groups.aa:
            ax, ay, anx, any_ = terms[i]
            bx, by, bnx, bny = terms[i2]
            out[k] = (0.0 + ax + bx, 0.0 + ay + by, 0.0 + anx + bnx, 0.0 + any_ + bny)
        for k, i, i2 in groups.ab:
            ax, ay, anx, any_ = terms[i]
            bx, by, bnx, bny = terms[i2]
            out[k] = (0.0 + ax - bx, 0.0 + ay - by, 0.0 + anx - bnx, 0.0 + any_ - bny)
        for k, i, i2 in groups.bb:
            ax, ay, anx, any_ = terms[i]
            bx, by, bnx, bny = terms[i2]
            out[k] = (0.0 - ax - bx, 0.0 - ay - by, 0.0 - anx - bnx, 0.0 - any_ - bny)
    else:
        out = list(previous)
        terms += [(-jx, -jy, -jnx, -jny) for jx, jy, jnx, jny in terms]
        for k, t in groups.one:
            jx, jy, jnx, jny = terms[t]
            sx, sy, snx, sny = out[k]
            out[k] = (sx + jx, sy + jy, snx + jnx, sny + jny)
        for k, t, t2 in groups.two:
            a, b = terms[t], terms[t2]
            if b < a:
                a, b = b, a
            ax, ay, anx, any_ = a
            bx, by, bnx, bny = b
            sx, sy, snx, sny = out[k]
            out[k] = (sx + ax + bx, sy + ay + by, snx + anx + bnx, sny + any_ + bny)
    if groups.many:
        if previous is None:
            terms += [(-jx, -jy, -jnx, -jny) for jx, jy, jnx, jny in terms]
        for k, found in groups.many:
            sx, sy, snx, sny = out[k]
            for vx, vy, vnx, vny in sorted(terms[t] for t in found):
                sx += vx
                sy += vy
                snx += vnx
                sny += vny
            out[k] = (sx, sy, snx, sny)
    return out
