"""The arrows of one tracked body, one function per overlay: its forces (gravity, support raw
and filtered, the controller's hover, drive, grip and push), its perceived gravity and up, its
contacts' normal and friction forces, its joints' forces, and the reactions its controller puts on
what it stands on, holds or pushes. Every arrow is one weight m·g long per ``w_px`` pixels
(:func:`playground.view.arrows.arrow_length`); the caller spreads and draws them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import pygame
import pymunk

from playground.vec import Vec
from playground.view.arrows import MIN_ARROW_PX, ScreenArrow, arrow_length, body_size
from playground.view.camera import Camera
from playground.view.draw import COLOURS
from playground.world.world import World

__all__ = [
    "arrow",
    "contacts",
    "controller_forces",
    "ending_at",
    "joint_forces",
    "joints_on",
    "off_body",
    "perceived",
    "reactions",
    "support_point",
    "vectors",
]

UP_WEIGHTS = 0.6  # the perceived-up unit arrow is this many weights long
LABEL_MIN_N = 0.5  # N: joint forces smaller than this are not labelled
LABEL_FONT_PX = 18  # px: size of the joint-force labels


def arrow(
    cam: Camera,
    at: Vec,
    force: Vec,
    mass: float,
    w_px: float,
    kind: str,
    width: int = 2,
    body: str = "",
) -> list[ScreenArrow]:
    """The arrow of ``force`` (N) acting at ``at`` (m) on a body of ``mass`` (kg) named
    ``body``, one weight per ``w_px`` px (none if too short to see or not finite)."""
    n = math.hypot(*force)
    length = arrow_length(n, mass, w_px)
    if not math.isfinite(n) or length < MIN_ARROW_PX:
        return []
    sx, sy = cam.vector((force[0] / n, force[1] / n))
    k = length / math.hypot(sx, sy)
    return [ScreenArrow(cam.to_screen(at), (sx * k, sy * k), kind, width, n, body)]


def support_point(ctrl: Any, body: pymunk.Body) -> Vec:
    """Where the support acts on an actor (m): at the hand while it holds on, at the hover's
    foot (the probe's ground point) while it finds ground, else at its centre of gravity."""
    joint = getattr(ctrl, "joint", None)
    if joint is not None:
        a = joint.a.local_to_world(joint.anchor_a)
        return (a.x, a.y)
    probe = getattr(ctrl, "probe", None)
    if probe is not None:
        return (float(probe.point[0]), float(probe.point[1]))
    c = body.local_to_world(body.center_of_gravity)
    return (c.x, c.y)


def off_body(a: ScreenArrow, radius_px: float) -> ScreenArrow:
    """The arrow moved along itself by ``radius_px`` (px): it starts at the body's outline
    instead of over the body (a body small on screen stays visible under its arrows)."""
    n = math.hypot(*a.d)
    if n <= 0.0:
        return a
    k = radius_px / n
    return replace(a, start=(a.start[0] + a.d[0] * k, a.start[1] + a.d[1] * k))


def vectors(
    cam: Camera,
    world: World,
    name: str,
    body: pymunk.Body,
    ctrl: Any,
    peak: Vec | None,
    w_px: float,
    *,
    bundled: bool = False,
) -> list[ScreenArrow]:
    """The body's forces, each from where it acts: gravity at its centre of gravity, the
    support (raw and filtered) at its hand or foot, hover and drive at the foot, grip at the
    hand; its push on what it pushes at the point it pushes. ``bundled`` (a body small on
    screen): only gravity and the support (filtered and raw), which sums the rest, starting at
    the body's outline so the body stays visible."""
    c = body.local_to_world(body.center_of_gravity)
    at = (c.x, c.y)
    m = body.mass
    g = world.gravity_at(name)
    pg = world.perceived_gravity(name)
    raw = peak if peak is not None else world.forces(name).support
    if bundled:
        r = 0.5 * cam.pixels(body_size(body))
        out = arrow(cam, at, (m * g[0], m * g[1]), m, w_px, "gravity", 2, name)
        out += arrow(cam, at, (-m * pg[0], -m * pg[1]), m, w_px, "support_filtered", 5, name)
        out += arrow(cam, at, raw, m, w_px, "support", 2, name)
        return [off_body(a, r) for a in out]
    foot = support_point(ctrl, body) if ctrl is not None else at
    out = arrow(cam, at, (m * g[0], m * g[1]), m, w_px, "gravity", 2, name)
    out += arrow(cam, foot, (-m * pg[0], -m * pg[1]), m, w_px, "support_filtered", 5, name)
    out += arrow(cam, foot, raw, m, w_px, "support", 2, name)
    forces, origins = controller_forces(ctrl)
    pushed = getattr(ctrl, "pushed", None)
    for kind, f in forces.items():
        if kind == "push":
            # Drawn as what it does: the push on the body it pushes, from the point it pushes
            # at (its head under a crate, pointing into the crate). Its recoil on the actor
            # itself is in the support.
            if pushed is not None:
                out += arrow(cam, pushed[0], pushed[1], m, w_px, "push", 2, name)
            continue
        out += arrow(cam, origins.get(kind, at), f, m, w_px, kind, 2, name)
    return out


def perceived(
    cam: Camera, world: World, name: str, body: pymunk.Body, w_px: float
) -> list[ScreenArrow]:
    c = body.local_to_world(body.center_of_gravity)
    m = body.mass
    pg = world.perceived_gravity(name)
    out = arrow(cam, (c.x, c.y), (m * pg[0], m * pg[1]), m, w_px, "perceived", 3)
    ux, uy = world.perceived_up(name)
    if math.isfinite(ux) and math.isfinite(uy) and (ux, uy) != (0.0, 0.0):
        sx, sy = cam.vector((ux, uy))
        k = UP_WEIGHTS * w_px / math.hypot(sx, sy)
        out.append(ScreenArrow(cam.to_screen((c.x, c.y)), (sx * k, sy * k), "up", 1))
    return out


def contacts(
    surf: pygame.Surface,
    cam: Camera,
    world: World,
    body: pymunk.Body,
    w_px: float,
    drawn: set[str],
    name: str = "",
    *,
    forces: bool = True,
) -> list[ScreenArrow]:
    """Per contact (a touching pair): its points, and (``forces``) at their middle the normal and
    friction force the other body put on this one this step."""
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
        drawn.add("contact")
        if not forces:
            continue
        mid = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        # A contact pushes: its arrows end where it acts, coming from the other body's side
        # (a crate's load presses down onto a head, a floor pushes up into the feet).
        for force, kind in ((normal, "normal"), (friction, "friction")):
            out += [ending_at(a) for a in arrow(cam, mid, force, m, w_px, kind, 3, name)]
    return out


def joint_forces(
    surf: pygame.Surface,
    cam: Camera,
    world: World,
    name: str,
    body: pymunk.Body,
    w_px: float,
    drawn: set[str],
    label_font: Callable[[], pygame.font.Font],
) -> list[ScreenArrow]:
    """Each joint on a tracked body: the force on it at its anchor (the reverse-integration
    reading when the joint is the only thing touching it, or the contact split's joint part),
    labelled with the joint's own |impulse|/h."""
    h = world.config.dt / world.config.substeps
    reading = world.forces(name)
    vector = reading.constraint
    if not all(math.isfinite(v) for v in vector):
        # Without the contact split: what the engine did minus what the contacts did (their
        # impulses are exact with collision persistence 1, see docs/design.md).
        touching: list[Vec] = []
        body.each_arbiter(lambda arb: touching.append((arb.total_impulse.x, arb.total_impulse.y)))
        jx = sum(j[0] for j in touching) / h
        jy = sum(j[1] for j in touching) / h
        vector = (reading.engine[0] - jx, reading.engine[1] - jy)
    out: list[ScreenArrow] = []
    joints = joints_on(world, body)
    for c in joints:
        which = "a" if c.a is body else "b"
        local = getattr(c, "anchor_" + which, None)
        if local is None:
            continue
        p = body.local_to_world(local)
        magnitude = abs(c.impulse) / h
        # Rotary limits, gears and motors only turn: the one joint with anchors carries it all.
        pushing = [j for j in joints if hasattr(j, "anchor_a")]
        if all(math.isfinite(v) for v in vector) and pushing == [c]:
            out += arrow(cam, (p.x, p.y), vector, body.mass, w_px, "joint_force", 3, name)
        if magnitude >= LABEL_MIN_N:
            text = f"{magnitude:.0f} N"
            label = label_font().render(text, True, COLOURS["joint_force"])
            sp = cam.to_screen((p.x, p.y))
            surf.blit(label, (sp[0] + 8, sp[1] - 16))
            drawn.add("joint_force")
    return out


def joints_on(world: World, body: pymunk.Body) -> list[pymunk.Constraint]:
    """The joints in the world that act on ``body``. Walks the space's constraints:
    ``body.constraints`` keeps a joint after ``space.remove(joint)`` (pymunk 7.3.1), so a
    released grip would still be drawn."""
    return [c for c in world.space.constraints if c.a is body or c.b is body]


def reactions(cam: Camera, ctrl: Any, body: pymunk.Body, w_px: float) -> list[ScreenArrow]:
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
        out += arrow(cam, probe.point, (-f[0], -f[1]), m, w_px, "reaction", 4)
    joint = getattr(ctrl, "joint", None)
    if joint is not None and joint.b.body_type == pymunk.Body.DYNAMIC:
        p = joint.b.local_to_world(joint.anchor_b)
        g = forces.grip
        out += arrow(cam, (p.x, p.y), (-g[0], -g[1]), m, w_px, "reaction", 4)
    pushed = getattr(ctrl, "pushed", None)
    if pushed is not None:
        at, f = pushed
        out += arrow(cam, at, f, m, w_px, "reaction", 4)
    return out


def ending_at(a: ScreenArrow) -> ScreenArrow:
    """The same arrow moved back along itself so that its tip is where it started."""
    return replace(a, start=(a.start[0] - a.d[0], a.start[1] - a.d[1]))


def controller_forces(ctrl: Any) -> tuple[dict[str, Vec], dict[str, Vec]]:
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
