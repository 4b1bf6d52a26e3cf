"""Replays: the player's intents of a session, per physics step, in a small JSON file.

A replay stores, for one level and one dt, the step index at which each new intent started and
the intent itself (only the fields that differ from :class:`~playground.intents.Intent`'s defaults).
Steps, not times, are the key, so playing it back feeds exactly the same intent into exactly the
same step: same level + same replay ⇒ bit-identical trajectory. Python's JSON writes floats with
``repr``, which reads back to the same double.

Replays are core, not view: :class:`Playback` drives a built scene headless (``playground run
LEVEL --replay FILE``) without pygame-ce installed; the view records them and plays them back.

>>> from playground.intents import Intent
>>> rec = Recorder(level="sandbox", dt=0.01)
>>> for step, move in enumerate([0.0, 1.0, 1.0, -1.0]):
...     rec.record(step, Intent(move=move))
>>> replay = rec.replay()
>>> [(s, i.move) for s, i in replay.changes]
[(0, 0.0), (1, 1.0), (3, -1.0)]
>>> replay.intent_at(2).move, replay.steps
(1.0, 4)
>>> Replay.from_json(replay.to_json()) == replay
True
"""

from __future__ import annotations

import bisect
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import tomli_w
from pydantic import ValidationError

from playground.controller.mouse import Grab, MouseSpring
from playground.intents import Intent
from playground.level.explain import problems
from playground.level.replay_document import MAX_REPLAY_STEPS, ReplayDocument
from playground.level.timeline import IntentTable
from playground.world.schedule import Stage
from playground.world.world import World

if TYPE_CHECKING:
    from playground.scene import Scene

__all__ = [
    "FORMAT",
    "Playback",
    "Recorder",
    "Replay",
    "ReplayError",
    "intent_from_dict",
    "intent_to_dict",
]

FORMAT = "playground-replay"
VERSION = 1


class ReplayError(ValueError):
    """A replay file that cannot be read: says which file and what was expected."""


def intent_to_dict(intent: Intent) -> dict[str, Any]:
    """The fields of ``intent`` that differ from the defaults, as a level's ``[[inputs]]`` table
    holds them (:class:`~playground.level.timeline.IntentTable`; JSON-ready: lists, not tuples).

    >>> intent_to_dict(Intent(move=-1.0, jump=True))
    {'move': -1.0, 'jump': True}
    """
    return IntentTable.of(intent).table()


def intent_from_dict(data: dict[str, Any], where: str = "intent") -> Intent:
    """Rebuild an intent from :func:`intent_to_dict`'s output, validated as a level's input is
    (strict: no ``1`` for ``true``); a problem names ``where``, the key and what was expected."""
    try:
        return IntentTable.model_validate(data).intent()
    except ValidationError as exc:
        found = "; ".join(str(p) for p in problems(exc, IntentTable))
        raise ReplayError(f"{where}: {found}") from None


