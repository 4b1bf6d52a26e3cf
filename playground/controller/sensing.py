"""Sensing, the first part of a controller's step: the body's state, the gravity at it, its up,
the ground under it (:class:`GroundHit`, from a swept probe) and the load pressing on it.

The functions here are the :class:`~playground.controller.controller.Controller`'s methods (it
binds them by name); they read the world and write only the controller's own sensed state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import pymunk

from playground._engine import raw
from playground.controller._vec import ZERO, unit_or
from playground.controller.states import CRUSHED, GROUNDED, HANGING
from playground.vec import Vec
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

# Body types read once (``pymunk.Body.X`` is two attribute lookups, three times a step).
KINEMATIC = pymunk.Body.KINEMATIC
DYNAMIC = pymunk.Body.DYNAMIC

__all__ = [
    "GroundHit",
    "contact_load",
    "gravity",
    "ground_acceleration",
    "probe",
    "sense",
    "touching",
]


@dataclass(slots=True)
class GroundHit:
    """What the ground probe found (plain values except the hit body). Read-only by convention,
    not frozen: a frozen dataclass sets each field through ``object.__setattr__``, which made
    building one ~5× dearer (~0.7 µs), and the probe builds one every step (a changed copy is
    made with ``dataclasses.replace``).

    Attributes:
        body: the body hit.
        point: the hit point on its surface, m.
        normal: the surface normal there (unit, pointing out of the ground).
        distance: from the hit point to the capsule's centre along up, m.
        walkable: the normal is within ``max_slope`` of up.
        frame_velocity: velocity that keeps the capsule's centre fixed to the ground over the
            coming step, m/s: the ground's velocity plus the chord (R(ω·dt) − 1)·d/dt its turn
            carries our centre along (d from its centre of gravity; ω × d to first order, like
            ``ground.velocity_at_world_point(centre)``). Standing still on the ground means
            moving at this velocity: on a turning floor it is taken at the centre, not at the hit
            point, which is ride height further out (inside a ring spinning at ω the hit point's
            speed is ω·R, the centre's ω·(R − ride height)).
        frame_acceleration: how much ``frame_velocity`` changes per second, m/s²: as the ground
            turns by ω·dt (the centripetal −ω²·d to first order), plus, on a kinematic ground,
            its own acceleration A + α × d read from how its velocity and spin changed since the
            last step (a mover sets them a step ahead, so this is the acceleration the coming
            step needs). A dynamic ground's change of velocity is partly our own reaction on it:
            feeding that back would push a light crate harder the more it yields, so its
            acceleration is left to the drive's feedback. Gravity minus ``frame_acceleration``
            is the gravity *felt* in the ground's frame: inside a spinning ring, ω²·r outward;
            in a lift accelerating up at a, g + a.
        spin: the body hit's angular velocity, rad/s (counter-clockwise): the balance damps
            our spin relative to it.
        dynamic: the body hit is dynamic, so it takes our reactions (the world drops forces on
            static and kinematic bodies).
    """

    body: pymunk.Body
    point: Vec
    normal: Vec
    distance: float
    walkable: bool
    frame_velocity: Vec
    frame_acceleration: Vec
    spin: float
    dynamic: bool


def sense(self: Controller, world: World) -> Vec:
    """Read the body (position, velocity, mass), the world's settings, the gravity at it, up, the
    ground under it (:attr:`~Controller.probe`) and the load on it; return the gravity, m/s².

    Up is the perceived one while supported and the field while airborne (it sees where it will
    land), fallen or getting up (contacts while lying and rising shake the inner ear).
    """
    h = self._h
    self._px, self._py = raw.position(h)
    self._vx, self._vy = raw.velocity(h)
    self._m = raw.mass(h)
    self._world_config = world.config
    gx, gy = self._gravity(world)

    supported = self.state in (GROUNDED, HANGING, CRUSHED)
    if supported:
        (ux, uy), perceived = world.perceived_up_and_gravity(self.name)
        if not (math.isfinite(ux) and math.isfinite(uy)):
            ux, uy = unit_or(-gx, -gy, self.up)
        elif math.hypot(*perceived) < self._up_threshold:
            # Just caught after a free fall: the inner ear still holds the up from before the
            # fall (after a gravity flip, the opposite one) until the new support has built
            # up a reading: keep the up we fell with meanwhile.
            ux, uy = self.up
    else:
        ux, uy = unit_or(-gx, -gy, self.up)
    self.up = (ux, uy)

    self.probe = self._probe(world, ux, uy)
    self.contact_load = self._contact_load(world, ux, uy)
    pushed = self.last_forces.push
    self.load = self.contact_load + max(0.0, -(pushed[0] * ux + pushed[1] * uy))
    return (gx, gy)


def gravity(self: Controller, world: World) -> Vec:
    """The gravity at the body, m/s²: ``world.gravity_at`` in general, and for a field uniform
    in space the value the GRAVITY stage has just put in ``space.gravity`` with the body's rule
    applied in plain floats (the numpy path costs ~0.2 ms a call for one body). Whether the
    field is uniform and the body's rule are read again only when the world says they changed
    (:attr:`World.gravity_version`)."""
    version = world.gravity_version
    if version != self._gravity_version:
        self._gravity_version = version
        self._uniform_field = world.gravity.uniform
        self._gravity_rule = world.gravity_rule(self.name)
    if not self._uniform_field:
        return world.gravity_at(self.name)
    gx, gy = raw.gravity(self._space_h)
    rule = self._gravity_rule
    if rule.direction is None:
        return (rule.scale * gx, rule.scale * gy)
    mag = rule.scale * math.hypot(gx, gy)
    return (mag * rule.direction[0], mag * rule.direction[1])


def probe(self: Controller, world: World, ux: float, uy: float) -> GroundHit | None:
    """Sweep a circle from the centre along −up; the nearest other shape is the ground."""
    cfg = self.config
    px, py = self._px, self._py
    length = cfg.probe_length
    # The nearest of every hit (playground._engine.sweep says why not pymunk's segment_query_first).
    found = self._sweep.nearest(px, py, px - ux * length, py - uy * length, cfg.probe_radius)
    ground = found[0].body if found is not None else None
    if found is None or ground is None:
        self._ground_motion = None
        return None
    _, hx, hy, nx, ny = found
    # The ground's frame at our centre, as pymunk's step needs it: positions move with the
    # velocity before the step, so standing still on a ground turning by θ = ω·dt this step
    # takes the velocity that carries our centre to where the ground carries that point,
    # V + (R(θ) − 1)·d/dt (d from the ground's centre of gravity), not the tangent ω × d,
    # which leads the turning ground by θ/2 each step; this velocity turns by θ each step,
    # hence the acceleration (R(θ) − 1)·(its turning part)/dt.
    dt = self._world_config.dt
    # The ground's type, velocity and spin, read once here for the frame, its own acceleration
    # and the balance.
    gh = raw.handle(ground)
    kind = raw.body_type(gh)
    w = raw.angular_velocity(gh)
    turn = w * dt
    if turn == 0.0 and kind != KINEMATIC:
        # Not turning: the chord below is exactly 0.0 for any d (cos 0 = 1, sin 0 = ±0), and
        # only a kinematic ground's own acceleration needs d: skip reading its centre (~1 µs).
        cos_t, sin_t = 1.0, 0.0
        dx = dy = rx = ry = 0.0
    else:
        cos_t, sin_t = math.cos(turn), math.sin(turn)
        cx, cy = raw.centre_of_gravity(gh)
        dx, dy = px - cx, py - cy
        rx = (cos_t * dx - sin_t * dy - dx) / dt
        ry = (sin_t * dx + cos_t * dy - dy) / dt
    vx, vy = raw.velocity(gh)
    own_x, own_y = self._ground_acceleration(ground, kind == KINEMATIC, vx, vy, w, dx, dy, dt)
    return GroundHit(
        body=ground,
        point=(hx, hy),
        normal=(nx, ny),
        distance=(px - hx) * ux + (py - hy) * uy,
        walkable=nx * ux + ny * uy >= self._cos_slope,
        frame_velocity=(vx + rx, vy + ry),
        frame_acceleration=(
            (cos_t * rx - sin_t * ry - rx) / dt + own_x,
            (sin_t * rx + cos_t * ry - ry) / dt + own_y,
        ),
        spin=w,
        dynamic=kind == DYNAMIC,
    )


def ground_acceleration(
    self: Controller,
    ground: pymunk.Body,
    kinematic: bool,
    vx: float,
    vy: float,
    w: float,
    dx: float,
    dy: float,
    dt: float,
) -> Vec:
    """The ground's own acceleration at our centre, A + α × d (m/s², d from its centre of
    gravity, m), from how its velocity (vx, vy), m/s, and spin w, rad/s, as the probe has just
    read them, changed since the last step (dt, s).

    Fed forward, it lets the drive and the hover keep up with an accelerating platform
    instead of lagging a·drive_time behind it (5 cm over a second at 1 m/s²). Only for a
    kinematic ground (zero otherwise, and on the first step over a new ground): a dynamic
    ground's change of velocity is partly our own reaction on it.
    """
    if not kinematic:
        self._ground_motion = None
        return ZERO
    prev = self._ground_motion
    self._ground_motion = (ground, vx, vy, w)
    if prev is None or prev[0] is not ground:
        return ZERO
    alpha = (w - prev[3]) / dt
    return ((vx - prev[1]) / dt - alpha * dy, (vy - prev[2]) / dt + alpha * dx)


def contact_load(self: Controller, world: World, ux: float, uy: float) -> float:
    """Force pressing on us along −up through contacts in the last step, N (the floor's push
    along +up does not count): each contact's impulse over the last substep's length."""
    wc = self._world_config
    return self._contacts.load(ux, uy, wc.dt / wc.substeps)


def touching(self: Controller) -> bool:
    """Whether any contact touches the body now."""
    return self._contacts.touching()
