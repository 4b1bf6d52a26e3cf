"""Stairs, as the ground probe sees them: the face under a corner the probe touches
(:func:`face`), the tread ahead that a moving body steps up onto (:func:`ahead`) and the tread
below that a grounded body steps down to (:func:`below`), each a change of the probe's hit
(:data:`~playground._engine.sweep.Hit`), so the hover and the drive act on stairs as on a floor.

The reach of a step, up and down, is :func:`reach`: the height of the capsule's lower cap's
centre over the ground at ride height. Lengths in m, speeds in m/s.

>>> from playground.controller.config import ControllerConfig
>>> round(reach(ControllerConfig()), 12)       # m: 0.95 − (0.9 − 0.25)
0.3
"""

from __future__ import annotations

import math

from playground._engine.sweep import Hit, Sweep, face_normal, sharp
from playground.controller.config import ControllerConfig
from playground.world import one_way

__all__ = [
    "CORNER_OFFSET",
    "CORNER_TILT",
    "SAME_FACE",
    "TREAD_PARALLEL",
    "ahead",
    "below",
    "clearance",
    "face",
    "lead_time",
    "reach",
    "step_up",
    "walkable",
]

CORNER_OFFSET = 1.0e-3
"""m: how far past a corner, away from the probe's axis, the face under it is read: far beyond
round-off at any coordinate a level uses, far inside any tread."""
TREAD_PARALLEL = 1.0e-3
"""rad: a surface ahead within this of the ground's own direction is a tread of a stair (a step
up); beyond it, a change of slope, which the probe under the body meets as it comes."""
CORNER_TILT = 0.01
"""rad: a probe's hit whose normal is within this of up is taken as it is, corner or face: a
corner that near the probe's axis (within probe_radius · sin 0.01, 1 mm for the default 0.1 m)
reads as its face to within the same angle, and flat ground costs no second query."""
SAME_FACE = 1.0e-12
"""A face's normal is the swept normal when their dot product is within this of 1 (round-off
on a face hit; a corner's normal differs by far more)."""

_COS_CORNER_TILT = math.cos(CORNER_TILT)
_COS_TREAD_PARALLEL = math.cos(TREAD_PARALLEL)


def reach(config: ControllerConfig) -> float:
    """The highest riser stepped up (and the deepest stepped down past the probe's length), m:
    the height of the capsule's lower cap's centre over the ground at ride height,
    ``ride_height − half_length``. A riser below it meets the round cap, which the hover
    lifts over it once the probe sees the tread beyond; a higher one meets the capsule's
    straight side, a wall."""
    return config.ride_height - config.half_length


def clearance(config: ControllerConfig) -> float:
    """The gap under the capsule at ride height, m: ``ride_height − height/2``. A riser no
    higher passes under it untouched, and the probe under the body lifts it as it comes: only
    a higher one is a step up (:func:`ahead`)."""
    return config.ride_height - 0.5 * config.height


def lead_time(config: ControllerConfig) -> float:
    """How far ahead in time a moving body looks for a tread to step up onto, s: half the
    hover's natural period, 1/(2·``hover_frequency``), in which the critically damped hover
    covers 1 − (1 + π)·e^(−π) = 82 % of a step up (it must be up before the cap reaches the
    riser). :func:`ahead` computes it inline."""
    return 0.5 / config.hover_frequency


def face(found: Hit, px: float, py: float, ux: float, uy: float, radius: float) -> Hit:
    """The probe's hit ``found`` with the normal of the face under it: where the probe's circle
    (``radius``, m, swept from (px, py) along −up) touches a sharp corner, its normal points from
    the corner to the circle, slanted however far the corner lies off the axis (a stair's nosing
    read as a slope, walkable or not by the offset alone); the face it stands for is the one just
    past the corner, away from the axis: the tread beyond a riser going up, the tread being left
    going down. Unchanged on a face, on a rounded shape, and within :data:`CORNER_TILT` of up."""
    shape, hx, hy, nx, ny = found
    if nx * ux + ny * uy >= _COS_CORNER_TILT or not sharp(shape):
        return found
    tx, ty = uy, -ux
    side = (hx - px) * tx + (hy - py) * ty
    if side == 0.0:
        return found
    off = CORNER_OFFSET if side > 0.0 else -CORNER_OFFSET
    sx, sy = hx + off * tx + ux * radius, hy + off * ty + uy * radius
    normal = face_normal(shape, sx, sy, -2.0 * radius * ux, -2.0 * radius * uy)
    if normal is None or abs(normal[0] * nx + normal[1] * ny - 1.0) <= SAME_FACE:
        return found
    return (shape, hx, hy, normal[0], normal[1])


