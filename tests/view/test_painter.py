"""The painter's legend lists only what the last frame drew, in the legend's fixed order, with
the m·g scale bar only beside force vectors; the compass is drawn only while the camera rolls.
(Whole frames are checked by pixels in tests/test_view_draw.py and tests/test_view_claims.py.)"""

from __future__ import annotations

import math

import pygame
import pytest

from playground.view.camera import Camera
from playground.view.overlay import Overlay
from playground.view.painter import Painter


def test_the_legend_follows_what_was_drawn_in_its_own_order() -> None:
    painter = Painter()
    painter.scale_body, painter.scale_px, painter.scale_newtons = "crate", 40.0, 98.1
    painter.drawn = {"normal", "contact"}
    assert [e.kind for e in painter.legend()] == ["contact", "normal"]
    painter.drawn = {"gravity", "grip_arm", "nullify"}
    entries = painter.legend()
    assert [e.kind for e in entries] == ["gravity", "hand", "nullify", "text"]
    assert entries[-1].text == "m·g of crate (98 N)" and entries[-1].length == 40.0


@pytest.mark.parametrize(
    ("kind", "scaled"),
    [("support", True), ("push", True), ("grip_arm", True), ("reaction", False), ("up", False)],
)
def test_the_scale_bar_goes_with_the_force_vectors_only(kind: str, scaled: bool) -> None:
    painter = Painter()
    painter.scale_body, painter.scale_px, painter.scale_newtons = "crate", 40.0, 98.1
    painter.drawn = {kind}
    assert ("text" in {e.kind for e in painter.legend()}) == scaled


def test_the_compass_shows_only_while_the_camera_rolls_and_it_is_on() -> None:
    surf = pygame.Surface((400, 300))
    font = pygame.font.Font(None, 20)
    cam = Camera(size=(400, 300))
    painter = Painter()
    assert painter.draw_compass(surf, font, cam, (200.0, 150.0)) is None
    cam.roll = math.pi
    rect = painter.draw_compass(surf, font, cam, (200.0, 150.0))
    assert rect is not None and rect.collidepoint(200, 150) and "compass" in painter.drawn
    assert Painter(Overlay(compass=False)).draw_compass(surf, font, cam, (200.0, 150.0)) is None
