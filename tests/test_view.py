"""Laws of the desktop view on small hand-built scenes: the camera transform, pictures drawn off
screen, replays that reproduce the keyboard exactly, and a view that never changes the physics."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pygame
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground import Category, Stage, World
from playground.intents import Intent, IntentSource
from playground.view import App, Camera, Replay, Session, Show
from playground.view.arrows import arrow_length, weight_pixels
from playground.view.draw import COLOURS
from playground.view.launcher import init_headless, play

SIZE = (640, 360)
TOL_ROUNDTRIP_M = 1e-9  # m: screen ↔ world round trip, double rounding over a few operations
COLOUR_TOL = 12  # per channel: an arrow's body is its exact colour; allow blending with panels
NEAR_PX = 80  # px: "near the body" for colour checks


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


class Pusher:
    """A stand-in controller: pushes its body sideways with ``move`` × 200 N and up with jump.

    It reads its intent the way the real controller does (from ``source`` at the step's time,
    falling back to ``intent``), so the view's input path is exercised end to end.
    """

    def __init__(self, world: World, name: str) -> None:
        self.world = world
        self.name = name
        self.intent = Intent()
        self.source: IntentSource | None = None
        world.on(Stage.CONTROL, self._control)

    def _control(self, world: World) -> None:
        src = self.source
        intent = src.intent(world.time) if src is not None else self.intent
        force = (200.0 * intent.move, 1500.0 if intent.jump else 0.0)
        world.apply_force(self.name, force, category=Category.APPLIED)


def scene(name: str = "bench") -> Show:
    """A floor, a 70 kg box driven by a :class:`Pusher`, and a 10 kg crate, both tracked."""
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("player", mass=70.0, size=(0.6, 1.8), position=(0.0, 0.9))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(2.0, 0.5))
    w.track("player", "crate")
    pusher = Pusher(w, "player")
    return Show(
        name=name,
        world=w,
        title="Bench",
        controllers={"player": pusher},
        player="player",
        follow="player",
        pixels_per_metre=60.0,
    )


def record(world: World) -> list[tuple[float, ...]]:
    """Append every step's state of every named body (and tracked forces) to a list."""
    rows: list[tuple[float, ...]] = []

    def observe(w: World) -> None:
        row: list[float] = [w.time]
        for n in w.names:
            b = w.body(n)
            row += [*b.position, *b.velocity, b.angle, b.angular_velocity]
        for b in w.tracked_bodies:
            name = w.name_of(b)
            assert name is not None
            row += [*w.forces(name).support, *w.perceived_gravity(name)]
        rows.append(tuple(row))

    world.on(Stage.OBSERVE, observe)
    return rows


def colour_near(surf: pygame.Surface, colour: tuple[int, int, int], at: tuple[float, float]) -> int:
    """Pixels of ``colour`` within NEAR_PX of ``at``."""
    arr = pygame.surfarray.array3d(surf).astype(int)  # (w, h, 3)
    x0, y0 = int(at[0]), int(at[1])
    w, h = surf.get_size()
    box = arr[
        max(x0 - NEAR_PX, 0) : min(x0 + NEAR_PX, w), max(y0 - NEAR_PX, 0) : min(y0 + NEAR_PX, h)
    ]
    return int((np.abs(box - np.array(colour)).max(axis=2) <= COLOUR_TOL).sum())


# -- camera and accumulator ----------------------------------------------------------------------


@settings(max_examples=200, deadline=None)
@given(
    x=st.floats(-1e4, 1e4),
    y=st.floats(-1e4, 1e4),
    zoom=st.floats(2.0, 1000.0),
    roll=st.floats(-10.0, 10.0),
)
def test_camera_round_trip(x: float, y: float, zoom: float, roll: float) -> None:
    """Law: screen → world inverts world → screen at any zoom and roll."""
    cam = Camera(size=SIZE, pixels_per_metre=zoom, centre=(3.0, -2.0))
    cam.set_roll(roll)
    back = cam.to_world(cam.to_screen((x, y)))
    assert math.hypot(back[0] - x, back[1] - y) <= TOL_ROUNDTRIP_M * max(1.0, abs(x), abs(y))


