"""The mouse on the world: a press picks the body under the cursor; moving no farther than
``DRAG_START_PX`` is still a click; farther drags a dynamic body by the very point pressed; a
static body is picked but never dragged; releasing forgets the press."""

from __future__ import annotations

import pymunk
import pytest

from playground import World
from playground.view.camera import Camera
from playground.view.pointer import DRAG_START_PX, Pointer, focus_notes


def scene() -> tuple[World, Camera]:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    wall = pymunk.Body(body_type=pymunk.Body.STATIC)
    wall.position = (3.0, 1.0)
    w.add("wall", wall, pymunk.Poly.create_box(wall, (0.5, 2.0)))
    return w, Camera(size=(640, 360), pixels_per_metre=60.0, centre=(0.0, 1.0))


def test_a_press_picks_and_a_move_past_the_threshold_drags_by_the_pressed_point() -> None:
    world, cam = scene()
    pointer = Pointer()
    start = cam.to_screen((0.25, 0.75))
    assert pointer.down(start, world, cam) == "crate"
    near = (start[0] + DRAG_START_PX, start[1])
    assert pointer.move(near, world, cam) is None, "within the threshold it is a click"
    far = (start[0], start[1] - 3 * DRAG_START_PX)
    grab = pointer.move(far, world, cam)
    assert grab is not None and grab.body == "crate"
    assert grab.anchor == pytest.approx((0.25, 0.25))
    assert grab.target == pytest.approx(cam.to_world(far))
    assert pointer.cursor == far
    pointer.up()
    assert pointer.press is None and pointer.cursor is None
    assert pointer.move(far, world, cam) is None


def test_empty_space_and_static_bodies_are_never_dragged() -> None:
    world, cam = scene()
    pointer = Pointer()
    sky = cam.to_screen((5.0, 4.0))
    assert pointer.down(sky, world, cam) is None
    assert pointer.move((sky[0], sky[1] - 50.0), world, cam) is None
    pointer.up()
    wall = cam.to_screen((3.0, 1.0))
    assert pointer.down(wall, world, cam) == "wall"
    assert pointer.move((wall[0], wall[1] - 50.0), world, cam) is None


def test_focus_notes_name_the_selected_body_only_when_there_is_one() -> None:
    world, _ = scene()
    world.track("crate")
    world.step()
    assert focus_notes(world, None, None, None) == []
    assert focus_notes(world, "ghost", None, None) == []
    lines = focus_notes(world, "crate", None, None)
    assert lines[0].startswith("selected: crate") and "support" in lines[1]
