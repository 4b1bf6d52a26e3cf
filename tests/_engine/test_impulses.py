"""``playground._engine.impulses``: each row's arbiter impulses summed from one read give the sums
of the rule they are defined by (each term, J and its normal part or their negation, added from
+0.0 or from the sums so far in the order Python sorts the terms), to the bit, by the compiled
helper and by its Python fallback alike. Random piles: ``tests/forces/test_impulse_sums.py``."""

from __future__ import annotations

import os
import struct
from array import array
from typing import Any, cast

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import impulses
from playground._engine.arbiters import ArbiterValues
from playground._engine.impulses import Impulse, ImpulsePlan

_ARBITER = struct.Struct("=4d")


class _Read:
    """A read of arbiters made up: what :func:`impulses.sum_impulses` takes of an
    :class:`ArbiterValues` (its ids, its doubles)."""

    def __init__(self, ids: list[int], values: list[tuple[float, float, float, float]]) -> None:
        self.ids = ids
        self._bytes = b"".join(_ARBITER.pack(*v) for v in values)

    def floats(self) -> memoryview:
        return memoryview(self._bytes)

    def values(self) -> Any:
        return _ARBITER.iter_unpack(self._bytes)


def _rule(
    ids: list[int],
    values: list[tuple[float, float, float, float]],
    row_ids: list[int],
    previous: list[Impulse] | None,
) -> list[Impulse]:
    """The sums by their definition, a row at a time."""
    out = []
    for k, body in enumerate(row_ids):
        terms = []
        for i, (jx, jy, nx, ny) in enumerate(values):
            dot = jx * nx + jy * ny
            term = (jx, jy, nx * dot, ny * dot)
            if ids[2 * i] == body:
                terms.append(term)
            if ids[2 * i + 1] == body:
                terms.append((-term[0], -term[1], -term[2], -term[3]))
        sx, sy, snx, sny = (0.0, 0.0, 0.0, 0.0) if previous is None else previous[k]
        for vx, vy, vnx, vny in sorted(terms):
            sx, sy, snx, sny = sx + vx, sy + vy, snx + vnx, sny + vny
        out.append((sx, sy, snx, sny))
    return out


def _bits(sums: list[Impulse]) -> list[str]:
    return [x.hex() for s in sums for x in s]


# Few distinct values, zeros of both signs among them: ties between terms are common.
_value = st.sampled_from([0.0, -0.0, 1.0, -1.0, 0.5, 3.0, -2.25, 1e-9, 7.1e3])
_values = st.tuples(_value, _value, _value, _value)


@settings(deadline=None, max_examples=300)
@given(
    arbiters=st.lists(st.tuples(st.integers(0, 5), st.integers(0, 5), _values), max_size=14),
    rows=st.lists(st.integers(0, 6), unique=True, max_size=6),
    previous=st.none() | st.lists(st.tuples(_value, _value, _value, _value), min_size=6),
)
def test_the_sums_follow_their_rule_bit_for_bit(
    arbiters: list[tuple[int, int, tuple[float, float, float, float]]],
    rows: list[int],
    previous: list[Impulse] | None,
) -> None:
    """Law: for any arbiters between bodies 0 to 5 (some rows with none, some with many, equal
    terms and signed zeros) the compiled helper and the Python fallback give each row's sums of
    the rule, from +0.0 or from the sums so far."""
    ids = [body for a, b, _ in arbiters for body in (a, b)]
    values = [v for _, _, v in arbiters]
    before = None if previous is None else previous[: len(rows)]
    plan = ImpulsePlan(ids, rows)
    read = cast(ArbiterValues, _Read(ids, values))
    want = _bits(_rule(ids, values, rows, before))
    assert _bits(impulses.sum_impulses_by_python(plan, read, before)) == want
    assert _bits(impulses.sum_impulses(plan, read, before)) == want


def test_a_resting_box_sums_its_weight() -> None:
    """A box at rest on a floor: its one arbiter's impulse is its weight over the step, all of
    it along the normal, whichever path sums it."""
    space = pymunk.Space()
    space.gravity = (0.0, -10.0)
    space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
    box = pymunk.Body(2.0, 1.0)
    box.position = (0.0, 0.5)
    space.add(box, pymunk.Poly.create_box(box, (1.0, 1.0)))
    for _ in range(60):
        space.step(0.01)
    arbiters = ArbiterValues()
    arbiters.read(space)
    plan = ImpulsePlan(arbiters.ids, [box.id])
    for sums in (
        impulses.sum_impulses(plan, arbiters, None),
        impulses.sum_impulses_by_python(plan, arbiters, None),
    ):
        ((jx, jy, jnx, jny),) = sums
        assert jy == pytest.approx(0.2) and jny == jy
        assert abs(jx) < 1e-12 and abs(jnx) < 1e-12


@pytest.mark.skipif(impulses.SUMS_BY != "compiled", reason="the compiled helper is not built")
def test_the_compiled_helper_refuses_what_it_cannot_read() -> None:
    """A term beyond the read, starts that do not cover the terms, indices of the wrong type,
    floats that are not whole arbiters or previous sums of the wrong shape raise, naming what is
    wrong, instead of reading memory that is not there."""
    from playground._engine import _impulses

    sums: Any = _impulses.sums  # called with wrong arguments on purpose
    one = _ARBITER.pack(1.0, 2.0, 0.0, 1.0)
    index = impulses._INDEX
    starts, terms = array(index, [0, 1]), array(index, [1])
    assert sums(one, starts, terms, None) == [(-1.0, -2.0, -0.0, -2.0)]
    with pytest.raises(ValueError, match="not below 2 x 1"):
        sums(one, starts, array(index, [2]), None)
    with pytest.raises(ValueError, match="starts"):
        sums(one, array(index, [0, 2]), terms, None)
    with pytest.raises(ValueError, match="decreases"):
        sums(one, array(index, [0, 1, 0, 1]), terms, None)
    with pytest.raises(TypeError, match="terms"):
        sums(one, starts, array("d", [1.0]), None)
    with pytest.raises(ValueError, match="whole number"):
        sums(one[:-8], starts, terms, None)
    with pytest.raises(ValueError, match="previous"):
        sums(one, starts, terms, [])
    with pytest.raises(TypeError, match="previous"):
        sums(one, starts, terms, [(1.0, 2.0)])
    with pytest.raises(TypeError, match="previous"):
        sums(one, starts, terms, ())


@pytest.mark.skipif(os.environ.get("CI") != "true", reason="only CI (.ci/run) must build it")
def test_ci_runs_the_compiled_helper_not_the_fallback() -> None:
    """CI installs on a machine with a compiler and Python's headers: there the scalar contact
    split must sum through the compiled helper, or CI would test only the fallback."""
    assert impulses.SUMS_BY == "compiled"