def test_camera_roll_puts_up_on_top() -> None:
    """Law: after rolling toward an up vector, that vector points to the top of the screen."""
    cam = Camera(size=SIZE, roll_time=0.0)
    for angle in np.linspace(-3.0, 3.0, 13):
        up = (math.cos(angle), math.sin(angle))
        cam.roll_toward(up, 0.016)
        sx, sy = cam.vector(up)
        assert abs(sx) <= TOL_ROUNDTRIP_M * cam.zoom and sy < 0.0


def test_arrow_scale_is_per_weight_and_follows_the_zoom() -> None:
    """Law: a body's weight is the same arrow length for a 10 kg crate and a 5 t whale of the
    same size; a larger force is never a shorter arrow; zooming in never shortens one weight."""
    w = weight_pixels(1.0, 60.0)
    assert arrow_length(10 * 9.81, 10.0, w) == pytest.approx(arrow_length(5000 * 9.81, 5000.0, w))
    lengths = [arrow_length(f, 70.0, w) for f in np.geomspace(1.0, 1e7, 50)]
    assert all(b >= a for a, b in itertools.pairwise(lengths))
    zooms = [weight_pixels(1.8, z) for z in np.geomspace(2.0, 1000.0, 30)]
    assert all(b >= a for a, b in itertools.pairwise(zooms)) and zooms[-1] > zooms[0]


# -- pictures ------------------------------------------------------------------------------------


def test_picture_shows_filtered_force_at_the_player_and_panels_fit() -> None:
    """The filtered support colour appears near the player; every HUD panel lies in the window."""
    app = App(lambda n: scene(n), "bench", size=SIZE)
    app.run_frames(30)
    surf = app.render()
    body = app.world.body("player")
    at = app.camera.to_screen((body.position.x, body.position.y))
    assert colour_near(surf, COLOURS["support_filtered"], at) > 20
    assert colour_near(surf, COLOURS["gravity"], at) > 10
    window = surf.get_rect()
    assert app.hud.rects and all(window.contains(r) for r in app.hud.rects)


