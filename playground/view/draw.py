"""Drawing the world: shapes, joints, contact points and force arrows with their legend.

Everything here only *reads* the world. Force arrows are scaled per body by its own weight, so that
a 10 kg crate and a 5 t whale both show readable arrows: with ``x = |F| / (m·g₀)`` (g₀ = 9.81 m/s²,
a fixed reference, so that a body whose gravity is nullified still has a scale), an arrow is
``WEIGHT_PX·x`` pixels long up to one weight and ``WEIGHT_PX·(1 + ln x)`` beyond, capped at
``MAX_ARROW_PX``. One weight is always the same on-screen length; a tenfold impact spike is only
3.3 weights long instead of leaving the window. Perceived up is a unit arrow of fixed length.

>>> round(arrow_pixels(98.1, 10.0), 6), round(arrow_pixels(5000.0 * 9.81, 5000.0), 6)
(60.0, 60.0)
>>> round(arrow_pixels(10.0 * 98.1, 10.0), 1)
198.2
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import pygame
import pymunk

from playground.view.camera import Camera
from playground.world import World

__all__ = [
    "COLOURS",
    "LEGEND",
    "Arrow",
    "Overlay",
    "arrow_pixels",
    "body_arrows",
    "draw_arrows",
    "draw_grid",
    "draw_legend",
    "draw_world",
]

Vec = tuple[float, float]
Colour = tuple[int, int, int]

G0 = 9.81  # m/s²: the reference weight per kilogram for arrow scaling
WEIGHT_PX = 60.0  # px: on-screen length of a force equal to the body's weight m·g₀
MAX_ARROW_PX = 260.0  # px: no arrow longer than this
UP_PX = 45.0  # px: length of the perceived-up unit arrow
UP_OFFSET_PX = 8.0  # px: the up arrow runs this far beside the force arrows
MIN_ARROW_PX = 2.0  # px: shorter arrows are not drawn
COORD_LIMIT = 1.0e5  # px: points are clamped here so far-away geometry never overflows SDL

COLOURS: dict[str, Colour] = {
    "background": (22, 24, 30),
    "grid": (34, 37, 46),
    "static": (120, 126, 140),
    "kinematic": (80, 140, 200),
    "dynamic": (196, 164, 112),
    "player": (236, 208, 92),
    "actor": (220, 110, 90),
    "joint": (160, 200, 160),
    "contact": (255, 230, 60),
    "support": (110, 210, 120),
    "support_filtered": (255, 60, 200),
    "gravity": (90, 150, 255),
    "hover": (255, 160, 40),
    "drive": (40, 220, 220),
    "grip": (255, 70, 70),
    "push": (190, 120, 255),
    "up": (245, 245, 245),
}

LEGEND: tuple[tuple[str, str], ...] = (
    ("support", "support force, raw (thin)"),
    ("support_filtered", "support force, filtered (thick)"),
    ("gravity", "gravity m·g"),
    ("hover", "hover spring"),
    ("drive", "drive"),
    ("grip", "grip"),
    ("push", "push"),
    ("up", "perceived up (unit)"),
    ("contact", "contact point"),
)


@dataclass(frozen=True, slots=True)
class Overlay:
    """What to draw on top of the shapes."""

    vectors: bool = True
    contacts: bool = True
    joints: bool = True


@dataclass(frozen=True, slots=True)
class Arrow:
    """A force arrow: where (m), the force (N), its colour key, and thick or thin."""

    origin: Vec
    force: Vec
    kind: str
    thick: bool = False


def arrow_pixels(force: float, mass: float) -> float:
    """On-screen length (px) of a force of magnitude ``force`` (N) on a body of ``mass`` (kg)."""
    if not (mass > 0.0 and math.isfinite(mass) and math.isfinite(force)):
        return 0.0
    x = abs(force) / (mass * G0)
    length = WEIGHT_PX * x if x <= 1.0 else WEIGHT_PX * (1.0 + math.log(x))
    return min(length, MAX_ARROW_PX)


def _clamp(p: Vec) -> tuple[float, float]:
    return (
        min(max(p[0], -COORD_LIMIT), COORD_LIMIT),
        min(max(p[1], -COORD_LIMIT), COORD_LIMIT),
    )


def _kind_colour(body: pymunk.Body, player: pymunk.Body | None, actors: set[int]) -> Colour:
    if player is not None and body is player:
        return COLOURS["player"]
    if body.id in actors:
        return COLOURS["actor"]
    if body.body_type == pymunk.Body.STATIC:
        return COLOURS["static"]
    if body.body_type == pymunk.Body.KINEMATIC:
        return COLOURS["kinematic"]
    return COLOURS["dynamic"]


def _shade(c: Colour, f: float) -> Colour:
    return (min(int(c[0] * f), 255), min(int(c[1] * f), 255), min(int(c[2] * f), 255))


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
        r = max(cam.pixels(shape.radius), 1.0)
        sc = _clamp(cam.to_screen((c.x, c.y)))
        pygame.draw.circle(surf, fill, sc, r)
        pygame.draw.circle(surf, edge, sc, r, 1)
        # A spoke shows the rotation.
        tip = body.local_to_world(shape.offset + pymunk.Vec2d(shape.radius, 0.0).rotated(0.0))
        pygame.draw.line(surf, edge, sc, _clamp(cam.to_screen((tip.x, tip.y))), 1)
    elif isinstance(shape, pymunk.Segment):
        a = body.local_to_world(shape.a)
        b = body.local_to_world(shape.b)
        sa = _clamp(cam.to_screen((a.x, a.y)))
        sb = _clamp(cam.to_screen((b.x, b.y)))
        r = cam.pixels(shape.radius)
        if r >= 1.5:
            # A capsule: a thick band with round caps.
            pygame.draw.line(surf, fill, sa, sb, max(round(2 * r), 1))
            pygame.draw.circle(surf, fill, sa, r)
            pygame.draw.circle(surf, fill, sb, r)
            d = (b - a).normalized().perpendicular() * shape.radius
            for s in (1.0, -1.0):
                p = _clamp(cam.to_screen((a.x + s * d.x, a.y + s * d.y)))
                q = _clamp(cam.to_screen((b.x + s * d.x, b.y + s * d.y)))
                pygame.draw.line(surf, edge, p, q, 1)
        else:
            pygame.draw.line(surf, edge, sa, sb, max(round(2 * r), 2))
    elif isinstance(shape, pymunk.Poly):
        pts = [
            _clamp(cam.to_screen((p.x, p.y)))
            for p in (body.local_to_world(v) for v in shape.get_vertices())
        ]
        if len(pts) >= 3:
            pygame.draw.polygon(surf, fill, pts)
            pygame.draw.polygon(surf, edge, pts, 1)


def _anchor(c: pymunk.Constraint, which: str) -> Vec | None:
    body = c.a if which == "a" else c.b
    local = getattr(c, "anchor_" + which, None)
    if local is None:
        return None
    w = body.local_to_world(local)
    return (w.x, w.y)


def draw_world(
    surf: pygame.Surface,
    cam: Camera,
    world: World,
    *,
    player: pymunk.Body | None = None,
    actors: Iterable[pymunk.Body] = (),
    overlay: Overlay = Overlay(),
) -> None:
    """Draw every shape of the world, its joints and (optionally) the tracked bodies' contacts."""
    actor_ids = {b.id for b in actors}
    for shape in world.space.shapes:
        body = shape.body
        if body is None:
            continue
        sleeping = body.body_type == pymunk.Body.DYNAMIC and body.is_sleeping
        _draw_shape(surf, cam, shape, _kind_colour(body, player, actor_ids), sleeping)
    if overlay.joints:
        for c in world.space.constraints:
            a = _anchor(c, "a")
            b = _anchor(c, "b")
            if isinstance(c, pymunk.GrooveJoint):
                g0, g1 = c.a.local_to_world(c.groove_a), c.a.local_to_world(c.groove_b)
                pygame.draw.line(
                    surf,
                    COLOURS["joint"],
                    _clamp(cam.to_screen((g0.x, g0.y))),
                    _clamp(cam.to_screen((g1.x, g1.y))),
                    2,
                )
                a = b  # the anchor slides along the groove: draw the groove and the anchor
            if a is None or b is None:
                # Rotary joints, gears and motors have no anchor points to draw.
                continue
            sa = _clamp(cam.to_screen(a))
            sb = _clamp(cam.to_screen(b))
            pygame.draw.line(surf, COLOURS["joint"], sa, sb, 2)
            pygame.draw.circle(surf, COLOURS["joint"], sa, 3)
            pygame.draw.circle(surf, COLOURS["joint"], sb, 3)
    if overlay.contacts:
        points: list[Vec] = []

        def collect(arb: pymunk.Arbiter) -> None:
            for cp in arb.contact_point_set.points:
                points.append((cp.point_a.x, cp.point_a.y))

        for body in world.solver.bodies:
            body.each_arbiter(collect)
        for p in points:
            pygame.draw.circle(surf, COLOURS["contact"], _clamp(cam.to_screen(p)), 3)


