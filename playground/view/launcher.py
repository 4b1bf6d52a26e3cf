"""Launching the view: a level by name into a :class:`~playground.view.session.Show`, the
``playground play`` command (window or headless), and replays played back without drawing.

Headless means ``SDL_VIDEODRIVER=dummy`` and only ``pygame.display`` and ``pygame.font``
initialised (never audio): it runs on CI machines without a display or a sound card.
"""

from __future__ import annotations

import os
import sys
from typing import Any

import pygame

from playground.scene.replay import Replay, ReplayError
from playground.view.app import App
from playground.view.capture import GIF_FPS, GifWriter, gif_path, parse_size, picture_path
from playground.view.clock import HEADLESS_FRAME
from playground.view.session import Session, Show

__all__ = [
    "DEFAULT_LEVEL",
    "attach_replay",
    "display_available",
    "init_headless",
    "level_names",
    "play",
    "replay_level",
    "run_play",
    "show_level",
    "show_scene",
]

DEFAULT_LEVEL = "sandbox"
WINDOW = (1280, 720)  # px: the default window size


def init_headless() -> None:
    """Initialise pygame for off-screen drawing: the dummy video driver, display and font only."""
    os.environ["SDL_VIDEODRIVER"] = "dummy"
    pygame.display.init()
    pygame.font.init()
    if pygame.display.get_surface() is None:
        # An off-screen 1×1 display: pygame_gui (the lab panel) converts its text surfaces to
        # the display's format, which needs one set.
        pygame.display.set_mode((1, 1))


def display_available() -> bool:
    """Whether a real display can be opened (an X11/Wayland session, or not Linux)."""
    driver = os.environ.get("SDL_VIDEODRIVER", "")
    if driver in ("dummy", "offscreen"):
        return False
    session = bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    return session or not sys.platform.startswith("linux")


def level_names() -> list[str]:
    """The shipped levels, by name, in the order next/previous cycles through them."""
    from playground.level.files import shipped

    return sorted(shipped())


def show_scene(name: str, scene: Any) -> Show:
    """A built :class:`playground.scene.Scene` as the view sees it."""
    level = scene.level
    world = scene.world
    controllers = dict(scene.controllers)
    player = "player" if "player" in controllers else next(iter(controllers), None)
    follow = level.view.follow if level.view.follow in world.names else player
    if level.view.fixed:
        follow = None
    return Show(
        name=name,
        world=world,
        title=level.title,
        description=level.description,
        controllers=controllers,
        player=player,
        follow=follow,
        camera=tuple(level.view.camera),
        pixels_per_metre=float(level.view.pixels_per_metre),
        roll=bool(level.view.roll),
        scene=scene,
    )


def show_level(level: str) -> Show:
    """Load and build a level (a path or a shipped name) for the view."""
    from playground.level.files import find
    from playground.level.loading import load
    from playground.scene import build

    path = find(level)
    return show_scene(path.stem, build(load(path)))


def attach_replay(show: Show, replay: Replay) -> Session:
    """Make ``replay`` drive the player of ``show`` from its first step (checks level and dt)."""
    replay.check(show.name, show.world)
    return Session(show, replay)


def replay_level(level: str, replay: Replay) -> Show:
    """Build ``level``, play ``replay`` headless (no drawing at all) and return the final show."""
    show = show_level(level)
    attach_replay(show, replay)
    for _ in range(replay.steps):
        show.world.step()
    return show


