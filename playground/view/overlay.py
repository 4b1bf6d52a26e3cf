"""The overlays drawn over the world, each a toggle: forces on the tracked bodies, contact points
with their normal and friction forces, joint forces at their anchors, the reactions the actors put
on the bodies under them, perceived gravity and its up, and a world-up compass with the camera's
roll. :class:`Painter` draws one frame of them and knows what it drew, so the legend lists only
what is on screen.

>>> Overlay().toggled("contacts").contacts, Overlay.from_names(["perceived"]).vectors
(True, False)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import pygame
import pymunk

from playground.view.arrows import (
    G0,
    MIN_ARROW_PX,
    PeakHold,
    ScreenArrow,
    arrow_length,
    body_size,
    spread,
    weight_pixels,
)
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
from playground.world.world import World

__all__ = ["OVERLAY_KEYS", "Overlay", "Painter", "roles_of"]

Vec = tuple[float, float]

UP_WEIGHTS = 0.6  # the perceived-up unit arrow is this many weights long
COMPASS_PX = 30  # px: radius of the world-up compass
ROLL_SHOWN_RAD = math.radians(0.5)  # the compass appears once the camera rolls this far
NULLIFY_RING_M = 1.2  # m: radius of the ring around the body X would nullify …
NULLIFY_RING_MIN_PX = 14.0  # px: … at least this big on screen
LABEL_MIN_N = 0.5  # N: joint forces smaller than this are not labelled
LABEL_FONT_PX = 18  # px: size of the joint-force labels

OVERLAY_KEYS: dict[int, tuple[str, str]] = {
    pygame.K_v: ("vectors", "forces"),
    pygame.K_1: ("contacts", "contacts"),
    pygame.K_2: ("joints", "joint forces"),
    pygame.K_3: ("reactions", "reactions"),
    pygame.K_4: ("perceived", "perceived g"),
    pygame.K_5: ("compass", "compass"),
}
"""Key → (overlay field, label on the overlay panel)."""


@dataclass(frozen=True, slots=True)
class Overlay:
    """Which overlays are on.

    Attributes:
        vectors: support (raw, peak-held, and filtered), gravity and the controller's forces.
        contacts: each contact's points, normal force and friction force.
        joints: each joint's force at its anchor (joints themselves are always drawn).
        reactions: the reaction of hover, drive, grip and push on the body they act on.
        perceived: the perceived gravity and the perceived up.
        compass: the world-up compass and roll angle, while the camera rolls.
    """

    vectors: bool = True
    contacts: bool = False
    joints: bool = False
    reactions: bool = False
    perceived: bool = False
    compass: bool = True

    def toggled(self, name: str) -> Overlay:
        """This overlay with ``name`` switched."""
        return dataclasses.replace(self, **{name: not getattr(self, name)})

    @classmethod
    def from_names(cls, names: Iterable[str]) -> Overlay:
        """Exactly the overlays named on (the compass is on unless turned off by the keys)."""
        on = set(names)
        fields = [f.name for f in dataclasses.fields(cls)]
        unknown = on.difference(fields)
        if unknown:
            raise ValueError(f"overlays: unknown {sorted(unknown)}, expected some of {fields}")
        return cls(**{f: (f in on) or f == "compass" for f in fields})


def roles_of(show: Any) -> dict[str, str]:
    """Actor name → role (player, enemy, other) of a :class:`~playground.view.app.Show`: the
    level's ``role`` when it gives one; otherwise the show's player is the player and any other
    actor is other."""
    roles: dict[str, str] = {}
    actors = getattr(getattr(getattr(show, "scene", None), "level", None), "actors", None) or ()
    declared = {a.name: a.role for a in actors if getattr(a, "role", None) is not None}
    for name in show.controllers:
        roles[name] = declared.get(name, "player" if name == show.player else "other")
    return roles


class Painter:
    """Draws the world and the overlays that are on, and keeps the per-step peaks."""

    def __init__(self, overlay: Overlay | None = None) -> None:
        self.overlay = overlay if overlay is not None else Overlay()
        self.hold = PeakHold()
        self.drawn: set[str] = set()
        self._legend: list[LegendEntry] = []
        self.scale_px = 0.0
        self.scale_body: str | None = None
        self.scale_newtons = 0.0
        self.compass_rect: pygame.Rect | None = None
        """Where the compass was drawn last frame (None: not drawn)."""
        self.compass_centre: Vec = (0.0, 0.0)
        self.nullify_px = 0.0
        """Radius of the nullify ring drawn last frame, px (0: none)."""
        self._label_font: pygame.font.Font | None = None

    def sample(self, world: World) -> None:
        """Call after every physics step (feeds the peak hold)."""
        self.hold.sample(world)

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
        for body in world.solver.bodies:
            name = world.name_of(body)
            if name is None:
                continue
            w_px = weight_pixels(body_size(body), cam.zoom)
            if name == focus or self.scale_body is None:
                self.scale_body, self.scale_px = name, w_px
                self.scale_newtons = body.mass * G0
            ctrl = controllers.get(name)
            if ov.vectors:
                arrows += self._vectors(cam, world, name, body, ctrl, peaks.get(name), w_px)
            if ov.perceived:
                arrows += self._perceived(cam, world, name, body, w_px)
            if ov.contacts:
                arrows += self._contacts(surf, cam, world, body, w_px)
            if ov.joints:
                arrows += self._joint_forces(surf, cam, world, name, body, w_px)
            if ov.reactions and ctrl is not None:
                arrows += self._reactions(cam, ctrl, body, w_px)
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

    def _arrow(
        self, cam: Camera, at: Vec, force: Vec, mass: float, w_px: float, kind: str, width: int = 2
    ) -> list[ScreenArrow]:
        n = math.hypot(*force)
        length = arrow_length(n, mass, w_px)
        if not math.isfinite(n) or length < MIN_ARROW_PX:
            return []
        sx, sy = cam.vector((force[0] / n, force[1] / n))
        k = length / math.hypot(sx, sy)
        return [ScreenArrow(cam.to_screen(at), (sx * k, sy * k), kind, width)]

    def _vectors(
        self,
        cam: Camera,
        world: World,
        name: str,
        body: pymunk.Body,
        ctrl: Any,
        peak: Vec | None,
        w_px: float,
    ) -> list[ScreenArrow]:
        c = body.local_to_world(body.center_of_gravity)
        at = (c.x, c.y)
        m = body.mass
        g = world.gravity_at(name)
        pg = world.perceived_gravity(name)
        raw = peak if peak is not None else world.forces(name).support
        out = self._arrow(cam, at, (m * g[0], m * g[1]), m, w_px, "gravity")
        out += self._arrow(cam, at, (-m * pg[0], -m * pg[1]), m, w_px, "support_filtered", 5)
        out += self._arrow(cam, at, raw, m, w_px, "support")
        forces, origins = _controller_forces(ctrl)
        pushed = getattr(ctrl, "pushed", None)
        for kind, f in forces.items():
            arrows = self._arrow(cam, origins.get(kind, at), f, m, w_px, kind)
            if kind == "push" and pushed is not None:
                # What it pushes pushes back: drawn pressing onto the point it pushes at (its
                # head under a crate), not from its centre down through the floor.
                arrows = [_ending_at(a) for a in self._arrow(cam, pushed[0], f, m, w_px, kind)]
            out += arrows
        return out

    def _perceived(
        self, cam: Camera, world: World, name: str, body: pymunk.Body, w_px: float
    ) -> list[ScreenArrow]:
        c = body.local_to_world(body.center_of_gravity)
        m = body.mass
        pg = world.perceived_gravity(name)
        out = self._arrow(cam, (c.x, c.y), (m * pg[0], m * pg[1]), m, w_px, "perceived", 3)
        ux, uy = world.perceived_up(name)
        if math.isfinite(ux) and math.isfinite(uy) and (ux, uy) != (0.0, 0.0):
            sx, sy = cam.vector((ux, uy))
            k = UP_WEIGHTS * w_px / math.hypot(sx, sy)
            out.append(ScreenArrow(cam.to_screen((c.x, c.y)), (sx * k, sy * k), "up", 1))
        return out

    def _contacts(
        self, surf: pygame.Surface, cam: Camera, world: World, body: pymunk.Body, w_px: float
    ) -> list[ScreenArrow]:
        """Per contact (a touching pair): its points, and at their middle the normal and friction
        force the other body put on this one this step."""
        h = world.config.dt / world.config.substeps
        found: list[tuple[list[Vec], Vec, Vec]] = []

        def visit(arb: pymunk.Arbiter) -> None:
            pts = [(p.point_a.x, p.point_a.y) for p in arb.contact_point_set.points]
            if not pts:
                return
            j = arb.total_impulse
            n = arb.normal
            # Walking a body's arbiters, pymunk puts the body's own shape first and gives the
            # impulse that shape received (a crate resting on a floor reads +m·g·h upward).
            fx, fy = j.x / h, j.y / h
            fn = fx * n.x + fy * n.y
            found.append((pts, (fn * n.x, fn * n.y), (fx - fn * n.x, fy - fn * n.y)))

        body.each_arbiter(visit)
        out: list[ScreenArrow] = []
        m = body.mass
        for pts, normal, friction in found:
            for p in pts:
                pygame.draw.circle(surf, COLOURS["contact"], cam.to_screen(p), 4)
            self.drawn.add("contact")
            mid = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
            # A contact pushes: its arrows end where it acts, coming from the other body's side
            # (a crate's load presses down onto a head, a floor pushes up into the feet).
            for force, kind in ((normal, "normal"), (friction, "friction")):
                out += [_ending_at(a) for a in self._arrow(cam, mid, force, m, w_px, kind, 3)]
        return out

    def _joint_forces(
        self,
        surf: pygame.Surface,
        cam: Camera,
        world: World,
        name: str,
        body: pymunk.Body,
        w_px: float,
    ) -> list[ScreenArrow]:
        """Each joint on a tracked body: the force on it at its anchor (the reverse-integration
        reading when the joint is the only thing touching it, or the contact split's joint part),
        labelled with the joint's own |impulse|/h."""
        h = world.config.dt / world.config.substeps
        reading = world.forces(name)
        touching: list[int] = []
        body.each_arbiter(lambda arb: touching.append(1))
        vector = reading.constraint
        if not all(math.isfinite(v) for v in vector):
            vector = reading.engine if not touching else (math.nan, math.nan)
        out: list[ScreenArrow] = []
        for c in body.constraints:
            which = "a" if c.a is body else "b"
            local = getattr(c, "anchor_" + which, None)
            if local is None:
                continue
            p = body.local_to_world(local)
            magnitude = abs(c.impulse) / h
            if all(math.isfinite(v) for v in vector) and len(body.constraints) == 1:
                out += self._arrow(cam, (p.x, p.y), vector, body.mass, w_px, "joint_force", 3)
            if magnitude >= LABEL_MIN_N:
                if self._label_font is None:
                    self._label_font = pygame.font.Font(None, LABEL_FONT_PX)
                text = f"{magnitude:.0f} N"
                label = self._label_font.render(text, True, COLOURS["joint_force"])
                sp = cam.to_screen((p.x, p.y))
                surf.blit(label, (sp[0] + 8, sp[1] - 16))
                self.drawn.add("joint_force")
        return out

    def _reactions(
        self, cam: Camera, ctrl: Any, body: pymunk.Body, w_px: float
    ) -> list[ScreenArrow]:
        """The opposite of the controller's hover and drive on the ground it stands on, of its
        grip on the body it holds and of its push on the body it pushes, where each acts (drawn
        on dynamic bodies, the only ones a force moves)."""
        out: list[ScreenArrow] = []
        forces = getattr(ctrl, "last_forces", None)
        if forces is None:
            return out
        m = body.mass
        probe = getattr(ctrl, "probe", None)
        if probe is not None and probe.body.body_type == pymunk.Body.DYNAMIC:
            f = (forces.hover[0] + forces.drive[0], forces.hover[1] + forces.drive[1])
            out += self._arrow(cam, probe.point, (-f[0], -f[1]), m, w_px, "reaction", 4)
        joint = getattr(ctrl, "joint", None)
        if joint is not None and joint.b.body_type == pymunk.Body.DYNAMIC:
            p = joint.b.local_to_world(joint.anchor_b)
            g = forces.grip
            out += self._arrow(cam, (p.x, p.y), (-g[0], -g[1]), m, w_px, "reaction", 4)
        pushed = getattr(ctrl, "pushed", None)
        if pushed is not None:
            at, f = pushed
            out += self._arrow(cam, at, f, m, w_px, "reaction", 4)
        return out

    # -- what is on screen -----------------------------------------------------------------------

    def legend(self) -> list[LegendEntry]:
        """Legend entries for what the last :meth:`draw` put on screen, in a fixed order."""
        catalogue = (
            ("support_filtered", "support, filtered", "thick"),
            ("support", "support, raw (frame peak)", "line"),
            ("gravity", "gravity m·g", "line"),
            ("hover", "hover spring", "line"),
            ("drive", "drive", "line"),
            ("grip", "grip", "line"),
            ("grip_arm", "hand (grip joint)", "thick"),
            ("push", "push on itself", "line"),
            ("contact", "contact point", "dot"),
            ("normal", "contact normal", "line"),
            ("friction", "contact friction", "line"),
            ("joint_force", "joint force", "line"),
            ("reaction", "reaction on ground", "thick"),
            ("perceived", "perceived gravity", "line"),
            ("up", "perceived up", "line"),
            ("nullify", "X nullifies this", "ring"),
            ("mouse", "mouse pull (applied)", "line"),
        )
        entries = [
            LegendEntry("hand" if k == "grip_arm" else k, text, swatch)
            for k, text, swatch in catalogue
            if k in self.drawn
        ]
        if any(k in self.drawn for k, _, _ in catalogue[:8]) and self.scale_body is not None:
            entries.append(
                LegendEntry(
                    "text",
                    f"m·g of {self.scale_body} ({self.scale_newtons:.0f} N)",
                    "scale",
                    self.scale_px,
                )
            )
        return entries

    def draw_legend(
        self, surf: pygame.Surface, font: pygame.font.Font, topright: Vec
    ) -> pygame.Rect:
        """The legend of what is on screen, its top-right corner at ``topright``."""
        return draw_legend(surf, font, self.legend(), topright)

    def draw_panel(
        self, surf: pygame.Surface, font: pygame.font.Font, topright: Vec
    ) -> pygame.Rect:
        """The overlay toggles with their keys, on or off."""
        line = font.get_linesize()
        items = [
            (pygame.key.name(k).upper(), label, bool(getattr(self.overlay, field)))
            for k, (field, label) in OVERLAY_KEYS.items()
        ]
        width = max(font.size(f"{k}  {label}")[0] for k, label, _ in items) + 26
        rect = pygame.Rect(0, int(topright[1]), width, line * len(items) + 8)
        rect.right = int(topright[0])
        panel = pygame.Surface(rect.size, pygame.SRCALPHA)
        panel.fill((0, 0, 0, 190))
        surf.blit(panel, rect.topleft)
        for i, (key, label, on) in enumerate(items):
            y = rect.y + 4 + i * line
            colour = COLOURS["text"] if on else COLOURS["dim"]
            box = pygame.Rect(rect.x + 6, y + line // 2 - 5, 10, 10)
            pygame.draw.rect(surf, colour, box, 0 if on else 1)
            surf.blit(font.render(f"{key}  {label}", True, colour), (rect.x + 22, y))
        return rect

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


def _ending_at(a: ScreenArrow) -> ScreenArrow:
    """The same arrow moved back along itself so that its tip is where it started."""
    return ScreenArrow((a.start[0] - a.d[0], a.start[1] - a.d[1]), a.d, a.kind, a.width)


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


def _controller_forces(ctrl: Any) -> tuple[dict[str, Vec], dict[str, Vec]]:
    """The controller's last hover, drive, grip and push forces (N) if it reports them, and where
    they act (m): hover and drive at the probe's ground point, grip at the hand."""
    forces = getattr(ctrl, "last_forces", None)
    out: dict[str, Vec] = {}
    at: dict[str, Vec] = {}
    if forces is None:
        return out, at
    for kind in ("hover", "drive", "grip", "push"):
        v = getattr(forces, kind, None)
        if v is not None:
            out[kind] = (float(v[0]), float(v[1]))
    probe = getattr(ctrl, "probe", None)
    if probe is not None:
        at["hover"] = at["drive"] = (float(probe.point[0]), float(probe.point[1]))
    joint = getattr(ctrl, "joint", None)
    if joint is not None:
        a = joint.a.local_to_world(joint.anchor_a)
        at["grip"] = (a.x, a.y)
    return out, at


def nearest(here: Vec, candidates: Sequence[tuple[str, Vec]]) -> str | None:
    """The name of the candidate (name, position m) nearest ``here`` (m), or None.

    >>> nearest((0.0, 0.0), [("a", (3.0, 0.0)), ("b", (1.0, 1.0))])
    'b'
    """
    best: tuple[float, str] | None = None
    for name, p in candidates:
        d = math.hypot(p[0] - here[0], p[1] - here[1])
        if best is None or d < best[0]:
            best = (d, name)
    return best[1] if best is not None else None
