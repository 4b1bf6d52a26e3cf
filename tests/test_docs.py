"""Laws of the teaching chapters (docs/chapters): the text and the code never disagree.

Every number a chapter quotes sits in a marker, ``<!-- num:NAME -->3.00<!-- /num -->`` (the value
of ``playground.figures.NUMBERS[NAME]`` rounded to the digits shown) or
``<!-- below:NAME -->1e-12<!-- /below -->`` (an upper bound on it). The snippets themselves run as
doctests (pytest collects ``docs/**/*.md``). The exercises' answers are checked as laws here.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from playground import figures
from playground.cli import main
from playground.controller import ControllerConfig

DOCS = Path(__file__).resolve().parent.parent / "docs"
CHAPTERS = sorted((DOCS / "chapters").glob("*.md"))
MARKER = re.compile(r"<!-- (num|below):(\w+) -->([^<]*)<!-- /\1 -->")
FIGURE = re.compile(r"!\[[^\]]*\]\(\.\./img/chapters/([^)]+)\)")
GIF = re.compile(r"!\[[^\]]*\]\(\.\./img/gifs/([^)]+)\)")

TOL_REL = 1e-9
"""Relative slack beyond the printed rounding: float noise across machines and BLAS builds."""

TOL_RING = 0.01
"""Relative: spinning_ring's player, perceived gravity against ω²·r at its centre (the 1€
filter's lag on a vector turning with the ring shortens it by under 0.3 %; the level's own check
allows 1 %)."""

TOL_LIMIT = 0.01
"""On 2πf·dt: the bisection's resolution (1e-3) plus the slow growth right at the limit."""

TOL_DRIFT = 1e-3
"""m: the drive's drift without the feed-forward against a·τ·T (the lag's own settling adds well
under a millimetre)."""

TOL_JERK_REL = 0.05
"""Relative: the drift with the feed-forward against a·dt·τ (its one-step-late reading where the
acceleration starts and stops; measured equal to 3 digits, 5 % for the hover's coupling)."""

TOL_LEAP_SHIFT = 1e-9
"""m: the leap's flight never touches the creature, so the landing spot moves by exactly the
creature's extra travel; only the rounding of positions of order 10 m differs."""

TOL_FIXED_POINT = 0.01
"""Relative: the 1€ filter's simulated ramp lag against the fixed point L = 1/(2π(min_cutoff +
β·s·(1 + L/Te))) (the issue's 1 %; the fixed point is the steady state, and after the ramp's one
second the derivative smoother at 1 Hz has settled to e^(−2π) ≈ 0.2 % of its start)."""

TOL_HALF_STEP = 0.01
"""Relative: the ring's tangential error against the end of the step, against ω·dt/2 (the
issue's 1 %; from dt = 1/60 s the engine's own tangential error is below it)."""

TOL_ESTIMATORS_AT_MID = 0.1
"""Relative: finite differences at their own mid-point against reverse integration at its own,
on the ring (measured 4 % apart at 1/30 s, 6.5 % at 1/60 s: pymunk corrects overlaps by moving
positions with a bias velocity that the velocities never show, so positions carry a little
extra)."""

MID_STEP_BOUND = 0.01
"""The chapter's claim: against mid-step the ring's error is under 1 % at every swept dt."""

TOL_APEX = 1e-3
"""m: the stepped apex against v²/2g + v·dt/2 (the next order, g·dt²/8 and the step on which the
apex falls, is below a millimetre from 60 Hz up; measured 0.3 mm at 60 Hz, 1.0 mm at 30 Hz)."""

TOL_CARRIED = 0.01
"""m/s: speed relative to the creature that still counts as carried (gravity_leap's own check)."""


def markers() -> list[tuple[str, str, str, str]]:
    """(chapter file, kind, name, text) of every marker in the chapters."""
    found = []
    for path in CHAPTERS:
        for kind, name, text in MARKER.findall(path.read_text(encoding="utf-8")):
            found.append((path.name, kind, name, text.strip()))
    return found


def printed_rounding(text: str) -> float:
    """Half a unit of the last printed digit of ``text`` ("5.0" → 0.05, "882.9" → 0.05)."""
    digits = len(text.split(".")[1]) if "." in text else 0
    return 0.5 * 10.0**-digits


def test_there_are_ten_chapters_and_an_index_linking_them_in_order() -> None:
    """The table of contents lists every chapter, in reading order."""
    assert len(CHAPTERS) == 10
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    positions = [index.find(f"chapters/{p.name}") for p in CHAPTERS]
    assert all(p >= 0 for p in positions), positions
    assert positions == sorted(positions)


