"""Drawing the world's bodies and joints: every shape by its true outline, filled and outlined with
anti-aliased edges, at any angle and zoom; joints by their kind (pivot, pin, slide, groove, spring
and a controller's grip); bodies coloured by type (static, kinematic, dynamic) and actors by role
(player, enemy, other). Also the anti-aliased arrow and the legend every overlay uses.

A capsule (a segment with a radius) is one closed outline: two half circles joined by straight
sides, computed in screen space, so it keeps its area and its outline at every angle:

>>> pts = capsule_outline((0.0, 0.0), (10.0, 0.0), 5.0)
>>> len(pts) >= 2 * MIN_ARC_POINTS, round(min(p[1] for p in pts), 6), round(max(p[0] for p in pts))
(True, -5.0, 15)
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

import pygame
import pygame.gfxdraw
import pymunk

from playground.vec import Vec
from playground.view.camera import Camera
from playground.world.world import World

__all__ = [
    "COLOURS",
    "ROLES",
    "Grip",
    "LegendEntry",
    "capsule_outline",
    "dashed_circle",
    "draw_arrow",
    "draw_edges",
    "draw_grid",
    "draw_grip",
    "draw_legend",
    "draw_world",
    "outlined_polygon",
    "shade_panel",
]
Colour = tuple[int, int, int]

COORD_LIMIT = 1.0e5  # px: points are clamped here so far-away geometry never overflows SDL
MIN_ARC_POINTS = 8  # outline points per half circle of a small capsule end
MAX_ARC_POINTS = 48  # … and of a large one (one point per px of radius in between)
MIN_RADIUS_PX = 1.5  # px: thinner segments (a floor line of radius 0) are drawn this thick
JOINT_DOT_PX = 4  # px: radius of a joint's anchor dot
HAND_PX = 5  # px: radius of the hand drawn where a grip holds
SWATCH_PX = 26  # px: length of a legend swatch

ROLES = ("player", "enemy", "other")
"""Actor roles: the player the keyboard drives, enemies (what X nullifies), anyone else."""

COLOURS: dict[str, Colour] = {
    "background": (22, 24, 30),
    "grid": (34, 37, 46),
    "static": (120, 126, 140),
    "kinematic": (80, 140, 200),
    "dynamic": (196, 164, 112),
    "player": (236, 208, 92),
    "enemy": (225, 90, 80),
    "other": (120, 220, 170),
    "nullify": (255, 120, 220),
    "nullified": (170, 255, 255),
    "off_screen": (236, 208, 92),
    "joint": (160, 200, 160),
    "contact": (255, 230, 60),
    "normal": (255, 255, 140),
    "friction": (255, 120, 40),
    "joint_force": (190, 255, 60),
    "support": (110, 210, 120),
    "support_filtered": (255, 60, 200),
    "gravity": (90, 150, 255),
    "hover": (255, 160, 40),
    "drive": (40, 220, 220),
    "grip": (255, 70, 70),
    "hand": (250, 150, 150),
    "push": (190, 120, 255),
    "reaction": (255, 200, 200),
    "perceived": (150, 200, 255),
    "up": (245, 245, 245),
    "text": (225, 228, 235),
    "dim": (150, 155, 165),
    "mouse": (255, 190, 225),
}


@dataclass(frozen=True, slots=True)
class Grip:
    """A controller's grip: its joint and the point of its body the hand reaches from (the top of
    the capsule, m, world)."""

    joint: pymunk.Constraint
    shoulder: Vec


def _clamp(p: Vec) -> tuple[float, float]:
    return (
        min(max(p[0], -COORD_LIMIT), COORD_LIMIT),
        min(max(p[1], -COORD_LIMIT), COORD_LIMIT),
    )


def _shade(c: Colour, f: float) -> Colour:
    return (min(int(c[0] * f), 255), min(int(c[1] * f), 255), min(int(c[2] * f), 255))


def outlined_polygon(
    surf: pygame.Surface, fill: Colour | None, edge: Colour, points: Sequence[Vec]
) -> None:
    """Fill a closed outline (screen px) and stroke it with an anti-aliased edge on the fill's
    border (``fill`` None: outline only). SDL_gfx's filled and anti-aliased polygons rasterise
    the same edges, so the stroke covers the fill's border exactly."""
    pts = [_clamp(p) for p in points]
    if len(pts) < 3:
        return
    if fill is not None:
        pygame.gfxdraw.filled_polygon(surf, pts, fill)
    pygame.gfxdraw.aapolygon(surf, pts, edge)