def ahead(
    sweep: Sweep,
    found: Hit,
    px: float,
    py: float,
    speed: float,
    move: float,
    config: ControllerConfig,
) -> Hit | None:
    """The tread ahead to step up onto, or None: a walking body (``move`` ≠ 0 along the ground's
    tangent, at ``speed`` m/s that way relative to the ground) looks ``radius + probe_radius +
    speed · lead_time`` ahead of its centre (px, py) (m) — where the leading edge of its probe's
    circle will be — for a surface parallel to the ground it stands on (``found``, walkable),
    more than :func:`clearance` above that ground and at most :func:`reach` above its feet
    (where they are at ride height): a ray down from the reach's height to the clearance's.
    The hover then lifts it over the riser before its cap meets it, and the drive carries it
    on at its speed. (A ray, not the probe's circle: on flat ground it ends short of the ground
    and meets nothing, the cheapest query there is; and it reads a face's normal, never a
    corner's.)"""
    _, hx, hy, nx, ny = found
    step_up = config.ride_height - config.half_length
    low = config.ride_height - 0.5 * config.height
    direction = 1.0 if move > 0.0 else -1.0
    tx, ty = direction * ny, -direction * nx
    d = config.radius + config.probe_radius + max(0.0, speed) * 0.5 / config.hover_frequency
    # The feet at ride height; the ray from d ahead at the reach over them down to the
    # clearance over the ground's own level.
    fx, fy = px - nx * config.ride_height, py - ny * config.ride_height
    ax, ay = fx + tx * d + nx * step_up, fy + ty * d + ny * step_up
    depth = (ax - hx) * nx + (ay - hy) * ny - low
    if depth <= 0.0:
        return None
    bx, by = ax - nx * depth, ay - ny * depth
    tread = sweep.nearest(ax, ay, bx, by, 0.0)
    # A ray that starts inside a shape (a wall, a box above the reach) gets Chipmunk's hit at
    # alpha 0, reported at the ray's end: that is no tread.
    if tread is None or (tread[1] == bx and tread[2] == by):
        return None
    step, sx, sy, mx, my = tread
    if (
        (sx - hx) * nx + (sy - hy) * ny <= low
        or mx * nx + my * ny < _COS_TREAD_PARALLEL
        or step.body is None
        or one_way.passes(step, ax, ay, 0.0)
    ):
        return None
    return tread


def walkable(found: Hit, ux: float, uy: float, config: ControllerConfig) -> bool:
    """The hit's normal is within ``max_slope`` of up (ux, uy)."""
    return found[3] * ux + found[4] * uy >= math.cos(config.max_slope)


def below(
    sweep: Sweep,
    px: float,
    py: float,
    down: tuple[float, float],
    up: tuple[float, float],
    config: ControllerConfig,
) -> Hit | None:
    """The walkable tread below that a grounded body steps down to, or None: the probe's circle
    swept from the centre (px, py) along the field's direction ``down`` (unit) for
    ``probe_length`` + :func:`reach`, its hit read as the face past a corner (:func:`face`)
    and walkable against ``up``. Walking down a flight faster than gravity lets it follow the
    treads, the body drops past the probe's reach for a moment: the ground found here keeps it
    grounded (the hover only pushes, so it still falls freely until the tread is within ride
    height), as Godot's floor snap and Rapier's snap-to-ground keep a character on the ground
    over a step down. Along the field, where it falls, not along its up, which leans back while
    the drive accelerates it (27° at the drive's 5 m/s²), so that its probe looks back up the
    flight and meets a riser's face. (Swept from the centre, not on from the probe's end: its
    circle there may already overlap the tread, whose top Chipmunk's index culls by the
    centre's path.)"""
    dx, dy = down
    length = config.probe_length + reach(config)
    radius = config.probe_radius
    found = sweep.nearest(px, py, px + dx * length, py + dy * length, radius)
    if found is None or one_way.passes(found[0], px, py, radius):
        return None
    found = face(found, px, py, -dx, -dy, radius)
    return found if walkable(found, up[0], up[1], config) else None


def step_up(
    sweep: Sweep,
    found: Hit,
    px: float,
    py: float,
    vx: float,
    vy: float,
    ux: float,
    uy: float,
    move: float,
    config: ControllerConfig,
) -> Hit | None:
    """:func:`ahead` for a body at (px, py) moving at (vx, vy) relative to its ground
    ``found`` (m, m/s), up (ux, uy), intending ``move``: None unless it means to move and the
    ground is walkable."""
    _, _, _, nx, ny = found
    if move == 0.0 or not walkable(found, ux, uy, config):
        return None
    direction = 1.0 if move > 0.0 else -1.0
    speed = direction * ((vx * ny) - (vy * nx))
    return ahead(sweep, found, px, py, speed, move, config)