@pytest.mark.parametrize(("chapter", "kind", "name", "text"), markers())
def test_quoted_number_is_what_the_code_computes(
    chapter: str, kind: str, name: str, text: str
) -> None:
    """A quoted number is the code's value rounded to the digits shown (or a bound above it)."""
    assert name in figures.NUMBERS, f"{chapter}: unknown number {name!r}"
    value = figures.NUMBERS[name]()
    quoted = float(text)
    if kind == "below":
        assert value < quoted, f"{chapter}: {name} = {value!r} is not below {text}"
    else:
        slack = printed_rounding(text) + TOL_REL * abs(value)
        assert abs(value - quoted) <= slack, f"{chapter}: {name} = {value!r}, text says {text}"


def test_every_number_the_code_makes_is_quoted() -> None:
    """No number is computed for nothing: each one in NUMBERS appears in some chapter."""
    quoted = {name for _, _, name, _ in markers()}
    assert set(figures.NUMBERS) <= quoted, sorted(set(figures.NUMBERS) - quoted)


def test_every_chapter_shows_a_figure_the_code_makes() -> None:
    """Each chapter embeds at least one figure, and every embedded figure is in FIGURES."""
    for path in CHAPTERS:
        shown = FIGURE.findall(path.read_text(encoding="utf-8"))
        assert shown, f"{path.name}: no figure"
        for name in shown:
            assert name in figures.FIGURES, f"{path.name}: {name} is not made by the code"


def test_one_command_regenerates_every_figure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``playground figures --out DIR`` writes one PNG per figure, headless, and shows its
    progress on stderr (figure by figure, to the last)."""
    assert main(["figures", "--out", str(tmp_path)]) == 0
    for name in figures.FIGURES:
        data = (tmp_path / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n", name
    err = capsys.readouterr().err
    total = len(figures.FIGURES)
    assert f"{total}/{total}" in err, err[-300:]
    assert list(figures.FIGURES)[-1] in err


def test_exercise_1_drift_is_a_dt_tau() -> None:
    """Chapter 1: with the ground's acceleration fed forward the drift is a·dt·τ; without it
    the drive is a first-order lag and the drift is a·τ·T."""
    drift = figures.ch1_player_drift_cm() / 100.0
    predicted = figures.ch1_predicted_drift_cm() / 100.0
    assert abs(drift - predicted) < TOL_JERK_REL * predicted
    lag = figures.ch1_lag_simulated_cm() / 100.0
    assert abs(lag - figures.ch1_lag_drift_cm() / 100.0) < TOL_DRIFT


def test_exercise_2_ghost_force_is_the_forgotten_damping() -> None:
    """Chapter 2: the naive estimate's first-step force is −m·(1 − d)·v₀/h."""
    d = figures.SLIDE_DAMPING**figures.DT
    expected = -10.0 * (1.0 - d) * 3.0 / figures.DT
    assert math.isclose(figures.ch2_ghost_force(), expected, rel_tol=1e-6)


def test_exercise_3_twice_the_spin_four_times_the_gravity() -> None:
    """Chapter 3: perceived gravity in the ring is ω²·r, so doubling ω quadruples it."""
    for rate in (1.5, 3.0):
        felt, exact = figures.ring_reading(rate)
        assert abs(felt - exact) < TOL_RING * exact
    assert abs(figures.ch3_ring_ratio() - 4.0) < 4.0 * 2 * TOL_RING


def test_exercise_4_median_of_3_removes_a_one_step_spike() -> None:
    """Chapter 4: a one-step spike passes the 1€ filter at most of its height, not the median."""
    assert figures.ch4_spike_median() == 0.0
    assert figures.ch4_spike_euro() > 0.5 * figures.SPIKE


def test_exercise_5_stability_limit_is_two_zeta_plus_two_root() -> None:
    """Chapter 5: with the spring read where pymunk's integrator uses it and the damper on the
    velocity after the step, the hover is stable while 2πf·dt < 2ζ + 2√(ζ² + 1), and an undamped
    one neither gains nor loses energy."""
    assert abs(figures.ch5_limit_zeta1() - (2.0 + 2.0 * math.sqrt(2.0))) < TOL_LIMIT
    assert abs(figures.ch5_limit_zeta05() - (1.0 + math.sqrt(5.0))) < TOL_LIMIT
    assert abs(figures.ch5_undamped_per_second() - 1.0) < TOL_LIMIT


