"""The app's own keys: P pauses the physics (and . steps once while paused), [ ] \\ set the speed,
PageDown/PageUp cycle the levels, R restarts with a fresh world, Esc quits."""

from __future__ import annotations

import pygame

from playground import World
from playground.view.app import App
from playground.view.clock import SPEEDS
from playground.view.session import Show

FRAME = 1.0 / 60.0  # s: one headless frame, two steps at dt 1/120 s


def show(name: str) -> Show:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    return Show(name=name, world=w, title=name.title())


def key(app: App, k: int) -> None:
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=k))


def test_pause_stops_the_steps_and_period_steps_once() -> None:
    app = App(show, "a", size=(320, 200))
    assert app.frame(FRAME) == 2
    key(app, pygame.K_p)
    assert app.frame(FRAME) == 0
    steps = app.world.steps
    key(app, pygame.K_PERIOD)
    assert app.world.steps == steps + 1
    key(app, pygame.K_p)
    assert app.frame(FRAME) == 2


def test_speed_keys_walk_the_speeds_and_backslash_resets() -> None:
    app = App(show, "a", size=(320, 200))
    for _ in range(len(SPEEDS) + 2):
        key(app, pygame.K_RIGHTBRACKET)
    assert app.speed == SPEEDS[-1]
    key(app, pygame.K_BACKSLASH)
    assert app.speed == 1.0
    key(app, pygame.K_LEFTBRACKET)
    assert app.speed == SPEEDS[SPEEDS.index(1.0) - 1]


def test_levels_cycle_restart_fresh_and_escape_quits() -> None:
    app = App(show, "a", levels=["a", "b", "c"], size=(320, 200))
    key(app, pygame.K_PAGEUP)
    assert app.level == "c"
    key(app, pygame.K_PAGEDOWN)
    key(app, pygame.K_PAGEDOWN)
    assert app.level == "b" and app.session.show.title == "B"
    app.frame(FRAME)
    world = app.world
    key(app, pygame.K_r)
    assert app.world is not world and app.world.steps == 0
    key(app, pygame.K_ESCAPE)
    assert not app.running