def capsule_outline(a: Vec, b: Vec, radius: float) -> list[Vec]:
    """The closed outline (px) of a capsule from ``a`` to ``b`` (px) of ``radius`` (px)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    base = math.atan2(dy, dx) if (dx, dy) != (0.0, 0.0) else 0.0
    n = min(max(round(radius), MIN_ARC_POINTS), MAX_ARC_POINTS)
    out: list[Vec] = []
    for centre, start in ((b, base - math.pi / 2.0), (a, base + math.pi / 2.0)):
        for k in range(n + 1):
            t = start + math.pi * k / n
            out.append((centre[0] + radius * math.cos(t), centre[1] + radius * math.sin(t)))
    return out


def _circle_outline(c: Vec, radius: float) -> list[Vec]:
    n = 2 * min(max(round(radius), MIN_ARC_POINTS), MAX_ARC_POINTS)
    return [
        (
            c[0] + radius * math.cos(2 * math.pi * k / n),
            c[1] + radius * math.sin(2 * math.pi * k / n),
        )
        for k in range(n)
    ]


def _draw_shape(
    surf: pygame.Surface, cam: Camera, shape: pymunk.Shape, colour: Colour, sleeping: bool
) -> None:
    body = shape.body
    assert body is not None  # shapes in a space always have a body
    # Dim fills keep the force arrows drawn on top readable.
    fill = _shade(colour, 0.3 if sleeping else 0.45)
    edge = colour
    if isinstance(shape, pymunk.Circle):
        c = body.local_to_world(shape.offset)
        sc = cam.to_screen((c.x, c.y))
        r = max(cam.pixels(shape.radius), MIN_RADIUS_PX)
        outlined_polygon(surf, fill, edge, _circle_outline(sc, r))
        # A spoke shows the rotation.
        tip = body.local_to_world(shape.offset + pymunk.Vec2d(shape.radius, 0.0))
        pygame.draw.aaline(surf, edge, _clamp(sc), _clamp(cam.to_screen((tip.x, tip.y))))
    elif isinstance(shape, pymunk.Segment):
        a = body.local_to_world(shape.a)
        b = body.local_to_world(shape.b)
        r = max(cam.pixels(shape.radius), MIN_RADIUS_PX)
        sa, sb = cam.to_screen((a.x, a.y)), cam.to_screen((b.x, b.y))
        outlined_polygon(surf, fill, edge, capsule_outline(sa, sb, r))
    elif isinstance(shape, pymunk.Poly):
        pts = [cam.to_screen((p.x, p.y)) for p in map(body.local_to_world, shape.get_vertices())]
        outlined_polygon(surf, fill, edge, pts)


def _draw_spoke(surf: pygame.Surface, cam: Camera, body: pymunk.Body) -> None:
    """A kinematic body's turn made visible: a dashed spoke from its centre of gravity along its
    own x axis to its farthest reach (a spinning ring's spin is otherwise hard to see)."""
    c = body.local_to_world(body.center_of_gravity)
    reach = 0.0
    for s in body.shapes:
        for r in _reach_points(s):
            reach = max(reach, (r - body.center_of_gravity).length)
    if reach <= 0.0:
        return
    tip = body.local_to_world(body.center_of_gravity + pymunk.Vec2d(reach, 0.0))
    a, b = _clamp(cam.to_screen((c.x, c.y))), _clamp(cam.to_screen((tip.x, tip.y)))
    _dashed(surf, COLOURS["kinematic"], a, b, dash=8.0)
    pygame.draw.circle(surf, COLOURS["kinematic"], a, JOINT_DOT_PX)


def _reach_points(s: pymunk.Shape) -> list[pymunk.Vec2d]:
    """Points of a shape (body coordinates) whose distances bound how far it reaches."""
    if isinstance(s, pymunk.Circle):
        return [s.offset + pymunk.Vec2d(s.radius, 0.0), s.offset - pymunk.Vec2d(s.radius, 0.0)]
    if isinstance(s, pymunk.Segment):
        return [s.a, s.b]
    if isinstance(s, pymunk.Poly):
        return list(s.get_vertices())
    return []


def _body_colour(body: pymunk.Body, roles: Mapping[int, str]) -> Colour:
    role = roles.get(body.id)
    if role is not None:
        return COLOURS[role]
    if body.body_type == pymunk.Body.STATIC:
        return COLOURS["static"]
    if body.body_type == pymunk.Body.KINEMATIC:
        return COLOURS["kinematic"]
    return COLOURS["dynamic"]


def _draw_joint(surf: pygame.Surface, cam: Camera, c: pymunk.Constraint) -> None:
    colour = COLOURS["joint"]

    def world(body: pymunk.Body, local: pymunk.Vec2d) -> Vec:
        w = body.local_to_world(local)
        return _clamp(cam.to_screen((w.x, w.y)))

    if isinstance(c, pymunk.GrooveJoint):
        g0, g1 = world(c.a, c.groove_a), world(c.a, c.groove_b)
        pygame.draw.line(surf, colour, g0, g1, 3)
        pygame.draw.circle(surf, colour, world(c.b, c.anchor_b), JOINT_DOT_PX)
        return
    anchors = [
        world(body, getattr(c, "anchor_" + which))
        for body, which in ((c.a, "a"), (c.b, "b"))
        if hasattr(c, "anchor_" + which)
    ]
    if len(anchors) < 2:
        # Rotary joints, gears and motors have no anchor points to draw.
        return
    sa, sb = anchors
    if isinstance(c, pymunk.PivotJoint):
        # A pin through both bodies: a ring with a cross.
        for p in (sa, sb):
            pygame.draw.circle(surf, colour, p, JOINT_DOT_PX + 2, 2)
            pygame.draw.aaline(surf, colour, (p[0] - 4, p[1]), (p[0] + 4, p[1]))
            pygame.draw.aaline(surf, colour, (p[0], p[1] - 4), (p[0], p[1] + 4))
        pygame.draw.aaline(surf, colour, sa, sb)
        return
    if isinstance(c, pymunk.DampedSpring):
        _zigzag(surf, colour, sa, sb)
    elif isinstance(c, pymunk.SlideJoint):
        _dashed(surf, colour, sa, sb)
    else:
        pygame.draw.line(surf, colour, sa, sb, 2)
    for p in (sa, sb):
        pygame.draw.circle(surf, colour, p, JOINT_DOT_PX)


def _dashed(surf: pygame.Surface, colour: Colour, a: Vec, b: Vec, dash: float = 6.0) -> None:
    n = math.hypot(b[0] - a[0], b[1] - a[1])
    k = max(int(n // dash), 1)
    for i in range(0, k, 2):
        t0, t1 = i / k, min((i + 1) / k, 1.0)
        p = (a[0] + (b[0] - a[0]) * t0, a[1] + (b[1] - a[1]) * t0)
        q = (a[0] + (b[0] - a[0]) * t1, a[1] + (b[1] - a[1]) * t1)
        pygame.draw.line(surf, colour, p, q, 2)


def _zigzag(surf: pygame.Surface, colour: Colour, a: Vec, b: Vec, turns: int = 8) -> None:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    if n < 1.0:
        return
    px, py = -dy / n * 4.0, dx / n * 4.0
    pts = [a]
    for i in range(1, 2 * turns):
        s = 1.0 if i % 2 else -1.0
        t = i / (2 * turns)
        pts.append((a[0] + dx * t + s * px, a[1] + dy * t + s * py))
    pts.append(b)
    pygame.draw.aalines(surf, colour, False, pts)


def draw_grip(surf: pygame.Surface, cam: Camera, grip: Grip) -> Vec:
    """The arm from the top of the capsule to where the hand holds, and the hand; returns where
    the hand is on screen (px)."""
    j = grip.joint
    held = j.b.local_to_world(getattr(j, "anchor_b", pymunk.Vec2d(0.0, 0.0)))
    hand = _clamp(cam.to_screen((held.x, held.y)))
    shoulder = _clamp(cam.to_screen(grip.shoulder))
    pygame.draw.line(surf, COLOURS["hand"], shoulder, hand, 4)
    pygame.draw.circle(surf, COLOURS["hand"], hand, HAND_PX)
    return hand


def draw_world(
    surf: pygame.Surface,
    cam: Camera,
    world: World,
    *,
    roles: Mapping[str, str] | None = None,
    grips: Iterable[Grip] = (),
) -> None:
    """Draw every shape of the world (actors by ``roles``: body name → role) and every joint
    except the controllers' ``grips`` (see :func:`draw_grip`)."""
    by_id = {world.body(n).id: r for n, r in (roles or {}).items() if n in world.names}
    movers: dict[int, pymunk.Body] = {}
    for shape in world.space.shapes:
        body = shape.body
        if body is None:
            continue
        sleeping = body.body_type == pymunk.Body.DYNAMIC and body.is_sleeping
        _draw_shape(surf, cam, shape, _body_colour(body, by_id), sleeping)
        if body.body_type == pymunk.Body.KINEMATIC:
            movers[body.id] = body
    for body in movers.values():
        _draw_spoke(surf, cam, body)
    grip_joints = {id(g.joint) for g in grips}
    for c in world.space.constraints:
        if id(c) not in grip_joints:
            _draw_joint(surf, cam, c)


def draw_edges(
    surf: pygame.Surface, cam: Camera, world: World, *, roles: Mapping[str, str] | None = None
) -> None:
    """Stroke the edge of every dynamic body again (its colour, no fill): drawn after the
    arrows, so a body stays visible under the forces drawn over it."""
    by_id = {world.body(n).id: r for n, r in (roles or {}).items() if n in world.names}
    for shape in world.space.shapes:
        body = shape.body
        if body is None or body.body_type != pymunk.Body.DYNAMIC:
            continue
        colour = _body_colour(body, by_id)
        if isinstance(shape, pymunk.Circle):
            c = body.local_to_world(shape.offset)
            r = max(cam.pixels(shape.radius), MIN_RADIUS_PX)
            outlined_polygon(surf, None, colour, _circle_outline(cam.to_screen((c.x, c.y)), r))
        elif isinstance(shape, pymunk.Segment):
            a, b = body.local_to_world(shape.a), body.local_to_world(shape.b)
            r = max(cam.pixels(shape.radius), MIN_RADIUS_PX)
            sa, sb = cam.to_screen((a.x, a.y)), cam.to_screen((b.x, b.y))
            outlined_polygon(surf, None, colour, capsule_outline(sa, sb, r))
        elif isinstance(shape, pymunk.Poly):
            pts = [
                cam.to_screen((p.x, p.y)) for p in map(body.local_to_world, shape.get_vertices())
            ]
            outlined_polygon(surf, None, colour, pts)


def dashed_circle(
    surf: pygame.Surface, colour: Colour, centre: Vec, radius: float, dashes: int = 16
) -> None:
    """A dashed ring of ``radius`` px around ``centre`` (px), 2 px wide."""
    c = _clamp(centre)
    for k in range(dashes):
        a0 = 2.0 * math.pi * k / dashes
        a1 = a0 + math.pi / dashes
        p = (c[0] + radius * math.cos(a0), c[1] + radius * math.sin(a0))
        q = (c[0] + radius * math.cos(a1), c[1] + radius * math.sin(a1))
        pygame.draw.line(surf, colour, p, q, 2)


def draw_arrow(surf: pygame.Surface, colour: Colour, start: Vec, d: Vec, width: int) -> None:
    """An arrow from ``start`` along ``d`` (px), ``width`` px wide, with anti-aliased edges."""
    start = _clamp(start)
    n = math.hypot(*d)
    if not math.isfinite(n) or n < 1.0:
        return
    ux, uy = d[0] / n, d[1] / n
    head = min(8.0 + 1.5 * width, 0.45 * n)
    half = max(width / 2.0, 0.5)
    # The shaft stops where the head starts, so a thick shaft never pokes past the tip.
    sx, sy = start[0] + ux * (n - head), start[1] + uy * (n - head)
    end = (start[0] + d[0], start[1] + d[1])
    if width <= 1:
        pygame.draw.aaline(surf, colour, start, (sx, sy))
    else:
        px, py = -uy * half, ux * half
        shaft = [
            (start[0] + px, start[1] + py),
            (sx + px, sy + py),
            (sx - px, sy - py),
            (start[0] - px, start[1] - py),
        ]
        outlined_polygon(surf, colour, colour, shaft)
    wing = head * 0.5 + half
    tip = [end, (sx - uy * wing, sy + ux * wing), (sx + uy * wing, sy - ux * wing)]
    outlined_polygon(surf, colour, colour, tip)


def draw_grid(surf: pygame.Surface, cam: Camera) -> None:
    """A faint world grid (1 m, or a coarser power of ten when zoomed out) so motion shows."""
    spacing = 1.0
    while cam.pixels(spacing) < 24.0:
        spacing *= 10.0
    w, h = surf.get_size()
    corners = [cam.to_world(c) for c in ((0.0, 0.0), (w, 0.0), (0.0, h), (w, h))]
    xs = [c[0] for c in corners]
    ys = [c[1] for c in corners]
    colour = COLOURS["grid"]
    x = math.floor(min(xs) / spacing) * spacing
    while x <= max(xs):
        pygame.draw.line(
            surf, colour, _clamp(cam.to_screen((x, min(ys)))), _clamp(cam.to_screen((x, max(ys))))
        )
        x += spacing
    y = math.floor(min(ys) / spacing) * spacing
    while y <= max(ys):
        pygame.draw.line(
            surf, colour, _clamp(cam.to_screen((min(xs), y))), _clamp(cam.to_screen((max(xs), y)))
        )
        y += spacing


@dataclass(frozen=True, slots=True)
class LegendEntry:
    """One legend line: a colour key, its text, and how its swatch looks (``line``, ``thick``,
    ``dot``, ``ring``, or ``scale``: a bar ``length`` px long)."""

    kind: str
    text: str
    swatch: str = "line"
    length: float = 20.0


def shade_panel(
    surf: pygame.Surface, rect: pygame.Rect, rgba: tuple[int, int, int, int] = (0, 0, 0, 190)
) -> None:
    """Darken ``rect`` of ``surf`` with the translucent colour ``rgba`` (a panel's backing)."""
    surf.blit(_translucent(rect.size, rgba), rect.topleft)


@functools.lru_cache(maxsize=64)
def _translucent(size: tuple[int, int], rgba: tuple[int, int, int, int]) -> pygame.Surface:
    # Made once per size and colour: panels keep their size from frame to frame, and a fresh
    # per-pixel-alpha surface every frame is most of a small panel's cost.
    panel = pygame.Surface(size, pygame.SRCALPHA)
    panel.fill(rgba)
    return panel


def draw_legend(
    surf: pygame.Surface, font: pygame.font.Font, entries: Sequence[LegendEntry], topright: Vec
) -> pygame.Rect:
    """Draw ``entries`` in a panel whose top-right corner is ``topright``; returns its rect."""
    if not entries:
        return pygame.Rect(int(topright[0]), int(topright[1]), 0, 0)
    line = font.get_linesize()
    sw = SWATCH_PX + 12

    def indent(e: LegendEntry) -> int:
        return int(max(e.length, SWATCH_PX) + 12) if e.swatch == "scale" else sw

    width = max(font.size(e.text)[0] + indent(e) for e in entries) + 8
    rect = pygame.Rect(0, int(topright[1]), width, line * len(entries) + 8)
    rect.right = int(topright[0])
    shade_panel(surf, rect)
    x = rect.x
    for i, e in enumerate(entries):
        cy = rect.y + 4 + i * line + line // 2
        colour = COLOURS[e.kind]
        if e.swatch == "dot":
            pygame.draw.circle(surf, colour, (x + 6 + SWATCH_PX // 2, cy), 3)
        elif e.swatch == "ring":
            pygame.draw.circle(surf, colour, (x + 6 + SWATCH_PX // 2, cy), 6, 2)
        elif e.swatch == "scale":
            x0, x1 = x + 6, x + 6 + e.length
            pygame.draw.line(surf, colour, (x0, cy), (x1, cy), 2)
            pygame.draw.line(surf, colour, (x0, cy - 4), (x0, cy + 4), 2)
            pygame.draw.line(surf, colour, (x1, cy - 4), (x1, cy + 4), 2)
        else:
            thick = 5 if e.swatch == "thick" else 2
            draw_arrow(surf, colour, (x + 6, cy), (SWATCH_PX, 0.0), thick)
        surf.blit(font.render(e.text, True, COLOURS["text"]), (x + indent(e), cy - line // 2))
    return rect