def test_exercise_1_twice_the_acceleration_twice_the_drift() -> None:
    """Chapter 1's exercise: at 2 m/s² the drift is a·dt·τ = 0.083 cm."""
    predicted = 2.0 * figures.DT * ControllerConfig().drive_time
    assert abs(figures.ch1_drift_2_cm() / 100.0 - predicted) < TOL_JERK_REL * predicted


def test_exercise_4_without_the_spike_stage_the_bounce_check_fails() -> None:
    """Chapter 4's exercise: with spike_filter off, the bounce level's spike check fails."""
    from playground.expectations import watch
    from playground.level import find, load
    from playground.scene import build

    level = load(find("bounce"))
    perception = level.tracking.perception.model_copy(update={"spike_filter": False})
    tracking = level.tracking.model_copy(update={"perception": perception})
    scene = build(level.model_copy(update={"tracking": tracking}))
    checks = watch(scene)
    scene.run(level.settings.seconds)
    verdict = {r.name: r.passed for r in checks.results()}
    assert verdict["spikes stay out of the filtered support"] is False
    assert verdict["the highest ball never outruns its free fall"] is True


def test_exercise_5_a_shove_below_the_threshold_is_recovered() -> None:
    """Chapter 5's exercise: a 140 N·s shove (below the measured threshold) does not knock the
    player over; one at the threshold does."""
    assert figures.shove(140.0)[0] is False
    assert figures.shove(figures.ch5_knockover())[0] is True


def test_exercise_6_a_faster_creature_is_landed_on_as_soon_and_further_back() -> None:
    """Chapter 6's exercise: the flight after the leap does not depend on the creature, so a
    creature flying Δv faster is landed on at the same moment, Δv·t further back (t since the
    start), and it still carries the player."""
    dv = figures.LEAP_FAST - figures.ch6_leap_speed()
    land = figures.ch6_leap_land_time()
    assert abs(figures.ch6_leap_fast_land_time() - land) < 0.5 * figures.DT
    shift = figures.ch6_leap_land_x() - figures.ch6_leap_fast_land_x()
    assert abs(shift - dv * (figures.LEAP_TIME + land)) < TOL_LEAP_SHIFT
    end = figures.leap_run(figures.LEAP_FAST)[-1]
    assert end[1] == 1.0, "the player should end standing on the faster creature"
    assert abs(end[2]) < figures.leap_half_width()
    assert end[4] < TOL_CARRIED


def test_euro_lag_is_the_fixed_point() -> None:
    """Chapter 4: the 1€ filter's lag on a ramp solves L = 1/(2π(min_cutoff + β·s·(1 + L/Te))),
    the derivative being taken against the previous filtered value (perception's filter and the
    tuned one)."""
    for measured, fixed in (
        (figures.ch4_lag_euro(), figures.ch4_lag_euro_fixed()),
        (figures.ch4_tuned_lag(), figures.ch4_tuned_lag_fixed()),
    ):
        assert abs(measured - fixed) < TOL_FIXED_POINT * fixed, (measured, fixed)
    beta_zero = figures.euro_ramp_lag(2.0, 0.0, figures.G, figures.DT)
    assert math.isclose(beta_zero, 1.0 / (2.0 * math.pi * 2.0), rel_tol=1e-9)


TOL_GROWTH = 0.01
"""Relative, on a growth per step: the peak-to-peak measurement samples peaks at whole steps, a
fraction of a step off the true crest (measured 0.08 % apart at 5 Hz, 1/120 s)."""


def test_naive_spring_is_explicit_euler() -> None:
    """Chapter 5: the naive spring −kx − cv is explicit Euler: stable only while 2πf·dt < 2ζ, and
    undamped it grows by √(1 + (2πf·dt)²) every step."""
    assert abs(figures.ch5_explicit_limit_zeta1() - 2.0) < TOL_LIMIT
    growth = figures.ch5_explicit_undamped_per_step()
    theory = figures.ch5_explicit_undamped_theory()
    assert abs(growth - theory) < TOL_GROWTH * theory
    assert theory > 1.0


