"""Laws of chapter 8's numbers (:mod:`tools.figures.ch08_fixed_step`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

from playground.controller import ControllerConfig
from tools.figures import ch08_fixed_step as ch8
from tools.figures.runs import DT, G

TOL_APEX = 1e-3
"""m: the stepped apex against v²/2g + v·dt/2 (the next order, g·dt²/8 and the step on which the
apex falls, is below a millimetre from 60 Hz up; measured 0.3 mm at 60 Hz, 1.0 mm at 30 Hz)."""


def test_chapter_8_counts_steps_as_the_view_does() -> None:
    """Chapter 8: the steps per frame drawn in the figure are the view's Accumulator's (a 144 Hz
    display, a 60 Hz one with a hitch below the view's cap on steps per frame)."""
    from playground.view.clock import Accumulator

    hitch = [1.0 / 60.0] * 10
    hitch[5] = ch8.CH8_HITCH
    for frames in ([1.0 / 144.0] * 300, hitch):
        acc = Accumulator(dt=DT)
        assert ch8.steps_per_frame(frames, DT) == [acc.advance(t) for t in frames]


def test_chapter_8_apex_is_first_order_in_dt() -> None:
    """Chapter 8: the jump stepped at dt rises v²/2g + v·dt/2 (to within a millimetre), so a
    finer step gives a lower jump."""
    v = ControllerConfig().jump_speed
    for rate in ch8.CH8_RATES[2:]:
        dt = 1.0 / rate
        assert abs(ch8.jump_apex(dt) - (v * v / (2 * G) + v * dt / 2)) < TOL_APEX
    apexes = [ch8.jump_apex(1.0 / r) for r in ch8.CH8_RATES]
    assert apexes == sorted(apexes, reverse=True)
