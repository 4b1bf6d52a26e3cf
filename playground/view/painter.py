"""Drawing one frame of the overlays: :class:`Painter` draws the world, every tracked body's arrows
for the overlays that are on (spread apart so none hides another), the hands of the actors that
hold on, the ring around the body X would nullify, the compass; and it knows what it drew, so the
legend lists only what is on screen.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import pygame

from playground.vec import Vec
from playground.view.arrows import G0, PeakHold, ScreenArrow, body_size, spread, weight_pixels
from playground.view.camera import Camera
from playground.view.draw import (
    COLOURS,
    Grip,
    LegendEntry,
    draw_arrow,
    draw_grip,
    draw_legend,
    draw_world,
)
from playground.view.force_arrows import (
    LABEL_FONT_PX,
    contacts,
    joint_forces,
    perceived,
    reactions,
    vectors,
)
from playground.view.overlay import Overlay
from playground.world.world import World

__all__ = ["LEGEND", "WEIGHED", "Painter"]

COMPASS_PX = 30  # px: radius of the world-up compass
ROLL_SHOWN_RAD = math.radians(0.5)  # the compass appears once the camera rolls this far
NULLIFY_RING_M = 1.2  # m: radius of the ring around the body X would nullify …
NULLIFY_RING_MIN_PX = 14.0  # px: … at least this big on screen

LEGEND: dict[str, tuple[str, str]] = {
    "support_filtered": ("support, filtered", "thick"),
    "support": ("support, raw (frame peak)", "line"),
    "gravity": ("gravity m·g", "line"),
    "hover": ("hover spring", "line"),
    "drive": ("drive", "line"),
    "grip": ("grip", "line"),
    "grip_arm": ("hand (grip joint)", "thick"),
    "push": ("push on itself", "line"),
    "contact": ("contact point", "dot"),
    "normal": ("contact normal", "line"),
    "friction": ("contact friction", "line"),
    "joint_force": ("joint force", "line"),
    "reaction": ("reaction on ground", "thick"),
    "perceived": ("perceived gravity", "line"),
    "up": ("perceived up", "line"),
    "nullify": ("X nullifies this", "ring"),
    "mouse": ("mouse pull (applied)", "line"),
}
"""Colour key → (legend text, swatch), in the legend's order."""
WEIGHED = tuple(LEGEND)[:8]
"""The force-vector keys (support … push): the legend's m·g scale bar is shown with them."""


