"""Laws of chapter 10's numbers (:mod:`tools.figures.ch10_stability`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

from tools.figures import ch10_stability as ch10


def test_chapter_10_guards_removed_are_caught() -> None:
    """Chapter 10: with ring_room's default wall the hard ring loses a body at 1/40 s (the
    containment check catches it), and without the runtime guard a runaway body goes on far past
    where the guard stops the world."""
    assert ch10.thin_ring_outcome().broke == "contained"
    assert ch10.hard_run("spinning ring", ch10.THIN_WALL_DT).broke is None
    stopped = ch10.ch10_guard_step()
    assert 0 < stopped < ch10.ch10_unguarded_last_step()
    assert ch10.runaway_run(False)[1] == 0 or ch10.runaway_run(False)[1] > stopped