@dataclass(frozen=True, slots=True)
class Replay:
    """A level's name, its dt (s), the number of steps, and the intent changes (step, intent)."""

    level: str
    dt: float
    steps: int
    changes: tuple[tuple[int, Intent], ...]
    actor: str = "player"
    grabs: tuple[tuple[int, Grab | None], ...] = ()
    """What the mouse held from each step on (None: nothing), when it changed."""
    _steps: tuple[int, ...] = field(init=False, repr=False, compare=False)
    _grab_steps: tuple[int, ...] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        # The change steps once, not rebuilt on every lookup (a 36 000-step replay with 18 000
        # changes spent most of its time rebuilding this list).
        object.__setattr__(self, "_steps", tuple(s for s, _ in self.changes))
        object.__setattr__(self, "_grab_steps", tuple(s for s, _ in self.grabs))

    def grab_at(self, step: int) -> Grab | None:
        """What the mouse held at ``step`` (None before the first drag)."""
        i = bisect.bisect_right(self._grab_steps, step) - 1
        return self.grabs[i][1] if i >= 0 else None

    def intent_at(self, step: int) -> Intent:
        """The intent in force at ``step`` (the default intent before the first change), found by
        bisection: O(log n) in the number of changes."""
        i = bisect.bisect_right(self._steps, step) - 1
        return self.changes[i][1] if i >= 0 else Intent()

    def to_json(self) -> str:
        head = {
            "format": FORMAT,
            "version": VERSION,
            "level": self.level,
            "dt": self.dt,
            "steps": self.steps,
            "actor": self.actor,
        }
        # One line per change keeps long sessions diffable and readable.
        lines = [f" {json.dumps(k)}: {json.dumps(v)}," for k, v in head.items()]
        rows = ",\n".join(f"  {json.dumps([s, intent_to_dict(i)])}" for s, i in self.changes)
        grabs = ""
        if self.grabs:
            held = ",\n".join(f"  {json.dumps([s, _grab_to_dict(g)])}" for s, g in self.grabs)
            grabs = ',\n "grabs": [\n' + held + "\n ]"
        return "{\n" + "\n".join(lines) + '\n "changes": [\n' + rows + "\n ]" + grabs + "\n}"

    @classmethod
    def from_json(cls, text: str, where: str = "replay") -> Replay:
        """Parse a replay document; errors name ``where``, the key and what was expected."""
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as exc:
            raise ReplayError(f"{where}: not JSON ({exc})") from None
        except RecursionError:
            raise ReplayError(f"{where}: nested too deeply (a replay nests three levels)") from None
        except ValueError as exc:  # an integer of more digits than Python converts
            raise ReplayError(f"{where}: not a replay ({exc})") from None
        if not isinstance(doc, dict) or doc.get("format") != FORMAT:
            raise ReplayError(f"{where}: expected a JSON object with format {FORMAT!r}")
        try:
            head = ReplayDocument.model_validate(doc)
        except ValidationError as exc:
            found = "; ".join(str(p) for p in problems(exc, ReplayDocument))
            raise ReplayError(f"{where}: {found}") from None
        level, dt, steps = head.level, head.dt, head.steps
        changes: list[tuple[int, Intent]] = []
        last = -1
        for k, entry in enumerate(head.changes):
            here = f"{where}: changes[{k}]"
            if not _entry(entry) or not isinstance(entry[1], dict):
                raise ReplayError(f"{here}: expected [step, {{intent fields}}], got {entry!r}")
            if entry[0] <= last:
                raise ReplayError(f"{here}: steps must increase, got {entry[0]} after {last}")
            last = entry[0]
            changes.append((entry[0], intent_from_dict(entry[1], here)))
        actor = head.actor
        grabs = _grabs_from(head.grabs, where)
        return cls(
            level=level,
            dt=dt,
            steps=steps,
            changes=tuple(changes),
            actor=actor,
            grabs=grabs,
        )

    def to_inputs(self) -> str:
        """The replay as a level's scripted input timeline (TOML ``[[inputs]]`` tables).

        Paste it into a level file and the bug found by hand becomes a regression test. Times are
        ``step·dt`` (s), the exact start time of the step that first held the intent.

        >>> from playground.intents import Intent
        >>> r = Replay("rest", 0.5, 3, ((0, Intent()), (2, Intent(move=-1.0, gravity=(0.0, 1.0)))))
        >>> print(r.to_inputs())
        [[inputs]]
        t = 0.0
        actor = "player"
        <BLANKLINE>
        [[inputs]]
        t = 1.0
        actor = "player"
        move = -1.0
        gravity = [
            0.0,
            1.0,
        ]
        <BLANKLINE>
        """
        tables = [
            {"t": step * self.dt, "actor": self.actor, **intent_to_dict(intent)}
            for step, intent in self.changes
        ]
        return tomli_w.dumps({"inputs": tables})

    def check(self, name: str, world: World) -> None:
        """ReplayError unless this replay can drive level ``name`` in ``world``: the same level,
        the same dt, and a world still at step 0."""
        if self.level != name:
            raise ReplayError(f"the replay is of level {self.level!r}, not {name!r}")
        dt = world.config.dt
        if self.dt != dt:
            raise ReplayError(
                f"the replay was recorded at dt = {self.dt!r} s, the level has {dt!r}"
            )
        if world.steps != 0:
            raise ReplayError(
                f"{name}: a replay starts at step 0, the world is at step {world.steps}"
            )

    def save(self, path: str | Path) -> None:
        Path(path).write_text(self.to_json() + "\n", encoding="utf-8")

    @classmethod
    def load(cls, path: str | Path) -> Replay:
        p = Path(path)
        try:
            text = p.read_text(encoding="utf-8")
        except OSError as exc:
            raise ReplayError(f"{p}: cannot read the replay ({exc.strerror})") from None
        return cls.from_json(text, where=str(p))


def _grab_to_dict(grab: Grab | None) -> dict[str, Any] | None:
    if grab is None:
        return None
    return {"body": grab.body, "anchor": list(grab.anchor), "target": list(grab.target)}


