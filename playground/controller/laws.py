"""Acting, the last part of a controller's step: the force laws — hover, drive, air steering,
balance, jump, push — each within its budget and each with its reaction (Newton's third law).

The functions here are the :class:`~playground.controller.controller.Controller`'s methods (it
binds them by name); the model they follow is in its docstring.

>>> ControllerForces().hover
(0.0, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import pymunk

from playground._engine import raw
from playground.controller._vec import ZERO, scaled, unit_or
from playground.controller.spring import hover_spring
from playground.controller.states import AIRBORNE, CRUSHED, GETTING_UP, GROUNDED, OFF_BALANCE
from playground.forces.ledger import Category
from playground.limits import MAX_IMPULSE
from playground.params import bounded_vec
from playground.vec import Vec
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller
    from playground.controller.sensing import GroundHit

# Enum members read once (``Category.X`` costs ~90 ns through the enum's metaclass).
SUPPORT = Category.SUPPORT
APPLIED = Category.APPLIED

__all__ = [
    "NO_FORCES",
    "ControllerForces",
    "act",
    "balance",
    "drive",
    "height",
    "hover",
    "jump",
    "push",
    "steer",
]


@dataclass(slots=True)
class ControllerForces:
    """The forces the controller put on its own body in the last step (N, N·m). Read-only by
    convention, not frozen (a frozen dataclass costs ~3× more to build, and one is built every
    step; a changed copy is made with ``dataclasses.replace``).

    ``grip`` is the joint force of the step before (a joint's force is known only after the
    step it acts in).
    """

    hover: Vec = ZERO
    drive: Vec = ZERO
    grip: Vec = ZERO
    push: Vec = ZERO
    balance_torque: float = 0.0


NO_FORCES = ControllerForces()


def act(self: Controller, world: World, gx: float, gy: float) -> None:
    """Act on what was sensed and decided, with the gravity ``(gx, gy)`` at the body (m/s²): the
    gravity switches, then the state's forces (none while off balance), each applied to the
    world with its category and recorded in :attr:`~Controller.last_forces`."""
    it = self.intent
    self._gravity_actions(world, it)
    cfg = self.config
    dt = self._world_config.dt
    t = world.time
    hit = self.probe
    ux, uy = self.up
    state = self.state

    hover = drive = push = ZERO
    torque = 0.0
    self.pushed = None
    if state is OFF_BALANCE:
        self.last_forces = NO_FORCES
        return

    # The forces on our own body, in the order they act, and the balance torque, written once at
    # the end (see World.apply_forces); so are their reactions on a dynamic ground (Newton's
    # third law: hover and drive at the hit point, and the balance torque), SUPPORT forces
    # because they stand in for a contact. Only a dynamic ground takes them: the world drops
    # forces on static and kinematic bodies. The push's and the jump's apply where they arise.
    own: list[tuple[float, float, Category]] = []
    reactions: list[tuple[float, float, Category]] = []
    jumped = False
    grounded = state in (GROUNDED, GETTING_UP, CRUSHED)
    reacting = grounded and hit is not None and hit.dynamic
    may_jump = state is GROUNDED or (state is AIRBORNE and t - self._grounded_at <= cfg.coyote_time)
    if may_jump and t - self._jump_pressed_at <= cfg.jump_buffer:
        # The take-off step still carries the weight (hover and drive act once more), so the
        # body leaves at exactly jump_speed relative to the ground.
        take_off = self._jump(world, hit if hit is not None else self._last_ground, ux, uy)
        if take_off is not None:
            jumped = True
            own.append((take_off[0], take_off[1], SUPPORT))
            self.state = AIRBORNE

    if grounded and hit is not None and hit.walkable:
        hover_f = self._hover(world, hit, gx, gy, t)
        hover = (hover_f * hit.normal[0], hover_f * hit.normal[1])
        if hover_f > 0.0:
            own.append((hover[0], hover[1], SUPPORT))
            if reacting:
                reactions.append((-hover[0], -hover[1], SUPPORT))
        if state is not CRUSHED:
            drive = self._drive(world, hit, it.move, gx, gy, hover_f, dt)
            if drive is not ZERO:
                own.append((drive[0], drive[1], SUPPORT))
                if reacting:
                    reactions.append((-drive[0], -drive[1], SUPPORT))
    elif state is AIRBORNE and it.move != 0.0 and not jumped:
        drive = self._steer(world, it.move, ux, uy, dt)
        if drive is not ZERO:
            own.append((drive[0], drive[1], APPLIED))

    if it.push:
        push = self._push(world, hit)
        if push is not ZERO:
            own.append((push[0], push[1], SUPPORT))
    balance: float | None = None
    if not cfg.lock_rotation:
        torque = balance = self._balance(world, hit if grounded else None, ux, uy, dt)
    if reacting and hit is not None:
        reaction = -balance if balance is not None else None
        if reactions or reaction is not None:
            world.apply_forces(hit.body, reactions, reaction, point=hit.point)
    if own or balance is not None:
        world.apply_forces(self.body, own, balance)

    grip = ZERO
    if self.joint is not None:
        e = world.forces(self.name).engine
        grip = scaled(e, self.grip)
    self.last_forces = ControllerForces(hover, drive, grip, push, torque)


def hover(self: Controller, world: World, hit: GroundHit, gx: float, gy: float, t: float) -> float:
    """The hover spring along the ground normal, within ``hover_force``: its magnitude, N (the
    target height rises smoothly while getting up); :func:`act` applies it and its reaction."""
    cfg = self.config
    target = cfg.ride_height
    if self.state is GETTING_UP:
        s = min(1.0, (t - self._getup_at) / cfg.getup_time)
        target = self._getup_from + (target - self._getup_from) * s * s * (3.0 - 2.0 * s)
    nx, ny = hit.normal
    height = self._height(hit)
    vx, vy = self._vx, self._vy
    # The height's rate of change over a rigidly moving ground is the velocity relative to the
    # ground's frame at our centre along n: the hit point's own velocity also carries
    # ω × (centre − hit), which on a turning floor with a slanted normal (a ring's chord
    # ends) reads as a spurious normal speed and makes the damper let go.
    gvx, gvy = hit.frame_velocity
    v_n = (vx - gvx) * nx + (vy - gvy) * ny
    # The weight felt in the ground's frame (gravity minus the frame's acceleration: inside a
    # spinning ring, the centrifugal m·ω²·r) as feed-forward: it rests exactly at ride height.
    ax, ay = hit.frame_acceleration
    m = self._m
    weight = m * max(0.0, -((gx - ax) * nx + (gy - ay) * ny))
    if weight == 0.0 and gx == 0.0 and gy == 0.0:
        # Weightless (a nullified body) and not pressed on this ground by its frame either:
        # nothing holds us on it, the legs push with nothing. Otherwise a weightless body
        # whose held up swings toward whatever it bumps (its inner ear reads the bump as
        # gravity) finds that body at its flank, a few tenths of a metre away, and the spring
        # kicks off it at its budget.
        return 0.0
    wc = self._world_config
    # hover_stiffness and hover_damping_coefficient, from the one mass read above.
    omega = self._omega
    k = m * omega * omega
    c = 2.0 * cfg.hover_damping * m * omega
    spring = hover_spring(k, c, m, target - height, v_n, wc.dt, wc.substeps)
    return min(cfg.hover_force, max(0.0, weight + spring))


def height(self: Controller, hit: GroundHit) -> float:
    """Height of the centre over the hit point along the ground normal, m."""
    return (self._px - hit.point[0]) * hit.normal[0] + (self._py - hit.point[1]) * hit.normal[1]


def drive(
    self: Controller,
    world: World,
    hit: GroundHit,
    move: float,
    gx: float,
    gy: float,
    hover: float,
    dt: float,
) -> Vec:
    """Drive along the ground tangent toward ground velocity + ``move``·max_speed, within
    ``ground_force`` and traction × ``hover`` (N): the force, N; :func:`act` applies it and its
    reaction."""
    cfg = self.config
    nx, ny = hit.normal
    tx, ty = ny, -nx  # the surface tangent: its normal rotated by −90°
    vx, vy = self._vx, self._vy
    # Relative to the ground's frame at our centre, not to the hit point: on a turning floor
    # the hit point, ride height further from the axis, moves faster than standing still.
    gvx, gvy = hit.frame_velocity
    v_t = (vx - gvx) * tx + (vy - gvy) * ty
    # Feed-forward: the tangential part of the gravity felt in the ground's frame (gravity
    # minus the ground's acceleration, its own included on a kinematic ground), so slopes
    # hold and a turning floor's chords (slopes to the centrifugal force) do not creep.
    ax, ay = hit.frame_acceleration
    accel = (move * cfg.max_speed - v_t) / max(cfg.drive_time, dt) - (
        (gx - ax) * tx + (gy - ay) * ty
    )
    budget = min(cfg.ground_force, cfg.traction * hover)
    f = max(-budget, min(budget, self._m * accel))
    if f == 0.0:
        return ZERO
    return (f * tx, f * ty)


def steer(self: Controller, world: World, move: float, ux: float, uy: float, dt: float) -> Vec:
    """Air steering toward move·max_speed along up's tangent; it never brakes."""
    cfg = self.config
    tx, ty = uy, -ux
    vx, vy = self._vx, self._vy
    f = self._m * (move * cfg.max_speed - (vx * tx + vy * ty)) / max(cfg.drive_time, dt)
    if f * move <= 0.0:
        return ZERO
    f = max(-cfg.air_force, min(cfg.air_force, f))
    return (f * tx, f * ty)


