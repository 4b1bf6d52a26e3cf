"""The :class:`Controller`: a force-driven capsule player (or enemy) in a world, whose step reads
sense → decide → act.

It holds its body, its hooks, its config, its :class:`~playground.controller.laws.Laws` and its
state between steps; the phases are functions of their own modules:
:mod:`~playground.controller.sensing`, :mod:`~playground.controller.decision`,
:mod:`~playground.controller.action` (with :mod:`~playground.controller.grab` and
:mod:`~playground.controller.switches` putting grips and gravity switches into the world).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable

import pymunk

from playground._engine.state import body_state
from playground.controller import switches
from playground.controller._vec import unit_or
from playground.controller.action import NO_FORCES, ControllerForces, act, exert
from playground.controller.config import ControllerConfig
from playground.controller.crowd import Crowd
from playground.controller.decision import decide
from playground.controller.grab import hold
from playground.controller.laws import Laws
from playground.controller.sensing import GroundHit, Sensed, Senses
from playground.controller.spring import TWO_PI, stable_hover
from playground.controller.states import ControllerState, State, Transition
from playground.intents import IDLE, Intent, IntentSource
from playground.params import finite
from playground.vec import Vec
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = ["DEFAULT_CONFIG", "DEFAULT_LAWS", "Controller"]

DEFAULT_CONFIG = ControllerConfig()
"""The configuration a controller gets unless given one."""
DEFAULT_LAWS = Laws()
"""The force laws a controller follows unless given others."""

_groups = itertools.count(1)


class Controller:
    """A force-driven capsule player (or enemy) in a :class:`World`.

    The model, each step, all along the controller's ``up``:

    - **probe**: a circle swept from the centre along −up (``probe_length``) finds the ground.
    - **stairs** (:mod:`~playground.controller.stairs`): the probe's reading of a sharp corner
      is the face past it, not the slant from the corner to the circle; walking, the body
      looks ``radius + probe_radius + speed/(2·hover_frequency)`` ahead (its probe's edge plus
      the way it goes in half the hover's period) for a tread parallel to its ground, above its
      clearance and at most
      the step's reach ``ride_height − half_length`` above its feet — the height of its lower
      cap's centre, above which a riser meets its straight side, a wall — and takes it for the
      ground, so the hover lifts it over the riser before the cap meets it; grounded and
      coming down, a tread up to that reach past ``probe_length`` keeps it grounded (the
      hover only pushes: it falls onto the tread as it would, without turning AIRBORNE).
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
    - **balance**: a PD torque toward up, bounded by ``balance_torque``, and through a loose
      dynamic ground by what the load on it holds down (the hover's force times
      :func:`~playground.controller.sensing.footing`: past it a tile tips under the feet).
      Needing more than the budget for ``balance_loss_time`` while supported loses balance
      (hover, drive and balance let go); once still for ``settle_time`` it gets up over
      ``getup_time``.
    - **jump**, **grab/hang/climb**, **push**, **gravity switches**: see the config.
    - **ledge**: grabbing next to a ledge (a walkable top within ``ledge_grab`` above the
      head) holds its edge with the grip joint on the ledge's own body; a climb up lets go of
      the joint and a climb force (the weight held, at most ``ledge_climb_acceleration``
      relative to the ledge, within the grip budget) lifts it clear of the top and carries it
      over, its reaction on a dynamic ledge (:mod:`~playground.controller.ledge`).

    Newton's third law: hover, drive, jump and balance react on the ground body at the hit point,
    push on the pushed body. The reactions are SUPPORT forces on the ground body too, because they
    stand in for a contact on both sides: a crate the player stands on must read the player's
    weight as a contact load (its accelerometer reads its own weight's worth, not the player's).
    Hover, drive, jump and push are SUPPORT on the player; air steering is APPLIED (nobody feels
    it); the grip is a real joint, so the solver reads it as an engine force.

    Each step (:meth:`step`, the CONTROL stage's hook) is ``sense`` (:class:`Senses`) →
    ``decide`` → ``act`` through :attr:`laws`; its results are the public readings below
    (:attr:`sensed`, :attr:`control_state`, :attr:`last_forces`, :attr:`transition`).

    Arguments: the ``world``, the body's ``name``, its start ``position`` (m) and ``angle``
    (rad); ``config`` (default ``ControllerConfig()``: a 70 kg, 1.8 m capsule); ``source``, what
    it wants each step (default: nothing but :attr:`intent`); ``laws`` (default ``Laws()``).

    In a game, set :attr:`intent` every frame (the per-frame input) and read :attr:`state`,
    :attr:`grounded`, :attr:`up`, :attr:`tilt`, :attr:`ground_velocity` and :attr:`felt` to
    animate it:

    >>> from playground import Intent, World
    >>> world = World()
    >>> floor = world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    >>> player = Controller(world, "player", position=(0.0, 0.95))
    >>> player.intent = Intent(move=1.0)          # held: walk right
    >>> world.run(1.0)                            # s
    >>> player.grounded, round(player.body.velocity.x, 2)     # m/s: its top speed
    (True, 4.0)
    >>> round(player.felt[1], 1), player.ground_velocity      # N: its weight; m/s: still ground
    (686.7, (0.0, 0.0))
    """

    def __init__(
        self,
        world: World,
        name: str,
        position: tuple[float, float],
        config: ControllerConfig | None = None,
        source: IntentSource | None = None,
        angle: float = 0.0,
        laws: Laws | None = None,
    ) -> None:
        # None stands for the defaults, so the signature (help(Controller)) stays one line.
        config = DEFAULT_CONFIG if config is None else config
        laws = DEFAULT_LAWS if laws is None else laws
        if not isinstance(config, ControllerConfig):
            raise ValueError(f"config: expected a ControllerConfig, got {config!r}")
        if not isinstance(laws, Laws):
            raise ValueError(f"laws: expected a Laws, got {laws!r}")
        finite("angle", angle)
        stable_hover(config, world.config.dt)
        self.world = world
        self.name = name
        # Set before its crowd exists (config and laws tell the crowd when they change).
        self._config = config
        self._laws = laws
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
        self.body = body
        """Its pymunk body, named ``name`` in the world (position m, velocity m/s, angle rad)."""
        self.shape = shape
        """Its capsule: a segment ``height − 2·radius`` long (m) with round ends of ``radius``
        (m), friction 0.8; a game may set its ``collision_type``."""
        world.add(name, body, shape)
        world.track(name)
        self.senses = Senses(world, name, body, pymunk.ShapeFilter(group=group))

        self.intent: Intent = IDLE
        """What it wants this step: the game's per-frame input (``move`` −1 … 1 of
        ``max_speed``, ``jump``, …), held until set again; a ``source`` sets it each step."""
        g = world.gravity_at(name)
        self._sensed = Sensed(body=body_state(body), up=unit_or(-g[0], -g[1], (0.0, 1.0)))
        self._control_state = ControllerState()
        self._last_forces: ControllerForces = NO_FORCES
        self._transition: Transition | None = None
        self.stale: Crowd | None = None
        """The crowd that ran this controller's last step, whose readings it has not built yet
        (None: the readings are up to date)."""

        self.removed = False
        self.reads_source = source is not None
        """Whether its INPUTS hook (:meth:`read_source`) reads its source each step (a crowd
        may read it in its place: :meth:`Crowd.read_sources
        <playground.controller.crowd.members.Members.read_sources>`)."""
        self._hooks: list[tuple[Stage, Callable[[World], None]]] = [(Stage.CONTROL, self.step)]
        if source is not None:
            self._hooks.insert(0, (Stage.INPUTS, self.read_source))
        for stage, hook in self._hooks:
            world.on(stage, hook)
        self.crowd = Crowd.of(world)
        """The crowd of the world's controllers (it runs them as one when they are many)."""
        self.crowd.join(self)

    # -- the readings of the last step (built from the crowd's arrays when it ran them) ----------

    @property
    def config(self) -> ControllerConfig:
        """Its body, sensing and budgets (m, kg, s, N; see :class:`ControllerConfig`); set a new
        one to change them from the next step on (its crowd reads it again then).

        >>> from playground import World
        >>> world = World()
        >>> player = Controller(world, "player", position=(0.0, 0.95))
        >>> player.config.height, player.config.radius                  # m
        (1.8, 0.25)
        """
        return self._config

    @config.setter
    def config(self, value: ControllerConfig) -> None:
        self._config = value
        self.crowd.settings_changed()

    @property
    def laws(self) -> Laws:
        """The force laws it follows (replace one with ``dataclasses.replace``)."""
        return self._laws

    @laws.setter
    def laws(self, value: Laws) -> None:
        self._laws = value
        self.crowd.settings_changed()

    @property
    def sensed(self) -> Sensed:
        """What the last step sensed (before the first: the body as built, up against
        gravity)."""
        if self.stale is not None:
            self.stale.materialize(self)
        return self._sensed

    @sensed.setter
    def sensed(self, value: Sensed) -> None:
        self._sensed = value

    @property
    def control_state(self) -> ControllerState:
        """The state after the last step's decisions."""
        if self.stale is not None:
            self.stale.materialize(self)
        return self._control_state

    @control_state.setter
    def control_state(self, value: ControllerState) -> None:
        self._control_state = value

    @property
    def last_forces(self) -> ControllerForces:
        """The forces of the last step."""
        if self.stale is not None:
            self.stale.materialize(self)
        return self._last_forces

    @last_forces.setter
    def last_forces(self, value: ControllerForces) -> None:
        self._last_forces = value

    @property
    def transition(self) -> Transition | None:
        """The change of :attr:`state` in the last step (None: it stayed)."""
        if self.stale is not None:
            self.stale.materialize(self)
        return self._transition

    @transition.setter
    def transition(self, value: Transition | None) -> None:
        self._transition = value

    default_laws: Laws = DEFAULT_LAWS
    """The laws a crowd runs on arrays (a controller with others runs its own step)."""

    @staticmethod
    def unpatched() -> bool:
        """Whether ``Controller.step`` is the one defined here (a break may patch it; a crowd
        then runs every controller through it)."""
        return Controller.step is SCALAR_STEP

    def tune_hover(self, frequency: float, damping: float) -> None:
        """Set the hover spring's frequency (Hz) and damping ratio from the next step on (a live
        tuning panel). ValueError, naming the limit, if the spring would be unstable at the
        world's dt."""
        config = dataclasses.replace(self.config, hover_frequency=frequency, hover_damping=damping)
        stable_hover(config, self.world.config.dt)
        self.config = config

    def remove(self) -> None:
        """Take the controller out of its world: its grip, body, shape and hooks go."""
        if self.removed:
            return
        state = self.control_state
        hold(self.world, state.grip, None, self.intent, self.config, self.world.config.dt)
        self.control_state = dataclasses.replace(state, grip=None)
        # An active crowd runs its members' CONTROL step, and may read their sources: their
        # own hooks of those stages are not registered.
        owned = self.crowd.leave(self)
        self.world.remove(self.name)
        self.senses.detach(self.world)
        for stage, hook in self._hooks:
            if stage not in owned:
                self.world.off(stage, hook)
        self.removed = True

    # -- reading ---------------------------------------------------------------------------------

    @property
    def state(self) -> State:
        """What the state machine is doing (``control_state.state``): GROUNDED, AIRBORNE,
        HANGING, CLIMBING, OFF_BALANCE, GETTING_UP or CRUSHED (:class:`State` says what each
        means for an animation); :attr:`transition` says when it changed.

        >>> from playground import World
        >>> world = World()
        >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))        # m
        >>> player = Controller(world, "player", position=(0.0, 3.0))        # m: 2 m too high
        >>> world.step()
        >>> player.state
        <State.AIRBORNE: 'airborne'>
        >>> world.run(1.0)                                                   # s: it falls, lands
        >>> player.state
        <State.GROUNDED: 'grounded'>
        """
        return self.control_state.state

    @property
    def grounded(self) -> bool:
        """Standing on walkable ground (``state`` is GROUNDED): the walk and idle animations."""
        return self.control_state.state is State.GROUNDED

    @property
    def ground_velocity(self) -> Vec:
        """Velocity the ground under it would carry its centre at, m/s ((0, 0) with no ground;
        ``GroundHit.frame_velocity``): subtract it from the body's velocity for the walk cycle's
        speed on a moving platform."""
        ground = self.sensed.ground
        return (0.0, 0.0) if ground is None else ground.frame_velocity

    @property
    def felt(self) -> Vec:
        """The force it felt in the last step, N: the support (contacts, joints and its own
        hover, drive and grip), as the world's force solver read it; m·g up when standing."""
        return self.world.forces(self.name).support

    @property
    def up(self) -> Vec:
        """The controller's up (unit), as the last step sensed it."""
        return self.sensed.up

    @property
    def probe(self) -> GroundHit | None:
        """The ground the last step's probe found (None: none)."""
        return self.sensed.ground

    @property
    def load(self) -> float:
        """Load borne from above in the last step, its mean over the substeps: contacts and the
        push's reaction, N."""
        return self.sensed.load

    @property
    def contact_load(self) -> float:
        """The contacts' part of :attr:`load`, N: each contact's impulse summed over the
        step's substeps, over dt."""
        return self.sensed.contact_load

    @property
    def pushed(self) -> tuple[Vec, Vec] | None:
        """Where (m) the last step's push acted on the pushed body, and the force on it (N)."""
        pushed = self.last_forces.pushed
        return None if pushed is None else (pushed[1], pushed[2])

    @property
    def joint(self) -> pymunk.PivotJoint | None:
        """The grip's joint (None: not holding)."""
        grip = self.control_state.grip
        return None if grip is None else grip.joint

    @property
    def mass(self) -> float:
        """The body's mass now, kg: ``config.mass`` until ``World.set_mass`` changes it. The
        hover's stiffness and damping, its weight feed-forward, the drive, the air steering and
        the jump all use it, so the spring keeps its frequency and the ride height its value."""
        return float(self.body.mass)

    @property
    def hover_stiffness(self) -> float:
        """The hover spring's stiffness k = m·(2πf)², N/m, for the mass now."""
        omega = TWO_PI * self.config.hover_frequency
        return self.mass * omega * omega

    @property
    def hover_damping_coefficient(self) -> float:
        """The hover's damping c = 2ζ·m·2πf, N·s/m, for the mass now."""
        omega = TWO_PI * self.config.hover_frequency
        return 2.0 * self.config.hover_damping * self.mass * omega

    @property
    def axis(self) -> Vec:
        """The capsule's own up: its local +y in world coordinates (a unit vector, no unit).

        >>> from playground import World
        >>> world = World()
        >>> player = Controller(world, "player", position=(0.0, 5.0), angle=math.pi / 2)  # m, rad
        >>> tuple(round(c, 6) for c in player.axis)          # turned a quarter: its head at −x
        (-1.0, 0.0)
        """
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
        """Magnitude of the grip joint's force, the last step's mean over its substeps, N (0
        when not hanging)."""
        grip = self.control_state.grip
        if grip is None:
            return 0.0
        return self.laws.grip(grip.impulses.total, self.world.config.dt)

    # -- the step --------------------------------------------------------------------------------

    def read_source(self, world: World) -> None:
        """The INPUTS stage's hook: take this step's intent from the source."""
        assert self.source is not None
        if self.removed:
            return
        intent = self.source.intent(world.time)
        if not isinstance(intent, Intent):
            # A duck-typed intent skips Intent's checks: a NaN move would win the whole budget.
            raise ValueError(f"{self.name}: the intent source returned {intent!r}, not an Intent")
        self.intent = intent

    def step(self, world: World) -> None:
        """The CONTROL stage's hook: one step of the controller, sense → decide → act."""
        if self.removed:
            return
        if self.stale is not None:
            self.stale.materialize(self)
        intent = self.intent
        config = self._config
        before = self._control_state
        last = self._last_forces
        sensed = self.senses.sense(
            world, self._sensed, before, intent, last.push, last.balance_short, config, last.drive
        )
        state = decide(sensed, before, intent, config)
        if before.grip is not None or state.grip is not None:
            hold(world, before.grip, state.grip, intent, config, sensed.dt)
        forces = act(sensed, state, intent, config, self._laws)
        if intent.restore_gravity or intent.gravity is not None or intent.nullify is not None:
            switches.switch(world, self.name, intent, before.gravity_wish, before.nullify_wish)
        exert(world, self.body, forces)
        self._sensed = sensed
        self._control_state = state
        self._last_forces = forces
        changed = state.state is not before.state
        self._transition = Transition(sensed.time, before.state, state.state) if changed else None


SCALAR_STEP = Controller.step
"""The step as defined here: while a break patches ``Controller.step``, a crowd runs every
controller through it."""
