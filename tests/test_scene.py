"""Laws of building a scene from a level.

A scene no setting can simulate is refused at build saying what to change. A player placed at
rest feels its weight from its first step: no load-time kick; the hover finds the ground where it
is when the level starts (a mover's platform included), the player stands at ride height over it,
so the first support reading is its weight and the perceived-gravity filter starts from g.
"""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Elevator, World
from playground.controller import Controller, State
from playground.level import LevelError, find, load, loads, shipped
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

TOL_REL = 1e-9
"""At rest at ride height the hover's spring term is exactly 0 and its feed-forward is the
weight: the reading differs from m·g only by float rounding."""

STAND_WINDOW = 0.2
"""m: a player placed at rest this close to its ride height over the ground is placed to stand on
it (the shipped levels' misplacements were 5 and 10 cm); one placed further up is dropped, and a
drop is not a load-time kick."""

START_STEPS = 12
"""0.1 s at the default dt: before anything in a shipped level reaches a player placed at rest
(the earliest event, the seesaw's plank tipping under the player, unloads it)."""


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


def at_rest(ctrl: Controller) -> bool:
    body = ctrl.body
    return body.velocity == (0.0, 0.0) and body.angular_velocity == 0.0


STARTS = [
    (level, name)
    for level in shipped()
    for name, actor in ((a.name, a) for a in load(find(level)).actors)
    if actor.velocity == (0.0, 0.0) and actor.angular_velocity == 0.0
]


def test_the_issue_levels_are_covered() -> None:
    """The levels where the kick was found place a player at rest (to stand: none is skipped)."""
    levels = {level for level, _ in STARTS}
    assert {"elevator", "moving_platform", "rotating_room", "rest"} <= levels


@pytest.mark.parametrize(("level", "name"), STARTS, ids=[f"{lv}-{n}" for lv, n in STARTS])
def test_player_placed_at_rest_reads_its_weight(level: str, name: str) -> None:
    """Law: on its first step a player placed at rest on the ground is grounded at ride height,
    its support along the ground normal is its weight m·g_n, and its perceived gravity along
    the field never exceeds |g| in the first START_STEPS steps (no spike for the filter)."""
    scene = build(load(find(level)))
    world = scene.world
    ctrl = scene.controllers[name]
    assert at_rest(ctrl)
    world.step()
    hit = ctrl.probe
    ride = ctrl.config.ride_height
    if hit is None or hit.distance - ride > STAND_WINDOW:
        pytest.skip(f"{level}: {name} is placed in the air, to fall")
    assert ctrl.state is State.GROUNDED, (level, name, ctrl.state)
    assert abs(hit.distance - ride) <= 1e-9, (
        f"{level}: {name} starts {hit.distance - ride:+.4f} m off its ride height {ride} m "
        "(place its centre ride_height above the ground's surface, segment radius included)"
    )
    nx, ny = hit.normal
    g = world.gravity_at(name)
    m = ctrl.body.mass
    weight = m * -(g[0] * nx + g[1] * ny)
    f = world.forces(name)
    support = f.support[0] * nx + f.support[1] * ny
    assert abs(support - weight) <= TOL_REL * weight, (level, name, f.support, weight)
    g_norm = math.hypot(*g)
    for _ in range(START_STEPS):
        pg = world.perceived_gravity(name)
        along = (pg[0] * g[0] + pg[1] * g[1]) / g_norm
        assert along <= g_norm * (1.0 + TOL_REL), (level, name, world.time, pg)
        world.step()


def test_a_placed_mover_is_found_before_the_first_step() -> None:
    """Law: a kinematic body placed by its mover is where queries find it at once (Chipmunk
    caches shape positions until it steps)."""
    world = World()
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("lift", plat, pymunk.Poly.create_box(plat, (3.0, 0.2)))
    world.add_mover("lift", Elevator(start=(0.0, -0.1), start_time=1.0))
    hit = world.space.segment_query_first((0.0, 1.0), (0.0, -1.0), 0.0, pymunk.ShapeFilter())
    assert hit is not None and hit.shape is not None and hit.shape.body is plat
    assert abs(hit.point.y - 0.0) <= 1e-12, hit.point
