"""The capsule player controller: hover, drive, balance, jump, grab, push — all relative to up.

A :class:`Controller` is a dynamic capsule that moves only through forces, within budgets. Its
"up" is the filtered perceived gravity while it is supported and the gravity field at the body
while airborne, so the same code works on a floor, a ceiling, a planet or inside a spinning ring.
Every force goes through ``world.apply_force`` with its category, so the solver's support force and
perceived gravity stay right. An enemy is the same controller with another intent source.

>>> from playground.world import World
>>> world = World()
>>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
>>> player = Controller(world, "player", position=(0.0, 1.0))
>>> world.run(2.0)
>>> player.state.value, round(player.probe.distance, 3)
('grounded', 0.95)
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, fields
from enum import Enum

import pymunk

from playground._validate import finite, positive
from playground.forces import Category
from playground.gravity import GravityRule
from playground.intents import IDLE, Intent, IntentSource
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "Controller",
    "ControllerConfig",
    "ControllerForces",
    "GroundHit",
    "State",
    "hover_limit",
    "hover_spring",
]

Vec = tuple[float, float]
TWO_PI = 2.0 * math.pi
_ZERO: Vec = (0.0, 0.0)
_groups = itertools.count(1)


class State(Enum):
    """What the controller is doing; the world, the view and tests read it."""

    GROUNDED = "grounded"
    AIRBORNE = "airborne"
    HANGING = "hanging"
    OFF_BALANCE = "off_balance"
    GETTING_UP = "getting_up"
    CRUSHED = "crushed"


@dataclass(frozen=True, slots=True)
class ControllerConfig:
    """Body, sensing and force budgets; defaults fit a 70 kg, 1.8 m person.

    Attributes:
        mass: kg, the body's mass when it is built (``World.set_mass`` may change it later: the
            controller follows the body's mass, see :attr:`Controller.mass`).
        height: capsule length, end to end, m.
        radius: capsule radius, m (less than half the height).
        lock_rotation: infinite moment of inertia: the capsule never tips (no balance needed).
        ride_height: distance held from the probe hit to the capsule's centre, m. Above half the
            height, so the feet hover a few centimetres over the ground and the capsule never
            scrapes it while walking.
        probe_length: how far the ground probe reaches from the centre along −up, m.
        probe_radius: radius of the probe's swept circle, m.
        hover_frequency: natural frequency of the hover spring, Hz (k = m·(2πf)²).
        hover_damping: damping ratio of the hover spring (c = 2ζ·m·2πf); 1 is critical, 0 is
            undamped. The spring is stable while 2πf·dt < :func:`hover_limit` (ζ), which is at
            least 2.
        hover_force: the legs' budget: the most the hover pushes with, N. Beyond it the capsule
            bottoms out and the contact takes the rest (a hard landing, a crushing load).
        max_slope: steepest walkable ground, rad between its normal and up.
        max_speed: walking speed at full move input, m/s.
        drive_time: time constant with which the drive closes the gap to its goal velocity, s.
        traction: foot friction coefficient: the drive is also bounded by traction × the hover
            force (no normal force, no traction).
        ground_force: drive force budget on the ground, N.
        air_force: steering force budget in the air, N (never used to brake).
        balance_frequency: natural frequency of the upright PD, Hz.
        balance_damping: damping ratio of the upright PD.
        balance_torque: balance torque budget, N·m.
        balance_loss_time: needing more than the budget this long while supported loses
            balance, s.
        settle_speed: below this speed relative to the ground a fallen body counts as still, m/s.
        settle_spin: below this angular speed a fallen body counts as still, rad/s.
        settle_time: how long a fallen body must stay still before getting up, s.
        getup_time: how long getting up takes, s.
        jump_speed: take-off speed along up relative to the ground, m/s.
        coyote_time: a jump still works this long after leaving the ground, s.
        jump_buffer: a jump press is remembered this long before landing, s.
        grab_reach: how far beyond the head the hands reach, m.
        grip_force: grip budget (the joint's max force), N.
        grip_slip: the grip lets go when its anchors drift this far apart, m.
        climb_speed: speed of the grip along the held body at full climb input, m/s.
        push_reach: how far beyond the body the arms reach to push, m.
        push_force: push budget, N.
        crush_force: crushed when the load from above exceeds this, N.
    """

    mass: float = 70.0
    height: float = 1.8
    radius: float = 0.25
    lock_rotation: bool = False
    ride_height: float = 0.95
    probe_length: float = 1.4
    probe_radius: float = 0.1
    hover_frequency: float = 5.0
    hover_damping: float = 1.0
    hover_force: float = 5000.0
    max_slope: float = 0.7
    max_speed: float = 4.0
    drive_time: float = 0.05
    traction: float = 1.0
    ground_force: float = 350.0
    air_force: float = 70.0
    balance_frequency: float = 2.5
    balance_damping: float = 1.5
    balance_torque: float = 600.0
    balance_loss_time: float = 0.3
    settle_speed: float = 0.3
    settle_spin: float = 0.5
    settle_time: float = 0.5
    getup_time: float = 1.0
    jump_speed: float = 4.0
    coyote_time: float = 0.1
    jump_buffer: float = 0.15
    grab_reach: float = 0.3
    grip_force: float = 2000.0
    grip_slip: float = 0.1
    climb_speed: float = 0.5
    push_reach: float = 0.5
    push_force: float = 1000.0
    crush_force: float = 1500.0

    def __post_init__(self) -> None:
        if not isinstance(self.lock_rotation, bool):
            raise ValueError(f"lock_rotation: expected a bool, got {self.lock_rotation!r}")
        non_negative = {
            "hover_damping",
            "traction",
            "air_force",
            "coyote_time",
            "jump_buffer",
            "climb_speed",
        }
        for f in fields(self):
            if f.name == "lock_rotation":
                continue
            value = getattr(self, f.name)
            if f.name in non_negative:
                finite(f.name, value)
                if value < 0.0:
                    raise ValueError(f"{f.name}: expected a number >= 0, got {value!r}")
            else:
                positive(f.name, value)
        if self.radius >= self.height / 2.0:
            raise ValueError(
                f"radius: expected less than half the height ({self.height / 2.0} m), "
                f"got {self.radius!r}"
            )
        if self.ride_height >= self.probe_length:
            raise ValueError(
                f"ride_height: expected less than probe_length ({self.probe_length} m), "
                f"got {self.ride_height!r}"
            )
        if self.max_slope >= math.pi / 2.0:
            raise ValueError(f"max_slope: expected less than π/2 rad, got {self.max_slope!r}")

    @property
    def half_length(self) -> float:
        """Half the distance between the capsule's two end-cap centres, m."""
        return self.height / 2.0 - self.radius


@dataclass(frozen=True, slots=True)
class GroundHit:
    """What the ground probe found (plain values except the hit body).

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
            its own acceleration A + α × d read from how its velocity and spin changed since the
            last step (a mover sets them a step ahead, so this is the acceleration the coming
            step needs). A dynamic ground's change of velocity is partly our own reaction on it:
            feeding that back would push a light crate harder the more it yields, so its
            acceleration is left to the drive's feedback. Gravity minus ``frame_acceleration``
            is the gravity *felt* in the ground's frame: inside a spinning ring, ω²·r outward;
            in a lift accelerating up at a, g + a.
    """

    body: pymunk.Body
    point: Vec
    normal: Vec
    distance: float
    walkable: bool
    frame_velocity: Vec
    frame_acceleration: Vec


@dataclass(frozen=True, slots=True)
class ControllerForces:
    """The forces the controller put on its own body in the last step (N, N·m).

    ``grip`` is the joint force of the step before (a joint's force is known only after the
    step it acts in).
    """

    hover: Vec = _ZERO
    drive: Vec = _ZERO
    grip: Vec = _ZERO
    push: Vec = _ZERO
    balance_torque: float = 0.0


_NO_FORCES = ControllerForces()


class Controller:
    """A force-driven capsule player (or enemy) in a :class:`World`.

    The model, each step, all along the controller's ``up``:

    - **probe**: a circle swept from the centre along −up (``probe_length``) finds the ground.
    - **hover**: a damped spring on the height over the hit point and on the velocity relative to
      the ground point, ``F = m·g_n + k·(ride − h) − c·v_rel`` with ``k = m(2πf)²``,
      ``c = 2ζm·2πf`` (m the body's mass now), and the weight felt in the ground's frame (gravity
      minus the ground's acceleration, :attr:`GroundHit.frame_acceleration`) as feed-forward, so
      it rests exactly at ride height, in a rising lift too. The spring reads the height the
      integrator will use and the damper the velocity after the step (:func:`hover_spring`), so
      it is stable while 2πf·dt < :func:`hover_limit`. It acts along the ground normal n (on
      flat ground under an upright player, n = up): a spring along a tilted up would read a
      slant distance and sag whenever the player leans (perceived up tilts while accelerating),
      while along n the hover and the drive are exactly a contact's normal and friction parts.
      It only pushes (a floor cannot pull), so jumping off or a gravity flip is never held back.
    - **drive**: toward ``ground velocity + move·max_speed`` along the ground tangent with time
      constant ``drive_time``, plus the tangential part of the gravity felt in the ground's frame
      (so slopes hold and an accelerating platform carries it without lag), bounded by
      ``ground_force`` and by ``traction × hover force``.
    - **balance**: a PD torque toward up, bounded by ``balance_torque``. Needing more than the
      budget for ``balance_loss_time`` while supported loses balance (hover, drive and balance let
      go); once still for ``settle_time`` it gets up over ``getup_time``.
    - **jump**, **grab/hang/climb**, **push**, **gravity switches**: see the config.

    Newton's third law: hover, drive, jump and balance react on the ground body at the hit point,
    push on the pushed body. The reactions are SUPPORT forces on the ground body too, because they
    stand in for a contact on both sides: a crate the player stands on must read the player's
    weight as a contact load (its accelerometer reads its own weight's worth, not the player's).
    Hover, drive, jump and push are SUPPORT on the player; air steering is APPLIED (nobody feels
    it); the grip is a real joint, so the solver reads it as an engine force.
    """

    def __init__(
        self,
        world: World,
        name: str,
        position: tuple[float, float],
        config: ControllerConfig = ControllerConfig(),
        source: IntentSource | None = None,
        angle: float = 0.0,
    ) -> None:
        if not isinstance(config, ControllerConfig):
            raise ValueError(f"config: expected a ControllerConfig, got {config!r}")
        finite("angle", angle)
        omega = _stable_hover(config, world.config.dt)
        self.world = world
        self.name = name
        self.config = config
        self.source = source
        half = config.half_length
        moment = (
            math.inf
            if config.lock_rotation
            else pymunk.moment_for_segment(config.mass, (0.0, -half), (0.0, half), config.radius)
        )
        body = pymunk.Body(config.mass, moment)
        body.position = position
        body.angle = angle
        shape = pymunk.Segment(body, (0.0, -half), (0.0, half), config.radius)
        shape.friction = 0.8
        group = next(_groups)
        shape.filter = pymunk.ShapeFilter(group=group)
        self._filter = pymunk.ShapeFilter(group=group)
        self.body = body
        self.shape = shape
        world.add(name, body, shape)
        world.track(name)

        self._omega = omega
        self._cos_slope = math.cos(config.max_slope)
        self._wb = TWO_PI * config.balance_frequency
        self._up_threshold = world.config.perception.up_threshold

        self.intent: Intent = IDLE
        self.state = State.AIRBORNE
        g = world.gravity_at(name)
        self.up: Vec = _unit_or(-g[0], -g[1], (0.0, 1.0))
        self.probe: GroundHit | None = None
        self.last_forces: ControllerForces = _NO_FORCES
        self.pushed: tuple[Vec, Vec] | None = None
        """Where (m) the last step's push acted on the pushed body, and the force on it (N)."""
        self.load: float = 0.0
        """Load borne from above in the last step: contacts and the push's reaction, N."""
        self.contact_load: float = 0.0
        """The contacts' part of :attr:`load`, N."""
        self.joint: pymunk.PivotJoint | None = None
        self._held_shape: pymunk.Shape | None = None
        self._jump_held = False
        self._jump_pressed_at = -math.inf
        self._grounded_at = -math.inf
        self._last_ground: GroundHit | None = None
        # The kinematic ground under us last step and its velocity (m/s) and spin (rad/s).
        self._ground_motion: tuple[pymunk.Body, float, float, float] | None = None
        self._rising = False
        self._saturated = 0.0
        self._still = 0.0
        self._getup_at = 0.0
        self._getup_from = 0.0
        self._gravity_wish: Vec | None = None
        self._nullify_wish: str | None = None
        # The body's state, read once at the start of each control step: position (m), velocity
        # (m/s), mass (kg). Nothing in the control stage moves a body (forces go to the ledger
        # until the physics stage), and each read from pymunk builds a new Vec2d.
        self._px = self._py = self._vx = self._vy = 0.0
        self._m = config.mass

        self.removed = False
        self._hooks: list[tuple[Stage, Callable[[World], None]]] = [(Stage.CONTROL, self._control)]
        if source is not None:
            self._hooks.insert(0, (Stage.INPUTS, self._read_source))
        for stage, hook in self._hooks:
            world.on(stage, hook)

    def tune_hover(self, frequency: float, damping: float) -> None:
        """Set the hover spring's frequency (Hz) and damping ratio from the next step on (a live
        tuning panel). ValueError, naming the limit, if the spring would be unstable at the
        world's dt."""
        config = dataclasses.replace(self.config, hover_frequency=frequency, hover_damping=damping)
        omega = _stable_hover(config, self.world.config.dt)
        self.config = config
        self._omega = omega

    def remove(self) -> None:
        """Take the controller out of its world: its grip, body, shape and hooks go."""
        if self.removed:
            return
        self._release(self.world)
        self.world.remove(self.name)
        for stage, hook in self._hooks:
            self.world.off(stage, hook)
        self.removed = True

    # -- reading ---------------------------------------------------------------------------------

    @property
    def mass(self) -> float:
        """The body's mass now, kg: ``config.mass`` until ``World.set_mass`` changes it. The
        hover's stiffness and damping, its weight feed-forward, the drive, the air steering and
        the jump all use it, so the spring keeps its frequency and the ride height its value."""
        return float(self.body.mass)

    @property
    def hover_stiffness(self) -> float:
        """The hover spring's stiffness k = m·(2πf)², N/m, for the mass now."""
        return self.mass * self._omega * self._omega

    @property
    def hover_damping_coefficient(self) -> float:
        """The hover's damping c = 2ζ·m·2πf, N·s/m, for the mass now."""
        return 2.0 * self.config.hover_damping * self.mass * self._omega

    @property
    def axis(self) -> Vec:
        """The capsule's own up: its local +y in world coordinates (unit)."""
        r = self.body.rotation_vector
        return (-r.y, r.x)

    @property
    def tilt(self) -> float:
        """Signed angle from the capsule's axis to ``up``, rad (CCW positive)."""
        ax, ay = self.axis
        ux, uy = self.up
        return math.atan2(ax * uy - ay * ux, ax * ux + ay * uy)

    @property
    def grip(self) -> float:
        """Magnitude of the grip joint's force in the last step, N (0 when not hanging)."""
        if self.joint is None:
            return 0.0
        cfg = self.world.config
        return float(self.joint.impulse) / (cfg.dt / cfg.substeps)

    # -- the step --------------------------------------------------------------------------------

    def _read_source(self, world: World) -> None:
        assert self.source is not None
        if self.removed:
            return
        intent = self.source.intent(world.time)
        if not isinstance(intent, Intent):
            # A duck-typed intent skips Intent's checks: a NaN move would win the whole budget.
            raise ValueError(f"{self.name}: the intent source returned {intent!r}, not an Intent")
        self.intent = intent

    def _control(self, world: World) -> None:
        if self.removed:
            return
        cfg = self.config
        body = self.body
        dt = world.config.dt
        t = world.time
        it = self.intent
        p = body.position
        self._px, self._py = p.x, p.y
        v = body.velocity
        self._vx, self._vy = vx, vy = v.x, v.y
        self._m = float(body.mass)
        gx, gy = self._gravity(world)
        self._gravity_actions(world, it)

        # Up: perceived while supported, the field while airborne (it sees where it will land),
        # fallen or getting up (contacts while lying and rising shake the inner ear).
        supported = self.state in (State.GROUNDED, State.HANGING, State.CRUSHED)
        if supported:
            ux, uy = world.perceived_up(self.name)
            if not (math.isfinite(ux) and math.isfinite(uy)):
                ux, uy = _unit_or(-gx, -gy, self.up)
            elif math.hypot(*world.perceived_gravity(self.name)) < self._up_threshold:
                # Just caught after a free fall: the inner ear still holds the up from before the
                # fall (after a gravity flip, the opposite one) until the new support has built
                # up a reading: keep the up we fell with meanwhile.
                ux, uy = self.up
        else:
            ux, uy = _unit_or(-gx, -gy, self.up)
        self.up = (ux, uy)

        hit = self._probe(world, ux, uy)
        self.probe = hit
        self.contact_load = self._contact_load(world, ux, uy)
        pushed = self.last_forces.push
        self.load = self.contact_load + max(0.0, -(pushed[0] * ux + pushed[1] * uy))

        if it.jump and not self._jump_held:
            self._jump_pressed_at = t
        self._jump_held = it.jump

        gvx, gvy = hit.frame_velocity if hit is not None else _ZERO
        v_up = (vx - gvx) * ux + (vy - gvy) * uy
        if self._rising and (v_up <= 0.0 or hit is None):
            self._rising = False

        self._update_grip(world, it)
        self._update_state(world, hit)
        state = self.state

        hover = drive = push = _ZERO
        torque = 0.0
        self.pushed = None
        if state is State.OFF_BALANCE:
            self.last_forces = _NO_FORCES
            return

        jumped = False
        grounded = state in (State.GROUNDED, State.GETTING_UP, State.CRUSHED)
        may_jump = state is State.GROUNDED or (
            state is State.AIRBORNE and t - self._grounded_at <= cfg.coyote_time
        )
        if may_jump and t - self._jump_pressed_at <= cfg.jump_buffer:
            # The take-off step still carries the weight (hover and drive act once more), so the
            # body leaves at exactly jump_speed relative to the ground.
            jumped = self._jump(world, hit if hit is not None else self._last_ground, ux, uy)
            if jumped:
                self.state = State.AIRBORNE

        if grounded and hit is not None and hit.walkable:
            hover_f = self._hover(world, hit, gx, gy, t)
            hover = (hover_f * hit.normal[0], hover_f * hit.normal[1])
            if state is not State.CRUSHED:
                drive = self._drive(world, hit, it.move, gx, gy, hover_f, dt)
        elif state is State.AIRBORNE and it.move != 0.0 and not jumped:
            drive = self._steer(world, it.move, ux, uy, dt)

        if it.push:
            push = self._push(world, hit)
        if not cfg.lock_rotation:
            torque = self._balance(world, hit if grounded else None, ux, uy, dt)

        grip = _ZERO
        if self.joint is not None:
            e = world.forces(self.name).engine
            grip = _scaled(e, self.grip)
        self.last_forces = ControllerForces(hover, drive, grip, push, torque)

    # -- sensing ---------------------------------------------------------------------------------

    def _gravity(self, world: World) -> Vec:
        """The gravity at the body, m/s²: ``world.gravity_at`` in general, and for a field uniform
        in space the value the GRAVITY stage has just put in ``space.gravity`` with the body's rule
        applied in plain floats (the numpy path costs ~0.2 ms a call for one body)."""
        if not world.gravity.uniform:
            return world.gravity_at(self.name)
        g = world.space.gravity
        rule = world.gravity_rule(self.name)
        if rule.direction is None:
            return (rule.scale * g.x, rule.scale * g.y)
        mag = rule.scale * math.hypot(g.x, g.y)
        return (mag * rule.direction[0], mag * rule.direction[1])

    def _probe(self, world: World, ux: float, uy: float) -> GroundHit | None:
        """Sweep a circle from the centre along −up; the nearest other shape is the ground."""
        cfg = self.config
        px, py = self._px, self._py
        length = cfg.probe_length
        # Every hit, then the nearest: with a radius, pymunk 7.3.1's segment_query_first can
        # return a farther shape (inside a 64-segment ring it reports a neighbouring chord's end
        # cap, normal 40° off, while the chord under the probe is 7 cm nearer).
        hits = world.space.segment_query(
            (px, py), (px - ux * length, py - uy * length), cfg.probe_radius, self._filter
        )
        info: pymunk.SegmentQueryInfo | None = None
        for h in hits:
            shape = h.shape
            # Strictly nearer only: of equally near hits the first wins (as min() would pick).
            if shape is not None and not shape.sensor and (info is None or h.alpha < info.alpha):
                info = h
        if info is None or info.shape is None or info.shape.body is None:
            self._ground_motion = None
            return None
        ground = info.shape.body
        hx, hy = info.point
        nx, ny = info.normal
        # The ground's frame at our centre, as pymunk's step needs it: positions move with the
        # velocity before the step, so standing still on a ground turning by θ = ω·dt this step
        # takes the velocity that carries our centre to where the ground carries that point,
        # V + (R(θ) − 1)·d/dt (d from the ground's centre of gravity), not the tangent ω × d,
        # which leads the turning ground by θ/2 each step; this velocity turns by θ each step,
        # hence the acceleration (R(θ) − 1)·(its turning part)/dt.
        dt = world.config.dt
        turn = ground.angular_velocity * dt
        cos_t, sin_t = math.cos(turn), math.sin(turn)
        cog = ground.local_to_world(ground.center_of_gravity)
        dx, dy = px - cog.x, py - cog.y
        rx = (cos_t * dx - sin_t * dy - dx) / dt
        ry = (sin_t * dx + cos_t * dy - dy) / dt
        v = ground.velocity
        own_x, own_y = self._ground_acceleration(ground, dx, dy, dt)
        return GroundHit(
            body=ground,
            point=(hx, hy),
            normal=(nx, ny),
            distance=(px - hx) * ux + (py - hy) * uy,
            walkable=nx * ux + ny * uy >= self._cos_slope,
            frame_velocity=(v.x + rx, v.y + ry),
            frame_acceleration=(
                (cos_t * rx - sin_t * ry - rx) / dt + own_x,
                (sin_t * rx + cos_t * ry - ry) / dt + own_y,
            ),
        )

    def _ground_acceleration(self, ground: pymunk.Body, dx: float, dy: float, dt: float) -> Vec:
        """The ground's own acceleration at our centre, A + α × d (m/s², d from its centre of
        gravity, m), read from how its velocity and spin changed since the last step (dt, s).

        Fed forward, it lets the drive and the hover keep up with an accelerating platform
        instead of lagging a·drive_time behind it (5 cm over a second at 1 m/s²). Only for a
        kinematic ground (zero otherwise, and on the first step over a new ground): a dynamic
        ground's change of velocity is partly our own reaction on it.
        """
        if ground.body_type != pymunk.Body.KINEMATIC:
            self._ground_motion = None
            return _ZERO
        v = ground.velocity
        w = ground.angular_velocity
        prev = self._ground_motion
        self._ground_motion = (ground, v.x, v.y, w)
        if prev is None or prev[0] is not ground:
            return _ZERO
        alpha = (w - prev[3]) / dt
        return ((v.x - prev[1]) / dt - alpha * dy, (v.y - prev[2]) / dt + alpha * dx)

    def _contact_load(self, world: World, ux: float, uy: float) -> float:
        """Force pressing on us along −up through contacts in the last step, N (the floor's push
        along +up does not count)."""
        h = world.config.dt / world.config.substeps
        load = 0.0

        def visit(arb: pymunk.Arbiter) -> None:
            nonlocal load
            # Our body is the arbiter's first; total_impulse is the impulse on it.
            jx, jy = arb.total_impulse
            load += max(0.0, -(jx * ux + jy * uy)) / h

        self.body.each_arbiter(visit)
        return load

    # -- states ----------------------------------------------------------------------------------

    def _update_state(self, world: World, hit: GroundHit | None) -> None:
        cfg = self.config
        t = world.time
        state = self.state
        on_ground = hit is not None and hit.walkable and not self._rising
        if on_ground:
            self._last_ground = hit
        if state is State.OFF_BALANCE:
            if self._is_still(hit):
                self._still += world.config.dt
            else:
                self._still = 0.0
            if self._still >= cfg.settle_time and hit is not None:
                self.state = State.GETTING_UP
                self._getup_at = t
                self._getup_from = self._height(hit)
                self._saturated = 0.0
            return
        if state is State.GETTING_UP:
            if hit is None:
                self.state = State.AIRBORNE
            elif t - self._getup_at >= cfg.getup_time and self._steady(world):
                self.state = State.GROUNDED
                self._grounded_at = t
            return
        if self._saturated > cfg.balance_loss_time:
            self._lose_balance(world)
            return
        if self.joint is not None:
            self.state = State.HANGING
            return
        if self.load > cfg.crush_force and self.contact_load > 0.0:
            # Crushed: bearing more than crush_force from above with the load still on us (a
            # crusher held off at arm's length by the push no longer pins us).
            self.state = State.CRUSHED
        elif on_ground:
            self.state = State.GROUNDED
        else:
            self.state = State.AIRBORNE
        if self.state is not State.AIRBORNE and on_ground:
            self._grounded_at = t

    def _steady(self, world: World) -> bool:
        """Up again: the axis and the perceived up both within max_slope of the up used while
        getting up (after a fall the inner ear needs a moment before it is trusted again)."""
        ux, uy = self.up
        px, py = world.perceived_up(self.name)
        return abs(self.tilt) < self.config.max_slope and px * ux + py * uy >= self._cos_slope

    def _is_still(self, hit: GroundHit | None) -> bool:
        cfg = self.config
        vx, vy = self._vx, self._vy
        gx, gy = hit.frame_velocity if hit is not None else _ZERO
        spin = self.body.angular_velocity - (hit.body.angular_velocity if hit is not None else 0.0)
        return math.hypot(vx - gx, vy - gy) < cfg.settle_speed and abs(spin) < cfg.settle_spin

    def _lose_balance(self, world: World) -> None:
        self._release(world)
        self.state = State.OFF_BALANCE
        self._still = 0.0
        self._saturated = 0.0

    # -- forces ----------------------------------------------------------------------------------

    def _hover(self, world: World, hit: GroundHit, gx: float, gy: float, t: float) -> float:
        cfg = self.config
        target = cfg.ride_height
        if self.state is State.GETTING_UP:
            s = min(1.0, (t - self._getup_at) / cfg.getup_time)
            target = self._getup_from + (target - self._getup_from) * s * s * (3.0 - 2.0 * s)
        nx, ny = hit.normal
        height = self._height(hit)
        vx, vy = self._vx, self._vy
        # The height's rate of change over a rigidly moving ground is the velocity relative to the
        # ground's frame at our centre along n: the hit point's own velocity also carries
        # ω × (centre − hit), which on a turning floor with a slanted normal (a ring's chord
        # ends) reads as a spurious normal speed and makes the damper let go.
        gvx, gvy = hit.frame_velocity
        v_n = (vx - gvx) * nx + (vy - gvy) * ny
        # The weight felt in the ground's frame (gravity minus the frame's acceleration: inside a
        # spinning ring, the centrifugal m·ω²·r) as feed-forward: it rests exactly at ride height.
        ax, ay = hit.frame_acceleration
        m = self._m
        weight = m * max(0.0, -((gx - ax) * nx + (gy - ay) * ny))
        if weight == 0.0 and gx == 0.0 and gy == 0.0:
            # Weightless (a nullified body) and not pressed on this ground by its frame either:
            # nothing holds us on it, the legs push with nothing. Otherwise a weightless body
            # whose held up swings toward whatever it bumps (its inner ear reads the bump as
            # gravity) finds that body at its flank, a few tenths of a metre away, and the spring
            # kicks off it at its budget.
            return 0.0
        wc = world.config
        # hover_stiffness and hover_damping_coefficient, from the one mass read above.
        omega = self._omega
        k = m * omega * omega
        c = 2.0 * cfg.hover_damping * m * omega
        spring = hover_spring(k, c, m, target - height, v_n, wc.dt, wc.substeps)
        f = min(cfg.hover_force, max(0.0, weight + spring))
        if f > 0.0:
            fx, fy = f * nx, f * ny
            world.apply_force(self.body, (fx, fy), category=Category.SUPPORT)
            _react(world, hit.body, fx, fy, hit.point)
        return f

    def _height(self, hit: GroundHit) -> float:
        """Height of the centre over the hit point along the ground normal, m."""
        return (self._px - hit.point[0]) * hit.normal[0] + (self._py - hit.point[1]) * hit.normal[1]

    def _drive(
        self,
        world: World,
        hit: GroundHit,
        move: float,
        gx: float,
        gy: float,
        hover: float,
        dt: float,
    ) -> Vec:
        cfg = self.config
        nx, ny = hit.normal
        tx, ty = ny, -nx  # the surface tangent: its normal rotated by −90°
        vx, vy = self._vx, self._vy
        # Relative to the ground's frame at our centre, not to the hit point: on a turning floor
        # the hit point, ride height further from the axis, moves faster than standing still.
        gvx, gvy = hit.frame_velocity
        v_t = (vx - gvx) * tx + (vy - gvy) * ty
        # Feed-forward: the tangential part of the gravity felt in the ground's frame (gravity
        # minus the ground's acceleration, its own included on a kinematic ground), so slopes
        # hold and a turning floor's chords (slopes to the centrifugal force) do not creep.
        ax, ay = hit.frame_acceleration
        accel = (move * cfg.max_speed - v_t) / max(cfg.drive_time, dt) - (
            (gx - ax) * tx + (gy - ay) * ty
        )
        budget = min(cfg.ground_force, cfg.traction * hover)
        f = max(-budget, min(budget, self._m * accel))
        if f == 0.0:
            return _ZERO
        fx, fy = f * tx, f * ty
        world.apply_force(self.body, (fx, fy), category=Category.SUPPORT)
        _react(world, hit.body, fx, fy, hit.point)
        return (fx, fy)

    def _steer(self, world: World, move: float, ux: float, uy: float, dt: float) -> Vec:
        """Air steering toward move·max_speed along up's tangent; it never brakes."""
        cfg = self.config
        tx, ty = uy, -ux
        vx, vy = self._vx, self._vy
        f = self._m * (move * cfg.max_speed - (vx * tx + vy * ty)) / max(cfg.drive_time, dt)
        if f * move <= 0.0:
            return _ZERO
        f = max(-cfg.air_force, min(cfg.air_force, f))
        world.apply_force(self.body, (f * tx, f * ty), category=Category.APPLIED)
        return (f * tx, f * ty)

    def _balance(
        self, world: World, hit: GroundHit | None, ux: float, uy: float, dt: float
    ) -> float:
        cfg = self.config
        body = self.body
        r = body.rotation_vector
        ax, ay = -r.y, r.x
        err = math.atan2(ax * uy - ay * ux, ax * ux + ay * uy)
        wb = self._wb
        # Damp the spin relative to the ground's, so the body turns with a turning floor (inside
        # a spinning ring) instead of lagging behind it.
        spin = body.angular_velocity - (hit.body.angular_velocity if hit is not None else 0.0)
        need = body.moment * (wb * wb * err - 2.0 * cfg.balance_damping * wb * spin)
        budget = cfg.balance_torque
        torque = max(-budget, min(budget, need))
        touching = hit is not None or self.contact_load > 0.0 or self._touching()
        if abs(need) > budget and touching and self.state is not State.GETTING_UP:
            self._saturated += dt
        else:
            self._saturated = 0.0
        world.apply_torque(body, torque, category=Category.APPLIED)
        if hit is not None and hit.body.body_type == pymunk.Body.DYNAMIC:
            world.apply_torque(hit.body, -torque, category=Category.SUPPORT)
        return torque

    def _touching(self) -> bool:
        found = False

        def visit(arb: pymunk.Arbiter) -> None:
            nonlocal found
            found = True

        self.body.each_arbiter(visit)
        return found

    def _jump(self, world: World, ground: GroundHit | None, ux: float, uy: float) -> bool:
        cfg = self.config
        vx, vy = self._vx, self._vy
        gvx, gvy = ground.frame_velocity if ground is not None else _ZERO
        dv = cfg.jump_speed - ((vx - gvx) * ux + (vy - gvy) * uy)
        self._jump_pressed_at = -math.inf
        self._grounded_at = -math.inf
        if dv <= 0.0:
            return False
        m = self._m
        jx, jy = m * dv * ux, m * dv * uy
        world.apply_impulse(self.body, (jx, jy), category=Category.SUPPORT)
        if ground is not None and ground.body.body_type == pymunk.Body.DYNAMIC:
            # The reaction, as _react's: a static or kinematic ground takes no impulse.
            world.apply_impulse(
                ground.body, (-jx, -jy), point=ground.point, category=Category.SUPPORT
            )
        self._rising = True
        return True

    def _push(self, world: World, hit: GroundHit | None) -> Vec:
        """Push the nearest dynamic body within reach of the head or the chest (not the ground),
        away from us, with the whole push budget; the reaction goes onto us."""
        cfg = self.config
        p = self.body.position
        ax, ay = self.axis
        half = cfg.half_length
        ground = hit.body if hit is not None else None
        best: pymunk.PointQueryInfo | None = None
        origin = (p.x, p.y)
        for qx, qy in ((p.x + ax * half, p.y + ay * half), (p.x, p.y)):
            for info in world.space.point_query(
                (qx, qy), cfg.radius + cfg.push_reach, self._filter
            ):
                shape = info.shape
                if (
                    shape is None
                    or shape.sensor
                    or shape.body is None
                    or shape.body is ground
                    or shape.body.body_type != pymunk.Body.DYNAMIC
                ):
                    continue
                if best is None or info.distance < best.distance:
                    best, origin = info, (qx, qy)
        if best is None or best.shape is None or best.shape.body is None:
            return _ZERO
        cx, cy = best.point
        nx, ny = _unit_or(cx - origin[0], cy - origin[1], (ax, ay))
        f = cfg.push_force
        world.apply_force(
            best.shape.body, (f * nx, f * ny), point=(cx, cy), category=Category.SUPPORT
        )
        world.apply_force(self.body, (-f * nx, -f * ny), category=Category.SUPPORT)
        self.pushed = ((cx, cy), (f * nx, f * ny))
        return (-f * nx, -f * ny)

    # -- grab, hang, climb -----------------------------------------------------------------------

    def _update_grip(self, world: World, it: Intent) -> None:
        cfg = self.config
        joint = self.joint
        if joint is not None:
            a = self.body.local_to_world(joint.anchor_a)
            held = joint.b
            b = held.local_to_world(joint.anchor_b)
            if not it.grab or math.hypot(a.x - b.x, a.y - b.y) > cfg.grip_slip:
                self._release(world)
            elif it.climb != 0.0:
                self._climb(world, joint, it.climb)
            return
        if not it.grab or self.state is State.OFF_BALANCE:
            return
        ax, ay = self.axis
        p = self.body.position
        half = cfg.half_length
        head = (p.x + ax * half, p.y + ay * half)
        info = world.space.point_query_nearest(head, cfg.radius + cfg.grab_reach, self._filter)
        if info is None or info.shape is None or info.shape.sensor or info.shape.body is None:
            return
        other = info.shape.body
        touch = info.point
        joint = pymunk.PivotJoint(
            self.body, other, self.body.world_to_local(touch), other.world_to_local(touch)
        )
        joint.max_force = cfg.grip_force
        joint.collide_bodies = False
        world.space.add(joint)
        self.joint = joint
        self._held_shape = info.shape
        self.state = State.HANGING

    def _climb(self, world: World, joint: pymunk.PivotJoint, climb: float) -> None:
        """Slide the held anchor along the held shape's surface."""
        held = joint.b
        shape = self._held_shape
        assert shape is not None
        p = held.local_to_world(joint.anchor_b)
        q = shape.point_query(p)
        nx, ny = q.gradient
        step = climb * self.config.climb_speed * world.config.dt
        moved = (p.x + ny * step, p.y - nx * step)
        on_surface = shape.point_query(moved).point
        joint.anchor_b = held.world_to_local(on_surface)

    def _release(self, world: World) -> None:
        if self.joint is not None:
            world.space.remove(self.joint)
            self.joint = None
            self._held_shape = None

    # -- gravity switches ------------------------------------------------------------------------

    def _gravity_actions(self, world: World, it: Intent) -> None:
        """Gravity switches act on a new intent value (a held intent acts once), from the next
        step on: this step's gravity was applied before the controllers run, and every controller
        (the nullified one included, whether it runs before or after us) must read the gravity
        that acts in its step."""
        name = self.name
        if it.restore_gravity:
            if not world.gravity_rule(name).is_default:
                _next_step(world, lambda w: w.set_gravity_rule(name, None))
        elif it.gravity is not None and it.gravity != self._gravity_wish:
            rule = GravityRule(direction=it.gravity)
            _next_step(world, lambda w: w.set_gravity_rule(name, rule))
        self._gravity_wish = it.gravity
        target = it.nullify
        if target is not None and target != self._nullify_wish:
            _next_step(world, lambda w: w.set_gravity_rule(target, GravityRule(scale=0.0)))
        self._nullify_wish = it.nullify


def _next_step(world: World, change: Callable[[World], None]) -> None:
    """Run ``change`` in the EVENTS stage of the next step, before its gravity is applied."""
    world.at(world.time + 0.5 * world.config.dt, change)


def _stable_hover(config: ControllerConfig, dt: float) -> float:
    """The hover's 2π·f (rad/s), or ValueError if the spring would be unstable at ``dt`` (s)."""
    omega = TWO_PI * config.hover_frequency
    limit = hover_limit(config.hover_damping)
    if omega * dt >= limit:
        raise ValueError(
            f"hover_frequency: 2π·f·dt must stay below 2ζ + 2√(ζ² + 1) = {limit:.4g} "
            f"(ζ = hover_damping = {config.hover_damping!r}) for a stable spring; with dt = "
            f"{dt} s expected f < {limit / (TWO_PI * dt):.4g} Hz, "
            f"got {config.hover_frequency!r}"
        )
    return omega


def hover_spring(
    stiffness: float,
    damping: float,
    mass: float,
    error: float,
    speed: float,
    dt: float,
    substeps: int = 1,
) -> float:
    """The hover's spring-and-damper force along the ground normal for one step, N.

    ``stiffness`` k (N/m), ``damping`` c (N·s/m), ``mass`` m (kg), ``error`` = ride height −
    height (m), ``speed`` = the body's velocity along the normal relative to the ground point
    (m/s), ``dt`` the step (s) split into ``substeps`` equal ``space.step`` calls.

    Why not simply ``k·error − c·speed``: pymunk integrates positions *before* velocities, so a
    force read from the state before the step is explicit Euler, which gains energy (an undamped
    spring grows at any dt; a damped one is stable only while 2πf·dt < 2ζ). The force is instead
    evaluated where the integrator will use it. Over a step of n substeps of h = dt/n with the
    force held constant (the world re-applies the same force every substep), pymunk gives

        v' = v + dt·a          x' = x + dt·v + dt²·a·(n − 1)/(2n)

    Let the spring read the gap predicted a fraction s of the step ahead, x + s·dt·v (relative to
    the ground point, which moves with the ground's velocity), and let the damper act on the
    velocity at the end of the step (implicit, so damping can never feed energy in): with
    ω² = k/m, b = c·dt/m, w = ω·dt,

        a = −ω²·(x + s·dt·v) − (c/m)·v'   ⇒   a = (−ω²·(x + s·dt·v) − (c/m)·v) / (1 + b)

    (the weight feed-forward cancels gravity along the normal, so v' = v + dt·a here).

    The step's matrix on (x, dt·v) has determinant (1 + w²(1 − s − (n − 1)/(2n))) / (1 + b):
    with s = (n + 1)/(2n) it is 1/(1 + b), and an undamped spring (b = 0) keeps its area
    (symplectic: semi-implicit Euler for n = 1, s = 1; the midpoint s → 1/2 for many substeps).
    Its trace is then 1 + (1 − w²)/(1 + b), and the roots stay inside the unit circle while
    w² < 4 + 2b, i.e. ``2πf·dt < 2ζ + 2√(ζ² + 1)`` (:func:`hover_limit`): exactly 2 for an
    undamped spring and more with damping, for every number of substeps. Substeps do not raise
    it: the force is computed once per step, so the step that counts is dt, not h. At rest
    (error = speed = 0) the force is exactly 0, so the weight feed-forward alone holds the body.

    >>> hover_spring(100.0, 0.0, 1.0, 0.01, 0.0, 0.01)
    1.0
    >>> hover_spring(100.0, 20.0, 1.0, 0.0, 0.0, 0.01, substeps=4)
    0.0
    """
    ahead = (substeps + 1) / (2.0 * substeps) * dt
    return (stiffness * (error - ahead * speed) - damping * speed) / (1.0 + damping * dt / mass)


def hover_limit(damping_ratio: float) -> float:
    """The largest stable 2πf·dt of the hover spring at damping ratio ζ: 2ζ + 2√(ζ² + 1).

    Derived in :func:`hover_spring`; independent of the substeps.

    >>> hover_limit(0.0)
    2.0
    >>> round(hover_limit(1.0), 4)
    4.8284
    """
    return 2.0 * damping_ratio + 2.0 * math.sqrt(damping_ratio * damping_ratio + 1.0)


def _react(world: World, ground: pymunk.Body, fx: float, fy: float, point: Vec) -> None:
    """Newton's third law for hover and drive: −(fx, fy) (N) on the ground at ``point`` (m), a
    SUPPORT force (it stands in for a contact). Only a dynamic ground takes it: the world drops
    forces on static and kinematic bodies, so for those the call would only repeat the check of
    a force of the magnitude ours has just passed (and of a hit point within the probe's reach).
    """
    if ground.body_type == pymunk.Body.DYNAMIC:
        world.apply_force(ground, (-fx, -fy), point=point, category=Category.SUPPORT)


def _unit_or(x: float, y: float, fallback: Vec) -> Vec:
    n = math.hypot(x, y)
    return (x / n, y / n) if n > 0.0 else fallback


def _scaled(direction: Vec, magnitude: float) -> Vec:
    """``direction`` made unit length and scaled to ``magnitude`` (zero if it has no length)."""
    return _mul(_unit_or(direction[0], direction[1], _ZERO), magnitude)


def _mul(v: Vec, s: float) -> Vec:
    return (v[0] * s, v[1] * s)
