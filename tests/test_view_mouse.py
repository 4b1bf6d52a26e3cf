"""Laws of the mouse in the desktop view: a press-and-move drags a dynamic body with a soft spring
whose force the force solver counts exactly as APPLIED; a click selects the body the HUD and the
scope follow; the wheel zooms. Events go through :meth:`App.handle`, as the window's loop sends
them (the real-window test sends real X events)."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pygame
import pytest

from playground import World
from playground.view import App, Replay, Show
from playground.view.app import ZOOM_STEP
from playground.view.draw import COLOURS
from playground.view.launcher import init_headless, replay_level, show_level

SIZE = (640, 360)
TOL_LEDGER_REL = 1e-9
"""The solver's APPLIED reading against the force the mouse put in the ledger: the same numbers
through a dozen float operations of reverse integration (measured ~1e-13)."""
TOL_HOLD_M = 0.05
"""m: a body held still by the mouse spring sits this close to the cursor (the spring's sag under
its weight at 5 Hz and dt = 1/120 s is g·(1 + 2ζω·dt)/ω² = 1.4 cm)."""
COLOUR_TOL = 12  # per channel


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


def bench() -> Show:
    """A floor and a 10 kg crate, nothing tracked, no player: the mouse is the only actor."""
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    return Show(name="bench", world=w, title="Bench", camera=(0.0, 2.0), pixels_per_metre=60.0)


def app_for(show: Show) -> App:
    return App(lambda _: show, show.name, size=SIZE)


def press(app: App, at: tuple[float, float]) -> None:
    pos = app.camera.to_screen(at)
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=pos))


def move(app: App, at: tuple[float, float]) -> None:
    pos = app.camera.to_screen(at)
    app.handle(pygame.event.Event(pygame.MOUSEMOTION, pos=pos, rel=(0, 0), buttons=(1, 0, 0)))


def release(app: App) -> None:
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=(0, 0)))


def test_drag_lifts_a_crate_and_the_solver_counts_the_pull_as_applied() -> None:
    """Law: pressing on the crate and moving the cursor 2 m up lifts it to the cursor; every step
    the solver's APPLIED reading equals the force the mouse put in the ledger, and the support
    (what the body feels through contacts) is zero while it hangs in the air."""
    show = bench()
    app = app_for(show)
    world = show.world
    press(app, (0.0, 0.5))
    move(app, (0.0, 2.5))
    assert app.session.grab is not None and app.session.grab.body == "crate"
    checked = 0
    for _ in range(120):
        app.frame(1.0 / 60.0)
        pull = app.session.pull
        assert pull is not None
        applied = world.forces("crate").applied
        scale = max(math.hypot(*pull[0]), 1.0)
        assert math.dist(applied, pull[0]) <= TOL_LEDGER_REL * scale
        checked += 1
    crate = world.body("crate")
    grabbed = crate.local_to_world(app.session.grab.anchor)
    assert math.dist((grabbed.x, grabbed.y), (0.0, 2.5)) < TOL_HOLD_M
    assert math.hypot(*world.forces("crate").support) < 1e-6 * crate.mass * 9.81
    assert checked == 120
    release(app)
    app.frame(1.0 / 60.0)
    assert app.session.grab is None and app.session.pull is None


def test_the_pull_is_drawn_from_the_grabbed_point() -> None:
    """Law: while dragging, the mouse's colour is on screen around the grabbed point (the band
    and the force arrow); after release it is gone."""
    show = bench()
    app = app_for(show)
    press(app, (0.2, 0.7))
    move(app, (1.5, 2.5))
    app.frame(1.0 / 60.0)
    pixels = pygame.surfarray.pixels3d(app.render()).astype(int)
    colour = np.array(COLOURS["mouse"])
    grabbed = app.world.body("crate").local_to_world(app.session.grab.anchor)
    x, y = (round(c) for c in app.camera.to_screen((grabbed.x, grabbed.y)))
    near = pixels[x - 30 : x + 31, y - 30 : y + 31]
    assert (np.abs(near - colour).max(axis=2) <= COLOUR_TOL).sum() >= 20
    release(app)
    press(app, (5.0, 5.0))  # a click on empty space also drops the selection marker
    release(app)
    app.frame(1.0 / 60.0)
    pixels = pygame.surfarray.pixels3d(app.render()).astype(int)
    assert (np.abs(pixels - colour).max(axis=2) <= COLOUR_TOL).sum() == 0


def test_click_selects_the_body_the_scope_follows_and_empty_space_returns_to_the_player() -> None:
    """Law: a click (no drag) on the crate selects it without pulling it; the scope then shows
    the crate's |support| (its weight at rest), and a click on empty space clears the choice."""
    show = bench()
    app = app_for(show)
    press(app, (0.0, 0.5))
    release(app)
    assert app.selected == "crate" and app.focus == "crate"
    assert app.session.grab is None
    for _ in range(30):
        app.frame(1.0 / 60.0)
    raw = app.scope.raw
    assert raw.size > 0
    assert raw[-1] == pytest.approx(10.0 * 9.81, rel=1e-6)
    press(app, (5.0, 4.0))
    release(app)
    assert app.selected is None


def test_wheel_zooms_by_one_step_per_notch() -> None:
    """Law: one wheel notch up multiplies the zoom by ZOOM_STEP, one down divides it."""
    app = app_for(bench())
    z = app.camera.zoom
    app.handle(pygame.event.Event(pygame.MOUSEWHEEL, x=0, y=1))
    assert app.camera.zoom == pytest.approx(z * ZOOM_STEP)
    app.handle(pygame.event.Event(pygame.MOUSEWHEEL, x=0, y=-2))
    assert app.camera.zoom == pytest.approx(z / ZOOM_STEP)


def test_a_drag_is_in_the_replay_and_plays_back_bit_for_bit(tmp_path: Path) -> None:
    """Law: what the mouse held at each step is recorded with the intents; the replay, saved
    and loaded, plays the drag back headless and ends in exactly the same state (same process:
    exact equality)."""
    app = App(show_level, "sandbox", size=SIZE)
    crate = app.world.body("crate")
    for _ in range(30):
        app.frame(1.0 / 60.0)
    press(app, (crate.position.x, crate.position.y))
    for k in range(1, 31):
        move(app, (crate.position.x + 0.02 * k, 0.4 + 0.08 * k))
        app.frame(1.0 / 60.0)
    release(app)
    for _ in range(30):
        app.frame(1.0 / 60.0)
    replay = app.replays()[-1]
    assert len(replay.grabs) > 2 and replay.grabs[-1][1] is None
    path = tmp_path / "drag.json"
    replay.save(path)
    loaded = Replay.load(path)
    assert loaded == replay
    show = replay_level("sandbox", loaded)
    for name in ("crate", "player"):
        a, b = show.world.body(name), app.world.body(name)
        assert (a.position, a.velocity, a.angle) == (b.position, b.velocity, b.angle)
    assert show.world.body("crate").position.y > 1.0  # it was lifted, and the replay lifted it
