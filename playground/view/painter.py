"""Drawing one frame of the overlays: :class:`Painter` draws the world, every tracked body's arrows
for the overlays that are on (spread apart so none hides another, bundled for a body small on
screen, the watched body's labelled with their values), the bodies' edges again over them, the
hands of the actors that hold on, the marks of nullified actors and of actors out of the window,
the ring around the body X would nullify, the compass; and it knows what it drew, so the legend
lists only what is on screen.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import pygame

from playground.vec import Vec
from playground.view.arrows import (
    BUNDLE_PX,
    G0,
    PeakHold,
    ScreenArrow,
    body_size,
    spread,
    weight_pixels,
)
from playground.view.camera import Camera
from playground.view.draw import (
    COLOURS,
    Grip,
    LegendEntry,
    dashed_circle,
    draw_arrow,
    draw_edges,
    draw_grip,
    draw_legend,
    draw_world,
    shade_panel,
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
NULLIFIED_GAP_PX = 6.0  # px: the nullified body's dashed ring clears its outline by this much
MARKER_INSET_PX = 18  # px: off-screen markers sit this far inside the window's edge …
MARKER_PX = 12.0  # px: … and are this long
LABEL_GAP_PX = 4.0  # px: between an arrow's tip and its label
LABEL_BACKING = (0, 0, 0, 150)  # the labels' translucent backing (RGBA)
LABELLED = frozenset(
    {"gravity", "support_filtered", "hover", "drive", "grip", "push", "normal", "friction"}
)
"""The arrow kinds whose values the watched body's arrows carry."""

