"""The overlay toggles: names in, exactly those on (the compass stays on), unknown names refused;
the panel draws one row per key with a filled box for an overlay that is on and an empty one for
an overlay that is off."""

from __future__ import annotations

import pygame
import pytest

from playground.view.draw import COLOURS
from playground.view.overlay import OVERLAY_KEYS, Overlay, draw_panel


def test_from_names_turns_on_exactly_those_and_the_compass() -> None:
    on = Overlay.from_names(["contacts", "joints"])
    assert on == Overlay(vectors=False, contacts=True, joints=True, compass=True)
    assert on.toggled("joints").joints is False
    with pytest.raises(ValueError, match=r"overlays: unknown \['forces'\]"):
        Overlay.from_names(["forces"])


def test_every_key_toggles_a_field_of_the_overlay() -> None:
    fields = {field for field, _ in OVERLAY_KEYS.values()}
    assert fields == {f.name for f in Overlay.__dataclass_fields__.values()}


def test_the_panel_fills_the_box_of_each_overlay_that_is_on() -> None:
    surf = pygame.Surface((400, 300))
    font = pygame.font.Font(None, 20)
    overlay = Overlay(vectors=True, contacts=False, joints=True, compass=False)
    rect = draw_panel(surf, font, overlay, (390, 10))
    assert rect.right == 390 and rect.top == 10
    line = font.get_linesize()
    for i, (field, _) in enumerate(OVERLAY_KEYS.values()):
        centre = (rect.x + 11, rect.y + 4 + i * line + line // 2)
        on = getattr(overlay, field)
        pixel = tuple(surf.get_at(centre))[:3]
        if on:
            assert pixel == tuple(COLOURS["text"]), (field, pixel)
        else:
            assert pixel not in (tuple(COLOURS["text"]), tuple(COLOURS["dim"])), (field, pixel)
