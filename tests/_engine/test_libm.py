"""``playground._engine.libm``: the C library's ``atan2`` over arrays gives ``math.atan2``'s
bits, by the compiled helper and by its fallback alike."""

from __future__ import annotations

import math
import os
import struct

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from playground._engine import libm

SPECIAL = [0.0, -0.0, 1.0, -1.0, math.inf, -math.inf, math.nan, 5e-324, -5e-324, 1e308]
values = st.one_of(st.sampled_from(SPECIAL), st.floats(allow_nan=True, allow_infinity=True))


def bits(x: float) -> bytes:
    """The float's bits; every NaN one value (its payload is no physics)."""
    return b"nan" if math.isnan(x) else struct.pack("<d", x)


def by_math(pairs: list[tuple[float, float]]) -> list[bytes]:
    return [bits(math.atan2(y, x)) for y, x in pairs]


@given(st.lists(st.tuples(values, values), max_size=60))
def test_atan2_is_math_atan2_bit_for_bit(pairs: list[tuple[float, float]]) -> None:
    """Law: libm.atan2 and its fallback give math.atan2 of each pair, to the bit (signed zeros,
    infinities and NaN among them)."""
    y = np.array([p for p, _ in pairs], dtype=np.float64)
    x = np.array([q for _, q in pairs], dtype=np.float64)
    want = by_math(pairs)
    assert [bits(v) for v in libm.atan2(y, x).tolist()] == want
    assert [bits(v) for v in libm.atan2_by_math(y, x).tolist()] == want


def test_atan2_on_the_angles_where_numpy_differs() -> None:
    """On 20 000 ordinary angles, where numpy's arctan2 may give another last bit (it does on
    a CPU with AVX-512), libm.atan2 gives math.atan2's."""
    rng = np.random.default_rng(27)
    y, x = rng.uniform(-1.0, 1.0, 20_000), rng.uniform(-1.0, 1.0, 20_000)
    want = np.array([math.atan2(a, b) for a, b in zip(y.tolist(), x.tolist(), strict=True)])
    assert libm.atan2(y, x).tobytes() == want.tobytes()


def test_atan2_broadcasts_and_takes_views_and_floats() -> None:
    """Shapes broadcast as numpy's do; strided views and plain floats are read as values."""
    y = np.arange(12.0).reshape(3, 4)[:, ::2] - 3.0  # a strided view, (3, 2)
    x = np.array([0.5, -2.0])
    got = libm.atan2(y, x)
    assert got.shape == (3, 2)
    want = [[math.atan2(a, b) for a, b in zip(r, x.tolist(), strict=True)] for r in y.tolist()]
    assert got.tolist() == want
    assert float(libm.atan2(1.0, -1.0)) == math.atan2(1.0, -1.0)
    # One shape, but strided (a column of rows), or integers: read as values too.
    rows = np.arange(8.0).reshape(4, 2) - 3.5
    a, b = rows[:, 0], rows[:, 1]
    assert not a.flags.c_contiguous
    want = [math.atan2(p, q) for p, q in zip(a.tolist(), b.tolist(), strict=True)]
    assert libm.atan2(a, b).tolist() == want
    ints = [math.atan2(p, q) for p, q in zip(a.tolist(), range(4), strict=True)]
    assert libm.atan2(a, np.arange(4)).tolist() == ints


@pytest.mark.skipif(libm.ATAN2_BY != "compiled", reason="the compiled helper is not built")
def test_the_compiled_helper_refuses_what_it_cannot_read() -> None:
    """A wrong dtype or lengths that differ are errors, not reads of memory that is not there."""
    from playground._engine import _libm

    one = np.zeros(1)
    with pytest.raises(ValueError, match="one length"):
        _libm.atan2(one, np.zeros(2), one)
    with pytest.raises(TypeError, match="float64"):
        _libm.atan2(np.zeros(1, dtype=np.float32), one, one)
    with pytest.raises(BufferError):
        _libm.atan2(one, one, b"12345678")  # read-only: nowhere to write


@pytest.mark.skipif(os.environ.get("CI") != "true", reason="only CI (.ci/run) must build it")
def test_ci_runs_the_compiled_helper_not_the_fallback() -> None:
    """CI installs on a machine with a compiler and Python's headers: there libm.atan2 must run
    through the compiled helper, or CI would test only the fallback."""
    assert libm.ATAN2_BY == "compiled"
