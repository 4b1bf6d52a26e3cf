"""The desktop app: a window (or an off-screen surface), the frame loop that steps physics at the
level's dt and draws at the display's rate, the app's own keys (pause, speed, zoom, overlays,
levels) and the picture of one frame: the world, the overlays, the HUD, the panels.

A level runs as a :class:`~playground.view.session.Session` (re)made at every start; time comes
from :mod:`playground.view.clock`, the player's keys from :mod:`playground.view.keyboard`, the
mouse from :mod:`playground.view.pointer`.
"""

from __future__ import annotations

import dataclasses
import math
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import pygame
import pymunk

from playground.scene.replay import Replay
from playground.vec import Vec
from playground.view.camera import Camera
from playground.view.capture import save_picture
from playground.view.clock import HEADLESS_FRAME, SPEEDS, Accumulator
from playground.view.frame import Drawers, Picture, draw_frame
from playground.view.free_body import free_body
from playground.view.hud import MARGIN, Hud, HudInfo, StageCosts
from playground.view.keyboard import CONTROLS
from playground.view.lab import Action, LabPanel
from playground.view.overlay import OVERLAY_KEYS, Overlay
from playground.view.painter import Painter
from playground.view.pointer import Pointer, focus_notes
from playground.view.scope import scope_on
from playground.view.session import Session, Show, roles_of
from playground.view.tuning import Knobs, TuningPanel
from playground.world.world import World

__all__ = ["App"]

ZOOM_STEP = 1.25  # zoom factor per key press or wheel notch
MAX_FPS = 240  # Hz: drawing is capped here when the display does not sync to its refresh
KEEP_IN_VIEW = 0.15  # the followed body stays at least this share of the window inside its edges


