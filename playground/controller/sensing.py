"""Sensing, the first phase of a controller's step: its body, the gravity at it, its up, the
ground under it (:class:`GroundHit`, from a swept probe), the load pressing on it and what its
hands could reach, returned as one :class:`Sensed` value by :meth:`Senses.sense`.

:class:`Senses` holds the sense organs (the probe's sweep, the arms' reach, the body's
contacts); it reads the world and writes nothing into it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pymunk

from playground._engine.contacts import Contacts
from playground._engine.reach import Reach
from playground._engine.state import (
    BodyState,
    body_motion,
    body_state,
    centre_of_gravity,
    jointed,
    radius_of_gyration,
    space_gravity,
)
from playground._engine.sweep import Sweep, nearest_where
from playground.controller import grab, ledge, stairs
from playground.controller._vec import ZERO, unit_or
from playground.controller.config import ControllerConfig
from playground.controller.elementwise import FLOATS, Ops
from playground.controller.grab import Grip
from playground.controller.ledge import LedgeHold
from playground.controller.states import (
    CLIMBING,
    CRUSHED,
    GETTING_UP,
    GROUNDED,
    HANGING,
    OFF_BALANCE,
    ControllerState,
)
from playground.intents import Intent
from playground.vec import Vec
from playground.world import one_way
from playground.world.world import World

# Body types read once (``pymunk.Body.X`` is two attribute lookups, three times a step).
KINEMATIC = pymunk.Body.KINEMATIC
DYNAMIC = pymunk.Body.DYNAMIC

__all__ = [
    "GroundHit",
    "PushTarget",
    "Sensed",
    "Senses",
    "effort",
    "effort_on",
    "footing",
    "height",
    "lean",
    "leaning",
    "up_speed",
]

GroundMotion = tuple[pymunk.Body, float, float, float]
"""A kinematic ground as the probe read it: the body, its velocity (m/s) and spin (rad/s)."""


@dataclass(slots=True)
class GroundHit:
    """What the ground probe found (plain values except the hit body). Read-only by convention,
    not frozen: a frozen dataclass sets each field through ``object.__setattr__``, which makes
    building one several times dearer, and the probe builds one every step (a changed copy is
    made with ``dataclasses.replace``).

    Attributes:
        body: the body hit.
        point: the hit point on its surface, m.
        normal: the surface normal there (unit, pointing out of the ground).
        distance: from the hit point to the capsule's centre along up, m.
        walkable: the normal is within ``max_slope`` of up.
        frame_velocity: velocity that keeps the capsule's centre fixed to the ground over the
            coming step, m/s: the ground's velocity plus the chord (R(ω·dt) − 1)·d/dt its turn
            carries our centre along (d from its centre of gravity; ω × d to first order, like
            ``ground.velocity_at_world_point(centre)``). Standing still on the ground means
            moving at this velocity: on a turning floor it is taken at the centre, not at the hit
            point, which is ride height further out (inside a ring spinning at ω the hit point's
            speed is ω·R, the centre's ω·(R − ride height)).
        frame_acceleration: how much ``frame_velocity`` changes per second, m/s²: as the ground
            turns by ω·dt (the centripetal −ω²·d to first order), plus, on a kinematic ground,
            its own acceleration (``own_acceleration``). Gravity minus ``frame_acceleration``
            is the gravity *felt* in the ground's frame: inside a spinning ring, ω²·r outward;
            in a lift accelerating up at a, g + a.
        own_acceleration: the part of ``frame_acceleration`` that is the ground's own, A + α × d,
            m/s², read from how a kinematic ground's velocity and spin changed since the last
            step (a mover sets them a step ahead, so this is the acceleration the coming step
            needs); zero on a dynamic ground, whose change of velocity is partly our own
            reaction on it (feeding that back would push a light crate harder the more it
            yields), and on the first step over a new ground.
        spin: the body hit's angular velocity, rad/s (counter-clockwise): the balance damps
            our spin relative to it.
        dynamic: the body hit is dynamic, so it takes our reactions (the world drops forces on
            static and kinematic bodies).
        lever: how far the feet's centre of pressure may move off the hit point before a loose
            ground tips, m (:func:`footing`): the balance torque through it is at most the
            hover's force times this (:func:`~playground.controller.action.act`); infinite on a
            static, kinematic or jointed ground.
    """

    body: pymunk.Body
    point: Vec
    normal: Vec
    distance: float
    walkable: bool
    frame_velocity: Vec
    frame_acceleration: Vec
    own_acceleration: Vec
    spin: float
    dynamic: bool
    lever: float = math.inf


@dataclass(slots=True)
class PushTarget:
    """The nearest dynamic body within the arms' reach: the body, the nearest point of it, m,
    and where the arms reach from (the head or the chest), m. Read-only by convention (one is
    built every step while pushing)."""

    body: pymunk.Body
    point: Vec
    origin: Vec


@dataclass(slots=True)
class Sensed:
    """What a controller sensed at the start of a step (read-only by convention, not frozen:
    one is built every step). Forces in N, impulses in N·s, lengths in m, times in s.

    Attributes:
        body: its own body's state.
        up: its up (unit): the perceived one while supported, the field's otherwise.
        time: the world's time.
        dt: the step's length, split into ``substeps`` engine steps.
        substeps: engine steps per step.
        gravity: the gravity at the body, m/s².
        perceived_up: the perceived up, read while supported or getting up (None otherwise).
        ground: the ground under it (None: the probe found nothing).
        ground_motion: the kinematic ground under it and its velocity and spin (None: none),
            which the next step's probe differentiates.
        contact_load: force pressing on it along −up through contacts in the last step: the
            step's mean over its substeps (each contact's impulse over them, over dt).
        load: the load borne from above: ``contact_load`` and the last push's reaction (the
            push's force, written unchanged before every substep: its own mean).
        touching: any contact touches the body.
        balance_short: the last step's balance needed more than its budget while touching
            (None: no balance acted).
        grip_impulse: the held joint's impulse over the last step's substeps (0 when not
            holding).
        slip: how far the held grip's anchors drifted apart (0 when not holding or not
            grabbing).
        handhold: the grip the hands could take (only looked for while grabbing, empty-handed
            and not off balance).
        engine: the engine force on the body in the last step, as the world's solver read it
            (read only while holding or taking a hold; zero otherwise).
        push_target: what the arms could push (only looked for while pushing).
        ledge: the ledge held by its edge or being climbed, as it is now (None: none).
        level: the up a ground's slope is measured against (unit): the field's while the
            perceived up is held to its lean (:func:`lean`), else ``up``; (0, 0) as built.
    """

    body: BodyState
    up: Vec
    time: float = 0.0
    dt: float = 0.0
    substeps: int = 1
    gravity: Vec = ZERO
    perceived_up: Vec | None = None
    ground: GroundHit | None = None
    ground_motion: GroundMotion | None = None
    contact_load: float = 0.0
    load: float = 0.0
    touching: bool = False
    balance_short: bool | None = None
    grip_impulse: float = 0.0
    slip: float = 0.0
    handhold: Grip | None = None
    engine: Vec = ZERO
    push_target: PushTarget | None = None
    ledge: LedgeHold | None = None
    level: Vec = ZERO


def footing(ground: pymunk.Body, x: float, y: float, nx: float, ny: float) -> float:
    """How far the feet's centre of pressure may move off the point (``x``, ``y``) (m) on a
    dynamic ``ground`` whose surface normal there is (``nx``, ``ny``) before the ground tips, m.

    A loose body (a tile, a stone, a crate) holds a torque only as far as the load pressing it
    keeps it down: a load N at a distance a from the edge it would tip over holds at most N·a,
    and beyond that the body flips under the feet. The body's extent is taken from its mass
    and moment: its radius of gyration √(I/m) stands for the half-width of its base (w/√12 for a
    slab w wide, a margin of √3 under w/2), less the point's offset from its centre of gravity
    along the surface, and 0 past it. A jointed body passes the torque on to its joint
    (a seesaw's plank to its pivot): infinite.

    >>> tile = pymunk.Body(3.0, 3.0 * (0.25**2 + 0.04**2) / 12.0)     # kg, kg·m²: 25 × 4 cm
    >>> round(footing(tile, 0.0, 0.02, 0.0, 1.0), 4), round(footing(tile, 0.05, 0.02, 0.0, 1.0), 4)
    (0.0731, 0.0231)
    >>> footing(tile, 0.1, 0.02, 0.0, 1.0)                              # past it: none
    0.0
    """
    if jointed(ground):
        return math.inf
    cx, cy = centre_of_gravity(ground)
    offset = abs((x - cx) * ny - (y - cy) * nx)
    return max(0.0, radius_of_gyration(ground) - offset)


def up_speed(sensed: Sensed, ground: GroundHit | None) -> float:
    """The body's speed along up relative to the ground's frame at its centre, m/s."""
    gvx, gvy = ground.frame_velocity if ground is not None else ZERO
    ux, uy = sensed.up
    body = sensed.body
    return (body.vx - gvx) * ux + (body.vy - gvy) * uy


def height(sensed: Sensed, hit: GroundHit) -> float:
    """Height of the centre over the hit point along the ground normal, m."""
    body = sensed.body
    return (body.x - hit.point[0]) * hit.normal[0] + (body.y - hit.point[1]) * hit.normal[1]


def lean(
    perceived: Vec, level: Vec, effort: Vec, weight: float, max_lean: float, ops: Ops = FLOATS
) -> Vec:
    """The perceived up (unit) held to the lean its own step explains: within ``max_lean``
    (rad) of the field's up ``level`` (unit), and on the side its legs' ``effort`` (N: the
    drive beyond holding the slope) pushes, no further than that effort leans its ``weight``
    (N) plus ``max_lean``.

    The inner ear reads every push as support: walking into a wall, the wall's deceleration
    tilts the perceived up away from it, and pressing into a slope too steep to stand on
    tilts it along the slope's normal. A lean its own legs make (leaning into its own step)
    is the controller's; one that a push from outside gives is not, and tipped by it the probe
    would take a wall for a floor. ``perceived`` itself comes back when it is within the
    bounds (in floats, the very tuple). Written over ``ops``
    (:mod:`~playground.controller.elementwise`): in arrays a crowd's members lean row by row,
    each as it would alone.

    >>> lean((0.6, 0.8), (0.0, 1.0), (0.0, 0.0), 686.7, 0.1)     # a push tips it 37°: held
    (0.09983341664682815, 0.9950041652780258)
    >>> lean((0.6, 0.8), (0.0, 1.0), (515.0, 0.0), 686.7, 0.1)   # its own step leans it so
    (0.6, 0.8)
    >>> import numpy as np
    >>> from playground.controller.elementwise import ARRAYS
    >>> x, y = lean((np.array([0.6, 0.6]), np.array([0.8, 0.8])), (0.0, 1.0),
    ...             (np.array([0.0, 515.0]), 0.0), 686.7, 0.1, ARRAYS)
    >>> x.tolist(), y.tolist()                                     # the two, as rows
    ([0.09983341664682815, 0.6], [0.9950041652780258, 0.8])
    """
    px, py = perceived
    ax, ay = level
    angle = ops.atan2(ax * py - ay * px, ax * px + ay * py)
    if ops.all(abs(angle) <= max_lean):
        return perceived
    ex, ey = effort
    own = ops.atan2(ax * ey - ay * ex, weight + ax * ex + ay * ey)
    held = ops.max(ops.min(0.0, own) - max_lean, ops.min(ops.max(0.0, own) + max_lean, angle))
    # Within max_lean, held is angle too (the bounds reach past ±max_lean): the rows kept are
    # those of either return.
    kept = held == angle
    if ops.all(kept):
        return perceived
    c, s = ops.cos(held), ops.sin(held)
    return (ops.where(kept, px, c * ax - s * ay), ops.where(kept, py, s * ax + c * ay))


def effort(drive: Vec, sensed: Sensed) -> Vec:
    """The legs' effort in a ``drive`` (N) acted on the ground ``sensed`` found: the drive
    less its hold on the slope, −m·g·t along the ground's tangent t (:func:`~playground.
    controller.laws.drive`): what leans the controller into its step."""
    hit = sensed.ground
    return effort_on(drive, None if hit is None else hit.normal, sensed.gravity, sensed.body.mass)


def effort_on(
    drive: Vec,
    normal: Vec | None,
    gravity: Vec,
    mass: float,
    ops: Ops = FLOATS,
    holding: bool = True,
) -> Vec:
    """:func:`effort` from its parts: the ground's ``normal`` (None: no ground), the
    ``gravity`` (m/s²) and the body's ``mass`` (kg) of that step. Written over ``ops``: in
    arrays, ``holding`` marks the rows that found a ground and drove (a float's ``normal`` is
    not None and ``drive`` not :data:`~playground.controller._vec.ZERO`); the others' effort is
    their drive as it is.

    >>> hold = (0.8 * 412.02, 0.6 * 412.02)    # N: 70 kg held up a 37° slope, m·g·sin 37°
    >>> effort_on(hold, (-0.6, 0.8), (0.0, -9.81), 70.0)             # holding it: no effort
    (0.0, 0.0)
    >>> effort_on((hold[0] + 100.0, hold[1]), (-0.6, 0.8), (0.0, -9.81), 70.0)
    (100.0, 0.0)
    """
    if normal is None or drive is ZERO:
        return drive
    nx, ny = normal
    gx, gy = gravity
    pull = mass * (gx * ny - gy * nx)  # gravity along the tangent (ny, −nx), N
    dx, dy = drive
    return (ops.where(holding, dx + pull * ny, dx), ops.where(holding, dy - pull * nx, dy))


PUSH_ECHO = 0.3
"""s: how long after its body last touched anything a lean beyond ``max_lean`` waits: pressed
against a wall or a too-steep slope, the contact throws it back off and the drive sends it in
again, and a lean into that step would wedge its head into the wall, which throws it back
again (a 0.8 s cycle against a 60° slope, levels/steep_slope.toml)."""


def leaning(state: ControllerState, intent: Intent, time: float, contacts: Contacts) -> bool:
    """Whether the lean its own step explains may count (:func:`lean`): it walks (its
    ``intent`` moves: standing, its drive only answers what the ground does) and nothing
    touches its body now, nor has for :data:`PUSH_ECHO` (``time`` the world's, s)."""
    return intent.move != 0.0 and time - state.touched_at > PUSH_ECHO and not contacts.touching()


# The states in which the controller is supported: its up is the perceived one.
SUPPORTED = (GROUNDED, HANGING, CRUSHED)


class Senses:
    """A controller's sense organs: the ground probe, the arms' reach, the body's contacts, and
    the gravity rule it last read."""

    __slots__ = (
        "_body",
        "_contacts",
        "_filter",
        "_gravity_rule",
        "_gravity_version",
        "_name",
        "_reach",
        "_space",
        "_sweep",
        "_uniform_field",
    )

    def __init__(
        self, world: World, name: str, body: pymunk.Body, shape_filter: pymunk.ShapeFilter
    ) -> None:
        self._name = name
        self._body = body
        self._filter = shape_filter
        self._space = world.space
        self._sweep = Sweep(world.space, shape_filter)
        self._reach = Reach(world.space, shape_filter)
        self._contacts = Contacts(body)
        # With substeps, the contacts add up each substep's impulses: the load is the step's
        # mean, as the force solver's readings are (pymunk keeps the last substep's only).
        world.on_substep(self._contacts.gather)
        # The field's uniformity and our gravity rule as of World.gravity_version: they change
        # only through the world's setters, and gravity() reads them again when it has moved.
        self._gravity_version = -1
        self._uniform_field = True
        self._gravity_rule = world.gravity_rule(name)

    def detach(self, world: World) -> None:
        """Stop reading ``world`` after its substeps (the controller leaves it)."""
        world.off_substep(self._contacts.gather)

    def sense(
        self,
        world: World,
        before: Sensed,
        state: ControllerState,
        intent: Intent,
        last_push: Vec,
        last_balance_short: bool | None,
        config: ControllerConfig,
        last_drive: Vec = ZERO,
    ) -> Sensed:
        """Read the body, the world's settings, the gravity at it, up, the ground under it, the
        load on it and what the hands reach, given the last step's reading (``before``), the
        state, the intent and the last step's push (N, on us) and balance verdict, and the
        last step's drive (``last_drive``, N: its effort is the lean it explains).

        Up is the perceived one while supported (within the lean its own forces explain
        while nothing touches it: :func:`lean`; slopes are then measured against the field's
        up) and the field while airborne (it sees where it
        will land), fallen or getting up (contacts while lying and rising shake the inner ear),
        or on a ledge.
        """
        name = self._name
        body = body_state(self._body)
        wc = world.config
        gx, gy = self.gravity(world)
        s = state.state
        perceived_up: Vec | None = None
        level: Vec | None = None
        # Hanging from a ledge or climbing it, up is the field's: the hands' pull sways with
        # the body, and its reading fed back into the balance rings (a 2-step oscillation
        # against a loose 300 kg crate at dt = 1/60 s, levels/ledge_climb.toml).
        if s in SUPPORTED and state.ledge is None:
            (ux, uy), perceived = world.perceived_up_and_gravity(name)
            perceived_up = (ux, uy)
            if not (math.isfinite(ux) and math.isfinite(uy)):
                ux, uy = unit_or(-gx, -gy, before.up)
            elif math.hypot(*perceived) < wc.perception.up_threshold:
                # Just caught after a free fall: the inner ear still holds the up from before
                # the fall (after a gravity flip, the opposite one) until the new support has
                # built up a reading: keep the up we fell with meanwhile.
                ux, uy = before.up
            elif gx != 0.0 or gy != 0.0:
                # A lean beyond max_lean only as far as its own step explains, and only while
                # nothing touches it: then nothing else pushes. Slopes are then measured
                # against the field's up: leaning into a climb does not steepen the slope.
                level = unit_or(-gx, -gy, before.up)
                weight = body.mass * math.hypot(gx, gy)
                leaned = lean(perceived_up, level, ZERO, weight, config.max_lean)
                if leaned is not perceived_up and leaning(
                    state, intent, world.time, self._contacts
                ):
                    own = effort(last_drive, before)
                    leaned = lean(perceived_up, level, own, weight, config.max_lean)
                ux, uy = leaned
        else:
            ux, uy = unit_or(-gx, -gy, before.up)
            if s is GETTING_UP:
                perceived_up = world.perceived_up(name)
        if level is None:
            level = (ux, uy)

        # Grounded and pulled toward the ground, it steps down to a tread below the probe's
        # length along the field (stairs.below); not while jumping (rising), nor falling away
        # from the ground (a gravity flip: the field along its up).
        down: Vec | None = None
        if s is GROUNDED and not state.rising and gx * ux + gy * uy < 0.0:
            g = math.hypot(gx, gy)
            down = (gx / g, gy / g)
        ground, motion = self.probe(
            body,
            ux,
            uy,
            wc.dt,
            before.ground_motion,
            config,
            intent.move,
            down,
            level,
            s is GROUNDED,
        )
        # Each contact's impulse summed over the step's substeps, over the step: its mean.
        contact_load, touching = self._contacts.load_and_touching(ux, uy, wc.dt)
        load = contact_load + max(0.0, -(last_push[0] * ux + last_push[1] * uy))

        grip = state.grip
        handhold = None
        if grip is None and intent.grab and s is not OFF_BALANCE and s is not CLIMBING:
            handhold = self.handhold((ux, uy), config)
        holding = grip is not None or handhold is not None
        grip_impulse = grip.impulses.total if grip is not None else 0.0
        slip = grab.slip(grip) if grip is not None and intent.grab else 0.0
        engine = world.forces(name).engine if holding else ZERO
        push_target = self.push_target(body, ground, config) if intent.push else None
        held = state.ledge
        if held is None:
            hand = grip if grip is not None else handhold
            held = None if hand is None else hand.ledge
        on_ledge = None if held is None else ledge.held(held)
        # In the order of the fields, positionally: building one with keywords is dearer
        # (docs/performance.md, row positional), and one is built every step.
        return Sensed(
            body, (ux, uy), world.time, wc.dt, wc.substeps, (gx, gy), perceived_up, ground,
            motion, contact_load, load, touching, last_balance_short, grip_impulse, slip,
            handhold, engine, push_target, on_ledge, level,
        )  # fmt: skip

    def handhold(self, up: Vec, config: ControllerConfig) -> Grip | None:
        """The grip the hands could take: a ledge's edge within reach first (taken only while
        not rising past it, so none while rising), else the nearest body within reach."""
        found = ledge.find(self._space, self._body, self._filter, up, config)
        if found is None:
            return grab.handhold(self._space, self._body, self._filter, config)
        if not ledge.catching(found, self._body, up):
            return None
        return ledge.grip(self._body, found, config)

    @property
    def sweep(self) -> Sweep:
        """The probe's sweep (this controller's filter): a crowd probes through it."""
        return self._sweep

    def gravity(self, world: World) -> Vec:
        """The gravity at the body, m/s²: ``world.gravity_at`` in general, and for a field
        uniform in space the value the GRAVITY stage has just put in ``space.gravity`` with the
        body's rule applied in plain floats (the numpy path costs far more for one body).
        Whether the field is uniform and the body's rule are read again only when the world
        says they changed (:attr:`World.gravity_version`)."""
        version = world.gravity_version
        if version != self._gravity_version:
            self._gravity_version = version
            self._uniform_field = world.gravity.uniform
            self._gravity_rule = world.gravity_rule(self._name)
        if not self._uniform_field:
            return world.gravity_at(self._name)
        gx, gy = space_gravity(self._space)
        return self._gravity_rule.apply(gx, gy)

    def probe(
        self,
        body: BodyState,
        ux: float,
        uy: float,
        dt: float,
        last_motion: GroundMotion | None,
        config: ControllerConfig,
        move: float = 0.0,
        down: Vec | None = None,
        level: Vec | None = None,
        standing: bool = False,
    ) -> tuple[GroundHit | None, GroundMotion | None]:
        """Sweep a circle from the centre along −up; the nearest other shape is the ground.
        Returns it and, if kinematic, its motion for the next step's probe (``last_motion``:
        the last step's; dt the step, s).

        On stairs (:mod:`~playground.controller.stairs`): a corner's hit stands for the face
        past it; moving (``move`` ≠ 0), a tread ahead within the step's reach is the ground
        (the hover lifts the body onto it before its cap meets the riser); stepping ``down``
        (grounded the step before and coming down: the field's direction, unit) where the probe
        finds no walkable ground, a tread up to the step's reach past the probe's length along
        it is the ground.

        Its slope is measured against ``level`` (unit; None: up); ``standing`` (GROUNDED), a
        shape too steep to stand on is passed over for a walkable one beside it within ride
        height (the foot of a steep slope, a wall)."""
        px, py = body.x, body.y
        length = config.probe_length
        # The nearest of every hit (playground._engine.sweep says why not pymunk's
        # segment_query_first).
        end, radius = (px - ux * length, py - uy * length), config.probe_radius
        found = self._sweep.nearest(px, py, end[0], end[1], radius)
        if found is not None and one_way.passes(found[0], px, py, radius):
            # A one-way platform seen from below or from inside: look past it.
            found = nearest_where(
                self._space, (px, py), end, radius, self._filter,
                lambda shape: not one_way.passes(shape, px, py, radius),
            )  # fmt: skip
        if found is not None:
            found = stairs.face(found, px, py, ux, uy, radius)
        lx, ly = (ux, uy) if level is None else level
        cos_max = math.cos(config.max_slope)
        if (
            standing
            and found is not None
            and found[3] * lx + found[4] * ly < cos_max
            and (px - found[1]) * ux + (py - found[2]) * uy > config.half_length
            and found[0].collision_type != one_way.ONE_WAY
        ):
            # Standing at the foot of ground too steep to stand on, whose face has come within
            # the probe's circle by its feet (below its lower cap's centre): the feet are still
            # on the walkable ground beside it. (A one-way shape is no slope: passes decides.)
            steep = found[0]
            beside = nearest_where(
                self._space, (px, py), end, radius, self._filter,
                lambda shape: shape is not steep and not one_way.passes(shape, px, py, radius),
            )  # fmt: skip
            if (
                beside is not None
                and beside[3] * lx + beside[4] * ly >= cos_max
                and (px - beside[1]) * ux + (py - beside[2]) * uy
                <= config.ride_height + config.probe_radius
            ):
                found = beside
        if down is not None and (found is None or not stairs.walkable(found, ux, uy, config)):
            found = stairs.below(self._sweep, px, py, down, (ux, uy), config) or found
        ground = found[0].body if found is not None else None
        if found is None or ground is None:
            return None, None
        if move != 0.0:
            # The tread ahead (stairs.step_up ahead of the velocity relative to this ground).
            _, gvx, gvy, _ = body_motion(ground)
            step = stairs.step_up(
                self._sweep, found, px, py, body.vx - gvx, body.vy - gvy, ux, uy, move, config
            )
            if step is not None and step[0].body is not None:
                found, ground = step, step[0].body
        _, hx, hy, nx, ny = found
        # The ground's frame at our centre, as pymunk's step needs it: positions move with the
        # velocity before the step, so standing still on a ground turning by θ = ω·dt this
        # step takes the velocity that carries our centre to where the ground carries that
        # point, V + (R(θ) − 1)·d/dt (d from the ground's centre of gravity), not the tangent
        # ω × d, which leads the turning ground by θ/2 each step; this velocity turns by θ each
        # step, hence the acceleration (R(θ) − 1)·(its turning part)/dt.
        kind, vx, vy, w = body_motion(ground)
        turn = w * dt
        if turn == 0.0 and kind != KINEMATIC:
            # Not turning: the chord below is exactly 0.0 for any d (cos 0 = 1, sin 0 = ±0), and
            # only a kinematic ground's own acceleration needs d: skip reading its centre.
            cos_t, sin_t = 1.0, 0.0
            dx = dy = rx = ry = 0.0
        else:
            cos_t, sin_t = math.cos(turn), math.sin(turn)
            cx, cy = centre_of_gravity(ground)
            dx, dy = px - cx, py - cy
            rx = (cos_t * dx - sin_t * dy - dx) / dt
            ry = (sin_t * dx + cos_t * dy - dy) / dt
        motion: GroundMotion | None = None
        own_x = own_y = 0.0
        if kind == KINEMATIC:
            # Fed forward, the ground's own acceleration lets the drive and the hover keep up
            # with an accelerating platform instead of lagging a·drive_time behind it.
            motion = (ground, vx, vy, w)
            if last_motion is not None and last_motion[0] is ground:
                alpha = (w - last_motion[3]) / dt
                own_x = (vx - last_motion[1]) / dt - alpha * dy
                own_y = (vy - last_motion[2]) / dt + alpha * dx
        distance = (px - hx) * ux + (py - hy) * uy
        walkable = nx * lx + ny * ly >= cos_max
        frame_velocity = (vx + rx, vy + ry)
        frame_acceleration = (
            (cos_t * rx - sin_t * ry - rx) / dt + own_x,
            (sin_t * rx + cos_t * ry - ry) / dt + own_y,
        )
        # Positionally, in the order of the fields (as Sensed, for speed).
        dynamic = kind == DYNAMIC
        lever = footing(ground, hx, hy, nx, ny) if dynamic else math.inf
        hit = GroundHit(
            ground, (hx, hy), (nx, ny), distance, walkable, frame_velocity, frame_acceleration,
            (own_x, own_y), w, dynamic, lever,
        )  # fmt: skip
        return hit, motion

    def push_target(
        self, body: BodyState, ground: GroundHit | None, config: ControllerConfig
    ) -> PushTarget | None:
        """The nearest dynamic body within reach of the head or the chest (not the ground)."""
        px, py = body.x, body.y
        ax, ay = -body.sin, body.cos
        half = config.half_length
        reach = config.radius + config.push_reach
        ground_body = ground.body if ground is not None else None
        qx, qy = px + ax * half, py + ay * half
        found = self._reach.nearest(qx, qy, reach, ground_body)
        # The head is asked first: the chest's find wins only if strictly nearer.
        chest = self._reach.nearest(
            px, py, reach, ground_body, math.inf if found is None else found[3]
        )
        if chest is not None:
            found, qx, qy = chest, px, py
        target = None if found is None else found[0].body
        if found is None or target is None:
            return None
        return PushTarget(target, (found[1], found[2]), (qx, qy))
