"""Scenes with exact answers (docs/design.md §5), built on :class:`~playground.world.World`.

Each builder takes the solver knobs and returns a :class:`Scene`: the world, the bodies whose
support forces (N) are summed into one measured vector, and the exact value of that sum for the
step just taken. The accuracy sweep measures every force estimator against these answers.

One convention for every scene: a reading is the mean force over a step (an impulse divided by
dt), so it is compared with the exact force at the *middle* of that step, which is the exact mean
over the step to second order. Compared with the end of the step instead, a force that turns at ω
shows a tangential error of exactly ω·dt/2: a time offset of half a step, not an inaccuracy.

>>> scene = build("rest", Knobs(dt=1 / 60))
>>> scene.world.run(1.0)
>>> [round(c, 3) for c in scene.exact(scene.world)]
[0.0, 686.7]
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import pymunk

from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.gravity import STANDARD_GRAVITY
from playground.movers import Elevator, Spin, ring_room
from playground.vec import Vec
from playground.world.config import WorldConfig
from playground.world.world import World

__all__ = ["SCENES", "Knobs", "Scene", "build", "hover_exact"]

PLAYER_MASS = 70.0
"""Mass of the measured body, kg (an adult player)."""

PLAYER_SIZE = (0.5, 1.0)
"""Width and height of the measured box, m."""


@dataclass(frozen=True, slots=True)
class Knobs:
    """The solver settings swept for accuracy.

    Attributes:
        dt: the fixed step, s.
        substeps: ``space.step`` calls per step.
        iterations: contact/joint solver iterations per substep.
        contact_split: also sum arbiter impulses (the "contact" estimator needs it).
    """

    dt: float = 1.0 / 120.0
    substeps: int = 1
    iterations: int = 10
    contact_split: bool = False

    def config(self) -> WorldConfig:
        """The world configuration for these knobs."""
        return WorldConfig(
            dt=self.dt,
            substeps=self.substeps,
            iterations=self.iterations,
            contact_split=self.contact_split,
        )


@dataclass(slots=True)
class Scene:
    """A world and what its measured force must be.

    Attributes:
        name: the scene's key in :data:`SCENES`.
        world: the world, at t = 0, measured bodies tracked (perceive off).
        bodies: the measured bodies; their support forces are summed, N.
        exact: the exact summed support force at the middle of the step just taken, N.
        scale: force the relative error is divided by, N.
        settle: seconds run before measuring.
        measure: seconds measured.
        joints: the force passes through a joint (an arbiter-impulse sum cannot see it).
        integral: the answer is the impulse over the window (∫F dt, N·s), not the force.
    """

    name: str
    world: World
    bodies: tuple[str, ...]
    exact: Callable[[World], Vec]
    scale: float
    settle: float
    measure: float
    joints: bool = False
    integral: bool = False

    @property
    def mass(self) -> float:
        """Total mass of the measured bodies, kg."""
        return sum(self.world.body(n).mass for n in self.bodies)


def _constant(value: Vec) -> Callable[[World], Vec]:
    def exact(world: World) -> Vec:
        return value

    return exact


def _floor(world: World) -> None:
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0), radius=0.05)


def _player(world: World, position: Vec, angle: float = 0.0, name: str = "player") -> None:
    world.add_box(name, mass=PLAYER_MASS, size=PLAYER_SIZE, position=position, angle=angle)


def rest(knobs: Knobs) -> Scene:
    """A box resting on flat ground: support = m·g."""
    world = World(knobs.config())
    _floor(world)
    _player(world, (0.0, 0.05 + PLAYER_SIZE[1] / 2))
    world.track("player", perceive=False)
    w = PLAYER_MASS * STANDARD_GRAVITY
    return Scene("rest", world, ("player",), _constant((0.0, w)), w, 0.5, 1.5)


INCLINE = math.radians(20.0)
"""Slope of the incline, rad (below the friction angle atan(0.8) ≈ 38.7°: it holds)."""


def incline(knobs: Knobs) -> Scene:
    """A box held by static friction on a 20° slope: N = m·g·cosθ, f = m·g·sinθ (sum: m·g up)."""
    world = World(knobs.config())
    c, s = math.cos(INCLINE), math.sin(INCLINE)
    world.add_static_segment((-10.0 * c, -10.0 * s), (10.0 * c, 10.0 * s), radius=0.05)
    lift = 0.05 + PLAYER_SIZE[1] / 2
    _player(world, (-s * lift, c * lift), angle=INCLINE)
    world.track("player", perceive=False)
    w = PLAYER_MASS * STANDARD_GRAVITY
    return Scene("incline", world, ("player",), _constant((0.0, w)), w, 0.5, 1.5)


ELEVATOR_ACCELERATION = 2.0
"""Upward acceleration of the elevator, m/s²."""


def elevator(knobs: Knobs) -> Scene:
    """A box on a platform accelerating up at a: N = m·(g + a)."""
    world = World(knobs.config())
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Poly.create_box(platform, (4.0, 0.2))
    shape.friction = 1.0
    world.add("platform", platform, shape)
    world.add_mover("platform", Elevator(start=(0.0, 0.0), acceleration=ELEVATOR_ACCELERATION))
    _player(world, (0.0, 0.1 + PLAYER_SIZE[1] / 2))
    world.track("player", perceive=False)
    n = PLAYER_MASS * (STANDARD_GRAVITY + ELEVATOR_ACCELERATION)
    return Scene("elevator", world, ("player",), _constant((0.0, n)), n, 0.5, 1.5)


STACK_LOADS = 4
"""Crates stacked on the player."""

STACK_LOAD_MASS = 200.0
"""Mass of each crate, kg (heavier than the player: a hard ratio for an iterative solver)."""


def stack(knobs: Knobs) -> Scene:
    """The player under a stack of heavy crates: ground contact = (m + ΣM)·g.

    The ground contact is the sum of the engine forces on every body of the stack (the contacts
    between them cancel in pairs), so it is what is measured.
    """
    world = World(knobs.config())
    _floor(world)
    h = PLAYER_SIZE[1]
    _player(world, (0.0, 0.05 + h / 2))
    names = ["player"]
    for i in range(STACK_LOADS):
        name = f"crate{i}"
        world.add_box(
            name, mass=STACK_LOAD_MASS, size=(0.5, 0.5), position=(0.0, 0.05 + h + 0.25 + 0.5 * i)
        )
        names.append(name)
    world.track(*names, perceive=False)
    w = (PLAYER_MASS + STACK_LOADS * STACK_LOAD_MASS) * STANDARD_GRAVITY
    return Scene("stack", world, tuple(names), _constant((0.0, w)), w, 1.0, 1.5)


RING_RADIUS = 5.0
"""Inner radius of the spinning ring, m."""

RING_RATE = 1.5
"""Spin of the ring, rad/s (floor speed 7.5 m/s; ≈ 1.1 g at the player's centre)."""


def ring(knobs: Knobs) -> Scene:
    """A box carried round the inside of a ring spinning in zero gravity: N = m·v²/r inward.

    The box starts moving with the floor, so the exact force is −m·ω²·r at its centre of mass r,
    taken at mid-step: the end-of-step position turned back by ω·dt/2.
    """
    world = World(knobs.config(), gravity=(0.0, 0.0))
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("ring", body, *ring_room(body, RING_RADIUS, segments=64))
    world.add_mover("ring", Spin(rate=RING_RATE))
    r0 = RING_RADIUS - PLAYER_SIZE[1] / 2
    _player(world, (0.0, -r0))
    player = world.body("player")
    player.velocity = (RING_RATE * r0, 0.0)
    player.angular_velocity = RING_RATE
    world.track("player", perceive=False)

    def exact(w: World) -> Vec:
        p = w.body("player").position
        k = -PLAYER_MASS * RING_RATE**2
        half = -0.5 * RING_RATE * w.config.dt  # rad: back to the middle of the step
        c, s = math.cos(half), math.sin(half)
        return (k * (c * p.x - s * p.y), k * (s * p.x + c * p.y))

    return Scene("ring", world, ("player",), exact, PLAYER_MASS * RING_RATE**2 * r0, 0.5, 1.5)


GRIP_ACCELERATION = 3.0
"""Upward acceleration of the flying object the player hangs from, m/s²."""


def grip(knobs: Knobs) -> Scene:
    """A box hanging from a pivot on a kinematic flyer accelerating up at a: grip = m·(g + a)."""
    world = World(knobs.config())
    flyer = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("flyer", flyer)
    world.add_mover("flyer", Elevator(start=(0.0, 5.0), acceleration=GRIP_ACCELERATION))
    _player(world, (0.0, 5.0 - PLAYER_SIZE[1] / 2))
    player = world.body("player")
    world.add_constraint(pymunk.PivotJoint(flyer, player, (0.0, 5.0)))
    world.track("player", perceive=False)
    n = PLAYER_MASS * (STANDARD_GRAVITY + GRIP_ACCELERATION)
    return Scene("grip", world, ("player",), _constant((0.0, n)), n, 0.5, 1.5, joints=True)


DROP_HEIGHT = 1.0
"""Height the box falls before landing, m."""

LANDING_WINDOW = 2.0
"""Seconds from release over which the impulse is summed (at rest well before the end)."""


def landing(knobs: Knobs) -> Scene:
    """A box dropped from h onto ground without bounce: ∫N dt over [0, T] = m·g·T.

    That is m·√(2gh) for the landing plus m·g·(T − fall time) for standing: the body starts and
    ends at rest, so the floor must have returned all the momentum gravity gave it.
    """
    world = World(knobs.config())
    _floor(world)
    _player(world, (0.0, 0.05 + PLAYER_SIZE[1] / 2 + DROP_HEIGHT))
    world.track("player", perceive=False)
    w = PLAYER_MASS * STANDARD_GRAVITY
    scale = PLAYER_MASS * math.sqrt(2.0 * STANDARD_GRAVITY * DROP_HEIGHT)
    return Scene(
        "landing", world, ("player",), _constant((0.0, w)), scale, 0.0, LANDING_WINDOW,
        integral=True,
    )  # fmt: skip


HOVER_FREQUENCY = 2.0
"""Natural frequency of the hover spring, Hz."""

HOVER_DAMPING = 0.3
"""Damping ratio ζ of the hover spring (underdamped: it rings)."""

HOVER_START = -0.04
"""Initial displacement from the ride height, m: below it, small enough that the spring force
never reaches zero (the hover only pushes, and a clipped spring is no longer linear)."""


def hover_exact(t: float) -> tuple[float, float]:
    """Exact displacement (m) and velocity (m/s) of the hover oscillator at time ``t`` (s).

    x'' + 2ζω₀x' + ω₀²x = 0, x(0) = x₀, x'(0) = 0, with σ = ζω₀ and ω_d = ω₀√(1 − ζ²)::

        x(t) = x₀·e^(−σt)·(cos ω_d t + σ/ω_d · sin ω_d t)
        x'(t) = −x₀·ω₀²/ω_d · e^(−σt) · sin ω_d t

    >>> hover_exact(0.0)
    (-0.04, 0.0)
    """
    w0 = 2.0 * math.pi * HOVER_FREQUENCY
    sigma = HOVER_DAMPING * w0
    wd = w0 * math.sqrt(1.0 - HOVER_DAMPING**2)
    e = math.exp(-sigma * t)
    x = HOVER_START * e * (math.cos(wd * t) + sigma / wd * math.sin(wd * t))
    v = -HOVER_START * w0 * w0 / wd * e * math.sin(wd * t)
    return x, v


def hover(knobs: Knobs) -> Scene:
    """The controller's hover spring over flat ground, released below its ride height.

    The hover is ``F = m·g + k·(ride − h) − c·v`` with k = m(2πf)², c = 2ζ·m(2πf) (the
    controller's model); it stands in for a contact (category SUPPORT), so the support force on
    the exact trajectory is m·g − k·x(t) − c·x'(t), x = h − ride. Stable while 2πf·dt < 2.
    """
    world = World(knobs.config())
    _floor(world)
    config = ControllerConfig(
        mass=PLAYER_MASS,
        hover_frequency=HOVER_FREQUENCY,
        hover_damping=HOVER_DAMPING,
        lock_rotation=True,
    )
    Controller(world, "player", position=(0.0, 0.05 + config.ride_height + HOVER_START),
               config=config)  # fmt: skip
    w0 = 2.0 * math.pi * HOVER_FREQUENCY
    k = PLAYER_MASS * w0 * w0
    c = 2.0 * HOVER_DAMPING * PLAYER_MASS * w0
    weight = PLAYER_MASS * STANDARD_GRAVITY

    def exact(w: World) -> Vec:
        x, v = hover_exact(w.time - 0.5 * w.config.dt)  # mid-step, as every scene
        return (0.0, weight - k * x - c * v)

    return Scene("hover", world, ("player",), exact, k * abs(HOVER_START), 0.0, 2.0)


SCENES: dict[str, Callable[[Knobs], Scene]] = {
    "rest": rest,
    "incline": incline,
    "elevator": elevator,
    "stack": stack,
    "ring": ring,
    "grip": grip,
    "landing": landing,
    "hover": hover,
}
"""Every scene builder by name, in the order reports list them."""


def build(name: str, knobs: Knobs) -> Scene:
    """Build the scene ``name`` (a key of :data:`SCENES`) with ``knobs``."""
    try:
        builder = SCENES[name]
    except KeyError:
        raise ValueError(f"scene: expected one of {', '.join(SCENES)}, got {name!r}") from None
    return builder(knobs)
