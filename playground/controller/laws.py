"""The controller's force laws — hover, drive, air steering, balance, jump, push, the grip's
reading and Newton's third law — each a function of what was sensed, held together as one
:class:`Laws` value that a controller owns (``controller.laws``).

Each law returns its force and writes nothing; :func:`~playground.controller.action.act`
calls them and applies the budgets' verdicts. Hover, drive, steer and balance are written over
``ops`` (:mod:`~playground.controller.elementwise`): in floats for one controller (the default),
in numpy arrays for a crowd (:mod:`~playground.controller.crowd.acting`), the same expressions. A
different law (a fault of the catalogue, an experiment) is a :class:`Laws` with that one
function replaced. The model they follow is in
:class:`~playground.controller.controller.Controller`'s docstring.

>>> Laws().reaction("hover", (0.0, 686.7))
(-0.0, -686.7)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

from playground.controller import ledge
from playground.controller._vec import unit_or
from playground.controller.config import ControllerConfig
from playground.controller.elementwise import FLOATS, Ops
from playground.controller.ledge import LedgeHold
from playground.controller.sensing import GroundHit, PushTarget, Sensed, height, up_speed
from playground.controller.spring import TWO_PI, hover_spring
from playground.controller.states import GETTING_UP, ControllerState
from playground.limits import MAX_IMPULSE
from playground.params import bounded_vec
from playground.vec import Vec

__all__ = [
    "RISE_SLOPE",
    "Laws",
    "Reacting",
    "balance",
    "climb",
    "drive",
    "grip",
    "hover",
    "jump",
    "push",
    "reaction",
    "slide",
    "steer",
]

Reacting = Literal["hover", "drive", "jump", "push", "climb"]
"""The laws whose force has a reaction on another body (or, for the push, on us)."""


RISE_SLOPE = 0.35
"""rad (20°): ground sloping more than this from up has the hover's rise held back
(:func:`hover`); flat ground, and a stair's tread, does not."""
_COS_RISE_SLOPE = math.cos(RISE_SLOPE)
_UNLIMITED = 1.0e9
"""m: a rise no height error reaches."""


def hover(
    sensed: Sensed,
    state: ControllerState,
    hit: GroundHit,
    config: ControllerConfig,
    ops: Ops = FLOATS,
    target: float | None = None,
) -> float:
    """The hover spring along the ground normal, within the legs' budget
    (:meth:`~playground.controller.config.ControllerConfig.hover_budget`): its magnitude, N (the
    target height, ``ride_height`` unless given, m, rises smoothly while getting up)."""
    target = config.ride_height if target is None else target
    if state.state is GETTING_UP:
        s = min(1.0, (sensed.time - state.getup_at) / config.getup_time)
        target = state.getup_from + (target - state.getup_from) * s * s * (3.0 - 2.0 * s)
    nx, ny = hit.normal
    h = height(sensed, hit)
    body = sensed.body
    # The height's rate of change over a rigidly moving ground is the velocity relative to the
    # ground's frame at our centre along n: the hit point's own velocity also carries
    # ω × (centre − hit), which on a turning floor with a slanted normal (a ring's chord
    # ends) reads as a spurious normal speed and makes the damper let go.
    gvx, gvy = hit.frame_velocity
    v_n = (body.vx - gvx) * nx + (body.vy - gvy) * ny
    # The weight felt in the ground's frame (gravity minus the frame's acceleration: inside a
    # spinning ring, the centrifugal m·ω²·r) as feed-forward: it rests exactly at ride height.
    gx, gy = sensed.gravity
    ax, ay = hit.frame_acceleration
    m = body.mass
    weight = m * ops.max(0.0, -((gx - ax) * nx + (gy - ay) * ny))
    # k = m·(2πf)², c = 2ζ·m·2πf for the mass now (Controller.hover_stiffness and
    # hover_damping_coefficient).
    omega = TWO_PI * config.hover_frequency
    k = m * omega * omega
    c = 2.0 * config.hover_damping * m * omega
    # Onto a slope the height along its normal drops at once where the probe's circle passes
    # from the floor to the slope (0.25 m at 45°), and the spring would rise at ω·e/2 and, a
    # floor that cannot pull, overshoot and leave the slope: on ground sloping over RISE_SLOPE
    # from up it pulls as from at most 8·g_n/ω² below, whence (critically damped) it rises at
    # 4·g_n/ω, a speed gravity alone stops in that gap. (A stair's tread, level, is met ahead
    # with the whole riser in view: stairs.py; there the rise is not held back.)
    ux, uy = sensed.up
    level = (nx * ux + ny * uy >= _COS_RISE_SLOPE) * _UNLIMITED
    rise = ops.max(8.0 * weight / k, level)
    spring = hover_spring(k, c, m, ops.min(rise, target - h), v_n, sensed.dt, sensed.substeps)
    force = ops.min(config.hover_budget(m), ops.max(0.0, weight + spring))
    # Weightless (a nullified body) and not pressed on this ground by its frame either: nothing
    # holds us on it, the legs push with nothing. Otherwise a weightless body whose held up
    # swings toward whatever it bumps (its inner ear reads the bump as gravity) finds that body
    # at its flank, a few tenths of a metre away, and the spring kicks off it at its budget.
    return ops.unless((weight == 0.0) & (gx == 0.0) & (gy == 0.0), force)  # type: ignore[no-any-return]