def test_help_and_far_camera_draw_without_raising() -> None:
    """Help, zoom extremes, roll and a camera 10 km away draw without error; the window is still
    only background where the world is out of sight."""
    app = App(lambda n: scene(n), "bench", size=SIZE)
    for key in (pygame.K_h, pygame.K_c, pygame.K_MINUS, pygame.K_EQUALS, pygame.K_v):
        app.handle(pygame.event.Event(pygame.KEYDOWN, key=key))
    app.run_frames(3)
    window = app.render().get_rect()
    assert all(window.contains(r) for r in app.hud.rects)
    app.session.show.follow = None
    app.show_help = False
    app.camera.centre = (1e4, 1e4)
    surf = app.render()
    centre = surf.get_at((SIZE[0] // 2, SIZE[1] // 3))[:3]
    assert tuple(centre) in (COLOURS["background"], COLOURS["grid"])


def test_screenshot_is_a_png(tmp_path: Path) -> None:
    app = App(lambda n: scene(n), "bench", size=SIZE)
    app.run_frames(2)
    out = app.screenshot(tmp_path / "shot.png")
    assert pygame.image.load(str(out)).get_size() == SIZE


# -- replays and determinism ---------------------------------------------------------------------

KEYS = (  # frame → key events, as a person would type them
    (5, pygame.KEYDOWN, pygame.K_d),
    (40, pygame.KEYDOWN, pygame.K_SPACE),
    (43, pygame.KEYUP, pygame.K_SPACE),
    (70, pygame.KEYUP, pygame.K_d),
    (71, pygame.KEYDOWN, pygame.K_LEFT),
    (100, pygame.KEYDOWN, pygame.K_LEFTBRACKET),  # slow motion: changes frames, not physics
    (130, pygame.KEYUP, pygame.K_LEFT),
)


def interactive(frames: int = 160) -> App:
    """An interactive session driven by key events through the window's own handler."""
    app = App(lambda n: scene(n), "bench", size=SIZE)
    for frame in range(frames):
        for at, kind, key in KEYS:
            if at == frame:
                app.handle(pygame.event.Event(kind, key=key))
        app.frame(1.0 / 60.0)
        app.render()
    return app


def state(world: World) -> list[float]:
    out: list[float] = [world.time, float(world.steps)]
    for n in world.names:
        b = world.body(n)
        out += [*b.position, *b.velocity, b.angle, b.angular_velocity]
    return out


def test_replay_reproduces_the_interactive_run_bit_for_bit(tmp_path: Path) -> None:
    """Law: a recorded replay, saved, loaded and played back without any view, ends in exactly
    the same state as the interactive run (same process: exact equality)."""
    app = interactive()
    replay = app.replays()[-1]
    assert replay.steps == app.world.steps
    assert any(i.move == 1.0 for _, i in replay.changes)
    assert any(i.jump for _, i in replay.changes)
    path = tmp_path / "run.json"
    replay.save(path)
    loaded = Replay.load(path)
    assert loaded == replay
    show = scene()
    Session(show, loaded)
    for _ in range(loaded.steps):
        show.world.step()
    assert state(show.world) == state(app.world)


def test_view_never_changes_the_physics() -> None:
    """Law: the same scene and intents stepped with the view drawing every frame and with no
    view at all give identical recordings."""
    app = interactive()
    replay = app.replays()[-1]
    with_view = scene()
    rows_view = record(with_view.world)
    viewer = App(lambda n: with_view, "bench", size=SIZE, replay=replay)
    while viewer.world.steps < replay.steps:
        viewer.frame(1.0 / 60.0)
        viewer.render()
    plain = scene()
    rows_plain = record(plain.world)
    Session(plain, replay)
    for _ in range(replay.steps):
        plain.world.step()
    assert rows_view[: replay.steps] == rows_plain


def test_replay_to_level_inputs_round_trips() -> None:
    """The replay's TOML input timeline holds one table per intent change at step·dt."""
    import tomllib

    replay = interactive(80).replays()[-1]
    doc = tomllib.loads(replay.to_inputs())
    assert len(doc["inputs"]) == len(replay.changes)
    for table, (step, intent) in zip(doc["inputs"], replay.changes, strict=True):
        assert table["t"] == step * replay.dt
        assert table.get("move", 0.0) == intent.move


def test_play_without_display_says_so(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """Plain ``play`` without a display exits 2 and suggests --headless."""
    for var in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(var, raising=False)
    assert play("anything") == 2
    assert "--headless" in capsys.readouterr().err


def test_restart_and_level_cycle_start_fresh_sessions() -> None:
    """R restarts the level at t = 0 keeping the finished session's replay; PgDn/PgUp cycle the
    level list; pause holds the time and '.' steps exactly once."""
    built: list[str] = []

    def load(name: str) -> Show:
        built.append(name)
        return scene(name)

    app = App(load, "a", levels=["a", "b"], size=SIZE)
    app.run_frames(10)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_r))
    assert app.world.steps == 0 and len(app.replays()) == 1
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_PAGEDOWN))
    assert app.level == "b"
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_PAGEUP))
    assert app.level == "a" and built == ["a", "a", "b", "a"]
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_p))
    app.run_frames(5)
    assert app.world.steps == 0
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_PERIOD))
    assert app.world.steps == 1


def test_play_with_an_unreachable_display_says_so(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """DISPLAY set but SDL can only open an invisible driver: exit 2 with --headless suggested,
    never an interactive loop nobody can see or quit."""
    monkeypatch.setenv("DISPLAY", ":99")
    monkeypatch.delenv("SDL_VIDEODRIVER", raising=False)
    assert play("rest") == 2
    assert "--headless" in capsys.readouterr().err
