"""The overhead profile (:mod:`playground.bench.overhead`): a bare baseline and every effect at
every size."""

from __future__ import annotations

from playground.bench import overhead


def test_overhead_quick_structure() -> None:
    """Law: the overhead profile has a bare baseline and every effect at every size."""
    rows = overhead.profile(sizes=(10, 30), repeats=1, settle_steps=5)
    effects = {r.effect for r in rows}
    assert set(overhead.EFFECTS) <= effects
    sizes = {r.bodies for r in rows}
    for n in sizes:
        assert {r.effect for r in rows if r.bodies == n} == effects
    for r in rows:
        assert r.us_per_step > 0.0 and r.bare_us > 0.0
        assert r.ratio > 0.0
    assert "| effect |" in overhead.overhead_markdown(rows)