SLIDE_REACH = 0.75
"""The part of the probe's length at which a sliding controller is held over its slope: the
probe, swept along up, reaches a slope θ at a height (along its normal) of only probe_radius +
probe_length·cosθ, less than ride_height beyond about 50°."""


def slide(
    sensed: Sensed, state: ControllerState, hit: GroundHit, config: ControllerConfig
) -> float:
    """The hover on ground too steep to stand on: the same spring along its normal, held at
    ride height or lower, where the probe still reaches the slope with a quarter of its length
    to spare (:data:`SLIDE_REACH`): its magnitude, N. No drive goes with it: the feet have no
    grip there, and the controller slides down the slope.

    >>> import math
    >>> from playground.controller.sensing import Sensed, GroundHit
    >>> from playground._engine.state import BodyState
    >>> c, s = math.cos(math.radians(60.0)), math.sin(math.radians(60.0))   # a 60° slope
    >>> hit = GroundHit(None, (0.0, 0.0), (-s, c), 1.25, False, (0.0, 0.0), (0.0, 0.0),
    ...                 (0.0, 0.0), 0.0, False)
    >>> config = ControllerConfig()
    >>> round(config.probe_radius + SLIDE_REACH * config.probe_length * c, 3)   # m: held at
    0.625
    >>> at = Sensed(BodyState(-0.625 * s, 0.625 * c, 0.0, 0.0, 1.0, 0.0, 0.0, 70.0, 1.0),
    ...             (0.0, 1.0), dt=1 / 120, gravity=(0.0, -9.81))
    >>> round(slide(at, ControllerState(), hit, config), 2), round(70.0 * 9.81 * c, 2)  # N
    (343.35, 343.35)
    """
    nx, ny = hit.normal
    ux, uy = sensed.up
    reach = config.probe_radius + SLIDE_REACH * config.probe_length * (nx * ux + ny * uy)
    return hover(sensed, state, hit, config, FLOATS, min(config.ride_height, reach))


def drive(
    sensed: Sensed,
    hit: GroundHit,
    move: float,
    hover: float,
    config: ControllerConfig,
    ops: Ops = FLOATS,
) -> Vec:
    """Drive along the ground tangent toward ground velocity + ``move``·max_speed: the force,
    N (the :data:`~playground.controller._vec.ZERO` vector itself when there is none).

    Two bounds, as a foot's: the legs' effort, ``ground_force``, is what they add to holding
    the slope (gravity's pull along the ground, −m·g·t, which the sole holds by friction, as a
    crate on a slope is held at no cost), so it lies within that hold ± ``ground_force``; and
    the whole of it within the friction, traction × ``hover`` (the hover's force, N, the
    normal force). On flat ground the hold is 0 and the effort is the whole drive; up a slope
    the legs keep their whole budget for the walk, and a slope steeper than atan(traction)
    wins against any effort.

    >>> import math
    >>> from playground.controller.sensing import Sensed, GroundHit
    >>> from playground._engine.state import BodyState
    >>> c, s = math.cos(math.radians(45.0)), math.sin(math.radians(45.0))   # a 45° slope
    >>> hit = GroundHit(None, (0.0, 0.0), (-s, c), 0.95, True, (0.0, 0.0), (0.0, 0.0),
    ...                 (0.0, 0.0), 0.0, False)
    >>> still = Sensed(BodyState(0.0, 0.95, 0.0, 0.0, 1.0, 0.0, 0.0, 70.0, 1.0), (0.0, 1.0),
    ...                dt=1 / 120, gravity=(0.0, -9.81))
    >>> f = drive(still, hit, 0.0, 70.0 * 9.81 * c, ControllerConfig())   # standing, no move
    >>> round(math.hypot(*f), 1), round(70.0 * 9.81 * s, 1)               # N: holds m·g·sinθ
    (485.6, 485.6)
    """
    nx, ny = hit.normal
    tx, ty = ny, -nx  # the surface tangent: its normal rotated by −90°
    body = sensed.body
    # Relative to the ground's frame at our centre, not to the hit point: on a turning floor
    # the hit point, ride height further from the axis, moves faster than standing still.
    gvx, gvy = hit.frame_velocity
    v_t = (body.vx - gvx) * tx + (body.vy - gvy) * ty
    # Feed-forward: the tangential part of the gravity felt in the ground's frame (gravity
    # minus the ground's acceleration, its own included on a kinematic ground), so slopes
    # hold and a turning floor's chords (slopes to the centrifugal force) do not creep.
    gx, gy = sensed.gravity
    ax, ay = hit.frame_acceleration
    accel = (move * config.max_speed - v_t) / max(config.drive_time, sensed.dt) - (
        (gx - ax) * tx + (gy - ay) * ty
    )
    m = body.mass
    hold = -m * (gx * tx + gy * ty)  # 0 on flat ground: the bounds are ±ground_force there
    effort = config.ground_budget(m)
    grip = config.traction * hover
    f = ops.max(hold - effort, ops.min(hold + effort, m * accel))
    f = ops.max(-grip, ops.min(grip, f))
    return ops.vector(f, tx, ty)  # type: ignore[no-any-return]