def balance(
    self: Controller, world: World, hit: GroundHit | None, ux: float, uy: float, dt: float
) -> float:
    """The upright PD torque toward up, within ``balance_torque``: the torque, N·m (:func:`act`
    writes it with our forces, and its reaction on a dynamic ground). Counts how long the budget
    falls short."""
    cfg = self.config
    h = self._h
    cos_a, sin_a = raw.rotation(h)
    ax, ay = -sin_a, cos_a
    err = math.atan2(ax * uy - ay * ux, ax * ux + ay * uy)
    wb = self._wb
    # Damp the spin relative to the ground's, so the body turns with a turning floor (inside
    # a spinning ring) instead of lagging behind it.
    spin = raw.angular_velocity(h) - (hit.spin if hit is not None else 0.0)
    need = raw.moment(h) * (wb * wb * err - 2.0 * cfg.balance_damping * wb * spin)
    budget = cfg.balance_torque
    torque = max(-budget, min(budget, need))
    touching = hit is not None or self.contact_load > 0.0 or self._touching()
    if abs(need) > budget and touching and self.state is not GETTING_UP:
        self._saturated += dt
    else:
        self._saturated = 0.0
    return torque


def jump(
    self: Controller, world: World, ground: GroundHit | None, ux: float, uy: float
) -> Vec | None:
    """Take off at ``jump_speed`` along up relative to the ground: apply the reaction on a
    dynamic ground and return the impulse on us as the force that gives it over the step, N;
    None if already rising that fast."""
    cfg = self.config
    vx, vy = self._vx, self._vy
    gvx, gvy = ground.frame_velocity if ground is not None else ZERO
    dv = cfg.jump_speed - ((vx - gvx) * ux + (vy - gvy) * uy)
    self._jump_pressed_at = -math.inf
    self._grounded_at = -math.inf
    if dv <= 0.0:
        return None
    m = self._m
    jx, jy = m * dv * ux, m * dv * uy
    bounded_vec("impulse", (jx, jy), MAX_IMPULSE, "N·s")
    if ground is not None and ground.body.body_type == pymunk.Body.DYNAMIC:
        # The reaction, as act's for hover and drive: a static or kinematic ground takes none.
        world.apply_impulse(ground.body, (-jx, -jy), point=ground.point, category=SUPPORT)
    self._rising = True
    dt = self._world_config.dt
    return (jx / dt, jy / dt)