LEGEND: dict[str, tuple[str, str]] = {
    "support_filtered": ("support, filtered", "thick"),
    "support": ("support, raw (frame peak)", "line"),
    "gravity": ("gravity m·g", "line"),
    "hover": ("hover spring", "line"),
    "drive": ("drive", "line"),
    "grip": ("grip", "line"),
    "grip_arm": ("hand (grip joint)", "thick"),
    "push": ("push (on what it pushes)", "line"),
    "contact": ("contact point", "dot"),
    "normal": ("contact normal (watched body)", "line"),
    "friction": ("contact friction (watched body)", "line"),
    "joint_force": ("joint force", "line"),
    "reaction": ("reaction on ground", "thick"),
    "perceived": ("perceived gravity", "line"),
    "up": ("perceived up", "line"),
    "nullify": ("X nullifies this", "ring"),
    "nullified": ("gravity nullified", "ring"),
    "off_screen": ("off screen (that way)", "dot"),
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
        self.bundled: set[str] = set()
        """The bodies whose arrows were bundled last frame (small on screen)."""
        self.labels: list[tuple[str, str, pygame.Rect]] = []
        """The watched body's arrow labels drawn last frame: (kind, text, rect px)."""
        self.markers: list[tuple[str, Vec]] = []
        """The off-screen markers drawn last frame: (body, where on screen, px)."""
        self.tags: list[tuple[str, str]] = []
        """The nullified bodies' tags drawn last frame: (body, text)."""

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
        self.bundled = set()
        self.labels = []
        self.markers = []
        self.tags = []
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
            small = cam.pixels(body_size(body)) < BUNDLE_PX
            if small:
                self.bundled.add(name)
            if ov.vectors:
                arrows += vectors(
                    cam, world, name, body, ctrl, peaks.get(name), w_px, bundled=small
                )
            if ov.perceived:
                arrows += perceived(cam, world, name, body, w_px)
            if ov.contacts:
                # Every body's contact points, but only the watched body's contact forces: each
                # contact's pair of arrows would otherwise lie over both bodies (crusher's crates
                # hid behind them). A click on another body watches it.
                arrows += contacts(
                    surf, cam, world, body, w_px, self.drawn, name, forces=name == focus
                )
            if ov.joints:
                arrows += joint_forces(surf, cam, world, name, body, w_px, self.drawn, self._labels)
            if ov.reactions and ctrl is not None:
                arrows += reactions(cam, ctrl, body, w_px)
        # Thick arrows first so thin ones stay visible on top; then moved apart.
        arrows.sort(key=lambda a: -a.width)
        window = surf.get_rect()
        placed = spread(arrows)
        for a in placed:
            draw_arrow(surf, COLOURS[a.kind], a.start, a.d, a.width)
            end = (a.start[0] + a.d[0], a.start[1] + a.d[1])
            if window.clipline(a.start, end):
                self.drawn.add(a.kind)
        # The bodies' edges again over the arrows: a body never disappears under its forces.
        draw_edges(surf, cam, world, roles=roles)
        if focus is not None and focus in world.names:
            self._label(surf, world, focus, placed)
        # The hands last: what holds on must never hide under the arrows it explains.
        for g in grips:
            if window.collidepoint(draw_grip(surf, cam, g)):
                self.drawn.add("grip_arm")
        self._nullified(surf, cam, world, controllers)
        self._off_screen(surf, cam, world, roles)
        if nullify_target is not None and nullify_target in world.names:
            t = world.body(nullify_target).position
            ring = max(cam.pixels(NULLIFY_RING_M), NULLIFY_RING_MIN_PX)
            centre = cam.to_screen((t.x, t.y))
            pygame.draw.circle(surf, COLOURS["nullify"], centre, ring, 3)
            self.nullify_px = ring
            if window.inflate(2 * ring, 2 * ring).collidepoint(centre):
                self.drawn.add("nullify")

    def _label(
        self, surf: pygame.Surface, world: World, name: str, arrows: list[ScreenArrow]
    ) -> None:
        """Write the value of each of ``name``'s force arrows beside its tip: N, and weights
        m·g where it feels gravity. A label that would cover one already written is left out."""
        body = world.body(name)
        weight = body.mass * math.hypot(*world.gravity_at(name))
        font = self._labels()
        window = surf.get_rect()
        taken: list[pygame.Rect] = []
        segments = [(a.start, (a.start[0] + a.d[0], a.start[1] + a.d[1])) for a in arrows]
        for a in arrows:
            if a.body != name or a.kind not in LABELLED or not math.isfinite(a.newtons):
                continue
            text = f"{a.newtons:.0f} N"
            if weight > 0.0:
                text += f" = {a.newtons / weight:.2f} m·g"
            image = font.render(text, True, COLOURS[a.kind])
            n = math.hypot(*a.d)
            ux, uy = a.d[0] / n, a.d[1] / n
            half_w = LABEL_GAP_PX + image.get_width() / 2.0
            half_h = LABEL_GAP_PX + image.get_height() / 2.0
            tip = (a.start[0] + a.d[0], a.start[1] + a.d[1])
            mid = (a.start[0] + a.d[0] / 2.0, a.start[1] + a.d[1] / 2.0)
            # Beyond the tip along the arrow; else before its tail; else beside its middle.
            spots = [
                (tip[0] + ux * half_w, tip[1] + uy * half_h),
                (a.start[0] - ux * half_w, a.start[1] - uy * half_h),
                (mid[0] - uy * half_w, mid[1] + ux * half_h),
                (mid[0] + uy * half_w, mid[1] - ux * half_h),
            ]
            fits = [
                r
                for r in (image.get_rect(center=(round(x), round(y))) for x, y in spots)
                if window.contains(r) and r.collidelist(taken) < 0
            ]
            # Rather where it crosses no arrow; where each spot would, the first free one.
            clear = [r for r in fits if not any(r.clipline(*seg) for seg in segments)]
            if not fits:
                continue
            rect = (clear or fits)[0]
            # On a dark backing: the value reads over the arrows and bodies it crosses.
            shade_panel(surf, rect, LABEL_BACKING)
            surf.blit(image, rect)
            taken.append(rect)
            self.labels.append((a.kind, text, rect))

    def _nullified(
        self,
        surf: pygame.Surface,
        cam: Camera,
        world: World,
        controllers: Mapping[str, Any],
    ) -> None:
        """Mark each actor whose gravity is nullified: a dashed ring and a tag with what its
        hover and drive still push with (nothing, with no ground in reach)."""
        font = self._labels()
        for name, ctrl in controllers.items():
            if name not in world.names or world.gravity_rule(name).scale != 0.0:
                continue
            body = world.body(name)
            c = body.local_to_world(body.center_of_gravity)
            centre = cam.to_screen((c.x, c.y))
            ring = max(cam.pixels(0.5 * body_size(body)) + NULLIFIED_GAP_PX, NULLIFY_RING_MIN_PX)
            dashed_circle(surf, COLOURS["nullified"], centre, ring)
            forces = getattr(ctrl, "last_forces", None)
            hover = math.hypot(*forces.hover) if forces is not None else 0.0
            drive = math.hypot(*forces.drive) if forces is not None else 0.0
            ground = "no ground in reach" if getattr(ctrl, "probe", None) is None else "on ground"
            lines = [
                f"{name}: gravity nullified",
                f"hover {hover:.0f} N, drive {drive:.0f} N ({ground})",
            ]
            y = centre[1] - ring - NULLIFIED_GAP_PX - len(lines) * font.get_linesize()
            for line in lines:
                image = font.render(line, True, COLOURS["nullified"])
                rect = image.get_rect(midtop=(round(centre[0]), round(y)))
                surf.blit(image, rect)
                y += font.get_linesize()
            self.tags.append((name, " / ".join(lines)))
            if surf.get_rect().inflate(2 * ring, 2 * ring).collidepoint(centre):
                self.drawn.add("nullified")

    def _off_screen(
        self, surf: pygame.Surface, cam: Camera, world: World, roles: Mapping[str, str]
    ) -> None:
        """For each player or enemy out of the window: a triangle at the window's edge pointing
        at it, with its name and distance (m)."""
        window = surf.get_rect()
        inner = window.inflate(-2 * MARKER_INSET_PX, -2 * MARKER_INSET_PX)
        font = self._labels()
        for name, role in roles.items():
            if role not in ("player", "enemy") or name not in world.names:
                continue
            p = world.body(name).position
            at = cam.to_screen((p.x, p.y))
            if window.collidepoint(at):
                continue
            cx, cy = window.center
            dx, dy = at[0] - cx, at[1] - cy
            # Where the ray from the window's centre toward the body leaves the inner rect.
            k = min(
                (inner.width / 2.0) / abs(dx) if dx else math.inf,
                (inner.height / 2.0) / abs(dy) if dy else math.inf,
            )
            mx, my = cx + dx * k, cy + dy * k
            n = math.hypot(dx, dy)
            ux, uy = dx / n, dy / n
            s = MARKER_PX
            tip = (mx + ux * s, my + uy * s)
            left = (mx - uy * s * 0.6, my + ux * s * 0.6)
            right = (mx + uy * s * 0.6, my - ux * s * 0.6)
            colour = COLOURS[role]
            pygame.draw.polygon(surf, colour, [tip, left, right])
            centre = cam.to_world((cx, cy))
            metres = math.hypot(p.x - centre[0], p.y - centre[1])
            image = font.render(f"{name} {metres:.0f} m", True, colour)
            rect = image.get_rect(center=(round(mx - ux * 2 * s), round(my - uy * 2 * s)))
            rect.clamp_ip(window)
            surf.blit(image, rect)
            self.markers.append((name, (mx, my)))
            self.drawn.add("off_screen")

    # -- what is on screen -----------------------------------------------------------------------

    def legend(self) -> list[LegendEntry]:
        """Legend entries for what the last :meth:`draw` put on screen, in a fixed order."""
        entries = [
            LegendEntry("hand" if k == "grip_arm" else k, text, swatch)
            for k, (text, swatch) in LEGEND.items()
            if k in self.drawn
        ]
        if self.bundled and self.overlay.vectors and "support_filtered" in self.drawn:
            names = ", ".join(sorted(self.bundled))
            entries.append(LegendEntry("dim", f"{names}: small, arrows bundled (= zooms)", "dot"))
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
        shade_panel(surf, rect)
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