def test_ring_tangential_error_is_half_a_step_of_turn() -> None:
    """Chapter 7: against the end of the step, the ring's reading points back by ω·dt/2 (within
    1 % from dt = 1/60 s; at 1/30 s by less than the mid-step error), and against the middle of
    the step its error is under 1 % at every dt; finite differences against their own mid-point
    are as accurate as reverse integration against its own."""
    for dt in figures.CH7_DTS:
        e = figures.ring_errors(dt)
        half = math.sin(e.half_turn)
        assert abs(e.tangential - half) < e.mid, (dt, e)
        if dt <= 1 / 60:
            assert abs(e.tangential - half) < TOL_HALF_STEP * half, (dt, e)
        assert e.mid < MID_STEP_BOUND, (dt, e)
        assert e.end > e.mid
        assert abs(e.fd_own - e.mid) < TOL_ESTIMATORS_AT_MID * e.mid, (dt, e)


def test_chapter_8_counts_steps_as_the_view_does() -> None:
    """Chapter 8: the steps per frame drawn in the figure are the view's Accumulator's (a 144 Hz
    display, a 60 Hz one with a hitch below the view's cap on steps per frame)."""
    from playground.view.app import Accumulator

    hitch = [1.0 / 60.0] * 10
    hitch[5] = figures.CH8_HITCH
    for frames in ([1.0 / 144.0] * 300, hitch):
        acc = Accumulator(dt=figures.DT)
        assert figures.steps_per_frame(frames, figures.DT) == [acc.advance(t) for t in frames]


def test_chapter_8_apex_is_first_order_in_dt() -> None:
    """Chapter 8: the jump stepped at dt rises v²/2g + v·dt/2 (to within a millimetre), so a
    finer step gives a lower jump."""
    v = ControllerConfig().jump_speed
    for rate in figures.CH8_RATES[2:]:
        dt = 1.0 / rate
        assert abs(figures.jump_apex(dt) - (v * v / (2 * figures.G) + v * dt / 2)) < TOL_APEX
    apexes = [figures.jump_apex(1.0 / r) for r in figures.CH8_RATES]
    assert apexes == sorted(apexes, reverse=True)


TOL_IMPULSE = 1e-12
"""In units of m·g: reverse integration against the arbiter sum on a contact that is not re-made
(round-off of a velocity difference divided by the step; measured 6e-15)."""


def test_chapter_9_stale_steps_are_exactly_the_remade_contacts() -> None:
    """Chapter 9: the arbiter sum differs from what was applied exactly on re-made contacts, by the
    arbiter sum of two steps earlier; everywhere else it equals reverse integration."""
    r = figures.stale_run()
    mg = 10.0 * figures.G
    excess = (r[:, 2] - r[:, 1]) / mg
    remade = r[:, 3] == 1.0
    assert np.all(np.abs(excess[~remade]) < TOL_IMPULSE)
    assert np.all(np.abs(excess[remade]) > TOL_IMPULSE)
    idx = np.nonzero(remade)[0]
    assert np.all(np.abs(excess[idx] - r[idx - 2, 2] / mg) < TOL_IMPULSE)
    assert figures.ch9_stale_steps() == np.count_nonzero(remade) > 0


def test_chapter_10_guards_removed_are_caught() -> None:
    """Chapter 10: with ring_room's default wall the hard ring loses a body at 1/30 s (the
    containment check catches it), and without the runtime guard a runaway body goes on far past
    where the guard stops the world."""
    assert figures.thin_ring_outcome().broke == "contained"
    assert figures.hard_run("spinning ring", figures.THIN_WALL_DT).broke is None
    stopped = figures.ch10_guard_step()
    assert 0 < stopped < figures.ch10_unguarded_last_step()
    assert figures.runaway_run(False)[1] == 0 or figures.runaway_run(False)[1] > stopped


SEED_CHAPTERS = ("01-", "02-", "06-")
"""Chapters built on the seed post's sequences: each shows its level moving."""


def test_seed_chapters_show_their_levels_moving() -> None:
    """The seed-sequence chapters embed at least one GIF of a level; every embedded GIF exists,
    is a GIF with more than one frame, and has a caption after it (what to look at)."""
    from PIL import Image

    for path in CHAPTERS:
        text = path.read_text(encoding="utf-8")
        shown = GIF.findall(text)
        if path.name.startswith(SEED_CHAPTERS):
            assert shown, f"{path.name}: no GIF"
        for name in shown:
            gif = DOCS / "img" / "gifs" / name
            assert gif.read_bytes()[:6] == b"GIF89a", name
            with Image.open(gif) as im:
                assert im.n_frames > 1, name
            after = text.split(f"(../img/gifs/{name})", 1)[1].splitlines()[1:]
            # The caption follows the image (or the row of images it belongs to).
            rest = [ln for ln in after if ln.strip() and not ln.startswith("![")]
            assert rest and rest[0].startswith("*"), f"{path.name}: {name} has no caption"
