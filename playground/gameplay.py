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
"""s: the longest a landing is followed after touchdown for the end of its fall. The default
hover (5 Hz, critically damped) stops a fall within 0.1 s; one not stopped by then (a ground
that falls away as fast) is reported with what was measured."""

MIN_LANDING_SPEED = 0.25
"""m/s: the slowest fall reported as a landing. Slower is the hover settling or a touchdown at
the top of a hop (a fall of v²/2g = 3 mm), nothing a game plays a sound for."""


@dataclass(frozen=True, slots=True)
class Landed:
    """Came down from the air onto walkable ground, and its fall was stopped.

    Touchdown is the step its ground probe first finds walkable ground after it was airborne
    (``probe_length`` below its centre, before the body itself touches: the hover spring takes
    the fall from there). The landing is followed until the body no longer moves toward the
    ground, and queued then (a few steps after touchdown), or :data:`LANDING_WINDOW` after
    touchdown, or when its state changes again. A fall slower than
    :data:`MIN_LANDING_SPEED` is no landing (a touchdown at the top of a low hop, a player
    built at its ride height).

    ``impulse`` is the momentum its support took out of the fall: the support along up beyond
    the weight, integrated from the moment it fell fastest to the moment it stopped, so
    ``impulse = mass · speed`` (N·s = kg · m/s) whatever stopped it (the hover, the capsule's own
    contact, both).
    """

    time: float
    """When it touched down: the start of that step, s of world time."""
    name: str
    """The controller's body."""
    speed: float
    """The fastest it fell toward the ground while landing, along up and relative to the
    ground, m/s (at touchdown, or later if the hover's first push was weaker than its weight)."""
    impact: float
    """The largest force it felt while landing (|support|), N."""
    impulse: float
    """The impulse that stopped the fall (support beyond the weight, along up), N·s: mass ×
    ``speed``."""


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
    """Let go of what it held (the grab released, the grip slipped, or up on the ledge it
    climbed)."""

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


class _Landing:
    """A landing being followed: its touchdown time (s), the fastest fall so far (m/s), the
    support's impulse beyond the weight since then (N·s) and the peak support (N)."""

    __slots__ = ("fastest", "impulse", "last", "peak", "touchdown")

    def __init__(self, touchdown: float, speed: float) -> None:
        self.touchdown = touchdown
        self.fastest = speed
        self.last = speed  # toward the ground after the last step followed, m/s
        self.impulse = 0.0
        self.peak = 0.0


class _Watch:
    """What is known of one controller between steps: its grip, its gravity, whether it has been
    airborne since it last landed, and a landing whose fall has not stopped yet."""

    __slots__ = ("airborne", "controller", "gravity", "holding", "landing")

    def __init__(self, controller: Controller, gravity: Vec) -> None:
        self.controller = controller
        self.holding = controller.control_state.grip is not None
        self.gravity = gravity
        self.landing: _Landing | None = None
        # A controller starts AIRBORNE: built above the ground, its first touchdown is a landing
        # (one built at its ride height does not fall, so it reports none).
        self.airborne = controller.state is State.AIRBORNE


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


def _toward_ground(controller: Controller, vx: float, vy: float) -> float:
    """The speed (vx, vy) (m/s) makes toward the ground along up, relative to the ground the
    last step sensed, m/s (negative: moving away)."""
    sensed = controller.sensed
    ground = sensed.ground
    gvx, gvy = ground.frame_velocity if ground is not None else (0.0, 0.0)
    ux, uy = sensed.up
    return -((vx - gvx) * ux + (vy - gvy) * uy)


def _follow(world: World, controller: Controller, landing: _Landing) -> bool:
    """Take the last step of a landing into account; whether its fall has stopped."""
    name = controller.name
    sx, sy = world.forces(name).support
    if not (math.isfinite(sx) and math.isfinite(sy)):
        return True
    sensed = controller.sensed
    ux, uy = sensed.up
    gx, gy = world.gravity_at(name)
    landing.peak = max(landing.peak, math.hypot(sx, sy))
    # The step's impulse along up of the support beyond the weight, N·s.
    net = (sx * ux + sy * uy + controller.mass * (gx * ux + gy * uy)) * sensed.dt
    before = landing.last
    v = controller.body.velocity
    now = _toward_ground(controller, v.x, v.y)
    landing.last = now
    if now <= 0.0:
        # Stopped within this step: its impulse until the speed crossed zero (linear in time).
        landing.impulse += net * before / (before - now) if before > 0.0 else 0.0
        return True
    if now > landing.fastest:
        landing.fastest = now
        landing.impulse = 0.0  # counted from the fastest moment on
    else:
        landing.impulse += net
    return False


def _events(world: World, watch: _Watch, gravity_moved: bool) -> Iterable[GameplayEvent]:
    """This step's events of one controller (updating what the watch keeps)."""
    controller = watch.controller
    name = controller.name
    t = controller.sensed.time  # the start of the step it happened in
    change = controller.transition
    before, after = (change.before, change.after) if change is not None else (None, None)
    state = controller.state

    landing = watch.landing
    if landing is None and watch.airborne and state is State.GROUNDED:
        # Touchdown: follow the fall from the speed it had at the start of this step.
        body = controller.sensed.body
        landing = watch.landing = _Landing(t, _toward_ground(controller, body.vx, body.vy))
        watch.airborne = False
    if landing is not None:
        stopped = _follow(world, controller, landing)
        if stopped or state is not State.GROUNDED or t - landing.touchdown > LANDING_WINDOW:
            watch.landing = None
            if landing.fastest >= MIN_LANDING_SPEED:
                yield Landed(
                    landing.touchdown, name, landing.fastest, landing.peak, landing.impulse
                )
    if state is State.AIRBORNE:
        watch.airborne = True

    if after is State.OFF_BALANCE:
        yield LostBalance(t, name)
    if before is State.GETTING_UP and after is State.GROUNDED:
        yield GotUp(t, name)
    if after is State.CRUSHED:
        yield Crushed(t, name, controller.load)
    if before is State.CRUSHED:
        yield Freed(t, name)

    grip = controller.control_state.grip
    # Climbing onto a ledge, its hands stay on the edge (the joint gives way to the climb's
    # force): it lets go once up.
    holding = grip is not None or state is State.CLIMBING
    if grip is not None and not watch.holding:
        held = grip.shape.body
        yield Grabbed(t, name, None if held is None else world.name_of(held))
    elif not holding and watch.holding:
        yield Released(t, name)
    watch.holding = holding

    if gravity_moved:
        gravity = world.gravity_at(name)
        if gravity != watch.gravity:
            yield GravityChanged(t, name, gravity)
        watch.gravity = gravity