def body_arrows(
    world: World,
    name: str,
    controller_forces: Mapping[str, Vec] | None = None,
    origins: Mapping[str, Vec] | None = None,
) -> list[Arrow]:
    """The force arrows of one tracked body: support raw and filtered, gravity, and the
    controller's own forces (``controller_forces``: kind → N, e.g. hover, drive, grip, push),
    drawn from where they act when known (``origins``: kind → m; default the centre of mass)."""
    body = world.body(name)
    c = body.local_to_world(body.center_of_gravity)
    origin = (c.x, c.y)
    m = body.mass
    out: list[Arrow] = []
    reading = world.forces(name)
    g = world.gravity_at(name)
    out.append(Arrow(origin, (m * g[0], m * g[1]), "gravity"))
    out.append(Arrow(origin, reading.support, "support"))
    pg = world.perceived_gravity(name)
    out.append(Arrow(origin, (-m * pg[0], -m * pg[1]), "support_filtered", thick=True))
    for kind, f in (controller_forces or {}).items():
        if kind in COLOURS:
            out.append(Arrow((origins or {}).get(kind, origin), f, kind))
    return out


def draw_arrows(
    surf: pygame.Surface,
    cam: Camera,
    arrows: Iterable[Arrow],
    mass: float,
    up: tuple[Vec, Vec] | None = None,
) -> None:
    """Draw the ``arrows`` of a body of ``mass`` (kg) and, if given, ``up`` = (origin m, unit
    vector): its perceived up."""
    # Thick (filtered) arrows first, so the thin raw ones stay visible on top of them.
    for arrow in sorted(arrows, key=lambda a: not a.thick):
        fx, fy = arrow.force
        n = math.hypot(fx, fy)
        length = arrow_pixels(n, mass)
        if length < MIN_ARROW_PX:
            continue
        sx, sy = cam.vector((fx / n, fy / n))
        k = length / math.hypot(sx, sy)
        width = 5 if arrow.thick else 2
        _arrow(surf, COLOURS[arrow.kind], cam.to_screen(arrow.origin), (sx * k, sy * k), width)
    if up is not None:
        origin, (ux, uy) = up
        n = math.hypot(ux, uy)
        if math.isfinite(n) and n > 0.0:
            sx, sy = cam.vector((ux / n, uy / n))
            k = UP_PX / math.hypot(sx, sy)
            # Beside the force arrows (UP_OFFSET_PX to the right of up), not on top of them.
            o = cam.to_screen(origin)
            side = (-sy * k * UP_OFFSET_PX / UP_PX, sx * k * UP_OFFSET_PX / UP_PX)
            start = (o[0] - side[0], o[1] - side[1])
            _arrow(surf, COLOURS["up"], start, (sx * k, sy * k), 1)


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


