"""The keyboard: held keys make the move and climb axes, E toggles the grab, and the gravity keys
are one-shot: G flips the gravity felt at the player once and restores it at the next press, X
names the enemy to nullify once."""

from __future__ import annotations

import pygame

from playground.view.keyboard import CONTROLS, Keyboard


def test_opposite_keys_cancel_and_release_stops() -> None:
    kb = Keyboard()
    kb.key_down(pygame.K_a)
    assert kb.intent(None, None).move == -1.0
    kb.key_down(pygame.K_RIGHT)
    assert kb.intent(None, None).move == 0.0
    kb.key_up(pygame.K_a)
    assert kb.intent(None, None).move == 1.0
    kb.key_down(pygame.K_w)
    assert kb.intent(None, None).climb == 1.0
    assert kb.touched


def test_e_toggles_the_grab() -> None:
    kb = Keyboard()
    kb.key_down(pygame.K_e)
    kb.key_up(pygame.K_e)
    assert kb.intent(None, None).grab
    kb.key_down(pygame.K_e)
    assert not kb.intent(None, None).grab


def test_g_flips_once_then_restores_once() -> None:
    kb = Keyboard()
    kb.key_down(pygame.K_g)
    first = kb.intent((0.0, -9.81), None)
    assert first.gravity is not None and first.gravity[1] > 0.0 == abs(first.gravity[0])
    assert not first.restore_gravity
    assert kb.intent((0.0, 9.81), None).gravity is None, "a flip is one-shot"
    kb.key_down(pygame.K_g)
    back = kb.intent((0.0, 9.81), None)
    assert back.restore_gravity and back.gravity is None and not kb.flipped


def test_x_names_the_target_once() -> None:
    kb = Keyboard()
    kb.key_down(pygame.K_x)
    assert kb.intent(None, "enemy").nullify == "enemy"
    assert kb.intent(None, "enemy").nullify is None


def test_the_help_lists_every_player_key() -> None:
    keys = " ".join(k for k, _ in CONTROLS)
    for name in ("A / D", "Space", "E", "F (hold)", "G", "X", "W / S"):
        assert name in keys


def test_a_tap_shorter_than_a_frame_is_seen_once() -> None:
    """Law: a key pressed and released before the next intent is read counts as held for that
    one intent, and only that one (defect: a Space tap shorter than a frame was lost)."""
    kb = Keyboard()
    kb.key_down(pygame.K_SPACE)
    kb.key_up(pygame.K_SPACE)
    kb.key_down(pygame.K_d)
    kb.key_up(pygame.K_d)
    tapped = kb.intent(None, None)
    assert tapped.jump and tapped.move == 1.0
    after = kb.intent(None, None)
    assert not after.jump and after.move == 0.0


def test_taking_over_keeps_the_grab_the_script_held() -> None:
    """Law: taking over from a script that holds on starts with the grab held, so a first E
    lets go (defect: the first E did nothing, a D tap let go)."""
    from playground.intents import Intent

    kb = Keyboard()
    kb.take_over(Intent(grab=True))
    kb.key_down(pygame.K_d)
    assert kb.intent(None, None).grab
    kb.key_down(pygame.K_e)
    assert not kb.intent(None, None).grab
