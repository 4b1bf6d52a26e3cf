"""The view on the shipped levels: every level draws off screen with its forces where the player
is, a replay of keyboard play reproduces the run exactly, and drawing leaves the level's recording
unchanged."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pygame
import pytest

from playground.view import App, Show
from playground.view.draw import COLOURS
from playground.view.launcher import (
    attach_replay,
    init_headless,
    level_names,
    replay_level,
    show_level,
)

SIZE = (800, 450)
FRAMES = 45  # frames of 1/60 s: long enough for the filtered force to build up at the player
COLOUR_TOL = 12  # per channel: an arrow's body is its exact colour; panels blend at most this much
NEAR_PX = 90  # px: "near the player"
MIN_PIXELS = 15  # filtered-force pixels that make a visible thick arrow (5 px wide, > 3 px long)
LEVELS = level_names()


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


def colour_near(surf: pygame.Surface, colour: tuple[int, int, int], at: tuple[float, float]) -> int:
    arr = pygame.surfarray.array3d(surf).astype(int)
    x0, y0 = int(at[0]), int(at[1])
    w, h = surf.get_size()
    box = arr[
        max(x0 - NEAR_PX, 0) : min(x0 + NEAR_PX, w), max(y0 - NEAR_PX, 0) : min(y0 + NEAR_PX, h)
    ]
    return int((np.abs(box - np.array(colour)).max(axis=2) <= COLOUR_TOL).sum())


@pytest.mark.parametrize("level", LEVELS)
def test_every_level_draws(level: str) -> None:
    """Each shipped level renders off screen without error; its HUD panels lie inside the window;
    the filtered support force's colour shows near the player when the player is supported and
    the level's view shows force vectors."""
    app = App(show_level, level, levels=LEVELS, size=SIZE)
    app.run_frames(FRAMES)
    surf = app.render()
    window = surf.get_rect()
    assert app.hud.rects and all(window.contains(r) for r in app.hud.rects)
    show = app.session.show
    if show.player is None:
        return
    body = app.world.body(show.player)
    at = app.camera.to_screen((body.position.x, body.position.y))
    assert window.collidepoint(at), f"{level}: the player is off screen at {at}"
    m = body.mass
    gx, gy = app.world.perceived_gravity(show.player)
    if app.overlay.vectors and m * float(np.hypot(gx, gy)) >= 0.2 * m * 9.81:
        assert colour_near(surf, COLOURS["support_filtered"], at) >= MIN_PIXELS


def _player_level() -> str:
    if "sandbox" in LEVELS:
        return "sandbox"
    for name in LEVELS:
        if show_level(name).player is not None:
            return name
    pytest.skip("no shipped level has a player")


KEYS = (
    (3, pygame.KEYDOWN, pygame.K_d),
    (30, pygame.KEYDOWN, pygame.K_SPACE),
    (33, pygame.KEYUP, pygame.K_SPACE),
    (50, pygame.KEYUP, pygame.K_d),
    (52, pygame.KEYDOWN, pygame.K_a),
    (60, pygame.KEYDOWN, pygame.K_g),  # flip own gravity
    (62, pygame.KEYUP, pygame.K_g),
    (80, pygame.KEYDOWN, pygame.K_RIGHTBRACKET),  # fast forward: more steps per frame
    (95, pygame.KEYUP, pygame.K_a),
    (100, pygame.KEYDOWN, pygame.K_g),  # restore it
)


def state(show: Show) -> list[float]:
    w = show.world
    out: list[float] = [w.time, float(w.steps)]
    for n in w.names:
        b = w.body(n)
        out += [*b.position, *b.velocity, b.angle, b.angular_velocity]
    return out


