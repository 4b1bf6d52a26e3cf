"""The laws' elementwise operations (:mod:`playground.controller.elementwise`): on arrays they
give, element by element, the bits the float operations give — signed zeros included, where
``np.maximum`` would not, and NaN where a float gives NaN."""

from __future__ import annotations

import math
import struct

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from playground.controller._vec import ZERO
from playground.controller.elementwise import ARRAYS, FLOATS

SPECIAL = [0.0, -0.0, 1.0, -1.0, math.inf, -math.inf, math.nan, 5e-324, -5e-324]
values = st.one_of(st.sampled_from(SPECIAL), st.floats(allow_nan=True, allow_infinity=True))


def bits(x: float) -> bytes:
    """The float's bits; every NaN one value (a NaN's payload is no physics: numpy's atan2 may
    carry another one than libm's through a NaN argument)."""
    return b"nan" if math.isnan(x) else struct.pack("<d", x)


@given(st.lists(st.tuples(values, values), min_size=1, max_size=50))
def test_max_min_atan2_are_the_float_ones_bit_for_bit(pairs: list[tuple[float, float]]) -> None:
    """Law: ARRAYS.max/min/atan2 on arrays = FLOATS' on each pair, to the bit."""
    a = np.array([p for p, _ in pairs])
    b = np.array([q for _, q in pairs])
    for name in ("max", "min", "atan2"):
        got = getattr(ARRAYS, name)(a, b).tolist()
        want = [getattr(FLOATS, name)(p, q) for p, q in pairs]
        assert [bits(x) for x in got] == [bits(x) for x in want], name


def test_np_maximum_would_not_do() -> None:
    """Why ARRAYS.max is not np.maximum: max(0.0, −0.0) is 0.0, np.maximum gives −0.0."""
    assert bits(max(0.0, -0.0)) == bits(0.0)
    assert bits(float(np.maximum(0.0, -0.0))) == bits(-0.0)
    assert bits(float(ARRAYS.max(np.array([0.0]), np.array([-0.0]))[0])) == bits(0.0)


@given(st.lists(st.tuples(values, st.booleans()), min_size=1, max_size=50))
def test_unless_and_vector_are_the_float_ones(rows: list[tuple[float, bool]]) -> None:
    """Law: ARRAYS.unless/vector = FLOATS' row by row (ZERO where the force is 0)."""
    f = np.array([x for x, _ in rows])
    cond = np.array([c for _, c in rows])
    got = ARRAYS.unless(cond, f).tolist()
    assert [bits(x) for x in got] == [bits(FLOATS.unless(c, x)) for x, c in rows]
    vx, vy = ARRAYS.vector(f, 0.6, -0.8)
    for k, (x, _) in enumerate(rows):
        want = FLOATS.vector(x, 0.6, -0.8)
        if want is ZERO:
            assert (vx[k], vy[k]) == (0.0, 0.0)
        else:
            assert [bits(v) for v in (vx[k], vy[k])] == [bits(v) for v in want]


def test_atan2_is_libms_where_numpys_simd_loop_is_not() -> None:
    """Why ARRAYS.atan2 is not np.arctan2: on a CPU with AVX-512, numpy's loop differs from
    libm's ``math.atan2`` in the last bit for some moderate pairs (a balance error's cross and
    dot products), which the float-generating test above rarely draws."""
    rng = np.random.default_rng(27)
    y, x = rng.uniform(-1.0, 1.0, 4096), rng.uniform(-1.0, 1.0, 4096)
    got = ARRAYS.atan2(y, x).tolist()
    assert got == [math.atan2(p, q) for p, q in zip(y.tolist(), x.tolist(), strict=True)]
    assert ARRAYS.atan2(np.array([[0.3]]), 0.7).tolist() == [[math.atan2(0.3, 0.7)]]


@given(st.lists(st.tuples(values, values), min_size=1, max_size=50))
def test_hypot_is_pythons_bit_for_bit(pairs: list[tuple[float, float]]) -> None:
    """Law: ARRAYS.hypot on arrays = ``math.hypot`` on each pair, to the bit."""
    got = ARRAYS.hypot(np.array([p for p, _ in pairs]), np.array([q for _, q in pairs]))
    assert [bits(x) for x in got.tolist()] == [bits(math.hypot(p, q)) for p, q in pairs]


def test_hypot_is_pythons_where_numpys_is_not() -> None:
    """Why ARRAYS.hypot is not np.hypot: CPython's ``math.hypot`` rounds its sum of squares
    otherwise than libm's hypot, which np.hypot calls (a crowd's weights, m·|g|)."""
    rng = np.random.default_rng(27)
    x, y = rng.uniform(-20.0, 20.0, 4096), rng.uniform(-20.0, 20.0, 4096)
    want = [math.hypot(p, q) for p, q in zip(x.tolist(), y.tolist(), strict=True)]
    assert ARRAYS.hypot(x, y).tolist() == want
    assert np.hypot(x, y).tolist() != want


finite = st.one_of(st.sampled_from([0.0, -0.0, 5e-324, -5e-324]), st.floats(allow_nan=False,
                   allow_infinity=False))  # fmt: skip


@given(st.lists(finite, min_size=1, max_size=50))
def test_cos_and_sin_are_libms_bit_for_bit(angles: list[float]) -> None:
    """Law: ARRAYS.cos/sin on arrays = ``math.cos``/``math.sin`` on each finite angle, to the
    bit (of an infinite one math raises, numpy gives NaN: no law turns by one)."""
    a = np.array(angles)
    assert [bits(x) for x in ARRAYS.cos(a).tolist()] == [bits(math.cos(x)) for x in angles]
    assert [bits(x) for x in ARRAYS.sin(a).tolist()] == [bits(math.sin(x)) for x in angles]


def test_cos_and_sin_are_libms_over_the_angles_a_law_turns_by() -> None:
    """The law above, densely where the lean turns (|angle| ≤ π + max_lean): numpy's loops for
    cos and sin are libm's bits, unlike its arctan2's (a numpy that changed this fails here)."""
    rng = np.random.default_rng(27)
    a = np.concatenate([rng.uniform(-4.0, 4.0, 65536), rng.uniform(-1e-3, 1e-3, 4096)])
    angles = a.tolist()
    assert ARRAYS.cos(a).tolist() == [math.cos(x) for x in angles]
    assert ARRAYS.sin(a).tolist() == [math.sin(x) for x in angles]


@given(st.lists(st.tuples(st.booleans(), values, values), min_size=1, max_size=50))
def test_where_and_all_are_the_float_ones(rows: list[tuple[bool, float, float]]) -> None:
    """Law: ARRAYS.where/all = FLOATS' row by row (all: over every row)."""
    cond = np.array([c for c, _, _ in rows])
    a, b = np.array([x for _, x, _ in rows]), np.array([y for _, _, y in rows])
    got = ARRAYS.where(cond, a, b).tolist()
    assert [bits(x) for x in got] == [bits(FLOATS.where(c, x, y)) for c, x, y in rows]
    assert bool(ARRAYS.all(cond)) == all(FLOATS.all(c) for c, _, _ in rows)
