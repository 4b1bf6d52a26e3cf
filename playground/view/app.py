"""The desktop app: a window (or an off-screen surface), the keyboard, a fixed-step accumulator and
the frame loop that steps physics at the level's dt and draws at the display's rate.

Physics and rendering are independent: each frame adds its wall time (× the speed factor) to an
accumulator and runs as many whole physics steps as fit; drawing only reads the world. The
keyboard becomes the player's :class:`~playground.intents.Intent` in the world's INPUTS stage,
through one path (:meth:`Session.input_hook`), which also records the replay — so a replay played
back headless feeds exactly the intents the window fed.

>>> acc = Accumulator(dt=0.01)
>>> acc.advance(0.025), acc.advance(0.006), acc.advance(0.0, speed=2.0)
(2, 1, 0)
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pygame
import pymunk

from playground.intents import Intent, IntentSource
from playground.mouse import Grab, MouseSpring
from playground.replay import Recorder, Replay
from playground.view.arrows import G0, MIN_ARROW_PX, arrow_length, body_size, weight_pixels
from playground.view.camera import Camera
from playground.view.capture import save_picture
from playground.view.draw import COLOURS, draw_arrow, draw_grid
from playground.view.hud import Hud, HudInfo, StageCosts
from playground.view.overlay import OVERLAY_KEYS, Overlay, Painter, nearest, roles_of
from playground.view.scope import Scope
from playground.view.tuning import Knobs, TuningPanel
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "CONTROLS",
    "Accumulator",
    "App",
    "Keyboard",
    "Session",
    "Show",
    "display_available",
]

Vec = tuple[float, float]

MAX_STEPS_PER_FRAME = 32  # physics steps run at most per frame; beyond that the view falls behind
SPEEDS = (0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0)  # slow motion … fast forward, × real time
HEADLESS_FRAME = 1.0 / 60.0  # s of wall time a headless frame stands for
ZOOM_STEP = 1.25  # zoom factor per key press or wheel notch
DRAG_START_PX = 4.0  # px: a press that moves farther than this drags; otherwise it is a click
PICK_PX = 6.0  # px: a click this close to a body's outline picks it
MOUSE_COLOUR = COLOURS["mouse"]
MAX_FPS = 240  # Hz: drawing is capped here when the display does not sync to its refresh


@dataclass(slots=True)
class Show:
    """A built level as the view sees it.

    Attributes:
        name: the level's name (stored in replays).
        world: the world, ready to step.
        title, description: for the HUD.
        controllers: controllers by body name (the player and enemies).
        player: the body name the keyboard drives (None: nobody).
        follow: the body name the camera follows (None: fixed camera).
        camera: the camera centre at start, m.
        pixels_per_metre: the zoom at start, px/m.
        roll: start with the camera rolling with the followed body's perceived up.
        scene: the :class:`playground.scene.Scene` it was built from, if any.
    """

    name: str
    world: World
    title: str
    description: str = ""
    controllers: Mapping[str, Any] = field(default_factory=dict)
    player: str | None = None
    follow: str | None = None
    camera: Vec = (0.0, 0.0)
    pixels_per_metre: float = 40.0
    roll: bool = False
    scene: Any = None


class Accumulator:
    """Turns wall time into whole physics steps of ``dt`` seconds (a fixed-step accumulator)."""

    def __init__(self, dt: float, max_steps: int = MAX_STEPS_PER_FRAME) -> None:
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt: expected a number of seconds > 0, got {dt!r}")
        self.dt = dt
        self.max_steps = max_steps
        self._acc = 0.0

    def advance(self, elapsed: float, speed: float = 1.0) -> int:
        """Add ``elapsed`` s of wall time at ``speed`` × and return the steps to run now."""
        self._acc += max(elapsed, 0.0) * speed
        # A small tolerance so 0.025 s at dt 0.01 gives 2 steps, not 1 because of rounding.
        n = int((self._acc + 1e-9 * self.dt) // self.dt)
        if n > self.max_steps:
            n = self.max_steps
            self._acc = 0.0
        else:
            self._acc -= n * self.dt
        return n

    def reset(self) -> None:
        self._acc = 0.0


# -- input ---------------------------------------------------------------------------------------

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
    ("4 / 5", "toggle perceived gravity / world-up compass"),
    ("C", "toggle camera roll"),
    ("F12", "screenshot"),
    ("T", "tuning panel (sliders; R restores the level's values)"),
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
        self._flip_pending = False
        self._restore_pending = False
        self._nullify_pending = False

    def key_down(self, key: int) -> None:
        self.held.add(key)
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

    def _axis(self, minus: tuple[int, ...], plus: tuple[int, ...]) -> float:
        return float(any(k in self.held for k in plus)) - float(any(k in self.held for k in minus))

    def intent(self, gravity: Vec | None, target: str | None) -> Intent:
        """The intent now. ``gravity``: the gravity at the player (m/s²), used to flip it;
        ``target``: the body to nullify when X was pressed. One-shot actions are consumed."""
        flip: Vec | None = None
        if self._flip_pending and gravity is not None and gravity != (0.0, 0.0):
            flip = (-gravity[0], -gravity[1])
        restore = self._restore_pending
        nullify = target if self._nullify_pending else None
        self._flip_pending = self._restore_pending = self._nullify_pending = False
        return Intent(
            move=self._axis((pygame.K_a, pygame.K_LEFT), (pygame.K_d, pygame.K_RIGHT)),
            jump=pygame.K_SPACE in self.held,
            grab=self.grab,
            push=pygame.K_f in self.held,
            climb=self._axis((pygame.K_s, pygame.K_DOWN), (pygame.K_w, pygame.K_UP)),
            gravity=flip,
            restore_gravity=restore,
            nullify=nullify,
        )


# -- session: one run of one level ---------------------------------------------------------------


class Session:
    """One run of a level: the show, the intent source (keyboard or a replay) and the recorder.

    :meth:`input_hook` runs once per step in the world's INPUTS stage: it takes the intent from
    the replay, or from the level's script until the first player key, or from the keyboard;
    records it; and hands it to the player's controller, whose intent source the session becomes.
    """

    def __init__(self, show: Show, replay: Replay | None = None) -> None:
        self.show = show
        self.keyboard = Keyboard()
        self.playback = replay
        self.recorder: Recorder | None = None
        self.current = Intent()
        self.script: IntentSource | None = None
        self.grab: Grab | None = None
        """What the mouse holds now (None: nothing); pulled toward in every step's CONTROL stage."""
        self.spring = MouseSpring()
        self.altered: set[str] = set()
        """What changed the run besides the recorded intents and drags ("live tuning"): a replay
        of this session then does not reproduce it."""
        self.pull: tuple[Vec, Vec] | None = None
        """The last step's mouse force (N) and the world point it acted at (m), or None."""
        show.world.on(Stage.CONTROL, self.pull_hook)
        player = show.player
        if player is not None and player in show.controllers:
            self.recorder = Recorder(level=show.name, dt=show.world.config.dt, actor=player)
            ctrl = show.controllers[player]
            if hasattr(ctrl, "source"):
                # The level's script plays until the first key, then the keyboard takes over.
                self.script = ctrl.source
                ctrl.source = self
            show.world.on(Stage.INPUTS, self.input_hook)
        elif replay is not None:
            raise ValueError(f"{show.name}: the replay drives {replay.actor!r}, not a controller")

    @property
    def world(self) -> World:
        return self.show.world

    @property
    def player(self) -> Any:
        p = self.show.player
        return self.show.controllers.get(p) if p is not None else None

    def nearest_enemy(self) -> str | None:
        """The enemy closest to the player whose gravity is not nullified yet (what X acts on),
        or None."""
        p = self.show.player
        if p is None or p not in self.world.names:
            return None
        here = self.world.body(p).position
        roles = roles_of(self.show)
        candidates = [
            (name, (self.world.body(name).position.x, self.world.body(name).position.y))
            for name, role in roles.items()
            if role == "enemy" and name != p and self.world.gravity_rule(name).scale != 0.0
        ]
        return nearest((here.x, here.y), candidates)

    def input_hook(self, world: World) -> None:
        """INPUTS stage: the player's intent for this step (keyboard or replay), recorded."""
        assert self.show.player is not None and self.recorder is not None
        if self.show.player not in world.names:
            return  # an event took the player out: nobody to steer
        if self.playback is not None:
            intent = self.playback.intent_at(world.steps)
        elif self.script is not None and not self.keyboard.touched:
            intent = self.script.intent(world.time)
        else:
            intent = self.keyboard.intent(world.gravity_at(self.show.player), self.nearest_enemy())
        self.current = intent
        self.player.intent = intent
        self.recorder.record(world.steps, intent)

    def pull_hook(self, world: World) -> None:
        """CONTROL stage: the mouse spring's force on the grabbed body, into the ledger as an
        APPLIED force at the grabbed point (see :mod:`playground.mouse`)."""
        grab = self.playback.grab_at(world.steps) if self.playback is not None else self.grab
        if self.recorder is not None:
            self.recorder.record_grab(world.steps, grab)
        pull = self.spring.apply(world, grab)
        self.pull = None if pull is None else (pull.force, pull.point)

    def intent(self, t: float) -> Intent:
        """The player's intent source (replaces a level's script): this step's intent."""
        return self.current

    def replay(self) -> Replay | None:
        return self.recorder.replay() if self.recorder is not None else None


