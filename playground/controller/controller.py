"""The :class:`Controller`: a force-driven capsule player (or enemy) and its step, which reads
sense → decide → act.

Its state lives here; the parts of its step live in their own modules, bound here as its
methods: :mod:`~playground.controller.sensing` (probe, up, load),
:mod:`~playground.controller.states` (the state machine), :mod:`~playground.controller.grab`
(grab, hang, climb), :mod:`~playground.controller.laws` (the force laws) and
:mod:`~playground.controller.switches` (gravity switches).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable

import pymunk

from playground._engine import raw
from playground._engine.contacts import Contacts
from playground._engine.reach import Reach
from playground._engine.sweep import Sweep
from playground.controller import grab, laws, sensing, states, switches
from playground.controller._vec import unit_or
from playground.controller.config import ControllerConfig
from playground.controller.laws import NO_FORCES, ControllerForces
from playground.controller.sensing import GroundHit
from playground.controller.spring import TWO_PI, stable_hover
from playground.controller.states import State
from playground.intents import IDLE, Intent, IntentSource
from playground.params import finite
from playground.vec import Vec
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = ["Controller"]

DEFAULT_CONFIG = ControllerConfig()
"""The configuration a controller gets unless given one."""

_groups = itertools.count(1)


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
        config: ControllerConfig = DEFAULT_CONFIG,
        source: IntentSource | None = None,
        angle: float = 0.0,
    ) -> None:
        if not isinstance(config, ControllerConfig):
            raise ValueError(f"config: expected a ControllerConfig, got {config!r}")
        finite("angle", angle)
        omega = stable_hover(config, world.config.dt)
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
        self._sweep = Sweep(world.space, self._filter)
        self._reach = Reach(world.space, self._filter)
        self.body = body
        # The body's cpBody*: the step reads its state through the C getters
        # (playground._engine.raw).
        self._h = raw.handle(body)
        self._contacts = Contacts(body)
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
        self.up: Vec = unit_or(-g[0], -g[1], (0.0, 1.0))
        self.probe: GroundHit | None = None
        self.last_forces: ControllerForces = NO_FORCES
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
        # The world's settings (dt, substeps), read once a step with the body's state:
        # World.config is a property, and the step's parts would read it five times.
        self._world_config = world.config
        # The world's cpSpace* (its space is made with it and never replaced), and the field's
        # uniformity and our gravity rule as of World.gravity_version: they change only through
        # the world's setters, and sense reads them again when that count has moved.
        self._space_h = raw.space_handle(world.space)
        self._gravity_version = -1
        self._uniform_field = True
        self._gravity_rule = world.gravity_rule(name)

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
        omega = stable_hover(config, self.world.config.dt)
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
        """The CONTROL stage's hook: one step of the controller."""
        if self.removed:
            return
        gx, gy = self._sense(world)
        self._decide(world)
        self._act(world, gx, gy)

    # The parts of the step, defined in the modules named.
    # sense: the body, the gravity at it, up, the ground under it, the load on it
    _sense = sensing.sense
    _gravity = sensing.gravity
    _probe = sensing.probe
    _ground_acceleration = sensing.ground_acceleration
    _contact_load = sensing.contact_load
    _touching = sensing.touching
    # decide: the jump press, the grip, the state machine
    _decide = states.decide
    _update_state = states.update_state
    _steady = states.steady
    _is_still = states.is_still
    _lose_balance = states.lose_balance
    _update_grip = grab.update_grip
    _climb = grab.climb
    _release = grab.release
    # act: gravity switches and the force laws
    _act = laws.act
    _gravity_actions = switches.gravity_actions
    _hover = laws.hover
    _height = laws.height
    _drive = laws.drive
    _steer = laws.steer
    _balance = laws.balance
    _jump = laws.jump
    _push = laws.push
