"""Gameplay events: what happened to each controller in a step — landed (with the impact), lost
balance, got up, crushed, freed, grabbed, released, gravity changed — for a game's sounds and
animations. :class:`Gameplay` reads the controllers' public state from outside their laws in the
OBSERVE stage and queues the events; the game takes them after the step, never inside it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from playground.controller import Controller, State
from playground.vec import Vec
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "Crushed",
    "Freed",
    "Gameplay",
    "GameplayEvent",
    "GotUp",
    "Grabbed",
    "GravityChanged",
    "Landed",
    "LostBalance",
    "Released",
]


LANDING_WINDOW = 0.5
"""s: the longest a landing is followed for its peak force. The default hover (5 Hz, critically
damped) settles within 0.2 s; a landing soft enough never to press past the weight is over too."""


@dataclass(frozen=True, slots=True)
class Landed:
    """Came down from the air onto walkable ground.

    Touchdown is the step its ground probe first finds walkable ground (``probe_length`` below
    its centre, before the body itself touches). The event is queued once the landing's force
    has peaked above its weight (a few steps later: the hover spring takes the fall), or
    :data:`LANDING_WINDOW` after touchdown, or when its state changes again; so ``impact`` is
    the whole landing's peak.
    """

    time: float
    """When it touched down: the start of that step, s of world time."""
    name: str
    """The controller's body."""
    speed: float
    """Speed toward the ground at touchdown, along up and relative to the ground, m/s."""
    impact: float
    """The largest force it felt while landing (|support|), N."""


@dataclass(frozen=True, slots=True)
class LostBalance:
    """Knocked over: its balance needed more than its budget for too long."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str


@dataclass(frozen=True, slots=True)
class GotUp:
    """On its feet again after losing its balance."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str


@dataclass(frozen=True, slots=True)
class Crushed:
    """Pinned under a load from above heavier than its ``crush_force``."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str
    load: float
    """The load borne from above then, N."""


@dataclass(frozen=True, slots=True)
class Freed:
    """No longer crushed (pushed the load off, or it slid away)."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str


@dataclass(frozen=True, slots=True)
class Grabbed:
    """Took hold of a body with its hands."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str
    held: str | None
    """The name of the body it holds in the world (None: a body the world has no name for)."""


@dataclass(frozen=True, slots=True)
class Released:
    """Let go of what it held (the grab released, or the grip slipped)."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str


@dataclass(frozen=True, slots=True)
class GravityChanged:
    """The gravity at its body changed by a change of the field or of a gravity rule (a flip,
    a switch of its own gravity, a nullify), not by moving through a field."""

    time: float
    """The start of the step it happened in, s of world time."""
    name: str
    gravity: Vec
    """The gravity at its body now, m/s²."""


GameplayEvent = Landed | LostBalance | GotUp | Crushed | Freed | Grabbed | Released | GravityChanged
"""Any of the events, each a frozen value with the world ``time`` (s, the start of the step it
happened in) and the controller's ``name``."""


class _Watch:
    """What is known of one controller between steps: its grip, its gravity, a landing whose
    force has not peaked yet (touchdown time, speed m/s, peak N)."""

    __slots__ = ("controller", "first", "gravity", "holding", "landing")

    def __init__(self, controller: Controller, gravity: Vec) -> None:
        self.controller = controller
        self.holding = controller.control_state.grip is not None
        self.gravity = gravity
        self.landing: tuple[float, float, float] | None = None
        # A controller starts AIRBORNE: standing where it was built is not a landing.
        self.first = True


