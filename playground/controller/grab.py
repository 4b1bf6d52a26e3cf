"""Grab, hang and climb: the hands hold a body through a pivot joint within a grip budget
(:class:`Grip`), let go when it slips or the grab is released, and slide the hold along the
held surface to climb.

Sensing finds the hold (:func:`handhold`) and how far it slipped (:func:`slip`); the state
machine takes or drops it; :func:`hold` puts the change into the world (lengths in m).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import pymunk

from playground.controller.config import ControllerConfig
from playground.intents import Intent
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.ledge import Ledge

__all__ = ["Grip", "Impulses", "handhold", "hold", "slip"]


class Impulses:
    """A joint's impulse summed over the substeps of a step, N·s: pymunk's ``impulse`` is the
    last substep's only, so the joint adds each substep's after the solver runs (its
    ``post_solve``), and :func:`hold` starts the sum again before each step."""

    __slots__ = ("total",)

    def __init__(self) -> None:
        self.total = 0.0

    def add(self, constraint: pymunk.Constraint, space: pymunk.Space) -> None:
        """The joint's ``post_solve``: add this substep's impulse."""
        self.total += constraint.impulse


@dataclass(frozen=True, slots=True)
class Grip:
    """A hold: the pivot joint from our body to the held body, the shape held (the climb
    slides along it) and the joint's impulse over the last step's substeps; ``ledge``, the
    ledge held by its edge (None: a hold anywhere on a body,
    :func:`~playground.controller.ledge.grip`). The joint's ``max_force`` is the grip budget,
    N."""

    joint: pymunk.PivotJoint
    shape: pymunk.Shape
    impulses: Impulses
    ledge: Ledge | None = None


def handhold(
    space: pymunk.Space,
    body: pymunk.Body,
    shape_filter: pymunk.ShapeFilter,
    config: ControllerConfig,
) -> Grip | None:
    """The grip the hands could take now: the nearest shape (not a sensor) within reach of the
    head, held where the hand touches it by a joint not yet in the world; None if none."""
    r = body.rotation_vector
    ax, ay = -r.y, r.x
    p = body.position
    half = config.half_length
    head = (p.x + ax * half, p.y + ay * half)
    info = space.point_query_nearest(head, config.radius + config.grab_reach, shape_filter)
    if info is None or info.shape is None or info.shape.sensor or info.shape.body is None:
        return None
    other = info.shape.body
    touch = info.point
    joint = pymunk.PivotJoint(body, other, body.world_to_local(touch), other.world_to_local(touch))
    joint.max_force = config.grip_budget(body.mass)
    joint.collide_bodies = False
    impulses = Impulses()
    joint.post_solve = impulses.add
    return Grip(joint, info.shape, impulses)


def slip(grip: Grip) -> float:
    """How far the grip's two anchors have drifted apart, m."""
    joint = grip.joint
    a = joint.a.local_to_world(joint.anchor_a)
    b = joint.b.local_to_world(joint.anchor_b)
    return math.hypot(a.x - b.x, a.y - b.y)


def hold(
    world: World,
    before: Grip | None,
    after: Grip | None,
    intent: Intent,
    config: ControllerConfig,
    dt: float,
) -> None:
    """Put the state machine's grip into the world: let go of ``before`` if it is not kept, add
    ``after``'s joint if it is new, and slide a kept hold along the held surface at the
    intent's climb × ``climb_speed`` over the step (``dt``, s); a ledge's edge is not slid
    along (climbing it is the state machine's CLIMBING). The grip held starts summing its
    impulse for the coming step."""
    if before is not None and before is not after:
        world.remove(before.joint)
        before.joint.post_solve = None
    if after is None:
        return
    after.impulses.total = 0.0
    if after is not before:
        world.add_constraint(after.joint)
    elif intent.climb != 0.0 and after.ledge is None:
        climb(after, intent.climb * config.climb_speed * dt)


def climb(grip: Grip, distance: float) -> None:
    """Slide the held anchor ``distance`` (m) along the held shape's surface, along the face
    turned to our body (the normal at the anchor itself is undefined: it lies on the surface,
    where pymunk's gradient is 0/0)."""
    joint = grip.joint
    held = joint.b
    p = held.local_to_world(joint.anchor_b)
    nx, ny = grip.shape.point_query(joint.a.position).gradient
    moved = (p.x + ny * distance, p.y - nx * distance)
    on_surface = grip.shape.point_query(moved).point
    if not (math.isfinite(on_surface.x) and math.isfinite(on_surface.y)):
        # Exactly on a polygon's face pymunk's nearest point is 0/0: it is the point itself.
        on_surface = pymunk.Vec2d(*moved)
    joint.anchor_b = held.world_to_local(on_surface)
