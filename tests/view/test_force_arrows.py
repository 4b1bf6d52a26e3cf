"""One body's arrows: an arrow is one weight long per weight of force and points along the force
on screen; a force too small to see gives no arrow; a pushing force is drawn ending where it acts;
the controller's forces are read where it reports them."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from playground.view.arrows import G0, MIN_ARROW_PX, ScreenArrow
from playground.view.camera import Camera
from playground.view.force_arrows import arrow, controller_forces, ending_at

W_PX = 60.0  # px: one weight on screen in these tests
TOL_PX = 1e-9  # px: the arrow's length is computed, not drawn: only rounding differs


def test_one_weight_is_w_px_long_and_points_the_way_of_the_force() -> None:
    cam = Camera(size=(400, 300), pixels_per_metre=50.0, centre=(0.0, 0.0))
    (a,) = arrow(cam, (0.0, 0.0), (10.0 * G0, 0.0), 10.0, W_PX, "gravity")
    assert math.hypot(*a.d) == pytest.approx(W_PX, abs=TOL_PX)
    assert a.d[0] > 0.0 and a.d[1] == pytest.approx(0.0, abs=TOL_PX)
    (up,) = arrow(cam, (0.0, 0.0), (0.0, 10.0 * G0), 10.0, W_PX, "gravity")
    assert up.d[1] < 0.0, "world up is screen up"
    assert a.start == cam.to_screen((0.0, 0.0)) and a.kind == "gravity" and a.width == 2


def test_a_force_too_small_or_not_finite_draws_nothing() -> None:
    cam = Camera(size=(400, 300))
    tiny = 0.5 * MIN_ARROW_PX / W_PX * 10.0 * G0
    assert arrow(cam, (0.0, 0.0), (tiny, 0.0), 10.0, W_PX, "support") == []
    assert arrow(cam, (0.0, 0.0), (math.nan, 0.0), 10.0, W_PX, "support") == []


def test_ending_at_puts_the_tip_where_the_arrow_started() -> None:
    a = ScreenArrow((100.0, 50.0), (30.0, -40.0), "normal", 3, 250.0, "crate")
    b = ending_at(a)
    assert (b.start[0] + b.d[0], b.start[1] + b.d[1]) == a.start
    assert (b.d, b.kind, b.width, b.newtons, b.body) == (a.d, a.kind, a.width, 250.0, "crate")


def test_controller_forces_act_at_the_probe_point() -> None:
    assert controller_forces(SimpleNamespace()) == ({}, {})
    forces = SimpleNamespace(hover=(0.0, 700.0), drive=(50.0, 0.0), grip=None, push=(1.0, 2.0))
    ctrl = SimpleNamespace(last_forces=forces, probe=SimpleNamespace(point=(1.0, -0.5)))
    out, at = controller_forces(ctrl)
    assert out == {"hover": (0.0, 700.0), "drive": (50.0, 0.0), "push": (1.0, 2.0)}
    assert at == {"hover": (1.0, -0.5), "drive": (1.0, -0.5)}


def test_a_joint_removed_from_the_space_is_no_longer_labelled() -> None:
    """Law: the joint overlay draws the joints in the world, not the ones pymunk still lists on
    the body after ``space.remove`` (defect: a released grip's "687 N" stayed at the old hand)."""
    import pygame
    import pymunk

    from playground import World
    from playground.view.force_arrows import joint_forces, joints_on

    w = World()
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.0))
    w.track("crate")
    crate = w.body("crate")
    joint = pymunk.PivotJoint(w.space.static_body, crate, (0.0, 0.5))
    w.space.add(joint)
    w.step()
    cam = Camera(size=(200, 200), pixels_per_metre=50.0)
    font = pygame.font.Font(None, 18)
    held: set[str] = set()
    joint_forces(pygame.Surface((200, 200)), cam, w, "crate", crate, W_PX, held, lambda: font)
    assert joints_on(w, crate) == [joint] and held == {"joint_force"}
    w.space.remove(joint)
    w.step()
    assert joint in crate.constraints, "pymunk still lists it: the overlay must not"
    drawn: set[str] = set()
    surf = pygame.Surface((200, 200))
    assert joint_forces(surf, cam, w, "crate", crate, W_PX, drawn, lambda: font) == []
    assert joints_on(w, crate) == [] and drawn == set()
    assert not pygame.surfarray.array3d(surf).any(), "no label drawn"