def steer(sensed: Sensed, move: float, config: ControllerConfig, ops: Ops = FLOATS) -> Vec:
    """Air steering toward move·max_speed along up's tangent, within ``air_force``: the force,
    N; it never brakes (:data:`~playground.controller._vec.ZERO` then)."""
    ux, uy = sensed.up
    tx, ty = uy, -ux
    body = sensed.body
    f = (
        body.mass
        * (move * config.max_speed - (body.vx * tx + body.vy * ty))
        / max(config.drive_time, sensed.dt)
    )
    air = config.air_budget(body.mass)
    f = ops.unless(f * move <= 0.0, ops.max(-air, ops.min(air, f)))
    return ops.vector(f, tx, ty)  # type: ignore[no-any-return]


def balance(
    sensed: Sensed, hit: GroundHit | None, config: ControllerConfig, ops: Ops = FLOATS
) -> float:
    """The upright PD torque toward up that the balance needs, N·m (before its budget:
    :func:`~playground.controller.action.act` bounds it by ``balance_torque`` and reports
    when it falls short). It damps the spin relative to ``hit``, the ground stood on (None:
    relative to the world)."""
    body = sensed.body
    ux, uy = sensed.up
    ax, ay = -body.sin, body.cos
    err: float = ops.atan2(ax * uy - ay * ux, ax * ux + ay * uy)
    wb = TWO_PI * config.balance_frequency
    # Damp the spin relative to the ground's, so the body turns with a turning floor (inside
    # a spinning ring) instead of lagging behind it.
    spin = body.spin - (hit.spin if hit is not None else 0.0)
    return body.moment * (wb * wb * err - 2.0 * config.balance_damping * wb * spin)


def jump(sensed: Sensed, ground: GroundHit | None, config: ControllerConfig) -> Vec:
    """The take-off impulse on us that leaves at ``jump_speed`` along up relative to the ground
    (None: relative to the world), N·s. ValueError if beyond the impulse limit."""
    dv = config.jump_speed - up_speed(sensed, ground)
    m = sensed.body.mass
    ux, uy = sensed.up
    impulse = (m * dv * ux, m * dv * uy)
    bounded_vec("impulse", impulse, MAX_IMPULSE, "N·s")
    return impulse


def push(sensed: Sensed, target: PushTarget, config: ControllerConfig) -> Vec:
    """The push on ``target``: the whole push budget, away from where the arms reach from, N
    (along the capsule's axis if that is the touching point itself)."""
    body = sensed.body
    cx, cy = target.point
    qx, qy = target.origin
    nx, ny = unit_or(cx - qx, cy - qy, (-body.sin, body.cos))
    f = config.push_budget(body.mass)
    return (f * nx, f * ny)


def climb(sensed: Sensed, hold: LedgeHold, config: ControllerConfig) -> Vec:
    """The climb onto the ledge ``hold``: its force on us, N (:func:`~playground.controller.
    ledge.climb`: the weight held, and at most ``ledge_climb_acceleration`` relative to the
    ledge, up clear of its top and then over it)."""
    body = sensed.body
    return ledge.climb(
        (body.x, body.y),
        (body.vx, body.vy),
        body.mass,
        sensed.gravity,
        sensed.up,
        hold,
        config,
        sensed.dt,
    )


def grip(impulse: float, dt: float) -> float:
    """The grip joint's force, N: the step's mean, its impulse summed over the step's substeps
    (N·s) over the step ``dt`` (s), as the force solver's readings are."""
    return impulse / dt


def reaction(law: Reacting, force: Vec) -> Vec:
    """Newton's third law: the force (N) or impulse (N·s) that the ``law``'s ``force`` puts
    back on the body it pushes against — the ground for the hover, the drive and the jump, the
    ledge for the climb, us for the push."""
    return (-force[0], -force[1])


@dataclass(frozen=True, slots=True)
class Laws:
    """The force laws a controller follows, one function each (the defaults are this
    module's). ``dataclasses.replace(laws, hover=...)`` makes a controller with another law.
    """

    hover: Callable[[Sensed, ControllerState, GroundHit, ControllerConfig], float] = hover
    slide: Callable[[Sensed, ControllerState, GroundHit, ControllerConfig], float] = slide
    drive: Callable[[Sensed, GroundHit, float, float, ControllerConfig], Vec] = drive
    steer: Callable[[Sensed, float, ControllerConfig], Vec] = steer
    balance: Callable[[Sensed, GroundHit | None, ControllerConfig], float] = balance
    jump: Callable[[Sensed, GroundHit | None, ControllerConfig], Vec] = jump
    push: Callable[[Sensed, PushTarget, ControllerConfig], Vec] = push
    climb: Callable[[Sensed, LedgeHold, ControllerConfig], Vec] = climb
    grip: Callable[[float, float], float] = grip
    reaction: Callable[[Reacting, Vec], Vec] = reaction