def _point(value: Any) -> tuple[float, float] | None:
    ok = isinstance(value, list) and len(value) == 2
    if not ok or not all(isinstance(v, float | int) and math.isfinite(v) for v in value):
        return None
    return (float(value[0]), float(value[1]))


def _entry(entry: Any) -> bool:
    """Whether ``entry`` is ``[step, value]`` with a step index within a replay's bounds."""
    ok = isinstance(entry, list) and len(entry) == 2 and type(entry[0]) is int
    return ok and 0 <= entry[0] <= MAX_REPLAY_STEPS


def _grabs_from(raw: list[Any], where: str) -> tuple[tuple[int, Grab | None], ...]:
    """The ``grabs`` list of a replay document: ``[step, {body, anchor, target} | null]``."""
    out: list[tuple[int, Grab | None]] = []
    last = -1
    for k, entry in enumerate(raw):
        here = f"{where}: grabs[{k}]"
        expected = 'expected [step, {"body", "anchor": [x, y], "target": [x, y]} or null]'
        if not _entry(entry):
            raise ReplayError(f"{here}: {expected}, got {entry!r}")
        if entry[0] <= last:
            raise ReplayError(f"{here}: steps must increase, got {entry[0]} after {last}")
        last = entry[0]
        g = entry[1]
        if g is None:
            out.append((entry[0], None))
            continue
        ok = isinstance(g, dict) and set(g) == {"body", "anchor", "target"}
        anchor = _point(g.get("anchor")) if ok else None
        target = _point(g.get("target")) if ok else None
        if not ok or not isinstance(g["body"], str) or anchor is None or target is None:
            raise ReplayError(f"{here}: {expected}, got {g!r}")
        out.append((entry[0], Grab(g["body"], anchor, target)))
    return tuple(out)


class Recorder:
    """Collects the intent applied at each physics step, and what the mouse held, into a
    :class:`Replay`."""

    def __init__(self, *, level: str, dt: float, actor: str = "player") -> None:
        self.level = level
        self.dt = dt
        self.actor = actor
        self._changes: list[tuple[int, Intent]] = []
        self._grabs: list[tuple[int, Grab | None]] = []
        self._steps = 0

    def record(self, step: int, intent: Intent) -> None:
        """Record ``intent`` as the one applied at ``step`` (steps must come in order)."""
        if step != self._steps:
            raise ValueError(f"step: expected {self._steps} (steps in order), got {step}")
        last = self._changes[-1][1] if self._changes else Intent()
        if not self._changes or intent != last:
            self._changes.append((step, intent))
        self._steps = step + 1

    def record_grab(self, step: int, grab: Grab | None) -> None:
        """Record what the mouse holds during ``step`` (stored only when it changes)."""
        last = self._grabs[-1][1] if self._grabs else None
        if grab != last:
            self._grabs.append((step, grab))

    def replay(self) -> Replay:
        return Replay(
            level=self.level,
            dt=self.dt,
            steps=self._steps,
            changes=tuple(self._changes),
            actor=self.actor,
            grabs=tuple(self._grabs),
        )


class Playback:
    """A replay driving a built scene headless: its actor's intent in the INPUTS stage of every
    step (after the actor's own script, which it overrides) and what the mouse held in the
    CONTROL stage (pulled by a :class:`~playground.controller.mouse.MouseSpring`, as the view
    pulls).

    >>> from playground.level import find, load
    >>> from playground.scene import build
    >>> scene = build(load(find("rest")))
    >>> replay = Replay("rest", scene.world.config.dt, 3, ((1, Intent(move=1.0)),))
    >>> playback = Playback(replay, "rest", scene)
    >>> scene.world.step(); scene.world.step()
    >>> scene.controllers["player"].intent.move
    1.0
    """

    def __init__(self, replay: Replay, name: str, scene: Scene) -> None:
        replay.check(name, scene.world)
        controller = scene.controllers.get(replay.actor)
        if controller is None:
            raise ReplayError(f"{name}: the replay drives {replay.actor!r}, not a controller")
        self.replay = replay
        self.controller = controller
        self.spring = MouseSpring()
        scene.world.on(Stage.INPUTS, self.input_hook)
        if replay.grabs:
            scene.world.on(Stage.CONTROL, self.pull_hook)

    def input_hook(self, world: World) -> None:
        """INPUTS stage: the actor holds the replay's intent for this step."""
        if self.replay.actor in world.names:
            self.controller.intent = self.replay.intent_at(world.steps)

    def pull_hook(self, world: World) -> None:
        """CONTROL stage: the mouse spring's pull on what the replay held at this step."""
        self.spring.apply(world, self.replay.grab_at(world.steps))