def _arrow(surf: pygame.Surface, colour: Colour, start: Vec, d: Vec, width: int) -> None:
    start = _clamp(start)
    end = (start[0] + d[0], start[1] + d[1])
    pygame.draw.line(surf, colour, start, end, width)
    n = math.hypot(*d)
    if n < 1.0:
        return
    ux, uy = d[0] / n, d[1] / n
    head = min(10.0 + width, 0.4 * n)
    left = (end[0] - head * (ux - 0.5 * uy), end[1] - head * (uy + 0.5 * ux))
    right = (end[0] - head * (ux + 0.5 * uy), end[1] - head * (uy - 0.5 * ux))
    pygame.draw.polygon(surf, colour, [end, left, right])


def draw_legend(surf: pygame.Surface, font: pygame.font.Font, topleft: Vec) -> pygame.Rect:
    """Draw the arrow legend; returns the rectangle it covers."""
    x, y = int(topleft[0]), int(topleft[1])
    line = font.get_linesize()
    width = max(font.size(text)[0] for _, text in LEGEND) + 36
    rect = pygame.Rect(x, y, width, line * len(LEGEND) + 8)
    panel = pygame.Surface(rect.size, pygame.SRCALPHA)
    panel.fill((0, 0, 0, 150))
    surf.blit(panel, rect.topleft)
    for i, (kind, text) in enumerate(LEGEND):
        cy = y + 4 + i * line + line // 2
        thick = 5 if kind == "support_filtered" else 2
        if kind == "contact":
            pygame.draw.circle(surf, COLOURS[kind], (x + 16, cy), 3)
        else:
            pygame.draw.line(surf, COLOURS[kind], (x + 6, cy), (x + 26, cy), thick)
        surf.blit(font.render(text, True, (220, 220, 220)), (x + 32, cy - line // 2))
    return rect
