"""The overlays drawn over the world, each a toggle: forces on the tracked bodies, contact points
with their normal and friction forces, joint forces at their anchors, the reactions the actors put
on the bodies under them, perceived gravity and its up, and a world-up compass with the camera's
roll. This module owns which are on, the keys that toggle them and the panel that lists them;
:class:`playground.view.painter.Painter` draws them.

>>> Overlay().toggled("contacts").contacts, Overlay.from_names(["perceived"]).vectors
(True, False)
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable
from dataclasses import dataclass

import pygame

from playground.vec import Vec
from playground.view.draw import COLOURS, shade_panel

__all__ = ["OVERLAY_KEYS", "Overlay", "draw_panel"]

OVERLAY_KEYS: dict[int, tuple[str, str]] = {
    pygame.K_v: ("vectors", "forces"),
    pygame.K_1: ("contacts", "contacts"),
    pygame.K_2: ("joints", "joint forces"),
    pygame.K_3: ("reactions", "reactions"),
    pygame.K_4: ("perceived", "perceived g"),
    pygame.K_5: ("compass", "compass"),
    pygame.K_6: ("free_body", "free-body diagram"),
}
"""Key → (overlay field, label on the overlay panel)."""
ALWAYS_ON = ("compass", "free_body")
"""Overlays on in every level (until toggled off)."""


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
        free_body: the watched body's free-body diagram, an inset.
    """

    vectors: bool = True
    contacts: bool = False
    joints: bool = False
    reactions: bool = False
    perceived: bool = False
    compass: bool = True
    free_body: bool = True

    def toggled(self, name: str) -> Overlay:
        """This overlay with ``name`` switched."""
        return dataclasses.replace(self, **{name: not getattr(self, name)})

    @classmethod
    def from_names(cls, names: Iterable[str]) -> Overlay:
        """Exactly the overlays named on (the compass and the free-body inset are on unless
        turned off by the keys)."""
        on = set(names)
        fields = [f.name for f in dataclasses.fields(cls)]
        unknown = on.difference(fields)
        if unknown:
            raise ValueError(f"overlays: unknown {sorted(unknown)}, expected some of {fields}")
        return cls(**{f: (f in on) or f in ALWAYS_ON for f in fields})


def draw_panel(
    surf: pygame.Surface, font: pygame.font.Font, overlay: Overlay, topright: Vec
) -> pygame.Rect:
    """The overlay toggles with their keys, on or off, in a panel whose top-right corner is
    ``topright``; returns its rect."""
    line = font.get_linesize()
    items = [
        (pygame.key.name(k).upper(), label, bool(getattr(overlay, field)))
        for k, (field, label) in OVERLAY_KEYS.items()
    ]
    width = max(font.size(f"{k}  {label}")[0] for k, label, _ in items) + 26
    rect = pygame.Rect(0, int(topright[1]), width, line * len(items) + 8)
    rect.right = int(topright[0])
    shade_panel(surf, rect)
    for i, (key, label, on) in enumerate(items):
        y = rect.y + 4 + i * line
        colour = COLOURS["text"] if on else COLOURS["dim"]
        box = pygame.Rect(rect.x + 6, y + line // 2 - 5, 10, 10)
        pygame.draw.rect(surf, colour, box, 0 if on else 1)
        surf.blit(font.render(f"{key}  {label}", True, colour), (rect.x + 22, y))
    return rect
