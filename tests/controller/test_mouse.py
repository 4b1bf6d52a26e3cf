"""Laws of the mouse spring (:mod:`playground.controller.mouse`) without any view: stable at any
step, and applied to a world as APPLIED force and torque on what a grab holds."""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Stage, World, WorldConfig
from playground.controller.mouse import Grab, MouseSpring

TOL_SETTLED_M = 0.01
"""m: beyond its static sag g/ω², a held plank is still this close to rest after 6 s (the swing
decays at 3/s: e^-18 of its first amplitude)."""
TOL_SETTLED_RAD_S = 0.01
"""rad/s: what is left of the swing after 6 s."""


def plank_world(dt: float) -> tuple[World, pymunk.Body]:
    world = World(WorldConfig(dt=dt))
    body = pymunk.Body(20.0, pymunk.moment_for_box(20.0, (4.0, 0.2)))
    body.position = (0.0, 0.0)
    world.add("plank", body, pymunk.Poly.create_box(body, (4.0, 0.2)))
    return world, body


@pytest.mark.parametrize("dt", [1.0 / 240.0, 1.0 / 60.0, 1.0 / 20.0])
def test_mouse_spring_holds_a_plank_by_its_end_at_any_dt(dt: float) -> None:
    """Law: the explicit spring is stable at large steps even where the effective mass is
    smallest (a long plank grabbed at its tip): it settles at the cursor instead of blowing up."""
    world, body = plank_world(dt)
    spring = MouseSpring()
    grab = Grab("plank", anchor=(2.0, 0.0), target=(2.5, 1.0))
    world.on(Stage.CONTROL, lambda w: spring.apply(w, grab))
    world.run(6.0)
    tip = body.local_to_world(grab.anchor)
    omega = spring.omega(body, grab.anchor, dt)
    sag = 9.81 * (1.0 + 2.0 * spring.damping_ratio * omega * dt) / omega**2
    assert math.dist((tip.x, tip.y), grab.target) < sag + TOL_SETTLED_M
    assert abs(body.angular_velocity) < TOL_SETTLED_RAD_S


def test_nothing_dynamic_held_is_no_pull() -> None:
    """No grab, a grab of a body not in the world, and a grab of a static body pull nothing."""
    world, _ = plank_world(1.0 / 120.0)
    floor = pymunk.Body(body_type=pymunk.Body.STATIC)
    world.add("floor", floor, pymunk.Segment(floor, (-5.0, -2.0), (5.0, -2.0), 0.1))
    spring = MouseSpring()
    assert spring.apply(world, None) is None
    assert spring.apply(world, Grab("ghost", (0.0, 0.0), (1.0, 1.0))) is None
    assert spring.apply(world, Grab("floor", (0.0, 0.0), (1.0, 1.0))) is None
    assert spring.apply(world, Grab("plank", (0.0, 0.0), (1.0, 1.0))) is not None