class Painter:
    """Draws the world and the overlays that are on, and keeps the per-step peaks."""

    def __init__(self, overlay: Overlay | None = None) -> None:
        self.overlay = overlay if overlay is not None else Overlay()
        self.hold = PeakHold()
        self.drawn: set[str] = set()
        self.scale_px = 0.0
        self.scale_body: str | None = None
        self.scale_newtons = 0.0
        self.scale_weighs = True
        """Whether the scale body feels gravity (else the scale bar is not called a weight)."""
        self.compass_rect: pygame.Rect | None = None
        """Where the compass was drawn last frame (None: not drawn)."""
        self.compass_centre: Vec = (0.0, 0.0)
        self.nullify_px = 0.0
        """Radius of the nullify ring drawn last frame, px (0: none)."""
        self._label_font: pygame.font.Font | None = None

    def sample(self, world: World) -> None:
        """Call after every physics step (feeds the peak hold)."""
        self.hold.sample(world)

    def _labels(self) -> pygame.font.Font:
        """The joint-force labels' font, made the first time a label is drawn."""
        if self._label_font is None:
            self._label_font = pygame.font.Font(None, LABEL_FONT_PX)
        return self._label_font

    # -- one frame -------------------------------------------------------------------------------

    def draw(
        self,
        surf: pygame.Surface,
        cam: Camera,
        world: World,
        controllers: Mapping[str, Any],
        roles: Mapping[str, str],
        *,
        focus: str | None = None,
        nullify_target: str | None = None,
    ) -> None:
        """Draw the world and the overlays. ``focus``: the body whose weight scale the legend
        shows; ``nullify_target``: the body X would nullify now (None: X would do nothing)."""
        self.drawn = set()
        self.compass_rect = None
        self.nullify_px = 0.0
        grips = [g for g in (_grip(c) for c in controllers.values()) if g is not None]
        draw_world(surf, cam, world, roles=roles, grips=grips)
        ov = self.overlay
        arrows: list[ScreenArrow] = []
        peaks = self.hold.peaks()
        self.scale_body = None
        for body in world.tracked_bodies:
            name = world.name_of(body)
            if name is None:
                continue
            w_px = weight_pixels(body_size(body), cam.zoom)
            if name == focus or self.scale_body is None:
                self.scale_body, self.scale_px = name, w_px
                self.scale_newtons = body.mass * G0
                self.scale_weighs = math.hypot(*world.gravity_at(name)) > 0.0
            ctrl = controllers.get(name)
            if ov.vectors:
                arrows += vectors(cam, world, name, body, ctrl, peaks.get(name), w_px)
            if ov.perceived:
                arrows += perceived(cam, world, name, body, w_px)
            if ov.contacts:
                arrows += contacts(surf, cam, world, body, w_px, self.drawn)
            if ov.joints:
                arrows += joint_forces(surf, cam, world, name, body, w_px, self.drawn, self._labels)
            if ov.reactions and ctrl is not None:
                arrows += reactions(cam, ctrl, body, w_px)
        # Thick arrows first so thin ones stay visible on top; then moved apart.
        arrows.sort(key=lambda a: -a.width)
        window = surf.get_rect()
        for a in spread(arrows):
            draw_arrow(surf, COLOURS[a.kind], a.start, a.d, a.width)
            end = (a.start[0] + a.d[0], a.start[1] + a.d[1])
            if window.clipline(a.start, end):
                self.drawn.add(a.kind)
        # The hands last: what holds on must never hide under the arrows it explains.
        for g in grips:
            if window.collidepoint(draw_grip(surf, cam, g)):
                self.drawn.add("grip_arm")
        if nullify_target is not None and nullify_target in world.names:
            t = world.body(nullify_target).position
            ring = max(cam.pixels(NULLIFY_RING_M), NULLIFY_RING_MIN_PX)
            centre = cam.to_screen((t.x, t.y))
            pygame.draw.circle(surf, COLOURS["nullify"], centre, ring, 3)
            self.nullify_px = ring
            if window.inflate(2 * ring, 2 * ring).collidepoint(centre):
                self.drawn.add("nullify")

    # -- what is on screen -----------------------------------------------------------------------

    def legend(self) -> list[LegendEntry]:
        """Legend entries for what the last :meth:`draw` put on screen, in a fixed order."""
        entries = [
            LegendEntry("hand" if k == "grip_arm" else k, text, swatch)
            for k, (text, swatch) in LEGEND.items()
            if k in self.drawn
        ]
        if any(k in self.drawn for k in WEIGHED) and self.scale_body is not None:
            text = (
                f"m·g of {self.scale_body} ({self.scale_newtons:.0f} N)"
                if self.scale_weighs
                else f"scale {self.scale_newtons:.0f} N (no gravity on {self.scale_body})"
            )
            entries.append(LegendEntry("text", text, "scale", self.scale_px))
        return entries

    def draw_legend(
        self, surf: pygame.Surface, font: pygame.font.Font, topright: Vec
    ) -> pygame.Rect:
        """The legend of what is on screen, its top-right corner at ``topright``."""
        return draw_legend(surf, font, self.legend(), topright)

    def draw_compass(
        self, surf: pygame.Surface, font: pygame.font.Font, cam: Camera, centre: Vec
    ) -> pygame.Rect | None:
        """World up on screen and the camera's roll, when the camera rolls (and the overlay is
        on); returns the rect it covers."""
        if not self.overlay.compass or abs(cam.roll) < ROLL_SHOWN_RAD:
            return None
        r = COMPASS_PX
        text = font.render(f"world up, roll {math.degrees(cam.roll):+.0f}°", True, COLOURS["text"])
        width = max(2 * r + 16, text.get_width() + 12)
        rect = pygame.Rect(0, 0, width, 2 * r + 16 + font.get_linesize())
        rect.center = (int(centre[0]), int(centre[1]))
        panel = pygame.Surface(rect.size, pygame.SRCALPHA)
        panel.fill((0, 0, 0, 190))
        surf.blit(panel, rect.topleft)
        c = (rect.centerx, rect.y + 8 + r)
        self.compass_rect, self.compass_centre = rect, (float(c[0]), float(c[1]))
        pygame.draw.circle(surf, COLOURS["dim"], c, r, 1)
        sx, sy = cam.vector((0.0, 1.0))
        k = (r - 2) / math.hypot(sx, sy)
        draw_arrow(
            surf,
            COLOURS["up"],
            (c[0] - sx * k * 0.6, c[1] - sy * k * 0.6),
            (sx * k * 1.6, sy * k * 1.6),
            3,
        )
        surf.blit(text, (rect.centerx - text.get_width() // 2, rect.bottom - font.get_linesize()))
        self.drawn.add("compass")
        return rect


def _grip(ctrl: Any) -> Grip | None:
    joint = getattr(ctrl, "joint", None)
    if joint is None:
        return None
    body = joint.a
    axis = getattr(ctrl, "axis", (0.0, 1.0))
    cfg = getattr(ctrl, "config", None)
    reach = (cfg.half_length + cfg.radius) if cfg is not None else 0.0
    p = body.position
    return Grip(joint, (p.x + axis[0] * reach, p.y + axis[1] * reach))
