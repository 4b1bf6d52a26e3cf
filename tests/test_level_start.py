"""Law: a player placed at rest by a level feels its weight from its first step.

No load-time kick: the hover finds the ground where it is when the level starts (a mover's
platform included), the player stands at ride height over it, so the first support reading is
its weight and the perceived-gravity filter starts from g, not from a spike.
"""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Elevator, World
from playground.controller import Controller, State
from playground.level import find, load, shipped
from playground.scene import build

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
