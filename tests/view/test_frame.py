"""One frame's picture: every panel inside the window and listed in the HUD's rects; the compact
picture leaves out the overlay panel and the notes, the full one shows them; the help is drawn
over everything when asked for."""

from __future__ import annotations

import pygame

from playground import World
from playground.view.app import App
from playground.view.draw import COLOURS
from playground.view.keyboard import CONTROLS
from playground.view.session import Show

SIZE = (640, 360)


def app() -> App:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    w.track("crate")
    show = Show(name="f", world=w, title="Frame", description="A crate on a floor.")
    a = App(lambda _: show, "f", size=SIZE)
    a.run_frames(10)
    return a


def test_the_full_frame_has_the_overlay_panel_and_every_panel_fits() -> None:
    a = app()
    surf = a.render()
    assert surf is a.surface
    window = surf.get_rect()
    assert all(window.contains(r) for r in a.hud.rects)
    overlay_panel = [r for r in a.hud.rects if r.right == SIZE[0] - 8 and r.top == 8]
    assert overlay_panel and overlay_panel[0].width > 0


def test_the_compact_frame_leaves_the_overlay_panel_out() -> None:
    a = app()
    a.compact = True
    a.render()
    top_right = [r for r in a.hud.rects if r.right == SIZE[0] - 8 and r.top == 8]
    assert all(r.width == 0 for r in top_right)


def test_help_is_drawn_over_the_frame() -> None:
    a = app()
    plain = pygame.surfarray.array3d(a.render()).copy()
    a.show_help = True
    helped = pygame.surfarray.array3d(a.render())
    assert (plain != helped).any()
    text = tuple(COLOURS["text"])
    assert (helped == text).all(axis=2).sum() > (plain == text).all(axis=2).sum()


def test_the_frame_is_drawn_from_its_picture_alone() -> None:
    """Law: ``draw_frame`` draws what the :class:`Picture` says: the same picture gives the same
    pixels after the app's own state changed, and a picture that asks for the help differs."""
    import dataclasses

    from playground.view.frame import Drawers, draw_frame

    a = app()
    picture = a.picture()
    drawers = Drawers(a.painter, a.hud, a.tuning, a.small, a.tiny)
    first = pygame.surfarray.array3d(draw_frame(pygame.Surface(SIZE), picture, drawers)).copy()
    a.show_help = True
    a.paused = True
    again = pygame.surfarray.array3d(draw_frame(pygame.Surface(SIZE), picture, drawers))
    assert (first == again).all()
    helped = dataclasses.replace(picture, help=(CONTROLS, "about"))
    shown = pygame.surfarray.array3d(draw_frame(pygame.Surface(SIZE), helped, drawers))
    assert (first != shown).any()