class App:
    """The view: a surface, a camera, the HUD, and a :class:`Session` per (re)start of a level.

    ``load(name)`` builds a level into a :class:`Show`; ``levels`` is the order for next/previous.
    """

    def __init__(
        self,
        load: Callable[[str], Show],
        level: str,
        *,
        levels: Sequence[str] = (),
        size: tuple[int, int] = (1280, 720),
        surface: pygame.Surface | None = None,
        replay: Replay | None = None,
    ) -> None:
        self.load = load
        self.levels = list(levels) or [level]
        self.surface = surface if surface is not None else pygame.Surface(size)
        self.size = self.surface.get_size()
        self.font = pygame.font.Font(None, 26)
        self.small = pygame.font.Font(None, 20)
        self.tiny = pygame.font.Font(None, 16)
        self.hud = Hud(self.font, self.small)
        self.painter = Painter()
        self.show_help = False
        self.compact = False
        """Leave out the stage costs, the notes and the overlay panel, and write the legend small
        (small pictures, GIFs)."""
        self.tuning = TuningPanel(self.small)
        self.paused = False
        self.speed_index = SPEEDS.index(1.0)
        self.running = True
        self.frames = 0
        self.render_hz = 0.0
        """Frames drawn per second of wall time, smoothed over about half a second."""
        self.physics_hz = 0.0
        """Physics steps per second of wall time, smoothed likewise."""
        self.costs = StageCosts()
        self._replay_in = replay
        self.finished: list[Replay] = []
        self.selected: str | None = None
        """The body the HUD and the scope follow when picked with the mouse (None: the player)."""
        self.pointer = Pointer()
        self.lab = LabPanel(self.size, self.levels)
        self.level = level
        self.start(level)

    # -- levels ----------------------------------------------------------------------------------

    def start(self, level: str) -> None:
        """(Re)start ``level``: a fresh world, camera, scope and recorder."""
        old = getattr(self, "session", None)
        if old is not None:
            done = old.replay()
            if done is not None and done.steps:
                self.finished.append(done)
        self.level = level
        show = self.load(level)
        world = show.world
        # Timing only reads the clock around each stage; the physics is the same with it on.
        world.config = dataclasses.replace(world.config, timing=True)
        replay = (
            self._replay_in
            if self._replay_in is not None and self._replay_in.level == level
            else None
        )
        self.session = Session(show, replay)
        self.accumulator = Accumulator(world.config.dt)
        self.camera = Camera(
            size=self.size, pixels_per_metre=show.pixels_per_metre, centre=show.camera
        )
        self.roll = show.roll
        self.painter = Painter(show.overlays())
        self.scope = scope_on(world, show.watched(), 4.0, world.config.dt)
        self.selected = None
        self.pointer = Pointer()
        self.tuning.show(Knobs.of(world, self.session.player))
        self.lab.level_started(level, self.overlay, self._knobs())
        self.costs = StageCosts()
        self._follow(0.0)

    def _cycle(self, delta: int) -> None:
        i = self.levels.index(self.level) if self.level in self.levels else 0
        self.start(self.levels[(i + delta) % len(self.levels)])

    # -- events ----------------------------------------------------------------------------------

    def handle(self, event: pygame.event.Event) -> None:
        """Handle one pygame event (keys, wheel, quit, and the lab panel's own)."""
        action = self.lab.action(event)
        if action is not None:
            self._act(action)
            return
        if self.lab.process(event):
            return
        if event.type == pygame.QUIT:
            self.running = False
        elif event.type == pygame.KEYDOWN:
            self._key(event.key)
        elif event.type == pygame.KEYUP:
            self.session.keyboard.key_up(event.key)
        elif event.type == pygame.MOUSEWHEEL:
            self.camera.zoom_by(ZOOM_STEP ** float(event.y))
        elif event.type == pygame.VIDEORESIZE:
            self.resize(event.size)
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == pygame.BUTTON_LEFT:
            self._mouse_down(event.pos)
        elif event.type == pygame.MOUSEMOTION:
            self._mouse_move(event.pos)
        elif event.type == pygame.MOUSEBUTTONUP and event.button == pygame.BUTTON_LEFT:
            self._mouse_up()

    def _act(self, action: Action) -> None:
        """Carry out what the lab panel asked for."""
        if action.kind == "level" and isinstance(action.value, str):
            self.start(action.value)
        elif action.kind == "restart":
            self.start(self.level)
        elif action.kind == "pause":
            self.paused = not self.paused
        elif action.kind == "step":
            self.paused = True
            self.step()
        elif action.kind == "overlay" and isinstance(action.value, Overlay):
            self.overlay = action.value
        elif action.kind == "knobs" and isinstance(action.value, Knobs):
            self.tune(action.value)

    # -- mouse -----------------------------------------------------------------------------------

    def _mouse_down(self, pos: Vec) -> None:
        """A press on the tuning panel moves a slider; elsewhere it picks the body under the
        cursor (and selects it); moving on drags it."""
        if not self.tuning.press(pos):
            self.select(self.pointer.down(pos, self.world, self.camera))

    def _mouse_move(self, pos: Vec) -> None:
        if self.tuning.drag(pos):
            return
        grab = self.pointer.move(pos, self.world, self.camera)
        if grab is not None:
            self.session.grab = grab

    def _mouse_up(self) -> None:
        self.tuning.release()
        self.pointer.up()
        self.session.grab = None

    def select(self, name: str | None) -> None:
        """Make the HUD and the scope follow the dynamic body ``name`` (None or anything else:
        the player). An untracked body is tracked from now on (tracking only reads)."""
        if name is not None and (
            name not in self.world.names or self.world.body(name).body_type != pymunk.Body.DYNAMIC
        ):
            name = None
        if name is not None and not self.world.is_tracked(name):
            self.world.track(name)
        if name != self.selected:
            self.selected = name
            focus = self.focus
            self.scope = scope_on(self.world, focus, self.scope.seconds, self.world.config.dt)

    @property
    def focus(self) -> str | None:
        """The body whose forces the HUD and the scope show: the selected body, or by default the
        player (else the followed body, else the first tracked one)."""
        if self.selected is not None and self.selected in self.world.names:
            return self.selected
        return self.session.show.watched()

    def _key(self, key: int) -> None:
        if key == pygame.K_ESCAPE:
            self.running = False
        elif key == pygame.K_r:
            self.start(self.level)
        elif key == pygame.K_p:
            self.paused = not self.paused
        elif key == pygame.K_PERIOD:
            if self.paused:
                self.step()
        elif key == pygame.K_LEFTBRACKET:
            self.speed_index = max(self.speed_index - 1, 0)
        elif key == pygame.K_RIGHTBRACKET:
            self.speed_index = min(self.speed_index + 1, len(SPEEDS) - 1)
        elif key == pygame.K_BACKSLASH:
            self.speed_index = SPEEDS.index(1.0)
        elif key == pygame.K_MINUS:
            self.camera.zoom_by(1.0 / ZOOM_STEP)
        elif key == pygame.K_EQUALS:
            self.camera.zoom_by(ZOOM_STEP)
        elif key == pygame.K_PAGEUP:
            self._cycle(-1)
        elif key == pygame.K_PAGEDOWN:
            self._cycle(1)
        elif key in OVERLAY_KEYS:
            self.overlay = self.overlay.toggled(OVERLAY_KEYS[key][0])
            self.lab.sync(self.overlay, self._knobs())
        elif key == pygame.K_l:
            self.lab.show(not self.lab.visible)
        elif key == pygame.K_c:
            self.roll = not self.roll
        elif key == pygame.K_h:
            self.show_help = not self.show_help
        elif key == pygame.K_t:
            self.tuning.visible = not self.tuning.visible
        elif key == pygame.K_F12:
            shot = self.screenshot(Path(f"playground-{self.level}-{self.world.steps:06d}.png"))
            print(f"playground play: screenshot saved to {shot.resolve()}", file=sys.stderr)
        else:
            self.session.key_down(key)

    # -- time ------------------------------------------------------------------------------------

    @property
    def world(self) -> World:
        return self.session.world

    @property
    def overlay(self) -> Overlay:
        """Which overlays are drawn."""
        return self.painter.overlay

    @overlay.setter
    def overlay(self, value: Overlay) -> None:
        self.painter.overlay = value

    @property
    def speed(self) -> float:
        return SPEEDS[self.speed_index]

    def step(self) -> None:
        """One physics step, then feed the scope."""
        self.world.step()
        self.painter.sample(self.world)
        self.scope.read(self.world)

    def frame(self, elapsed: float) -> int:
        """Advance one frame of ``elapsed`` s of wall time: physics steps, then the camera.
        Returns the number of physics steps run."""
        if self.tuning.changed and self.tuning.knobs is not None:
            self.tune(self.tuning.knobs)
        n = 0 if self.paused else self.accumulator.advance(elapsed, self.speed)
        grab = self.session.grab
        cursor = self.pointer.cursor
        if grab is not None and cursor is not None:
            # The hand stays under the cursor while the camera follows something else.
            self.session.grab = dataclasses.replace(grab, target=self.camera.to_world(cursor))
        for _ in range(n):
            self.step()
        self._follow(elapsed)
        self.costs.update(self.world.timings, elapsed)
        self.lab.update(elapsed, self.world, self.costs.means)
        if elapsed > 0.0:
            # Rates are smoothed over about half a second; the first frame sets them.
            a = 1.0 if self.frames == 0 else min(elapsed / 0.5, 1.0)
            self.render_hz += a * (1.0 / elapsed - self.render_hz)
            self.physics_hz += a * (n / elapsed - self.physics_hz)
        self.frames += 1
        return n

    def _follow(self, elapsed: float) -> None:
        name = self.session.show.follow
        if name is None or name not in self.world.names:
            self.camera.roll_toward(None, elapsed)
            return
        body = self.world.body(name)
        c = body.local_to_world(body.center_of_gravity)
        if elapsed == 0.0:
            self.camera.centre = (c.x, c.y)
        else:
            self.camera.follow((c.x, c.y), elapsed)
            # Following lags a fast body by speed × follow time: never let it leave the window.
            self.camera.keep_in_view((c.x, c.y), KEEP_IN_VIEW)
        up: Vec | None = None
        if self.roll:
            try:
                up = self.world.perceived_up(name)
            except KeyError:
                up = None
        if elapsed == 0.0 and up is not None:
            self.camera.roll_toward(up, math.inf)
        else:
            self.camera.roll_toward(up, elapsed)

    # -- drawing ---------------------------------------------------------------------------------

    def render(self) -> pygame.Surface:
        """Draw the world, the overlays and the HUD onto :attr:`surface`."""
        drawers = Drawers(self.painter, self.hud, self.tuning, self.small, self.tiny)
        surf = draw_frame(self.surface, self.picture(), drawers)
        lab = self.lab.draw(surf, self.small)
        if lab is not None:
            self.hud.rects.append(lab)
        return surf

    def picture(self) -> Picture:
        """What this frame shows, read from the session, the world and the app's own state."""
        session = self.session
        show = session.show
        world = self.world
        state = getattr(getattr(session.player, "state", None), "value", None)
        watched = self.focus
        diagram = None
        if self.overlay.free_body and not self.compact and watched is not None:
            diagram = free_body(world, watched, show.controllers.get(watched))
        return Picture(
            world=world,
            camera=self.camera,
            controllers=show.controllers,
            roles=roles_of(show),
            focus=watched,
            selected=self.selected,
            nullify_target=session.nearest_enemy(),
            grab=session.grab,
            pull=session.pull,
            hud=HudInfo(
                title=show.title,
                sim_time=world.time,
                physics_hz=self.physics_hz,
                render_hz=self.render_hz,
                speed=self.speed,
                paused=self.paused,
                state=str(state) if state is not None else None,
                stage_costs={} if self.compact else self.costs.means,
                notes=[] if self.compact else self._notes(),
            ),
            scope=self.scope if self.scope.name else None,
            free_body=diagram,
            compact=self.compact,
            tuning=self.tuning.visible,
            help=(CONTROLS, show.description) if self.show_help else None,
            hud_left=self.lab.rect.right + MARGIN if self.lab.visible else MARGIN,
        )

    def _notes(self) -> list[str]:
        """The HUD's notes: the help key, a flipped gravity, the selected body, who plays."""
        session = self.session
        notes = ["H: controls"]
        if session.keyboard.flipped:
            notes.append("own gravity flipped (G restores)")
        notes.extend(focus_notes(self.world, self.selected, session.grab, session.pull))
        if session.playback is not None:
            notes.append("replaying")
        elif session.script is not None and not session.keyboard.touched:
            notes.append("scripted demo: press a key to take over")
        return notes

    # -- live tuning -----------------------------------------------------------------------------

    def _knobs(self) -> Knobs:
        """The values the tuning panel edits, as the world and the player's controller have them."""
        return Knobs.of(self.world, self.session.player)

    def tune(self, knobs: Knobs) -> None:
        """Apply ``knobs`` between two steps (they act from the next step on): dt and substeps
        to the world (and the accumulator), the 1€ parameters to perceived gravity, the hover to
        the player's controller. The hover frequency is first kept below its limit at the new dt."""
        knobs = knobs.stable()
        dt = self.world.config.dt
        knobs.apply(self.world, self.session.player)
        self.accumulator.dt = knobs.dt
        if knobs.dt != dt:
            self.scope = scope_on(self.world, self.scope.name, self.scope.seconds, knobs.dt)
        self.session.altered.add("live tuning")
        self.tuning.applied(self._knobs())
        self.lab.sync(self.overlay, self._knobs())

    def screenshot(self, path: Path) -> Path:
        """Save the current picture (type from the suffix: .png, .bmp, .tga, .jpg), whole or not
        at all."""
        self.render()
        return save_picture(self.surface, path)

    # -- loops -----------------------------------------------------------------------------------

    def run_frames(
        self,
        frames: int,
        frame_time: float = HEADLESS_FRAME,
        *,
        window: pygame.Surface | None = None,
        each: Any = None,
    ) -> None:
        """``frames`` frames of ``frame_time`` s each, drawing every frame: off screen, or shown in
        ``window`` if given. ``each.offer(surface)`` (e.g. a GIF writer) sees every drawn frame."""
        for _ in range(frames):
            if not self.running:
                break
            for event in pygame.event.get():
                self.handle(event)
            self.frame(frame_time)
            self.render()
            if each is not None:
                each.offer(self.surface)
            if window is not None:
                self._present()

    def run_window(self, window: pygame.Surface) -> None:
        """The interactive loop: events, physics by wall clock, draw, flip."""
        clock = time.perf_counter
        limiter = pygame.time.Clock()
        last = clock()
        while self.running:
            for event in pygame.event.get():
                self.handle(event)
            limiter.tick(MAX_FPS)
            now = clock()
            self.frame(min(now - last, 0.25))
            last = now
            self.render()
            self._present()

    def _present(self) -> None:
        """Show the drawn frame in the window (whatever its size is now)."""
        window = pygame.display.get_surface()
        if window is not None:
            window.blit(self.surface, (0, 0))
            pygame.display.flip()

    def resize(self, size: tuple[int, int]) -> None:
        """Draw at ``size`` (px) from now on: a window resized by its user."""
        w, h = max(int(size[0]), 1), max(int(size[1]), 1)
        if (w, h) == self.size:
            return
        self.surface = pygame.Surface((w, h))
        self.size = (w, h)
        self.camera.size = (w, h)
        self.lab.resize((w, h))

    def replays(self) -> list[Replay]:
        """Replays of every finished session and the current one."""
        now = self.session.replay()
        return [*self.finished, *([now] if now is not None and now.steps else [])]