def test_replay_of_keyboard_play_is_exact(tmp_path: Path) -> None:
    """Law: keyboard play recorded to a replay file and played back headless without a view ends
    in exactly the same state (same process: exact equality)."""
    level = _player_level()
    app = App(show_level, level, levels=LEVELS, size=SIZE)
    for frame in range(120):
        for at, kind, key in KEYS:
            if at == frame:
                app.handle(pygame.event.Event(kind, key=key))
        app.frame(1.0 / 60.0)
        app.render()
    replay = app.replays()[-1]
    assert len(replay.changes) >= 5
    path = tmp_path / "play.json"
    replay.save(path)
    from playground.view import Replay

    back = replay_level(level, Replay.load(path))
    assert state(back) == state(app.session.show)


def test_drawing_leaves_the_recording_unchanged(tmp_path: Path) -> None:
    """Law: a level stepped by the view (drawing every frame) and stepped alone give identical
    recordings (the levels' own CSV recorder, floats written with repr)."""
    from playground.scene.recording import recording

    level = _player_level()
    frames = 60
    with contextlib.ExitStack() as stack:

        def load(name: str) -> Show:
            show = show_level(name)
            stack.enter_context(recording(show.scene, tmp_path / "view.csv"))
            return show

        app = App(load, level, size=SIZE)
        app.run_frames(frames)
        steps = app.world.steps
    # The same inputs without a view: the view's own replay (the keyboard replaced the script).
    plain = show_level(level)
    attach_replay(plain, app.replays()[-1])
    with recording(plain.scene, tmp_path / "plain.csv"):
        for _ in range(steps):
            plain.world.step()
    view_csv = (tmp_path / "view.csv").read_text()
    assert view_csv.count("\n") > steps
    assert view_csv == (tmp_path / "plain.csv").read_text()


TOL_UP_ON_SCREEN = 0.05  # rad: the roll lags its target by a first-order filter of 0.3 s


@pytest.mark.skipif("gravity_flip" not in LEVELS, reason="gravity_flip is not shipped")
def test_rolling_camera_keeps_perceived_up_at_the_top() -> None:
    """Law: with camera roll on, once the player has settled after a gravity flip, its perceived
    up points to the top of the screen (the world is drawn upside down)."""
    app = App(show_level, "gravity_flip", size=SIZE)
    app.roll = True
    app.run_frames(240)
    up = app.world.perceived_up("player")
    sx, sy = app.camera.vector(up)
    assert abs(np.arctan2(sx, -sy)) <= TOL_UP_ON_SCREEN
    assert abs(abs(app.camera.roll) - np.pi) <= TOL_UP_ON_SCREEN


@pytest.mark.skipif("null_enemy" not in LEVELS, reason="null_enemy is not shipped")
def test_x_nullifies_the_nearest_enemy() -> None:
    """X (one-shot) nullifies the gravity of the enemy nearest the player, as a recorded intent."""
    app = App(show_level, "null_enemy", size=SIZE)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_x))
    app.run_frames(3)
    assert app.world.gravity_rule("enemy").scale == 0.0
    replay = app.replays()[-1]
    assert [i.nullify for _, i in replay.changes].count("enemy") == 1


