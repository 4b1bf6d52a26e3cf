"""The benchmarks' timer (:mod:`playground.bench.blocks`): blocks alternate, every bare block is
prepared, and the ratio is the median of adjacent pairs."""

from __future__ import annotations

from playground.bench.blocks import Blocks, interleave


def test_interleave_alternates_and_prepares_every_b_block() -> None:
    """Law: blocks alternate which side goes first, and ``prepare_b`` runs (untimed) before
    every block of b, so b always starts from a fresh copy."""
    calls: list[str] = []
    t = interleave(
        lambda: calls.append("a"),
        lambda: calls.append("b"),
        repeats=4,
        steps=2,
        prepare_b=lambda: calls.append("p"),
    )
    assert len(t.a) == len(t.b) == 4
    # a first on even blocks, b first on odd ones
    assert "".join(calls) == "aa" + "pbb" + "pbb" + "aa" + "aa" + "pbb" + "pbb" + "aa"


def test_blocks_ratio_is_the_median_of_adjacent_pairs() -> None:
    """Law: the ratio is the median of a/b pair by pair (one disturbed block moves it not at
    all), ``best`` the fastest over the fastest, ``spread`` the extreme pair ratios."""
    t = Blocks(a=(2.0, 2.0, 50.0), b=(1.0, 1.0, 1.0))
    assert t.ratio == 2.0
    assert t.best == 2.0
    assert t.spread == (2.0, 50.0)
