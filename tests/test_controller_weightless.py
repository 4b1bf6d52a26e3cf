"""A weightless controller's hover pushes with nothing, whatever its probe finds.

With no gravity (a nullified enemy) nothing holds the body on a ground, so the hover, and with it
the traction the drive gets from the hover's normal force, is exactly 0 N. In particular a
nullified enemy that bumps into a crate reads the bump as gravity, its up swings toward the
crate, and its probe finds the crate at its flank: the hover spring must not kick off it.
"""

from __future__ import annotations

import math

import pymunk

from playground import Controller, GravityRule, World
from playground.level import find, load
from playground.scene import build

SKIN = 0.05
"""Radius of ``add_static_segment``'s segment: the floor's surface is this far above y = 0, m."""

NULLIFIED_AT = 11.5
"""Sandbox: the tour nullifies the enemy at this time, s."""

LET_GO = 0.2
"""Sandbox: time after the nullify by which the spring has released the weight it held, s
(the level's own check starts 0.2 s after the nullify too)."""

BUMP_END = 16.0
"""Sandbox: run past the enemy's bump into the crate (about 14.9 s), s."""


def touching(ctrl: Controller) -> list[pymunk.Body]:
    """The bodies the controller's capsule is in contact with now."""
    found: list[pymunk.Body] = []
    ctrl.body.each_arbiter(lambda arb: found.extend(b for b in arb.bodies if b is not ctrl.body))
    return found


def test_weightless_hover_does_not_push_when_compressed() -> None:
    """Zero gravity, feet on the floor 4 cm inside ride height: the spring would push, but
    nothing holds the body on the floor, so the hover pushes with nothing."""
    world = World(gravity=(0.0, 0.0))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    body = Controller(world, "body", position=(0.0, SKIN + 0.91))
    world.step()
    assert body.probe is not None
    assert body.probe.distance < body.config.ride_height - 0.03
    assert body.last_forces.hover == (0.0, 0.0)
    assert body.last_forces.drive == (0.0, 0.0)


def test_nullified_enemy_bumping_the_crate_gets_no_hover() -> None:
    """Sandbox run on past its tour: the nullified enemy glides into the crate; its hover and
    drive stay 0 N from the nullify's release on (it read the 5000 N budget at 14.98 s)."""
    scene = build(load(find("sandbox")))
    world = scene.world
    enemy = scene.controllers["enemy"]
    hovers: list[float] = []
    touched_crate = False
    crate = world.body("crate")
    while world.time < BUMP_END:
        world.step()
        if world.time < NULLIFIED_AT + LET_GO:
            continue
        assert world.gravity_rule("enemy") == GravityRule(scale=0.0)
        hovers.append(math.hypot(*enemy.last_forces.hover))
        touched_crate |= crate in touching(enemy)
    assert touched_crate
    assert max(hovers) == 0.0