class Gameplay:
    """Queues each watched controller's gameplay events, step by step, for the game to take.

    It hooks the world's OBSERVE stage (after the physics, the forces and the filter) and reads
    only public state: the step's state change (``Controller.transition``), the grip, the felt
    force (``World.forces(name).support``) and the gravity at the body. Nothing is delivered
    from inside the step: take the events after ``world.step()`` with :meth:`poll` (a list) or
    :meth:`deliver` (a callback each).

    >>> from playground import Controller, World
    >>> world = World()
    >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    >>> player = Controller(world, "player", position=(0.0, 2.0))     # 1 m above ride height
    >>> events = Gameplay(world, [player])
    >>> world.run(1.0)
    >>> [type(e).__name__ for e in events.poll()]
    ['Landed']
    >>> events.poll()                             # taken: the queue is empty until the next event
    []
    """

    def __init__(self, world: World, controllers: Iterable[Controller] = ()) -> None:
        self.world = world
        self._watches: list[_Watch] = []
        self._queue: list[GameplayEvent] = []
        self._gravity_version = world.gravity_version
        for controller in controllers:
            self.watch(controller)
        world.on(Stage.OBSERVE, self._observe)

    def watch(self, controller: Controller) -> None:
        """Queue this controller's events too, from the next step on."""
        gravity = self.world.gravity_at(controller.name)
        self._watches.append(_Watch(controller, gravity))

    def poll(self) -> list[GameplayEvent]:
        """The events queued since the last poll, oldest first; the queue is emptied."""
        events, self._queue = self._queue, []
        return events

    def deliver(self, handler: Callable[[GameplayEvent], None]) -> int:
        """Call ``handler`` with each queued event, oldest first, and empty the queue; returns
        how many there were. Call it after the step (a handler may step the world again)."""
        events = self.poll()
        for event in events:
            handler(event)
        return len(events)

    def close(self) -> None:
        """Stop watching (unhook from the world)."""
        self.world.off(Stage.OBSERVE, self._observe)

    def _observe(self, world: World) -> None:
        gravity_moved = world.gravity_version != self._gravity_version
        self._gravity_version = world.gravity_version
        for watch in self._watches:
            if not watch.controller.removed:
                self._queue.extend(_events(world, watch, gravity_moved))


def _felt(world: World, name: str) -> float:
    fx, fy = world.forces(name).support
    return math.hypot(fx, fy) if math.isfinite(fx) and math.isfinite(fy) else 0.0


def _events(world: World, watch: _Watch, gravity_moved: bool) -> Iterable[GameplayEvent]:
    """This step's events of one controller (updating what the watch keeps)."""
    controller = watch.controller
    name = controller.name
    t = controller.sensed.time  # the start of the step it happened in
    change = controller.transition
    before, after = (change.before, change.after) if change is not None else (None, None)

    if watch.landing is not None:
        touchdown, speed, peak = watch.landing
        felt = _felt(world, name)
        gx, gy = world.gravity_at(name)
        weight = controller.mass * math.hypot(gx, gy)
        if (felt < peak and peak >= weight) or change is not None or t - touchdown > LANDING_WINDOW:
            watch.landing = None
            yield Landed(touchdown, name, speed, max(peak, felt))
        else:
            watch.landing = (touchdown, speed, max(peak, felt))
    if before is State.AIRBORNE and after is State.GROUNDED and not watch.first:
        sensed = controller.sensed
        ground = sensed.ground
        gvx, gvy = ground.frame_velocity if ground is not None else (0.0, 0.0)
        ux, uy = sensed.up
        speed = -((sensed.body.vx - gvx) * ux + (sensed.body.vy - gvy) * uy)
        watch.landing = (t, speed, _felt(world, name))
    watch.first = False

    if after is State.OFF_BALANCE:
        yield LostBalance(t, name)
    if before is State.GETTING_UP and after is State.GROUNDED:
        yield GotUp(t, name)
    if after is State.CRUSHED:
        yield Crushed(t, name, controller.load)
    if before is State.CRUSHED:
        yield Freed(t, name)

    grip = controller.control_state.grip
    if grip is not None and not watch.holding:
        held = grip.shape.body
        yield Grabbed(t, name, None if held is None else world.name_of(held))
    elif grip is None and watch.holding:
        yield Released(t, name)
    watch.holding = grip is not None

    if gravity_moved:
        gravity = world.gravity_at(name)
        if gravity != watch.gravity:
            yield GravityChanged(t, name, gravity)
        watch.gravity = gravity
