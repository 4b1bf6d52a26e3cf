"""Laws of chapter 6's numbers (:mod:`tools.figures.ch06_playing_with_gravity`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

from tools.figures import ch06_playing_with_gravity as ch6
from tools.figures.runs import DT

TOL_LEAP_SHIFT = 1e-9
"""m: the leap's flight never touches the creature, so the landing spot moves by exactly the
creature's extra travel; only the rounding of positions of order 10 m differs."""

TOL_CARRIED = 0.01
"""m/s: speed relative to the creature that still counts as carried (gravity_leap's own check)."""


def test_exercise_6_a_faster_creature_is_landed_on_as_soon_and_further_back() -> None:
    """Chapter 6's exercise: the flight after the leap does not depend on the creature, so a
    creature flying Δv faster is landed on at the same moment, Δv·t further back (t since the
    start), and it still carries the player."""
    dv = ch6.LEAP_FAST - ch6.ch6_leap_speed()
    land = ch6.ch6_leap_land_time()
    assert abs(ch6.ch6_leap_fast_land_time() - land) < 0.5 * DT
    shift = ch6.ch6_leap_land_x() - ch6.ch6_leap_fast_land_x()
    assert abs(shift - dv * (ch6.LEAP_TIME + land)) < TOL_LEAP_SHIFT
    end = ch6.leap_run(ch6.LEAP_FAST)[-1]
    assert end[1] == 1.0, "the player should end standing on the faster creature"
    assert abs(end[2]) < ch6.leap_half_width()
    assert end[4] < TOL_CARRIED
