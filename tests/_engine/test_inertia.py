"""``playground._engine.inertia``: many bodies' mass and moment read in one call give the very
doubles ``body.mass`` and ``body.moment`` give, by the compiled helper and by its fallback alike,
as they are now (a change between two reads is read)."""

from __future__ import annotations

import math
import os
import struct

import numpy as np
import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import inertia, raw
from playground._engine.inertia import Inertia

masses = st.floats(min_value=1e-6, max_value=1e9, allow_nan=False, allow_infinity=False)
moments = st.one_of(st.just(math.inf), masses)


def _bits(values: list[float]) -> bytes:
    """The values' IEEE 754 bytes: equal only if equal to the last bit."""
    return struct.pack(f"{len(values)}d", *values)


@settings(deadline=None)
@given(st.lists(st.tuples(masses, moments), max_size=40))
def test_a_read_gives_each_bodys_mass_and_moment_bit_for_bit(
    values: list[tuple[float, float]],
) -> None:
    """Law: Inertia.read and its cffi fallback give body.mass and body.moment of each body, in
    the list's order, to the bit (an infinite moment among them: a body that does not turn)."""
    bodies = [pymunk.Body(m, i) for m, i in values]
    want_mass = _bits([b.mass for b in bodies])
    want_moment = _bits([b.moment for b in bodies])
    for mass, moment in (
        Inertia(bodies).read(),
        inertia.read_by_cffi([raw.handle(b) for b in bodies]),
    ):
        assert _bits(mass.tolist()) == want_mass
        assert _bits(moment.tolist()) == want_moment


def test_a_read_sees_a_change_and_keeps_the_arrays_it_gave() -> None:
    """A mass set between two reads is read by the second; the first read's arrays stay as
    they were (a caller keeps them)."""
    a, b = pymunk.Body(2.0, 0.5), pymunk.Body(70.0, 1.25)
    reads = Inertia([a, b])
    first = reads.read()
    b.mass, b.moment = 140.0, 2.5
    second = reads.read()
    assert [x.tolist() for x in first] == [[2.0, 70.0], [0.5, 1.25]]
    assert [x.tolist() for x in second] == [[2.0, 140.0], [0.5, 2.5]]


@pytest.mark.skipif(inertia.INERTIA_BY != "compiled", reason="the compiled helper is not built")
def test_the_compiled_helper_refuses_what_it_cannot_read() -> None:
    """Wrong item types, a mismatched length, a null body or a read-only output raise, naming
    what is wrong, instead of reading or writing memory that is not there."""
    from playground._engine import _inertia

    body = pymunk.Body(2.0, 0.5)
    get_mass, get_moment = inertia._MASS_ADDRESS, inertia._MOMENT_ADDRESS
    one = np.array([inertia._address(raw.handle(body))], dtype=np.uintp)
    with pytest.raises(ValueError, match="2 x 1"):
        _inertia.mass_moment(get_mass, get_moment, one, np.zeros(3))
    with pytest.raises(TypeError, match="bodies"):
        _inertia.mass_moment(get_mass, get_moment, one.astype(np.float64), np.zeros(2))
    with pytest.raises(TypeError, match="out"):
        _inertia.mass_moment(get_mass, get_moment, one, np.zeros(2, dtype=np.float32))
    with pytest.raises(ValueError, match="null"):
        _inertia.mass_moment(get_mass, get_moment, np.zeros(1, dtype=np.uintp), np.zeros(2))
    with pytest.raises(ValueError, match="must not be null"):
        _inertia.mass_moment(0, get_moment, one, np.zeros(2))
    read_only = np.zeros(2)
    read_only.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        _inertia.mass_moment(get_mass, get_moment, one, read_only)
    out = np.zeros(2)
    _inertia.mass_moment(get_mass, get_moment, one, out)
    assert out.tolist() == [2.0, 0.5]


@pytest.mark.skipif(os.environ.get("CI") != "true", reason="only CI (.ci/run) must build it")
def test_ci_runs_the_compiled_helper_not_the_fallback() -> None:
    """CI installs on a machine with a compiler and Python's headers: there Inertia.read must run
    through the compiled helper, or CI would test only the fallback."""
    assert inertia.INERTIA_BY == "compiled"
