"""The mouse on the world: a press picks the body under the cursor (a click selects it), moving on
drags a dynamic body by the point pressed through the mouse spring, releasing lets go; and what
the view shows of it: the selected body's marker, the spring's band and force arrow, and the
HUD's lines about the selected body.
"""

from __future__ import annotations

import math

import pygame
import pymunk

from playground.controller.mouse import Grab
from playground.vec import Vec
from playground.view.arrows import MIN_ARROW_PX, arrow_length, body_size, weight_pixels
from playground.view.camera import Camera
from playground.view.draw import COLOURS, draw_arrow
from playground.world.world import World

__all__ = ["DRAG_START_PX", "PICK_PX", "Pointer", "draw_mouse", "focus_notes"]

DRAG_START_PX = 4.0  # px: a press that moves farther than this drags; otherwise it is a click
PICK_PX = 6.0  # px: a click this close to a body's outline picks it
MOUSE_COLOUR = COLOURS["mouse"]


class Pointer:
    """The left button's press and drag, in screen pixels; never touches the world."""

    def __init__(self) -> None:
        self.press: tuple[Vec, str | None, Vec] | None = None
        """Where the button went down (px), the body picked there and the point of it (m, in the
        body's frame); None while the button is up."""
        self.cursor: Vec | None = None
        """The cursor while dragging, px (None: not dragging)."""

    def down(self, pos: Vec, world: World, camera: Camera) -> str | None:
        """The button goes down at ``pos``: the body picked there (None: empty space)."""
        at = camera.to_world(pos)
        name = world.body_at(at, PICK_PX / camera.zoom)
        anchor: Vec = (0.0, 0.0)
        if name is not None:
            local = world.body(name).world_to_local(at)
            anchor = (local.x, local.y)
        self.press = (pos, name, anchor)
        return name

    def move(self, pos: Vec, world: World, camera: Camera) -> Grab | None:
        """The cursor moves to ``pos``: the grab it drags with, or None (no press, not far enough
        yet, or nothing dynamic picked)."""
        press = self.press
        if press is None:
            return None
        start, name, anchor = press
        if self.cursor is None and math.dist(start, pos) <= DRAG_START_PX:
            return None
        if name is None or world.body(name).body_type != pymunk.Body.DYNAMIC:
            return None
        self.cursor = pos
        return Grab(name, anchor, camera.to_world(pos))

    def up(self) -> None:
        """The button goes up: no press, no drag."""
        self.press = None
        self.cursor = None


def draw_mouse(
    surf: pygame.Surface,
    cam: Camera,
    world: World,
    selected: str | None,
    grab: Grab | None,
    pull: tuple[Vec, Vec] | None,
) -> bool:
    """The selected body's marker, and the mouse spring: a band from the grabbed point to the
    cursor and its force arrow (the very force put in the ledger). Returns whether the arrow was
    drawn."""
    if selected is not None and selected in world.names:
        body = world.body(selected)
        c = body.local_to_world(body.center_of_gravity)
        pygame.draw.circle(surf, MOUSE_COLOUR, cam.to_screen((c.x, c.y)), 5, 2)
    if grab is None or grab.body not in world.names:
        return False
    body = world.body(grab.body)
    p = body.local_to_world(grab.anchor)
    start = cam.to_screen((p.x, p.y))
    pygame.draw.line(surf, MOUSE_COLOUR, start, cam.to_screen(grab.target), 1)
    pygame.draw.circle(surf, MOUSE_COLOUR, start, 4)
    n = math.hypot(*pull[0]) if pull is not None else 0.0
    length = arrow_length(n, body.mass, weight_pixels(body_size(body), cam.zoom))
    if pull is not None and math.isfinite(n) and length >= MIN_ARROW_PX:
        sx, sy = cam.vector((pull[0][0] / n, pull[0][1] / n))
        k = length / math.hypot(sx, sy)
        draw_arrow(surf, MOUSE_COLOUR, cam.to_screen(pull[1]), (sx * k, sy * k), 3)
        return True
    return False


def focus_notes(
    world: World, name: str | None, grab: Grab | None, pull: tuple[Vec, Vec] | None
) -> list[str]:
    """HUD lines for the selected body ``name``: its name, support and applied forces, and the
    mouse's pull (N) while something is grabbed."""
    if name is None or name not in world.names:
        return []
    try:
        reading = world.forces(name)
    except KeyError:
        return []
    lines = [
        f"selected: {name} (click empty space: player)",
        f"  support {math.hypot(*reading.support):7.1f} N   "
        f"applied {math.hypot(*reading.applied):7.1f} N",
    ]
    if pull is not None and grab is not None:
        lines.append(f"  mouse ({grab.body}) {math.hypot(*pull[0]):7.1f} N")
    return lines
