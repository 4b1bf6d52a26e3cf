"""Laws of feasibility: a scene no setting can simulate is refused at build, saying what to
change."""

from __future__ import annotations

import pytest

from playground.level import LevelError, find, loads
from playground.scene import build

BASE = """title = "Hostile"
description = "A crate on a floor."
[[geometry]]
kind = "segment"
a = [-10.0, 0.0]
b = [10.0, 0.0]
"""

CRATE = """
[[props]]
name = "crate"
position = [0.0, 0.5]
mass = 10.0
shapes = [{kind = "box", size = [1.0, 1.0]}]
"""


def _build_problems(text: str) -> list[str]:
    with pytest.raises(LevelError) as info:
        build(loads(text))
    return [str(p) for p in info.value.problems]


def test_an_unstable_spring_is_refused_with_the_stiffness_to_use() -> None:
    """Law: a spring with ω·h ≥ 2 at the level's step is refused, naming the largest stiffness
    that is stable. 1e6 N/m on 10 kg at 1/120 s: ω·h = 316·/120 ≈ 2.6."""
    spring = (
        "[[joints]]\nkind = 'spring'\na = 'crate'\nb = 'static'\nanchor_a = [0.0, 0.5]\n"
        "anchor_b = [0.0, 3.0]\nstiffness = 1e6\n"
    )
    (problem,) = _build_problems(BASE + CRATE + spring)
    assert problem.startswith("joints.0.stiffness: 2πf·dt = 2.64")
    assert "lower the stiffness below 5.76e+05" in problem
    # Just below the limit it builds.
    build(loads(BASE + CRATE + spring.replace("1e6", "5.7e5")))


def test_a_joint_across_a_huge_mass_ratio_is_refused() -> None:
    """Law: a joint between bodies more than MAX_MASS_RATIO apart in mass is refused."""
    light = CRATE.replace("crate", "pebble").replace("mass = 10.0", "mass = 0.001")
    light = light.replace("[0.0, 0.5]", "[5.0, 0.5]")
    pin = "[[joints]]\nkind = 'pin'\na = 'crate'\nb = 'pebble'\nanchor_a = [0.0, 0.5]\n"
    pin += "anchor_b = [5.0, 0.5]\n"
    problems = _build_problems(BASE + CRATE + light + pin)
    assert any(
        p.startswith("joints.0: 'crate' and 'pebble' differ in mass 1e+04-fold") for p in problems
    )


def test_a_stack_across_a_huge_mass_ratio_is_refused() -> None:
    """Law: a body resting on another more than MAX_MASS_RATIO apart in mass is refused."""
    heavy = CRATE.replace("crate", "anvil").replace("mass = 10.0", "mass = 1e5")
    heavy = heavy.replace("[0.0, 0.5]", "[0.0, 1.5]")
    problems = _build_problems(BASE + CRATE.replace("mass = 10.0", "mass = 1.0") + heavy)
    assert any("at a mass ratio of 1e+05" in p for p in problems), problems


def test_a_body_spawned_inside_another_is_refused() -> None:
    """Law: shapes overlapping by more than MAX_OVERLAP at the start are refused."""
    other = CRATE.replace("crate", "twin").replace("[0.0, 0.5]", "[0.5, 0.5]")
    problems = _build_problems(BASE + CRATE + other)
    assert any("starts 0.5 m inside" in p and "move it out" in p for p in problems), problems
    # Side by side (just touching) builds.
    build(loads(BASE + CRATE + other.replace("[0.5, 0.5]", "[1.0, 0.5]")))


def test_a_probe_longer_than_the_room_is_refused() -> None:
    """Law: an actor's probe longer than the static room is across is refused."""
    actor = (
        "[[actors]]\nname = 'player'\nposition = [0.0, 1.0]\n"
        "controller = { probe_length = 30.0, ride_height = 0.95 }\n"
    )
    problems = _build_problems(BASE + actor)
    assert any(p.startswith("actors.0.controller.probe_length: 30 m is longer") for p in problems)


def test_every_shipped_level_passes_the_build_checks() -> None:
    """The checks leave every shipped level alone."""
    for name in ("crusher", "seesaw", "flying_whale", "spinning_ring", "sandbox", "bounce"):
        build(loads(find(name).read_text(encoding="utf-8")))
