"""Laws of the filter chain: a spike stage before the 1€ filter, and the shared interface."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import OneEuroFilter

DT = 1 / 60  # s, the physics step


@settings(max_examples=50, deadline=None)
@given(height=st.floats(5.0, 1e6), at=st.integers(20, 100), seed=st.integers(0, 2**32 - 1))
def test_chain_peak_not_higher_than_one_euro_alone(height: float, at: int, seed: int) -> None:
    """Median3 before 1€ keeps a bounce spike out: the chain's peak stays within the clean
    signal's range and is never higher than the peak of 1€ alone, which lets the spike through.
    """
    rng = np.random.default_rng(seed)
    n = 150
    clean = np.sin(np.arange(n) * DT * 2 * np.pi) + rng.normal(0.0, 0.05, size=n)
    spiky = clean.copy()
    spiky[at] += height
    chain = FilterChain(Median3(), OneEuroFilter(1.0, 0.5))
    alone = OneEuroFilter(1.0, 0.5)
    chain_out = [chain.filter(float(x), DT) for x in spiky]
    alone_out = [alone.filter(float(x), DT) for x in spiky]
    assert max(chain_out) <= clean.max()
    assert max(chain_out) <= max(alone_out)


def test_chain_interface() -> None:
    """The chain shares the interface: select and reset reach every stage; value is the last's."""
    chain = FilterChain(Median3(), OneEuroFilter(1.0, 0.5))
    before = chain.value
    assert before is None, "no output before the first sample"
    chain.filter(np.array([[1.0, 2.0], [3.0, 4.0]]), DT)
    chain.select(np.array([1]))
    np.testing.assert_array_equal(chain.filter(np.array([[3.0, 4.0]]), DT), [[3.0, 4.0]])
    value = chain.value
    assert value is not None and value.shape == (1, 2)
    chain.reset()
    assert all(s.value is None for s in (chain, *chain.stages))
    with pytest.raises(ValueError, match="stages"):
        FilterChain()


@pytest.mark.parametrize(
    "make",
    [lambda: FilterChain(Median3(), OneEuroFilter(2.0, 0.05, 1.0)), Median3],
    ids=["median-then-1€", "median"],
)
def test_filter_rows_is_filter_bit_for_bit(make: Callable[[], FilterChain | Median3]) -> None:
    """Law: ``filter_rows`` of the chain a world's perceived gravity runs (and of its median
    stage alone) gives what ``filter`` gives, to the last bit and with the same state after: on
    rows that all started, on a first sample, with a NaN row (held in every stage), and with a
    dt that is not valid (every row holds)."""
    rng = np.random.default_rng(7)
    short, generic = make(), make()
    for step in range(200):
        x = rng.normal(size=(40, 2)) * 10.0 + 9.81
        if step % 17 == 3:
            x[7] = np.nan
        if step % 29 == 11:
            x[3] = (1e300, -1e300)  # finite, but its differences overflow
        dt = 0.0 if step % 23 == 5 else 1.0 / 120.0
        a, b = short.filter_rows(x, dt), generic.filter(x, dt)
        assert a.tobytes() == b.tobytes(), step
        assert short.value is not None and generic.value is not None
        assert short.value.tobytes() == generic.value.tobytes(), step
