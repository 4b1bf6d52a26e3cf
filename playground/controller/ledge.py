"""Ledges: a top edge within the hands' reach (:func:`find`), grabbed with a pivot joint on the
ledge's own body (:func:`grip`), and the climb onto it (:func:`climb`): a force that lifts the
body clear of the top, then carries it over, with its reaction on the ledge.

A ledge is any shape with a face beside the head and a walkable top above it within
``ledge_grab`` of the head: a static wall, a moving (kinematic) pillar, a loose crate. The hands
hold the point of the ledge's body beside the edge at the edge's height, on the capsule's axis, so
the body hangs straight under its hands and clear of the face; the joint moves with the ledge, so
a rising pillar carries the player and a crate feels its weight. Lengths in m, speeds in m/s.

>>> import pymunk
>>> space = pymunk.Space()
>>> wall = pymunk.Poly.create_box(space.static_body, (2.0, 2.5))
>>> wall.body.position = (0.0, 0.0)
>>> space.add(wall)
>>> player = pymunk.Body(70.0, pymunk.moment_for_box(70.0, (0.5, 1.8)))
>>> player.position = (1.35, 0.55)      # its face 0.35 m from the axis, the top 0.7 m above
>>> found = find(space, player, pymunk.ShapeFilter(), (0.0, 1.0), ControllerConfig())
>>> found is not None and tuple(round(c, 3) for c in found.edge), found.side
((1.0, 1.25), (-1.0, 0.0))
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pymunk

from playground._engine.state import BodyState
from playground.controller.config import ControllerConfig
from playground.controller.grab import Grip, Impulses
from playground.vec import Vec

__all__ = [
    "Ledge",
    "LedgeHold",
    "approach",
    "catching",
    "climb",
    "find",
    "grip",
    "held",
    "up",
]

FACE_DEPTH = 0.5
"""How far past the face, in the capsule's radii, the hands feel for the top (a thin ledge's top
is still found; a corner rounded by a shape's radius is not mistaken for a slope)."""


@dataclass(frozen=True, slots=True)
class Ledge:
    """A ledge found: its body and shape, the edge (where its face meets its top) and the
    direction from the player toward it, both in the ledge body's frame (they turn and move with
    it)."""

    body: pymunk.Body
    shape: pymunk.Shape
    edge: Vec
    side: Vec

    @property
    def world_edge(self) -> Vec:
        """The edge in world coordinates now, m."""
        p = self.body.local_to_world(self.edge)
        return (p.x, p.y)

    @property
    def world_side(self) -> Vec:
        """The direction toward the ledge in world coordinates now (unit)."""
        r = self.body.rotation_vector
        sx, sy = self.side
        return (r.x * sx - r.y * sy, r.y * sx + r.x * sy)


@dataclass(slots=True)
class LedgeHold:
    """The ledge held or climbed, as sensing read it this step (read-only by convention).

    Attributes:
        ledge: the ledge.
        edge: the edge in world coordinates, m.
        side: toward the ledge, along its top (unit).
        velocity: the ledge body's velocity at the edge, m/s.
        dynamic: the ledge body is dynamic, so it takes the climb's reaction.
    """

    ledge: Ledge
    edge: Vec
    side: Vec
    velocity: Vec
    dynamic: bool


def held(ledge: Ledge) -> LedgeHold:
    """Read ``ledge`` as it is now."""
    ex, ey = ledge.world_edge
    v = ledge.body.velocity_at_world_point((ex, ey))
    dynamic = ledge.body.body_type == pymunk.Body.DYNAMIC
    return LedgeHold(ledge, (ex, ey), ledge.world_side, (v.x, v.y), dynamic)


def find(
    space: pymunk.Space,
    body: pymunk.Body,
    shape_filter: pymunk.ShapeFilter,
    up: Vec,
    config: ControllerConfig,
) -> Ledge | None:
    """The ledge the hands could take now, or None.

    The nearest shape within ``radius + ledge_grab`` of the head must lie beside it (across
    ``up``), and a walkable top of it (its normal within ``max_slope`` of up) must lie between
    the head's cap centre and ``ledge_grab`` above the top of the head, with room above it."""
    ux, uy = up
    tx, ty = uy, -ux
    p = body.position
    half = config.half_length
    hx, hy = p.x + ux * half, p.y + uy * half
    reach = config.radius + config.ledge_grab
    near = space.point_query_nearest((hx, hy), reach, shape_filter)
    if near is None or near.shape is None or near.shape.sensor or near.shape.body is None:
        return None
    shape, ledge_body = near.shape, near.shape.body
    cx, cy = near.point.x, near.point.y
    across = (cx - hx) * tx + (cy - hy) * ty
    if across == 0.0:
        # Straight above or below the head: a ceiling or a floor, no edge beside it.
        return None
    sign = 1.0 if across > 0.0 else -1.0
    sx, sy = sign * tx, sign * ty
    inward = abs(across) + FACE_DEPTH * config.radius
    top = config.radius + config.ledge_grab
    ax, ay = hx + sx * inward + ux * top, hy + sy * inward + uy * top
    bx, by = hx + sx * inward, hy + sy * inward
    if space.point_query_nearest((ax, ay), 0.0, shape_filter) is not None:
        return None  # no room above the top there: a wall higher than the reach
    hit = shape.segment_query((ax, ay), (bx, by), 0.0)
    if hit is None or hit.shape is None:
        return None
    nx, ny = hit.normal.x, hit.normal.y
    if nx * ux + ny * uy < math.cos(config.max_slope):
        return None
    rise = (hit.point.x - cx) * ux + (hit.point.y - cy) * uy
    edge = ledge_body.world_to_local((cx + ux * rise, cy + uy * rise))
    r = ledge_body.rotation_vector
    side = (r.x * sx + r.y * sy, -r.y * sx + r.x * sy)
    return Ledge(ledge_body, shape, (edge.x, edge.y), side)


