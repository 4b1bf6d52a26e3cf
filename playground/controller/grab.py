"""Grab, hang and climb: the hands hold a body through a pivot joint within a grip budget, let go
when it slips or the grab is released, and slide the hold along the held surface to climb.

The functions here are the :class:`~playground.controller.controller.Controller`'s methods (it
binds them by name).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import pymunk

from playground.controller.states import HANGING, OFF_BALANCE
from playground.intents import Intent
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["climb", "release", "update_grip"]


def update_grip(self: Controller, world: World, it: Intent) -> None:
    """Keep, slide or let go of the grip held; or, with the grab held and none yet, grab the
    nearest shape within reach of the head (a pivot joint with ``grip_force`` as its budget)."""
    cfg = self.config
    joint = self.joint
    if joint is not None:
        a = self.body.local_to_world(joint.anchor_a)
        held = joint.b
        b = held.local_to_world(joint.anchor_b)
        if not it.grab or math.hypot(a.x - b.x, a.y - b.y) > cfg.grip_slip:
            self._release(world)
        elif it.climb != 0.0:
            self._climb(world, joint, it.climb)
        return
    if not it.grab or self.state is OFF_BALANCE:
        return
    ax, ay = self.axis
    p = self.body.position
    half = cfg.half_length
    head = (p.x + ax * half, p.y + ay * half)
    info = world.space.point_query_nearest(head, cfg.radius + cfg.grab_reach, self._filter)
    if info is None or info.shape is None or info.shape.sensor or info.shape.body is None:
        return
    other = info.shape.body
    touch = info.point
    joint = pymunk.PivotJoint(
        self.body, other, self.body.world_to_local(touch), other.world_to_local(touch)
    )
    joint.max_force = cfg.grip_force
    joint.collide_bodies = False
    world.add_constraint(joint)
    self.joint = joint
    self._held_shape = info.shape
    self.state = HANGING


def climb(self: Controller, world: World, joint: pymunk.PivotJoint, climb: float) -> None:
    """Slide the held anchor along the held shape's surface."""
    held = joint.b
    shape = self._held_shape
    assert shape is not None
    p = held.local_to_world(joint.anchor_b)
    q = shape.point_query(p)
    nx, ny = q.gradient
    step = climb * self.config.climb_speed * world.config.dt
    moved = (p.x + ny * step, p.y - nx * step)
    on_surface = shape.point_query(moved).point
    joint.anchor_b = held.world_to_local(on_surface)


def release(self: Controller, world: World) -> None:
    """Let go: the grip joint leaves the world."""
    if self.joint is not None:
        world.remove(self.joint)
        self.joint = None
        self._held_shape = None
