"""The free-body diagram: an inset that draws the watched body as a dot with every force on it
from that dot — gravity, the contacts', the joints', the controller's hover, drive and push
recoil — and their sum, m·a, each labelled in N. Directions are as on screen (the camera's
roll included); lengths share one scale, the largest force reaching the inset's edge.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import pygame

from playground.vec import Vec
from playground.view.camera import Camera
from playground.view.draw import COLOURS, draw_arrow, shade_panel
from playground.view.force_arrows import joints_on
from playground.world.world import World

__all__ = ["INSET_PX", "MIN_INSET_PX", "FreeBody", "draw_free_body", "free_body"]

INSET_PX = 150  # px: the inset's side (smaller where the window leaves less room) …
MIN_INSET_PX = 120  # px: … but never smaller: below this it is left out
REACH = 0.38  # the largest force is this share of the side long
MIN_SHOWN_N = 0.5  # N: smaller forces are left out of the diagram


@dataclass(frozen=True, slots=True)
class FreeBody:
    """The forces on one body this step, N, by colour key (``"net"``: their sum)."""

    name: str
    forces: tuple[tuple[str, Vec], ...]
    net: Vec


def free_body(world: World, name: str, ctrl: Any) -> FreeBody:
    """The forces on ``name`` this step: gravity m·g, the contacts' sum (from the arbiters),
    the joints' (the engine's force minus the contacts'), the controller's hover, drive and
    push recoil, and the sum of them all."""
    body = world.body(name)
    m = body.mass
    g = world.gravity_at(name)
    reading = world.forces(name)
    h = world.config.dt / world.config.substeps
    impulses: list[Vec] = []
    body.each_arbiter(lambda arb: impulses.append((arb.total_impulse.x, arb.total_impulse.y)))
    contact = (sum(j[0] for j in impulses) / h, sum(j[1] for j in impulses) / h)
    forces: list[tuple[str, Vec]] = [("gravity", (m * g[0], m * g[1]))]
    if impulses:
        forces.append(("normal", contact))
    if joints_on(world, body):
        forces.append(
            ("joint_force", (reading.engine[0] - contact[0], reading.engine[1] - contact[1]))
        )
    last = getattr(ctrl, "last_forces", None)
    for kind in ("hover", "drive", "push"):
        v = getattr(last, kind, None)
        if v is not None:
            forces.append((kind, (float(v[0]), float(v[1]))))
    shown = tuple((k, f) for k, f in forces if math.hypot(*f) >= MIN_SHOWN_N)
    net = (sum(f[0] for _, f in forces), sum(f[1] for _, f in forces))
    return FreeBody(name, shown, net)


def draw_free_body(
    surf: pygame.Surface,
    font: pygame.font.Font,
    cam: Camera,
    diagram: FreeBody,
    bottomright: Vec,
    side: int = INSET_PX,
) -> pygame.Rect:
    """Draw ``diagram`` in a square inset of ``side`` px whose bottom-right corner is
    ``bottomright`` (px); returns its rect."""
    rect = pygame.Rect(0, 0, side, side)
    rect.bottomright = (int(bottomright[0]), int(bottomright[1]))
    shade_panel(surf, rect, (0, 0, 0, 200))
    line = font.get_linesize()
    surf.blit(
        font.render(f"free body: {diagram.name}", True, COLOURS["text"]), (rect.x + 6, rect.y + 4)
    )
    centre = (rect.centerx, rect.centery + line)
    items = [*diagram.forces, ("net", diagram.net)]
    largest = max((math.hypot(*f) for _, f in items), default=0.0)
    scale = REACH * side / largest if largest > 0.0 else 0.0
    taken: list[pygame.Rect] = []
    for kind, f in items:
        n = math.hypot(*f)
        if n < MIN_SHOWN_N or scale == 0.0:
            continue
        sx, sy = cam.vector((f[0] / n, f[1] / n))
        k = n * scale / math.hypot(sx, sy)
        d = (sx * k, sy * k)
        colour = COLOURS["up"] if kind == "net" else COLOURS[kind]
        draw_arrow(surf, colour, centre, d, 1 if kind == "net" else 2)
        label = font.render(f"{'m·a ' if kind == 'net' else ''}{n:.0f} N", True, colour)
        at = label.get_rect(center=(round(centre[0] + d[0] * 1.15), round(centre[1] + d[1] * 1.15)))
        at.clamp_ip(rect)
        if at.collidelist(taken) < 0:
            surf.blit(label, at)
            taken.append(at)
    pygame.draw.circle(surf, COLOURS["text"], centre, 4)
    return rect
