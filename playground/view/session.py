"""A level as the view runs it: the built :class:`Show` and one :class:`Session` per (re)start —
the intent source (keyboard, the level's script, or a replay), the recorder, and the mouse's
pull on a grabbed body, all fed to the world through its stage hooks.

The keyboard becomes the player's :class:`~playground.intents.Intent` in the world's INPUTS
stage through one path (:meth:`Session.input_hook`), which also records the replay — so a replay
played back headless feeds exactly the intents the window fed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from playground.controller.mouse import Grab, MouseSpring
from playground.intents import Intent, IntentSource
from playground.scene.replay import Recorder, Replay
from playground.vec import Vec
from playground.view.keyboard import Keyboard
from playground.view.overlay import Overlay
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = ["Session", "Show", "nearest", "roles_of"]


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

    def overlays(self) -> Overlay:
        """The overlays the level asks for in its ``[view]`` table (else the default: force
        vectors and the compass), whatever was on before: a level looks the same however it
        is reached."""
        names = getattr(getattr(getattr(self.scene, "level", None), "view", None), "overlays", None)
        return Overlay.from_names(names) if names is not None else Overlay()

    def watched(self) -> str | None:
        """The body the HUD and the scope watch unless one is selected: the player; else the body
        the camera follows; else the first tracked body (None: no body is tracked)."""
        world = self.world
        tracked = [n for n in (world.name_of(b) for b in world.tracked_bodies) if n is not None]
        return next((n for n in (self.player, self.follow, *tracked) if n in tracked), None)


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

    def key_down(self, key: int) -> None:
        """A player key went down. The first one takes over from the level's script, keeping
        what the script held (see :meth:`Keyboard.take_over`)."""
        if not self.keyboard.touched and self.script is not None and self.playback is None:
            self.keyboard.take_over(self.current)
        self.keyboard.key_down(key)

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
        APPLIED force at the grabbed point (see :mod:`playground.controller.mouse`)."""
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


def roles_of(show: Any) -> dict[str, str]:
    """Actor name → role (player, enemy, other) of a :class:`Show`: the
    level's ``role`` when it gives one; otherwise the show's player is the player and any other
    actor is other."""
    roles: dict[str, str] = {}
    actors = getattr(getattr(getattr(show, "scene", None), "level", None), "actors", None) or ()
    declared = {a.name: a.role for a in actors if getattr(a, "role", None) is not None}
    for name in show.controllers:
        roles[name] = declared.get(name, "player" if name == show.player else "other")
    return roles


def nearest(here: Vec, candidates: Sequence[tuple[str, Vec]]) -> str | None:
    """The name of the candidate (name, position m) nearest ``here`` (m), or None.

    >>> nearest((0.0, 0.0), [("a", (3.0, 0.0)), ("b", (1.0, 1.0))])
    'b'
    """
    best: tuple[float, str] | None = None
    for name, p in candidates:
        d = math.hypot(p[0] - here[0], p[1] - here[1])
        if best is None or d < best[0]:
            best = (d, name)
    return best[1] if best is not None else None
