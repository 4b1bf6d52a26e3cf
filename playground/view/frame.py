"""The picture of one frame: :class:`Picture`, the value that says what to draw (the world and
its camera, the actors, the watched body, the mouse, the HUD's lines, the scope, which panels),
and :func:`draw_frame`, which draws it — the grid, the world and its overlays, the mouse, the HUD
and the scope, the overlay panel, the legend, the compass and the free-body inset down the right
edge, the tuning panel and the help. Every panel's rect goes into the HUD's ``rects`` (they must
all fit the window, and pixel checks leave them out). Drawing only reads the world.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import pygame

from playground.controller.mouse import Grab
from playground.vec import Vec
from playground.view.camera import Camera
from playground.view.draw import COLOURS, draw_grid
from playground.view.free_body import INSET_PX, MIN_INSET_PX, FreeBody, draw_free_body
from playground.view.hud import MARGIN, Hud, HudInfo
from playground.view.overlay import draw_panel
from playground.view.painter import Painter
from playground.view.pointer import draw_mouse
from playground.view.scope import Scope
from playground.view.tuning import TuningPanel
from playground.world.world import World

__all__ = ["Drawers", "Picture", "draw_frame"]

FREE_BODY_GAP_PX = 8  # px: between the free-body inset and the scope, and the window's edge
ACTOR_CLEAR_PX = 80  # px: the inset keeps an actor's centre at least half this far outside it


@dataclass(frozen=True, slots=True)
class Picture:
    """What one frame shows.

    Attributes:
        world, camera: the world and the camera it is seen through.
        controllers, roles: the actors' controllers and roles, by body name.
        focus: the body whose arrows are labelled and whose weight is the legend's scale.
        selected: the body picked with the mouse (None: none).
        nullify_target: the body X would nullify now (None: X would do nothing).
        grab, pull: what the mouse holds and its last pull (N at a point, m), if anything.
        hud: the HUD's lines; scope: the oscilloscope (None: no body watched).
        free_body: the watched body's free-body diagram (None: not shown).
        compact: leave out the overlay panel and write the legend small.
        tuning: draw the tuning panel.
        help: the controls (key, action) and the level's description, when the help is shown.
        hud_left: the HUD's left edge, px (right of the lab panel while it is shown).
    """

    world: World
    camera: Camera
    controllers: Mapping[str, Any]
    roles: Mapping[str, str]
    focus: str | None
    selected: str | None
    nullify_target: str | None
    grab: Grab | None
    pull: tuple[Vec, Vec] | None
    hud: HudInfo
    scope: Scope | None
    free_body: FreeBody | None
    compact: bool
    tuning: bool
    help: tuple[Sequence[tuple[str, str]], str] | None
    hud_left: int = MARGIN


@dataclass(frozen=True, slots=True)
class Drawers:
    """The parts that draw (and remember what they drew last): the overlays' painter, the HUD,
    the tuning panel, and the panels' fonts."""

    painter: Painter
    hud: Hud
    tuning: TuningPanel
    small: pygame.font.Font
    tiny: pygame.font.Font


def draw_frame(surf: pygame.Surface, picture: Picture, drawers: Drawers) -> pygame.Surface:
    """Draw ``picture`` onto ``surf`` with ``drawers`` and return ``surf``."""
    surf.fill(COLOURS["background"])
    draw_grid(surf, picture.camera)
    _world(surf, picture, drawers.painter)
    drawers.hud.draw(surf, picture.hud, picture.scope, picture.hud_left)
    _panels(surf, picture, drawers)
    return surf


def _world(surf: pygame.Surface, p: Picture, painter: Painter) -> None:
    """The world, its overlays, the selection marker and the mouse spring."""
    painter.draw(
        surf,
        p.camera,
        p.world,
        p.controllers,
        p.roles,
        focus=p.focus,
        nullify_target=p.nullify_target,
    )
    if draw_mouse(surf, p.camera, p.world, p.selected, p.grab, p.pull):
        painter.drawn.add("mouse")


def _panels(surf: pygame.Surface, p: Picture, d: Drawers) -> None:
    """Down the right edge the overlay panel, the legend and the compass, the free-body inset
    above the scope; the tuning panel under the HUD; the help over everything."""
    hud = d.hud
    width, height = surf.get_size()
    right = width - 8
    if p.compact:
        panel = pygame.Rect(right, 8, 0, 0)
    else:
        panel = draw_panel(surf, d.small, d.painter.overlay, (right, 8))
    font = d.tiny if p.compact else d.small
    legend = d.painter.draw_legend(surf, font, (right, panel.bottom + 4))
    hud.rects += [panel, legend]
    compass = d.painter.draw_compass(surf, d.small, p.camera, (right - 60, legend.bottom + 60))
    if compass is not None:
        hud.rects.append(compass)
    if p.free_body is not None:
        above = hud.scope_layout.plot.top if hud.scope_layout is not None else height
        bottom = min(above - 2 * FREE_BODY_GAP_PX - d.small.get_linesize(), height)
        place = _free_body_place(p, bottom, (right, p.hud_left), hud.rects)
        if place is not None:
            corner, side = place
            rect = draw_free_body(surf, d.small, p.camera, p.free_body, corner, side)
            hud.rects.append(rect)
    if p.tuning:
        below = max((r.bottom for r in hud.rects[:2]), default=0)
        hud.rects.append(d.tuning.draw(surf, (p.hud_left, below + 4)))
    if p.help is not None:
        hud.draw_help(surf, *p.help)


def _free_body_place(
    p: Picture, bottom: int, edges: tuple[int, int], panels: Sequence[pygame.Rect]
) -> tuple[tuple[int, int], int] | None:
    """Where the free-body inset goes: its bottom-right corner (px) and side (px), at the right
    edge or else the left one (``edges``: the right edge's x and the left one's), as large as
    the panels above it leave room for, covering no actor (None: nowhere; the inset is left out
    rather than hide what the level shows)."""
    actors = [
        p.camera.to_screen((b.position.x, b.position.y))
        for b in (p.world.body(n) for n in p.roles if n in p.world.names)
    ]
    right, left = edges
    for x0, x1 in ((right - INSET_PX, right), (left, left + INSET_PX)):
        top = max(
            (r.bottom for r in panels if r.right > x0 and r.left < x1 and r.bottom <= bottom),
            default=0,
        )
        side = min(INSET_PX, bottom - top - FREE_BODY_GAP_PX)
        if side < MIN_INSET_PX:
            continue
        corner = (x1, bottom) if x1 == right else (x0 + side, bottom)
        rect = pygame.Rect(corner[0] - side, bottom - side, side, side)
        clear = rect.inflate(ACTOR_CLEAR_PX, ACTOR_CLEAR_PX)
        if rect.collidelist(list(panels)) < 0 and not any(clear.collidepoint(a) for a in actors):
            return corner, side
    return None
