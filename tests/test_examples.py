"""The examples run headless (SDL's dummy video driver) and do what their docstrings say; they use
only the public API."""

from __future__ import annotations

import ast
import importlib.util
import itertools
import math
import os
import re
from pathlib import Path
from types import ModuleType

import pytest

from playground import Intent, State

pytest.importorskip("pygame")

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
RIDE_TOL_PX = 2.0
"""px (0.09 m): how far the rider may sit from the platform's ride height while carried; the
hover spring's sag as the platform turns a corner is under 1 px."""

PLATFORM_HALF_WIDTH_PX = 25.0
"""Half the moving platform's length, px (pymunk's)."""


def example(name: str) -> ModuleType:
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_no_example_imports_a_private_name() -> None:
    """Law: ``grep -rn "playground\\._" examples`` finds nothing."""
    private = re.compile(r"playground\._|from playground\.[a-z_.]*\b_")
    for path in EXAMPLES.glob("*.py"):
        assert not private.search(path.read_text(encoding="utf-8")), path.name


def walk_right_and_hop(frame: int) -> Intent:
    return Intent(move=1.0, jump=frame % 120 == 60)


@pytest.fixture(scope="module")
def platformer() -> ModuleType:
    return example("platformer")


@pytest.fixture(scope="module")
def six_hundred_frames(platformer: ModuleType) -> list[tuple[float, float, State]]:
    return platformer.main(frames=600, intents=walk_right_and_hop)  # type: ignore[no-any-return]


def test_the_platformer_runs_600_frames_inside_its_walls(
    six_hundred_frames: list[tuple[float, float, State]],
) -> None:
    assert len(six_hundred_frames) == 600
    for x, y, _state in six_hundred_frames:
        assert math.isfinite(x) and math.isfinite(y)
        assert 10 < x < 680 and 50 < y < 370  # px: pymunk's walls
    states = {state for _x, _y, state in six_hundred_frames}
    assert {State.GROUNDED, State.AIRBORNE} <= states


def test_the_player_walks_up_the_45_degree_ramp(
    six_hundred_frames: list[tuple[float, float, State]],
) -> None:
    assert max(x for x, _y, _state in six_hundred_frames) > 270  # px: the ramp's top end


def test_the_player_rides_the_moving_platform(platformer: ModuleType) -> None:
    """Set down on the platform, it is carried along the first two legs (to (650, 300) px)."""
    from playground import Waypoints

    trace = platformer.main(frames=300, start=(650, 130))
    corners = tuple(
        (x / platformer.PPM, y / platformer.PPM) for x, y in ((650, 100), (600, 200), (650, 300))
    )
    path = Waypoints(corners, speed=platformer.PLATFORM_SPEED, mode="loop")
    ride = platformer.PLAYER.ride_height * platformer.PPM + 5  # px: hover + the platform's radius
    offsets = []
    for frame in range(60, 300):  # landed by 0.5 s; the second leg ends at 2.8 s
        x, y, state = trace[frame]
        (px, py), _angle = path.pose((frame + 1) / platformer.fps)
        assert state is State.GROUNDED
        assert abs(y - py * platformer.PPM - ride) < RIDE_TOL_PX, frame
        offsets.append(x - px * platformer.PPM)
    # carried along each leg without sliding; the turn at (600, 200) px throws it 7 px aside
    first_leg = offsets[: 150 - 60]
    assert max(first_leg) - min(first_leg) < RIDE_TOL_PX
    assert max(abs(o) for o in offsets) < PLATFORM_HALF_WIDTH_PX  # and it never leaves it
    assert trace[299][1] - trace[60][1] > 150  # px: carried up two platforms' worth


def test_the_player_jumps_up_through_the_one_way_platform_and_stands_on_it(
    platformer: ModuleType,
) -> None:
    trace = platformer.main(frames=180, start=(295, 74), intents=lambda f: Intent(jump=f == 30))
    x, y, state = trace[-1]
    assert state is State.GROUNDED
    assert y > 105 + platformer.PLAYER.ride_height * platformer.PPM - RIDE_TOL_PX  # px: on top
    assert abs(x - 295) < 5


RIDE_TOL_M = 0.01
"""m: the planet walker's height over the ground may differ from its ride height by this (the
hover's sag as the ground curves away under a walk at 4 m/s is under 3 mm)."""


def test_the_planet_walk_goes_half_way_round_at_ride_height() -> None:
    planet = example("planet")
    trace = planet.main(frames=600, intents=lambda f: Intent(move=1.0))
    assert len(trace) == 600
    # each frame's turn round the centre, clockwise from the top (rad), summed
    turns = [
        math.atan2(y0 * x1 - x0 * y1, x0 * x1 + y0 * y1)
        for (x0, y0), (x1, y1) in itertools.pairwise(trace)
    ]
    assert all(turn >= 0.0 for turn in turns)  # never slips back
    assert math.degrees(math.fsum(turns)) > 190  # 10 s at 4 m/s: 209° of a lap at 10.95 m
    ride = planet.RADIUS + 0.95  # m: the surface plus the default ride height
    for x, y in trace[120:]:  # once at its walking speed (by 1 s)
        assert abs(math.hypot(x, y) - ride) < RIDE_TOL_M


TOL_FELT_N = 1.0
"""N: standing still the felt force is m·g to within the hover's settling (under 0.1 N); in the
air it is the solver's rounding only."""


def test_the_lesson_sandbox_feels_weight_standing_nothing_in_the_air_and_a_landing() -> None:
    lesson = example("lesson_sandbox")
    felt = lesson.main(frames=240, intents=lambda f: Intent(jump=f == 60))
    weight = lesson.PLAYER.mass * 9.81  # N
    assert all(abs(f - weight) < TOL_FELT_N for f in felt[30:60])  # standing
    airborne = felt[66:100]  # s 1.1–1.67: the 4 m/s jump is in the air for 0.8 s
    assert all(f < TOL_FELT_N for f in airborne)  # free fall: it feels no gravity
    assert max(felt[100:140]) > 2 * weight  # the landing
    assert all(abs(f - weight) < TOL_FELT_N for f in felt[200:])  # standing again


def _public_names_used() -> set[str]:
    """The names the examples import from ``playground``."""
    names: set[str] = set()
    for path in EXAMPLES.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module == "playground":
                names |= {alias.name for alias in node.names}
    return names


def test_every_public_name_an_example_uses_has_a_runnable_example() -> None:
    """Law: each class or function the examples import has a doctest in its own docstring."""
    import playground

    used = _public_names_used()
    assert {"Controller", "World", "FixedStep"} <= used
    missing = [n for n in sorted(used) if ">>>" not in (getattr(playground, n).__doc__ or "")]
    assert not missing, missing


TOL_SUPPORT_N = 1e-6
"""N: a crate at rest reads its weight to the solver's rounding (the README's 98.1 to 6 places)."""


def test_the_crate_reads_its_weight_with_the_solver_alone() -> None:
    """A 10 kg crate on a plain pymunk space, read by ForceSensor: 98.1 N once at rest; more
    while it lands."""
    crate = example("crate")
    trace = crate.main(frames=180)
    assert max(fy for _fx, fy in trace[:60]) > 2 * crate.MASS * 9.81  # N: the landing
    for fx, fy in trace[120:]:  # s 2–3: at rest
        assert abs(fx) < TOL_SUPPORT_N and abs(fy - 98.1) < TOL_SUPPORT_N