def play(
    level: str = DEFAULT_LEVEL,
    *,
    headless: bool = False,
    frames: int | None = None,
    screenshot: str | None = None,
    replay_out: str | None = None,
    replay: str | None = None,
    size: tuple[int, int] = WINDOW,
    gif: str | None = None,
) -> int:
    """``playground play``: open ``level`` in a window (or off screen); returns an exit code.

    Without a display and without ``headless`` it says so and returns 2; so do an output path
    that cannot be written (checked before anything runs). Headless runs ``frames`` frames
    (default 120) of 1/60 s each and saves ``screenshot`` if given; ``gif`` records those frames
    as an animated GIF (one in three: 20 fps, real time). ``replay`` (a file) drives the player
    instead of the keyboard. On exit the player's inputs since the last (re)start are written to
    ``replay_out`` if given.
    """
    from playground.level.errors import LevelError
    from playground.world.guard import RunawayError

    try:
        shot = picture_path(screenshot) if screenshot is not None else None
        movie = gif_path(gif) if gif is not None else None
    except ValueError as exc:
        print(f"playground play: {exc}", file=sys.stderr)
        return 2
    if movie is not None and frames is None and not headless:
        print("playground play: --gif: needs --frames N in a window", file=sys.stderr)
        return 2
    if movie is not None and frames == 0:
        print("playground play: --gif: needs at least one frame, got --frames 0", file=sys.stderr)
        return 2
    if not headless and not display_available():
        print(
            "playground play: no display found (DISPLAY/WAYLAND_DISPLAY unset). "
            "Use --headless (e.g. --headless --frames 120 --screenshot out.png).",
            file=sys.stderr,
        )
        return 2
    names = level_names()
    try:
        show = show_level(level)
        watch = Replay.load(replay) if replay is not None else None
        if watch is not None:
            attach_replay(show, watch)
    except (LevelError, ReplayError) as exc:
        print(f"playground play: {exc}", file=sys.stderr)
        return 2
    recorder = GifWriter(every=round(1.0 / (HEADLESS_FRAME * GIF_FPS))) if movie else None
    window: pygame.Surface | None = None
    if headless:
        init_headless()
    else:
        window = _open_window(size)
        if window is None:
            return 2
        pygame.display.set_caption("playground")
    app = App(show_level, level, levels=names, size=size, replay=watch)
    code = 0
    try:
        if window is None or frames is not None:
            app.run_frames(120 if frames is None else frames, window=window, each=recorder)
        else:
            app.run_window(window)
    except KeyboardInterrupt:
        # Ctrl-C ends the session, not its replay: save what was played, then report it.
        played = app.replays()
        if replay_out is not None and played:
            played[-1].save(replay_out)
        raise
    except RunawayError as exc:
        # One line, and what was played so far is still saved below (pictures, replay).
        print(f"playground play: {level}: {exc}", file=sys.stderr)
        code = 1
    if shot is not None:
        app.screenshot(shot)
    if movie is not None and recorder is not None:
        recorder.save(movie)
    if replay_out is not None:
        replays = app.replays()
        if replays:
            replays[-1].save(replay_out)
            if app.session.altered:
                print(
                    f"playground play: note: {replay_out} holds the intents and mouse drags; "
                    f"this session's {' and '.join(sorted(app.session.altered))} is not in it",
                    file=sys.stderr,
                )
    if window is not None:
        pygame.display.quit()
    return code


def _open_window(size: tuple[int, int]) -> pygame.Surface | None:
    """A window synced to the display if it can be (None, with a message, if none opens)."""
    try:
        pygame.display.init()
        driver = pygame.display.get_driver()
        if driver in ("offscreen", "dummy"):
            # SDL falls back to an invisible driver when the display cannot be reached.
            print(
                f"playground play: no display could be opened (SDL chose {driver!r}); "
                "use --headless.",
                file=sys.stderr,
            )
            return None
        pygame.font.init()
        try:
            return pygame.display.set_mode(size, pygame.RESIZABLE, vsync=1)
        except pygame.error:
            return pygame.display.set_mode(size, pygame.RESIZABLE)
    except pygame.error as exc:
        print(f"playground play: cannot open a window ({exc}); use --headless.", file=sys.stderr)
        return None


def run_play(args: Any) -> int:
    """Run ``playground play`` from the CLI's parsed arguments (level, headless, frames,
    screenshot, replay_out, replay, size, gif)."""
    if args.frames is not None and args.frames < 0:
        print(f"playground play: --frames: expected >= 0, got {args.frames}", file=sys.stderr)
        return 2
    try:
        size = parse_size(args.size) if args.size is not None else WINDOW
    except ValueError as exc:
        print(f"playground play: {exc}", file=sys.stderr)
        return 2
    return play(
        args.level,
        headless=args.headless,
        frames=args.frames,
        screenshot=args.screenshot,
        replay_out=args.replay_out,
        replay=args.replay,
        size=size,
        gif=args.gif,
    )