def catching(ledge: Ledge, body: pymunk.Body, up: Vec) -> bool:
    """The body is not rising relative to the ledge (falling past it, at the top of a jump, or
    at rest): a hand closing on an edge that the body still rises past would be torn off."""
    ex, ey = ledge.world_edge
    v = ledge.body.velocity_at_world_point((ex, ey))
    w = body.velocity
    return (w.x - v.x) * up[0] + (w.y - v.y) * up[1] <= 0.0


def grip(body: pymunk.Body, ledge: Ledge, config: ControllerConfig) -> Grip:
    """The grip on ``ledge``: a pivot joint (not yet in the world) from the point of our axis at
    the edge's height to the same point of the ledge's body, within the grip budget."""
    ex, ey = ledge.world_edge
    r = body.rotation_vector
    ax, ay = -r.y, r.x
    p = body.position
    along = (ex - p.x) * ax + (ey - p.y) * ay
    hand = (p.x + ax * along, p.y + ay * along)
    joint = pymunk.PivotJoint(body, ledge.body, (0.0, along), ledge.body.world_to_local(hand))
    joint.max_force = config.grip_budget(body.mass)
    joint.collide_bodies = False
    impulses = Impulses()
    joint.post_solve = impulses.add
    return Grip(joint, ledge.shape, impulses, ledge)


def up(body: BodyState, hold: LedgeHold, config: ControllerConfig) -> bool:
    """The climb is over: the centre is ``radius`` past the edge (the feet are over the top)
    and it moves slower than ``settle_speed`` relative to the ledge, so it stands without the
    step a stop from a run would need (its inner ear has felt the climb's push over the top,
    and a stop on top of that would tilt its up)."""
    ex, ey = hold.edge
    sx, sy = hold.side
    past = (body.x - ex) * sx + (body.y - ey) * sy
    vx, vy = hold.velocity
    slow = math.hypot(body.vx - vx, body.vy - vy) < config.settle_speed
    return past >= config.radius and slow


def approach(distance: float, speed: float, acceleration: float, tau: float) -> float:
    """The acceleration that brings a body ``distance`` m short of a point (signed, along one
    axis), moving at ``speed`` m/s along that axis, to rest there, m/s²: toward the speed that
    braking at half of ``acceleration`` stops in the distance left, √(a·|d|) (the other half is
    the margin to correct with), and within |d|/``tau`` near it, with time constant ``tau``
    (s), plus the change of that goal speed as it closes in (so braking does not lag).

    >>> round(approach(1.0, 0.0, 4.0, 0.05), 6), round(approach(1.0, 2.0, 4.0, 0.05), 6)
    (40.0, -2.0)
    """
    d = abs(distance)
    sign = 1.0 if distance >= 0.0 else -1.0
    toward = speed * sign
    goal = math.sqrt(acceleration * d)
    if goal < d / tau:
        slope = acceleration / (2.0 * goal)  # d(goal)/d(d)
    else:
        goal, slope = d / tau, 1.0 / tau
    return sign * ((goal - toward) / tau - slope * toward)


def climb(
    position: Vec,
    velocity: Vec,
    mass: float,
    gravity: Vec,
    up: Vec,
    hold: LedgeHold,
    config: ControllerConfig,
    dt: float,
) -> Vec:
    """The climb's force on the body (m, m/s, kg, m/s², s), N: its weight held, and an
    acceleration of at most ``ledge_climb_acceleration`` relative to the ledge toward the point
    to be: up to ride height over the top, and once the capsule's bottom is halfway from the
    top's level to where it rides over it (clear of the corner), over the top to ``radius +
    probe_radius`` past the edge, arriving at rest along each (:func:`approach`; the rise has
    the first call on the acceleration). There the hover takes over at rest at ride height.
    Within the grip budget."""
    ux, uy = up
    ex, ey = hold.edge
    sx, sy = hold.side
    dx, dy = position[0] - ex, position[1] - ey
    height = dx * ux + dy * uy
    past = dx * sx + dy * sy
    a = config.ledge_climb_acceleration
    tau = max(config.drive_time, dt)
    vx, vy = velocity[0] - hold.velocity[0], velocity[1] - hold.velocity[1]
    rise = approach(config.ride_height - height, vx * ux + vy * uy, a, tau)
    # The rise first: what is left of the acceleration carries it over (its top never drops
    # under it while the climb goes over the edge).
    rise = max(-a, min(a, rise))
    ahead = 0.0
    if height >= 0.5 * (config.height / 2.0 + config.ride_height):
        ahead = approach(config.radius + config.probe_radius - past, vx * sx + vy * sy, a, tau)
        left = math.sqrt(max(0.0, a * a - rise * rise))
        ahead = max(-left, min(left, ahead))
    accx, accy = rise * ux + ahead * sx, rise * uy + ahead * sy
    fx, fy = mass * (accx - gravity[0]), mass * (accy - gravity[1])
    force = math.hypot(fx, fy)
    budget = config.grip_budget(mass)
    if force > budget:
        fx, fy = fx * budget / force, fy * budget / force
    return (fx, fy)