def test_cli_run_replay_ends_where_the_interactive_run_ended(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Law: ``playground run LEVEL --replay FILE --json`` reports exactly the player's final
    position and velocity of the interactive session that recorded FILE (JSON floats round-trip
    exactly); ``playground play --replay`` shows it headless."""
    import json

    from playground.cli import main

    level = _player_level()
    app = App(show_level, level, size=SIZE)
    for frame in range(90):
        for at, kind, key in KEYS:
            if at == frame:
                app.handle(pygame.event.Event(kind, key=key))
        app.frame(1.0 / 60.0)
    path = tmp_path / "session.json"
    app.replays()[-1].save(path)
    capsys.readouterr()
    assert main(["run", level, "--replay", str(path), "--json"]) in (0, 1)
    report = json.loads(capsys.readouterr().out)
    body = app.world.body("player")
    assert report["steps"] == app.world.steps
    assert report["bodies"]["player"]["position"] == list(body.position)
    assert report["bodies"]["player"]["velocity"] == list(body.velocity)
    shot = tmp_path / "shot.png"
    args = ["play", level, "--headless", "--frames", "3", "--replay", str(path)]
    assert main([*args, "--screenshot", str(shot)]) == 0
    assert shot.exists()


def test_replay_as_level_inputs_reproduces_the_session() -> None:
    """Law: a session's replay turned into ``[[inputs]]`` and appended to the level file gives a
    level whose own scripted run (no view, no replay) ends in exactly the session's state — a bug
    found by hand becomes a level test."""
    from playground.level import find, loads
    from playground.scene import build

    level = "rest"
    if level not in LEVELS:
        pytest.skip("rest is not shipped")
    app = App(show_level, level, size=SIZE)
    for frame in range(120):
        for at, kind, key in KEYS:
            if at == frame:
                app.handle(pygame.event.Event(kind, key=key))
        app.frame(1.0 / 60.0)
    replay = app.replays()[-1]
    text = find(level).read_text(encoding="utf-8") + "\n" + replay.to_inputs()
    scene = build(loads(text, "rest+replay"))
    for _ in range(replay.steps):
        scene.world.step()
    show = Show(name=level, world=scene.world, title="")
    assert state(show) == state(app.session.show)


# -- issue 26's defects, each on the level it was seen in ----------------------------------------


def _key(app: App, key: int, *, up: bool = True) -> None:
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=key))
    if up:
        app.handle(pygame.event.Event(pygame.KEYUP, key=key))


def test_taking_over_a_scripted_grip_keeps_hanging() -> None:
    """flying_whale: a D tap at 1.6 s, while the script hangs on, keeps the player hanging; the
    first E then lets go (defect: the tap dropped the grip, and the first E did nothing)."""
    app = App(show_level, "flying_whale", levels=LEVELS, size=SIZE)
    ctrl = app.session.show.controllers["player"]
    app.run_frames(round(1.6 * 60))
    assert ctrl.joint is not None
    _key(app, pygame.K_d)
    app.run_frames(30)
    assert ctrl.joint is not None and ctrl.state.value == "hanging"
    _key(app, pygame.K_e)
    app.run_frames(30)
    assert ctrl.joint is None


def test_a_level_looks_the_same_however_it_is_reached() -> None:
    """Every level's overlays, camera and roll are its own after PgDn from any other level
    (defect: incline → moving_platform kept incline's overlays and drew no arrows)."""
    for before, after in (("incline", "moving_platform"), ("crusher", "null_enemy")):
        app = App(show_level, before, levels=[before, after], size=SIZE)
        app.run_frames(3)
        _key(app, pygame.K_4)  # an overlay the next level does not ask for
        _key(app, pygame.K_PAGEDOWN)
        direct = App(show_level, after, levels=LEVELS, size=SIZE)
        assert app.level == after
        assert app.overlay == direct.overlay
        assert (app.camera.zoom, app.camera.centre, app.roll) == (
            direct.camera.zoom,
            direct.camera.centre,
            direct.roll,
        )
        assert app.overlay != App(show_level, before, size=SIZE).overlay


def test_the_scopes_spike_label_leaves_its_title_readable() -> None:
    """crusher: the 22941 N landing spike's value is drawn clear of the scope's title, whose
    pixels stay its own dim text on the panel (defect: the value was written over the title)."""
    app = App(show_level, "crusher", levels=LEVELS, size=(1280, 720))
    app.run_frames(90)
    app.render()
    layout = app.hud.scope_layout
    assert layout is not None and layout.spike is not None, "the spike is clipped and labelled"
    assert not layout.spike.colliderect(layout.title)
    arr = pygame.surfarray.array3d(app.surface).astype(int)
    r = layout.title
    region = arr[r.left : r.right, r.top : r.bottom].reshape(-1, 3)
    support = np.abs(region - np.array(COLOURS["support"])).max(axis=1) <= COLOUR_TOL
    assert not support.any()
    dim = np.abs(region - np.array(COLOURS["dim"])).max(axis=1) <= COLOUR_TOL
    assert dim.sum() >= MIN_PIXELS, "the title is written"