# -- the app -------------------------------------------------------------------------------------


def display_available() -> bool:
    """Whether a real display can be opened (an X11/Wayland session, or not Linux)."""
    driver = os.environ.get("SDL_VIDEODRIVER", "")
    if driver in ("dummy", "offscreen"):
        return False
    session = bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
    return session or not sys.platform.startswith("linux")


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
        self._render_hz = 0.0
        self._physics_hz = 0.0
        self._costs = StageCosts()
        self._replay_in = replay
        self.finished: list[Replay] = []
        self.selected: str | None = None
        """The body the HUD and the scope follow when picked with the mouse (None: the player)."""
        self._press: tuple[Vec, str | None, Vec] | None = None  # screen px, body, anchor (m)
        self._cursor: Vec | None = None  # screen px while dragging
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
        self.painter = Painter(_overlay_hint(show, self.painter.overlay))
        self.scope = Scope(
            seconds=4.0,
            dt=world.config.dt,
            **_scope_of(world, _scope_body(show)),
        )
        self._scope_steps = -1
        self.selected = None
        self._press = None
        self._cursor = None
        self.tuning.show(self._knobs())
        self._costs = StageCosts()
        self._follow(0.0)

    def _cycle(self, delta: int) -> None:
        i = self.levels.index(self.level) if self.level in self.levels else 0
        self.start(self.levels[(i + delta) % len(self.levels)])

    # -- events ----------------------------------------------------------------------------------

    def handle(self, event: pygame.event.Event) -> None:
        """Handle one pygame event (keys, wheel, quit)."""
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

    # -- mouse -----------------------------------------------------------------------------------

    def _mouse_down(self, pos: Vec) -> None:
        """A press on the tuning panel moves a slider; elsewhere it picks the body under the
        cursor (and selects it); moving on drags it."""
        if self.tuning.press(pos):
            return
        at = self.camera.to_world(pos)
        name = self.world.body_at(at, PICK_PX / self.camera.zoom)
        anchor: Vec = (0.0, 0.0)
        if name is not None:
            local = self.world.body(name).world_to_local(at)
            anchor = (local.x, local.y)
        self._press = (pos, name, anchor)
        self.select(name)

    def _mouse_move(self, pos: Vec) -> None:
        if self.tuning.drag(pos):
            return
        press = self._press
        if press is None:
            return
        start, name, anchor = press
        if self._cursor is None and math.dist(start, pos) <= DRAG_START_PX:
            return
        if name is None or self.world.body(name).body_type != pymunk.Body.DYNAMIC:
            return
        self._cursor = pos
        self.session.grab = Grab(name, anchor, self.camera.to_world(pos))

    def _mouse_up(self) -> None:
        self.tuning.release()
        self._press = None
        self._cursor = None
        self.session.grab = None

    def select(self, name: str | None) -> None:
        """Make the HUD and the scope follow the dynamic body ``name`` (None or anything else:
        the player). An untracked body is tracked from now on (tracking only reads)."""
        if name is not None and (
            name not in self.world.names or self.world.body(name).body_type != pymunk.Body.DYNAMIC
        ):
            name = None
        if name is not None and self.world.solver.row_of(self.world.body(name)) is None:
            self.world.track(name)
        if name != self.selected:
            self.selected = name
            focus = self.focus
            self.scope = Scope(
                seconds=self.scope.seconds,
                dt=self.world.config.dt,
                **_scope_of(self.world, focus),
            )
            self._scope_steps = -1

    @property
    def focus(self) -> str | None:
        """The body whose forces the HUD and the scope show: the selected body, or by default the
        player (else the followed body, else the first tracked one)."""
        if self.selected is not None and self.selected in self.world.names:
            return self.selected
        return _scope_body(self.session.show)

    def _key(self, key: int) -> None:
        kb = self.session.keyboard
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
            kb.key_down(key)

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
        self._sample()

    def _sample(self) -> None:
        p = self.scope.name or None
        if p is None or self.world.steps == self._scope_steps:
            return
        try:
            reading = self.world.forces(p)
            pg = self.world.perceived_gravity(p)
        except KeyError:
            return
        m = self.world.body(p).mass
        self.scope.push(math.hypot(*reading.support), m * math.hypot(*pg))
        self._scope_steps = self.world.steps

    def frame(self, elapsed: float) -> int:
        """Advance one frame of ``elapsed`` s of wall time: physics steps, then the camera.
        Returns the number of physics steps run."""
        if self.tuning.changed and self.tuning.knobs is not None:
            self.tune(self.tuning.knobs)
        n = 0 if self.paused else self.accumulator.advance(elapsed, self.speed)
        grab = self.session.grab
        if grab is not None and self._cursor is not None:
            # The hand stays under the cursor while the camera follows something else.
            self.session.grab = dataclasses.replace(grab, target=self.camera.to_world(self._cursor))
        for _ in range(n):
            self.step()
        self._follow(elapsed)
        self._costs.update(self.world.timings, elapsed)
        if elapsed > 0.0:
            # Rates are smoothed over about half a second; the first frame sets them.
            a = 1.0 if self.frames == 0 else min(elapsed / 0.5, 1.0)
            self._render_hz += a * (1.0 / elapsed - self._render_hz)
            self._physics_hz += a * (n / elapsed - self._physics_hz)
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
        surf = self.surface
        surf.fill(COLOURS["background"])
        draw_grid(surf, self.camera)
        show = self.session.show
        world = self.world
        self.painter.draw(
            surf,
            self.camera,
            world,
            show.controllers,
            roles_of(show),
            focus=self.selected
            if self.selected is not None
            else (show.follow if show.follow in show.controllers else show.player),
            nullify_target=self.session.nearest_enemy(),
        )
        self._draw_mouse(surf)
        ctrl = self.session.player
        state = getattr(getattr(ctrl, "state", None), "value", None)
        notes = ["H: controls"]
        if self.session.keyboard.flipped:
            notes.append("own gravity flipped (G restores)")
        notes.extend(self._focus_notes())
        if self.session.playback is not None:
            notes.append("replaying")
        elif self.session.script is not None and not self.session.keyboard.touched:
            notes.append("scripted demo: press a key to take over")
        self.hud.draw(
            surf,
            HudInfo(
                title=show.title,
                sim_time=world.time,
                physics_hz=self._physics_hz,
                render_hz=self._render_hz,
                speed=self.speed,
                paused=self.paused,
                state=str(state) if state is not None else None,
                stage_costs={} if self.compact else self._costs.means,
                notes=[] if self.compact else notes,
            ),
            self.scope if self.scope.name else None,
        )
        right = self.size[0] - 8
        if self.compact:
            panel = pygame.Rect(right, 8, 0, 0)
        else:
            panel = self.painter.draw_panel(surf, self.small, (right, 8))
        font = self.tiny if self.compact else self.small
        legend = self.painter.draw_legend(surf, font, (right, panel.bottom + 4))
        self.hud.rects += [panel, legend]
        compass = self.painter.draw_compass(
            surf, self.small, self.camera, (right - 60, legend.bottom + 60)
        )
        if compass is not None:
            self.hud.rects.append(compass)
        if self.tuning.visible:
            below = max((r.bottom for r in self.hud.rects[:2]), default=0)
            self.hud.rects.append(self.tuning.draw(surf, (8, below + 4)))
        if self.show_help:
            self.hud.draw_help(surf, CONTROLS, show.description)
        return surf

    # -- live tuning -----------------------------------------------------------------------------

    def _knobs(self) -> Knobs:
        """The values the tuning panel edits, as the world and the player's controller have them."""
        cfg = self.world.config
        hover = getattr(self.session.player, "config", None)
        return Knobs(
            hover_frequency=getattr(hover, "hover_frequency", None),
            hover_damping=getattr(hover, "hover_damping", None),
            min_cutoff=cfg.perception.min_cutoff,
            beta=cfg.perception.beta,
            dt=cfg.dt,
            substeps=cfg.substeps,
        )

    def tune(self, knobs: Knobs) -> None:
        """Apply ``knobs`` between two steps (they act from the next step on): dt and substeps
        to the world (and the accumulator), the 1€ parameters to perceived gravity, the hover to
        the player's controller. The hover frequency is first kept below its limit at the new dt."""
        knobs = knobs.stable()
        world = self.world
        cfg = world.config
        if (knobs.dt, knobs.substeps) != (cfg.dt, cfg.substeps):
            world.config = dataclasses.replace(cfg, dt=knobs.dt, substeps=knobs.substeps)
            self.accumulator.dt = knobs.dt
            if knobs.dt != cfg.dt:
                self.scope = Scope(
                    seconds=self.scope.seconds, dt=knobs.dt, **_scope_of(world, self.scope.name)
                )
        p = cfg.perception
        if (knobs.min_cutoff, knobs.beta) != (p.min_cutoff, p.beta):
            world.set_perception(
                dataclasses.replace(p, min_cutoff=knobs.min_cutoff, beta=knobs.beta)
            )
        ctrl = self.session.player
        if knobs.hover_frequency is not None and knobs.hover_damping is not None:
            ctrl.tune_hover(knobs.hover_frequency, knobs.hover_damping)
        self.session.altered.add("live tuning")
        self.tuning.show(self._knobs())
        self.tuning.changed = False

    def _draw_mouse(self, surf: pygame.Surface) -> None:
        """The selected body's marker, and the mouse spring: a band from the grabbed point to the
        cursor and its force arrow (the very force put in the ledger)."""
        world, cam = self.world, self.camera
        if self.selected is not None and self.selected in world.names:
            body = world.body(self.selected)
            c = body.local_to_world(body.center_of_gravity)
            pygame.draw.circle(surf, MOUSE_COLOUR, cam.to_screen((c.x, c.y)), 5, 2)
        grab, pull = self.session.grab, self.session.pull
        if grab is None or grab.body not in world.names:
            return
        body = world.body(grab.body)
        p = body.local_to_world(grab.anchor)
        start = cam.to_screen((p.x, p.y))
        pygame.draw.line(surf, MOUSE_COLOUR, start, cam.to_screen(grab.target), 1)
        pygame.draw.circle(surf, MOUSE_COLOUR, start, 4)
        n = math.hypot(*pull[0]) if pull is not None else 0.0
        length = arrow_length(n, body.mass, weight_pixels(body_size(body), cam.zoom))
        if pull is not None and math.isfinite(n) and length >= MIN_ARROW_PX:
            sx, sy = cam.vector((pull[0][0] / n, pull[0][1] / n))
            k = length / math.hypot(sx, sy)
            draw_arrow(surf, MOUSE_COLOUR, cam.to_screen(pull[1]), (sx * k, sy * k), 3)
            self.painter.drawn.add("mouse")

    def _focus_notes(self) -> list[str]:
        """HUD lines for the selected body: its name, support and applied forces, the mouse's."""
        name = self.selected
        if name is None or name not in self.world.names:
            return []
        try:
            reading = self.world.forces(name)
        except KeyError:
            return []
        lines = [
            f"selected: {name} (click empty space: player)",
            f"  support {math.hypot(*reading.support):7.1f} N   "
            f"applied {math.hypot(*reading.applied):7.1f} N",
        ]
        pull = self.session.pull
        if pull is not None and self.session.grab is not None:
            lines.append(f"  mouse ({self.session.grab.body}) {math.hypot(*pull[0]):7.1f} N")
        return lines

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

    def replays(self) -> list[Replay]:
        """Replays of every finished session and the current one."""
        now = self.session.replay()
        return [*self.finished, *([now] if now is not None and now.steps else [])]


def _overlay_hint(show: Show, current: Overlay) -> Overlay:
    """The overlays the level asks for in its ``[view]`` table (else the ones on now)."""
    names = getattr(getattr(getattr(show.scene, "level", None), "view", None), "overlays", None)
    return Overlay.from_names(names) if names is not None else current


def _scope_body(show: Show) -> str | None:
    """The scope's body unless one is selected: the player; else the body the camera follows;
    else the first tracked body."""
    world = show.world
    tracked = [n for n in (world.name_of(b) for b in world.solver.bodies) if n is not None]
    return next((n for n in (show.player, show.follow, *tracked) if n in tracked), None)


def _scope_of(world: World, name: str | None) -> dict[str, Any]:
    """The scope's body and its weight m·g (N; g₀ where it feels no gravity)."""
    if name is None or name not in world.names:
        return {}
    g = math.hypot(*world.gravity_at(name))
    return {"name": name, "weight": world.body(name).mass * (g if g > 0.0 else G0)}
