"""The keyboard: the controls the help lists, and the held keys and toggles that become the
player's :class:`~playground.intents.Intent` (move, jump, grab, push, climb, and the one-shot
gravity actions). The app's own keys (pause, speed, zoom, overlays, …) are handled by
:class:`playground.view.app.App`; this module never touches the world.
"""

from __future__ import annotations

import pygame

from playground.intents import Intent

__all__ = ["CONTROLS", "Keyboard"]

CONTROLS: tuple[tuple[str, str], ...] = (
    ("A / D, Left / Right", "move"),
    ("W / S, Up / Down", "climb while hanging"),
    ("Space", "jump"),
    ("E", "grab / release"),
    ("F (hold)", "push"),
    ("G", "flip own gravity / restore it"),
    ("X", "nullify the nearest enemy's gravity"),
    ("R", "restart"),
    ("P", "pause"),
    (". (period)", "single step (while paused)"),
    ("[ / ]", "slow motion / fast forward"),
    ("\\", "normal speed"),
    ("- / = , wheel", "zoom out / in"),
    ("PgUp / PgDn", "previous / next level"),
    ("V", "toggle force vectors"),
    ("1 / 2 / 3", "toggle contacts / joint forces / reactions"),
    ("4 / 5 / 6", "toggle perceived gravity / world-up compass / free-body inset"),
    ("C", "toggle camera roll"),
    ("F12", "screenshot"),
    ("T", "tuning panel (sliders; R restores the level's values)"),
    ("L", "lab panel (levels, overlays, buttons, sliders, counters, costs)"),
    ("mouse: press + move", "drag a body (soft spring)"),
    ("mouse: click", "follow a body's forces (empty space: the player)"),
    ("H", "show / hide this help"),
    ("Esc", "quit"),
)


class Keyboard:
    """Held keys and toggles → the player's intent. Never touches the world.

    >>> kb = Keyboard()
    >>> kb.key_down(pygame.K_d); kb.key_down(pygame.K_SPACE)
    >>> intent = kb.intent(None, None)
    >>> intent.move, intent.jump, intent.grab
    (1.0, True, False)
    """

    def __init__(self) -> None:
        self.held: set[int] = set()
        self.touched = False
        """Whether any player key was pressed yet (until then a level's script plays)."""
        self.grab = False
        self.flipped = False
        self._tapped: set[int] = set()
        self._flip_pending = False
        self._restore_pending = False
        self._nullify_pending = False

    def take_over(self, playing: Intent) -> None:
        """Take over from the intent a script was ``playing``: the held toggles (the grab)
        start as it held them, so the first key changes only what it is meant to (a tap of D
        while a script hangs on keeps hanging).

        >>> kb = Keyboard()
        >>> kb.take_over(Intent(grab=True)); kb.key_down(pygame.K_d)
        >>> kb.intent(None, None).grab
        True
        """
        self.grab = playing.grab

    def key_down(self, key: int) -> None:
        self.held.add(key)
        # Seen by the next intent even if it is released before that (a tap shorter than a frame).
        self._tapped.add(key)
        self.touched = True
        if key == pygame.K_e:
            self.grab = not self.grab
        elif key == pygame.K_g:
            if self.flipped:
                self._restore_pending = True
            else:
                self._flip_pending = True
            self.flipped = not self.flipped
        elif key == pygame.K_x:
            self._nullify_pending = True

    def key_up(self, key: int) -> None:
        self.held.discard(key)

    @staticmethod
    def _axis(down: set[int], minus: tuple[int, ...], plus: tuple[int, ...]) -> float:
        return float(any(k in down for k in plus)) - float(any(k in down for k in minus))

    def intent(self, gravity: tuple[float, float] | None, target: str | None) -> Intent:
        """The intent now. ``gravity``: the gravity at the player (m/s²), used to flip it;
        ``target``: the body to nullify when X was pressed. One-shot actions are consumed, and
        so are taps: a key pressed since the last intent counts as held for this one."""
        flip: tuple[float, float] | None = None
        if self._flip_pending and gravity is not None and gravity != (0.0, 0.0):
            flip = (-gravity[0], -gravity[1])
        restore = self._restore_pending
        nullify = target if self._nullify_pending else None
        self._flip_pending = self._restore_pending = self._nullify_pending = False
        down = self.held | self._tapped
        self._tapped = set()
        return Intent(
            move=self._axis(down, (pygame.K_a, pygame.K_LEFT), (pygame.K_d, pygame.K_RIGHT)),
            jump=pygame.K_SPACE in down,
            grab=self.grab,
            push=pygame.K_f in down,
            climb=self._axis(down, (pygame.K_s, pygame.K_DOWN), (pygame.K_w, pygame.K_UP)),
            gravity=flip,
            restore_gravity=restore,
            nullify=nullify,
        )