def push(self: Controller, world: World, hit: GroundHit | None) -> Vec:
    """Push the nearest dynamic body within reach of the head or the chest (not the ground),
    away from us, with the whole push budget; the reaction goes onto us."""
    cfg = self.config
    # The position sensed this step and the capsule's axis (Controller.axis) from the C getter:
    # the same numbers as body.position and body.rotation_vector, without their Vec2d.
    px, py = self._px, self._py
    cos_a, sin_a = raw.rotation(self._h)
    ax, ay = -sin_a, cos_a
    half = cfg.half_length
    reach = cfg.radius + cfg.push_reach
    ground = hit.body if hit is not None else None
    qx, qy = px + ax * half, py + ay * half
    found = self._reach.nearest(qx, qy, reach, ground)
    # The head is asked first: the chest's find wins only if strictly nearer.
    chest = self._reach.nearest(px, py, reach, ground, math.inf if found is None else found[3])
    if chest is not None:
        found, qx, qy = chest, px, py
    body = None if found is None else found[0].body
    if found is None or body is None:
        return ZERO
    _, cx, cy, _ = found
    nx, ny = unit_or(cx - qx, cy - qy, (ax, ay))
    f = cfg.push_force
    world.apply_force(body, (f * nx, f * ny), point=(cx, cy), category=SUPPORT)
    self.pushed = ((cx, cy), (f * nx, f * ny))
    return (-f * nx, -f * ny)
