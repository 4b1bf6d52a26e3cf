"""The world: a pymunk space in SI units and the fixed step that runs every stage top-down.

The stages (docs/design.md §4) are named by :class:`Stage`; a stage the scene does not need is
skipped without cost (uniform gravity is ``space.gravity``; no tracked body, no solver; no
perceiver, no filter). Each stage can be timed.

>>> world = World()
>>> box = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
>>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
>>> world.track("crate")
>>> world.run(1.0)
>>> round(world.forces("crate").support[1], 6)
98.1
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from enum import Enum

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

from playground._batch import BodyRows, lookup, read_positions
from playground._validate import bounded, bounded_vec, finite, in_range
from playground.forces import BodyForces, Category, ForceLedger, ForceSolver
from playground.gravity import GravityField, GravityRule, RotatingRoom, Uniform, apply_rules
from playground.guard import (
    FORCE_BOUNDS,
    FORCE_COLUMNS,
    GUARD_EVERY,
    STATE_BOUNDS,
    STATE_COLUMNS,
    RunawayError,
    first_bad,
)
from playground.limits import (
    MAX_ANGLE,
    MAX_ANGULAR_SPEED,
    MAX_COORDINATE,
    MAX_DT,
    MAX_FORCE,
    MAX_GRAVITY,
    MAX_IMPULSE,
    MAX_LENGTH,
    MAX_MASS,
    MAX_MOMENT,
    MAX_SPEED,
    MIN_DT,
    MIN_MASS,
    MIN_MOMENT,
    RUNAWAY_FORCE,
)
from playground.movers import Mover, Path
from playground.perception import PerceivedGravity, Perception
from playground.scalar import SCALAR_MAX_BODIES, ScalarPath

__all__ = ["Stage", "StageTiming", "World", "WorldConfig"]

Vec = tuple[float, float]
Hook = Callable[["World"], None]

_NEVER = 2**62
"""A step number no run reaches: the guard's next check when the guard is off."""
_DEFAULT_RULE = GravityRule()
"""The rule of a body that has none (frozen, so one instance serves every read)."""
_F = batch.BodyFields
_STATE = _F.BODY_ID | _F.POSITION | _F.ANGLE | _F.VELOCITY | _F.ANGULAR_VELOCITY
"""The guard's read: x, y, angle, vx, vy, w per body (batch packs fields in this order)."""


class Stage(Enum):
    """The stages of one step, in the order they run."""

    INPUTS = 1
    EVENTS = 2
    GRAVITY = 3
    MOVERS = 4
    CONTROL = 5
    PHYSICS = 6
    FORCES = 7
    FILTER = 8
    OBSERVE = 9


_HOOK_LISTS = {
    Stage.INPUTS: "_inputs",
    Stage.EVENTS: "_event_hooks",
    Stage.CONTROL: "_controls",
    Stage.OBSERVE: "_observers",
}
"""The World attribute holding each stage's hooks."""


@dataclass(frozen=True, slots=True)
class WorldConfig:
    """Simulation settings, frozen.

    Attributes:
        dt: the fixed step, s, within [``MIN_DT``, ``MAX_DT``] of :mod:`playground.limits`.
        substeps: ``space.step`` calls per step (each of dt/substeps). Every force and torque
            on a body when the step starts acts for the whole step, as over one
            ``space.step(dt)``: those applied through the world and those set straight on a
            pymunk body (``body.force``), tracked or not. pymunk clears forces after each
            ``space.step``, so the world re-applies them before each substep.
        iterations: the contact/joint solver's iterations per substep.
        damping: fraction of velocity kept after one second (pymunk's convention; 1 = none).
        collision_slop: allowed overlap, m. pymunk's default 0.1 is meant for pixels: in metres
            it lets a body sink 10 cm into the floor. 5 mm is invisible at human scale and still
            large enough to keep resting contacts persistent (no jitter).
        sleep_time: idle time before bodies fall asleep, s (inf: never). With sleeping on, the
            solver checks each tracked body for sleep (per-body Python) and forces are written
            per body rather than in one batch.
        contact_split: also split engine forces into contacts and constraints (costs a batch
            read of every arbiter per substep).
        timing: time each stage (off by default: ``perf_counter`` calls cost ~1 µs a stage).
        guard: stop with :class:`~playground.guard.RunawayError` when a body goes non-finite or
            runs away (see :mod:`playground.guard`). Off only to watch a blow-up on purpose; then
            :meth:`World.apply_force` takes any finite force.
        perception: how perceived gravity is filtered.
    """

    dt: float = 1.0 / 120.0
    substeps: int = 1
    iterations: int = 10
    damping: float = 1.0
    collision_slop: float = 0.005
    sleep_time: float = math.inf
    contact_split: bool = False
    timing: bool = False
    guard: bool = True
    perception: Perception = field(default_factory=Perception)

    def __post_init__(self) -> None:
        in_range("dt", self.dt, MIN_DT, MAX_DT, "s")
        for name in ("substeps", "iterations"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise ValueError(f"{name}: expected an integer >= 1, got {value!r}")
        finite("damping", self.damping)
        if not 0.0 < self.damping <= 1.0:
            raise ValueError(f"damping: expected a number in (0, 1], got {self.damping!r}")
        finite("collision_slop", self.collision_slop)
        if self.collision_slop < 0.0:
            raise ValueError(
                f"collision_slop: expected a number >= 0 m, got {self.collision_slop!r}"
            )
        if not self.sleep_time > 0.0:
            raise ValueError(
                f"sleep_time: expected a number of seconds > 0, got {self.sleep_time!r}"
            )


@dataclass(slots=True)
class StageTiming:
    """Wall-clock cost of one stage: total seconds, calls, and the last call's seconds."""

    total: float = 0.0
    calls: int = 0
    last: float = 0.0

    @property
    def mean(self) -> float:
        """Mean seconds per call."""
        return self.total / self.calls if self.calls else 0.0


class World:
    """A pymunk space in SI units, stepped at a fixed dt through the stages of :class:`Stage`.

    Bodies are added by name (:meth:`add`); the world registers masses for per-body gravity and
    tracks forces only for bodies passed to :meth:`track`. Scripts and controllers hook into the
    INPUTS, EVENTS, CONTROL and OBSERVE stages with :meth:`on`; forces and torques go through
    :meth:`apply_force` and :meth:`apply_torque` (they check their input and land in
    :attr:`ledger`, which records their categories for the solver). A force set straight on a
    pymunk body acts too, for the whole step like any other (see ``WorldConfig.substeps``); the
    solver counts it as APPLIED. The space drops an arbiter as soon as its contact ends
    (``collision_persistence`` 1), so arbiter impulses are the impulses applied (see
    :class:`~playground.forces.ForceSolver`).
    """

    def __init__(
        self,
        config: WorldConfig | None = None,
        gravity: GravityField | Sequence[float] | None = None,
    ) -> None:
        self._config = config if config is not None else WorldConfig()
        self.space = pymunk.Space()
        # Chipmunk keeps an arbiter 3 steps after its contact ends by default; a contact made
        # again from it starts from the old accumulated impulse without applying it, so the
        # arbiter reports an impulse the bodies never received (see ForceSolver). Dropping
        # arbiters at once loses no warm start (such a first contact is never warm-started), and
        # the new contact no longer starts from an impulse that lets it pull, or grip beyond its
        # own normal impulse.
        self.space.collision_persistence = 1
        # space.step calls outside the bare path (which runs only with nothing tracked): the
        # solver's substep stamps.
        self._space_steps = 0
        self._bare = False
        self._plan_dirty = True
        self.time = 0.0
        self._epoch = (0, 0.0)  # (steps, time) when dt last changed
        self.steps = 0
        self.ledger = ForceLedger(on_first=self._replan)
        self._solver = ForceSolver(
            contact_split=self.config.contact_split,
            check_sleep=math.isfinite(self.config.sleep_time),
        )
        self._perceived = PerceivedGravity(self.config.perception)
        # Few tracked bodies: the scalar path serves them in plain floats (see _plan).
        self._scalar = ScalarPath()
        self.scalar_max_bodies = SCALAR_MAX_BODIES
        """Most tracked bodies the scalar path serves (0: never; set before stepping)."""
        self._scalar_on = False
        self._scalar_synced = True
        self.config = self._config
        self.timings: dict[Stage, StageTiming] = {s: StageTiming() for s in Stage}
        self._bodies: dict[str, pymunk.Body] = {}
        # Each body's id by name: ``body.id`` is a call into chipmunk, and controllers look up
        # their rule and tracked row by name every step.
        self._ids: dict[str, int] = {}
        self._names: dict[int, str] = {}
        self._rules: dict[int, GravityRule] = {}
        self._movers: list[Mover] = []
        # One plain list per hook stage (not a dict keyed by Stage: an Enum's hash is Python code
        # and the step checks these every time).
        self._inputs: list[Hook] = []
        self._event_hooks: list[Hook] = []
        self._controls: list[Hook] = []
        self._observers: list[Hook] = []
        self._gravity_stage = False
        self._events: list[tuple[float, int, Hook]] = []
        self._perceivers: set[int] = set()
        self._rows = BodyRows()
        self._pos_buffer = batch.Buffer()
        self._registry_dirty = True
        self._reg_ids = np.zeros(0, dtype=np.uintp)
        self._reg_mass = np.zeros(0)
        self._reg_scale = np.zeros(0)
        self._reg_dir = np.zeros((0, 2))
        self._field_force: NDArray[np.float64] | None = None
        self._field_ids = np.zeros(0, dtype=np.uintp)
        self._field_rows: (
            tuple[
                NDArray[np.uintp],
                NDArray[np.intp],
                NDArray[np.float64],
                NDArray[np.float64],
                NDArray[np.float64],
            ]
            | None
        ) = None
        self._field: GravityField = Uniform()
        self._guard_next = GUARD_EVERY if self._config.guard else _NEVER
        self._state_buffer = batch.Buffer()
        self.gravity = gravity if gravity is not None else Uniform()

    # -- configuration ---------------------------------------------------------------------------

    @property
    def config(self) -> WorldConfig:
        """The simulation settings. Replacing them applies the new space settings (dt, substeps,
        iterations, damping, slop, sleeping, contact split, timing); perception is fixed."""
        return self._config

    @config.setter
    def config(self, config: WorldConfig) -> None:
        if config.perception != self._config.perception:
            raise ValueError("config.perception: change it with set_perception")
        if config.dt != self._config.dt:
            # Time goes on from now at the new step (time is counted from this epoch, not as a
            # running sum, so it does not drift).
            self._epoch = (self.steps, self.time)
        self._config = config
        self.space.iterations = config.iterations
        self.space.damping = config.damping
        self.space.collision_slop = config.collision_slop
        self.space.sleep_time_threshold = config.sleep_time
        self._solver.contact_split = config.contact_split
        self._solver.check_sleep = math.isfinite(config.sleep_time)
        self._guard_next = self.steps + GUARD_EVERY if config.guard else _NEVER
        self._plan_dirty = True

    def set_perception(self, perception: Perception) -> None:
        """Re-tune how perceived gravity is filtered (1€ parameters, up threshold) from the next
        step on, keeping the filter's state; the spike stage is fixed when the world is built."""
        if not isinstance(perception, Perception):
            raise ValueError(f"perception: expected a Perception, got {perception!r}")
        self._perceived.tune(perception)
        self._config = dataclasses.replace(self._config, perception=perception)

    def _replan(self) -> None:
        """Plan the next step again (something it must do has appeared)."""
        self._plan_dirty = True

    @property
    def solver(self) -> ForceSolver:
        """The force solver: membership and readings of the tracked bodies (the scalar path's
        readings are copied in when it serves them)."""
        self._sync_scalar()
        return self._solver

    @property
    def perceived(self) -> PerceivedGravity:
        """Perceived gravity of the tracked bodies (filled from the scalar path when it serves)."""
        self._sync_scalar()
        return self._perceived

    def _sync_scalar(self) -> None:
        if self._scalar_on and not self._scalar_synced:
            self._scalar.store(self._solver, self._perceived)
            self._scalar_synced = True

    def _leave_scalar(self) -> None:
        """Hand the scalar path's state back before the tracked set or the masses change."""
        if self._scalar_on:
            self._sync_scalar()
            self._scalar_on = False
            self._plan_dirty = True

    def _plan(self) -> None:
        """Decide whether the next steps are bare (nothing but ``space.step``), and which path
        serves the tracked bodies: plain floats for a few with one substep, no contact split and
        no per-body field (:mod:`playground.scalar`), numpy and ``pymunk.batch`` otherwise."""
        cfg = self._config
        scalar = (
            0 < len(self._solver.bodies) <= self.scalar_max_bodies
            and cfg.substeps == 1
            and not cfg.contact_split
            and (not self._gravity_stage or self._field.uniform)
        )
        if scalar != self._scalar_on:
            if scalar:
                self._scalar.load(self._solver, self._perceived)
                self._scalar_synced = True
            else:
                self._sync_scalar()
            self._scalar_on = scalar
        self._bare = not (
            self._inputs
            or self._events
            or self._event_hooks
            or self._gravity_stage
            or self._movers
            or self._controls
            or self._solver.bodies
            or self._perceivers
            or self._observers
            or len(self.ledger)
            or self._config.timing
            or self._config.substeps != 1
        )
        self._plan_dirty = False

    # -- gravity ---------------------------------------------------------------------------------

    @property
    def gravity(self) -> GravityField:
        """The gravity field (m/s²). A plain (gx, gy) is accepted and becomes :class:`Uniform`."""
        return self._field

    @gravity.setter
    def gravity(self, value: GravityField | Sequence[float]) -> None:
        if not isinstance(value, GravityField):
            bounded_vec("gravity", tuple(value), MAX_GRAVITY, "m/s²")
            value = Uniform((float(value[0]), float(value[1])))
        self._field = value
        self.space.gravity = self._space_gravity(self.time)
        self._update_gravity_stage()

    def _space_gravity(self, t: float) -> Vec:
        """What ``space.gravity`` holds: the field if uniform, else zero (forces do the work)."""
        f = self._field
        if isinstance(f, Uniform):
            return f.g
        if isinstance(f, RotatingRoom):
            return f.vector(t)
        if f.uniform:
            g = f.at(np.zeros((1, 2)), t)[0]
            return (float(g[0]), float(g[1]))
        return (0.0, 0.0)

    def set_gravity_rule(self, name: str, rule: GravityRule | None) -> None:
        """Give one body its own gravity: a scale (0 nullifies it) or its own direction.

        ``None`` restores the field.
        """
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only dynamic bodies feel gravity")
        if rule is None or rule.is_default:
            self._rules.pop(body.id, None)
        else:
            self._rules[body.id] = rule
        self._registry_dirty = True
        self._update_gravity_stage()

    def gravity_rule(self, name: str) -> GravityRule:
        """The body's rule (the default rule if it has none)."""
        self.body(name)  # KeyError naming the known bodies
        return self._rules.get(self._ids[name], _DEFAULT_RULE)

    def gravity_at(self, name: str) -> Vec:
        """The gravity this body feels now (field and rule), m/s²."""
        body = self.body(name)
        g = self._field.at(np.array([[body.position.x, body.position.y]]), self.time)
        rule = self._rules.get(body.id, _DEFAULT_RULE)
        d = np.array([rule.direction if rule.direction is not None else (np.nan, np.nan)])
        out = apply_rules(g, np.array([rule.scale]), d)[0]
        return (float(out[0]), float(out[1]))

    # -- bodies ----------------------------------------------------------------------------------

    def add(self, name: str, body: pymunk.Body, *shapes: pymunk.Shape) -> pymunk.Body:
        """Add a named body and its shapes. Names are unique.

        Its mass, state and shapes must lie in the ranges of :mod:`playground.limits`
        (``ValueError`` naming the attribute otherwise): pymunk aborts the process on some
        absurd values and carries NaN through every later step on others.
        """
        if not isinstance(name, str) or not name:
            raise ValueError(f"name: expected a non-empty string, got {name!r}")
        if name in self._bodies:
            raise ValueError(f"{name}: a body with this name already exists")
        _check_body(name, body, shapes)
        self.space.add(body, *shapes)
        self._bodies[name] = body
        self._ids[name] = body.id
        self._names[body.id] = name
        self._registry_dirty = True
        return body

    def remove(self, name: str) -> None:
        """Remove a body, its shapes and constraints, and stop tracking it."""
        body = self._bodies.pop(name)
        del self._ids[name]
        del self._names[body.id]
        self._rules.pop(body.id, None)
        self._update_gravity_stage()
        if self._solver.row_of(body) is not None:
            self._untrack(body)
        self._movers = [m for m in self._movers if m.body is not body]
        self._plan_dirty = True
        self.space.remove(*body.shapes, *body.constraints, body)
        self._registry_dirty = True

    def body(self, name: str) -> pymunk.Body:
        """The body called ``name`` (KeyError naming the known bodies otherwise)."""
        try:
            return self._bodies[name]
        except KeyError:
            known = ", ".join(sorted(self._bodies)) or "none"
            raise KeyError(f"no body named {name!r} (known: {known})") from None

    def body_at(self, point: Vec, radius: float = 0.0) -> str | None:
        """The named body with a shape at world ``point`` (m) or within ``radius`` (m) of it (the
        nearest if several), or None (unnamed bodies such as static ground do not count).

        >>> world = World()
        >>> _ = world.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
        >>> world.body_at((0.2, 0.7)), world.body_at((2.0, 0.5)), world.body_at((0.6, 0.5), 0.2)
        ('crate', None, 'crate')
        """
        bounded_vec("point", point, MAX_COORDINATE, "m")
        finite("radius", radius)
        info = self.space.point_query_nearest(point, max(radius, 0.0), pymunk.ShapeFilter())
        if info is None or info.shape is None or info.shape.body is None:
            return None
        return self._names.get(info.shape.body.id)

    def name_of(self, body: pymunk.Body) -> str | None:
        return self._names.get(body.id)

    @property
    def names(self) -> list[str]:
        return list(self._bodies)

    def set_mass(self, name: str, mass: float, moment: float | None = None) -> None:
        """Change a body's mass (kg) and optionally moment (kg·m²; ∞ locks its rotation); the
        solver follows."""
        in_range("mass", mass, MIN_MASS, MAX_MASS, "kg")
        if moment is not None and moment != math.inf:
            in_range("moment", moment, MIN_MOMENT, MAX_MOMENT, "kg·m²")
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only a dynamic body has a mass to change")
        body.mass = mass
        if moment is not None:
            body.moment = moment
        self._solver.refresh_masses()
        if self._scalar_on:
            self._scalar.refresh_masses()
        self._registry_dirty = True

    def sleep(self, name: str) -> None:
        """Put a body to sleep now, with every dynamic body it touches or is jointed to.

        Chipmunk sleeps and wakes such a group together; a body put to sleep alone while it
        touches an awake one corrupts its memory, and one put to sleep twice aborts the process.
        So the whole group is woken, then put to sleep around ``name``; a sleeping body is left
        as it is. Any force, contact or change of gravity wakes the group again.
        """
        if not math.isfinite(self._config.sleep_time):
            raise ValueError(
                f"{name}: sleeping is off in this world (WorldConfig.sleep_time = inf); "
                "give the world a finite sleep_time to put bodies to sleep"
            )
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only a dynamic body can sleep")
        if body.is_sleeping:
            return
        group = _group(body)
        for other in group:
            other.activate()
        body.sleep()
        for other in group:
            if other is not body:
                other.sleep_with_group(body)

    def wake(self, name: str) -> None:
        """Wake a sleeping body and its group (nothing happens to an awake one)."""
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only a dynamic body sleeps or wakes")
        body.activate()

    def add_box(
        self,
        name: str,
        *,
        mass: float,
        size: Vec,
        position: Vec,
        angle: float = 0.0,
        friction: float = 0.8,
        elasticity: float = 0.0,
    ) -> pymunk.Body:
        """A dynamic box of ``size`` (w, h in m) and ``mass`` (kg)."""
        in_range("mass", mass, MIN_MASS, MAX_MASS, "kg")
        _check_size("size", size)
        bounded_vec("position", position, MAX_COORDINATE, "m")
        bounded("angle", angle, MAX_ANGLE, "rad")
        _check_surface("", friction, elasticity)
        body = pymunk.Body(mass, pymunk.moment_for_box(mass, size))
        body.position = position
        body.angle = angle
        shape = pymunk.Poly.create_box(body, size)
        shape.friction = friction
        shape.elasticity = elasticity
        return self.add(name, body, shape)

    def add_static_segment(
        self,
        a: Vec,
        b: Vec,
        radius: float = 0.05,
        *,
        friction: float = 1.0,
        elasticity: float = 0.0,
    ) -> pymunk.Segment:
        """A static segment from ``a`` to ``b`` (m) on the space's static body."""
        bounded_vec("a", a, MAX_COORDINATE, "m")
        bounded_vec("b", b, MAX_COORDINATE, "m")
        in_range("radius", radius, 0.0, MAX_LENGTH, "m")
        _check_surface("", friction, elasticity)
        seg = pymunk.Segment(self.space.static_body, a, b, radius)
        seg.friction = friction
        seg.elasticity = elasticity
        self.space.add(seg)
        return seg

    def add_mover(self, name: str, path: Path) -> Mover:
        """Drive the kinematic body ``name`` along ``path`` (placed at its pose now)."""
        mover = Mover(self.body(name), path)
        mover.place(self.time)
        self._movers.append(mover)
        self._plan_dirty = True
        return mover

    # -- forces ----------------------------------------------------------------------------------

    def track(self, *names: str, perceive: bool = True) -> None:
        """Recover engine forces for these dynamic bodies every step; ``perceive`` also filters
        their perceived gravity."""
        self._leave_scalar()
        for name in names:
            body = self.body(name)
            old = len(self._solver.bodies)
            self._solver.track(body)
            if len(self._solver.bodies) > old:
                self._perceived.resize(np.concatenate([np.arange(old), [-1]]).astype(np.intp))
            if perceive:
                self._perceivers.add(body.id)
        self._plan_dirty = True

    def _untrack(self, body: pymunk.Body) -> None:
        self._leave_scalar()
        row = self._solver.row_of(body)
        assert row is not None
        n = len(self._solver.bodies)
        self._solver.untrack(body)
        self._perceived.resize(np.delete(np.arange(n), row).astype(np.intp))
        self._perceivers.discard(body.id)
        self._plan_dirty = True

    def apply_force(
        self,
        body: pymunk.Body | str,
        force: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Apply ``force`` (N, world frame) at world ``point`` (m) during the coming step."""
        b = self._own(body)
        bounded_vec("force", force, RUNAWAY_FORCE if self._config.guard else math.inf, "N")
        if point is not None:
            bounded_vec("point", point, MAX_COORDINATE, "m")
        if b.body_type == pymunk.Body.DYNAMIC:
            self.ledger.add(b, force, point=point, category=category)
            self._plan_dirty = True

    def apply_torque(
        self, body: pymunk.Body | str, torque: float, *, category: Category = Category.APPLIED
    ) -> None:
        """Apply a pure ``torque`` (N·m, counter-clockwise) during the coming step."""
        b = self._own(body)
        # A torque is a force times a lever of at most the world's size: the same runaway bound.
        limit = RUNAWAY_FORCE * MAX_COORDINATE if self._config.guard else math.inf
        bounded("torque", torque, limit, "N·m")
        if b.body_type == pymunk.Body.DYNAMIC:
            self.ledger.add_torque(b, torque, category)
            self._plan_dirty = True

    def apply_impulse(
        self,
        body: pymunk.Body | str,
        impulse: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Apply ``impulse`` (N·s) spread over the coming step, as the force impulse/dt."""
        bounded_vec("impulse", impulse, MAX_IMPULSE, "N·s")
        dt = self.config.dt
        self.apply_force(body, (impulse[0] / dt, impulse[1] / dt), point=point, category=category)

    def _own(self, body: pymunk.Body | str) -> pymunk.Body:
        """The body by name, or a body object that is in this world (``ValueError`` otherwise)."""
        if isinstance(body, str):
            return self.body(body)
        if not isinstance(body, pymunk.Body) or body.space is not self.space:
            raise ValueError(f"body: expected a body name or a body of this world, got {body!r}")
        return body

    def forces(self, name: str) -> BodyForces:
        """The last readings of a tracked body."""
        if self._scalar_on:
            return self._scalar.reading(self._tracked_row(name))
        return self._solver.reading(self._tracked_row(name))

    def perceived_gravity(self, name: str) -> Vec:
        """The filtered perceived gravity of a tracked body, m/s²."""
        if self._scalar_on:
            return self._scalar.gravity(self._tracked_row(name))
        g = self._perceived.gravity[self._tracked_row(name)]
        return (float(g[0]), float(g[1]))

    def perceived_up(self, name: str) -> Vec:
        """Unit vector opposite the perceived gravity, held through weak readings."""
        if self._scalar_on:
            return self._scalar.up(self._tracked_row(name))
        u = self._perceived.up[self._tracked_row(name)]
        return (float(u[0]), float(u[1]))

    def _tracked_row(self, name: str) -> int:
        row = self._solver.row_of(self.body(name), self._ids[name])
        if row is None:
            raise KeyError(f"{name}: not tracked (call world.track({name!r}) first)")
        return row

    # -- hooks and events ------------------------------------------------------------------------

    def on(self, stage: Stage, hook: Hook) -> None:
        """Run ``hook(world)`` every step in ``stage`` (INPUTS, EVENTS, CONTROL or OBSERVE)."""
        if stage not in (Stage.INPUTS, Stage.EVENTS, Stage.CONTROL, Stage.OBSERVE):
            raise ValueError(f"stage: hooks run in INPUTS, EVENTS, CONTROL or OBSERVE, not {stage}")
        self._hook_list(stage).append(hook)
        self._plan_dirty = True

    def off(self, stage: Stage, hook: Hook) -> None:
        """Stop running ``hook`` in ``stage``: the opposite of :meth:`on`. Safe from inside a
        step: the stage that is running finishes with the hooks it started with.

        >>> world = World()
        >>> def count(w: World) -> None: ...
        >>> world.on(Stage.OBSERVE, count)
        >>> world.off(Stage.OBSERVE, count)
        >>> world.off(Stage.OBSERVE, count)
        Traceback (most recent call last):
        ...
        ValueError: hook: count is not registered in OBSERVE
        """
        hooks = self._hook_list(stage)
        if hook not in hooks:
            name = getattr(hook, "__name__", repr(hook))
            raise ValueError(f"hook: {name} is not registered in {stage.name}")
        kept = list(hooks)  # a new list: a step iterating the old one is not disturbed
        kept.remove(hook)
        setattr(self, _HOOK_LISTS[stage], kept)
        self._plan_dirty = True

    def _hook_list(self, stage: Stage) -> list[Hook]:
        hooks: list[Hook] = getattr(self, _HOOK_LISTS[stage])
        return hooks

    def at(self, t: float, event: Hook) -> None:
        """Run ``event(world)`` once, in the EVENTS stage of the first step starting at or after
        ``t`` (s). Events at the same time run in the order they were scheduled."""
        finite("t", t)
        self._events.append((t, len(self._events), event))
        self._events.sort(key=lambda e: (e[0], e[1]))
        self._plan_dirty = True

    # -- the step --------------------------------------------------------------------------------

    def step(self) -> None:
        """Advance one fixed step of ``config.dt`` seconds through the stages, top-down."""
        if self._plan_dirty:
            self._plan()
        if self._bare:
            # A scene that calls for no effect costs what bare pymunk costs.
            self.space.step(self._config.dt)
            self.steps += 1
            self.time = self._epoch[1] + (self.steps - self._epoch[0]) * self._config.dt
            if self.steps >= self._guard_next:
                self._guard_all()
            return
        run = self._run_timed if self._config.timing else self._run
        # 1. inputs: scripts and keyboards turn into intents
        if self._inputs:
            run(Stage.INPUTS, self._run_hooks, self._inputs)
        # 2. events: scheduled scene changes
        if (self._events and self._events[0][0] <= self.time + 1e-12) or self._event_hooks:
            run(Stage.EVENTS, self._run_events)
        # 3. gravity: space.gravity for a uniform field, per-body forces for anything else
        if self._gravity_stage:
            run(Stage.GRAVITY, self._apply_gravity)
        # 4. movers: kinematic bodies get the velocity that reaches their next pose
        if self._movers:
            run(Stage.MOVERS, self._drive_movers)
        # 5. control: controllers sense and put their forces in the ledger
        if self._controls:
            run(Stage.CONTROL, self._run_hooks, self._controls)
        # 6. physics: flush forces, step the space (re-applying forces every substep)
        run(Stage.PHYSICS, self._physics)
        # 7. forces: reverse integration for tracked bodies
        if self._solver.bodies:
            run(Stage.FORCES, self._solve_forces)
        # 8. filter: perceived gravity for the bodies that perceive
        if self._perceivers:
            run(Stage.FILTER, self._filter)
        if len(self.ledger):
            self.ledger.clear()
            self._plan_dirty = True
        self._field_force = None
        self.steps += 1
        # Not a running sum: no drift over long runs (the epoch moves only when dt changes).
        self.time = self._epoch[1] + (self.steps - self._epoch[0]) * self._config.dt
        # the guard: nothing non-finite or runaway reaches the observers
        if self._solver.bodies and self._config.guard:
            self._guard_tracked()
        if self.steps >= self._guard_next:
            self._guard_all()
        # 9. observe: recorders, checks, views — read-only
        if self._observers:
            run(Stage.OBSERVE, self._run_hooks, self._observers)

    def run(self, seconds: float) -> None:
        """Step for ``seconds`` of simulated time (rounded to whole steps)."""
        steps = seconds / self.config.dt
        if not (math.isfinite(steps) and steps >= 0.0):
            raise ValueError(f"seconds: expected a finite number of seconds >= 0, got {seconds!r}")
        for _ in range(round(steps)):
            self.step()

    @staticmethod
    def _run(stage: Stage, fn: Callable[..., None], *args: object) -> None:
        fn(*args)

    def _run_timed(self, stage: Stage, fn: Callable[..., None], *args: object) -> None:
        t0 = time.perf_counter()
        fn(*args)
        elapsed = time.perf_counter() - t0
        timing = self.timings[stage]
        timing.total += elapsed
        timing.calls += 1
        timing.last = elapsed

    def _guard_tracked(self) -> None:
        """Stop if a tracked body's force reading is not finite or beyond the runaway bound."""
        if self._scalar_on:
            bad = self._scalar.first_bad(RUNAWAY_FORCE)
            if bad is not None:
                row, col = bad
                value = self._scalar.engine(row)[col]
                self._runaway(self._solver.bodies[row].id, FORCE_COLUMNS[col], value, RUNAWAY_FORCE)
            return
        bad = first_bad(self._solver.engine, FORCE_BOUNDS)
        if bad is not None:
            row, col = bad
            body = self._solver.bodies[row]
            value = float(self._solver.engine[row, col])
            self._runaway(body.id, FORCE_COLUMNS[col], value, float(FORCE_BOUNDS[col]))

    def _guard_all(self) -> None:
        """Stop if any body's position, angle or velocity is not finite or runs away."""
        self._guard_next = self.steps + GUARD_EVERY
        buffer = self._state_buffer
        buffer.clear()
        batch.get_space_bodies(self.space, _STATE, buffer)
        rows = np.frombuffer(buffer.float_buf(), dtype=np.float64).reshape(-1, 6)
        bad = first_bad(rows, STATE_BOUNDS)
        if bad is not None:
            row, col = bad
            body_id = int(np.frombuffer(buffer.int_buf(), dtype=np.uintp)[row])
            self._runaway(body_id, STATE_COLUMNS[col], float(rows[row, col]), STATE_BOUNDS[col])

    def _runaway(
        self, body_id: int, column: tuple[str, str, str], value: float, bound: float
    ) -> None:
        name = self._names.get(body_id)
        who = repr(name) if name is not None else f"an unnamed body (id {body_id})"
        raise RunawayError(who, self.steps, self.time, column, value, float(bound))

    def _run_hooks(self, hooks: list[Hook]) -> None:
        for hook in hooks:
            hook(self)

    def _run_events(self) -> None:
        while self._events and self._events[0][0] <= self.time + 1e-12:
            _, _, event = self._events.pop(0)
            event(self)
            self._plan_dirty = True
        for hook in self._event_hooks:
            hook(self)

    # -- stage bodies ----------------------------------------------------------------------------

    def _update_gravity_stage(self) -> None:
        """The gravity stage runs only for a non-constant field or bodies with their own rule."""
        self._gravity_stage = bool(self._rules) or not isinstance(self._field, Uniform)
        self._plan_dirty = True

    def _refresh_registry(self) -> None:
        """Sorted ids, masses and rules of every named dynamic body, for vectorised gravity."""
        dyn = [b for b in self._bodies.values() if b.body_type == pymunk.Body.DYNAMIC]
        dyn.sort(key=lambda b: b.id)
        self._reg_ids = np.array([b.id for b in dyn], dtype=np.uintp)
        self._reg_mass = np.array([b.mass for b in dyn], dtype=np.float64)
        rules = [self._rules.get(b.id, GravityRule()) for b in dyn]
        self._reg_scale = np.array([r.scale for r in rules], dtype=np.float64)
        self._reg_dir = np.array(
            [r.direction if r.direction is not None else (np.nan, np.nan) for r in rules],
            dtype=np.float64,
        ).reshape(-1, 2)
        self._registry_dirty = False
        self._field_rows = None

    def _apply_gravity(self) -> None:
        if self._registry_dirty:
            self._refresh_registry()
        g_space = self._space_gravity(self.time)
        if self.space.gravity != g_space:
            self.space.gravity = g_space  # setting it wakes every body: only when it changes
        if self._field.uniform:
            # Only bodies with their own rule need a correction force: m·(g_rule − g_space), in
            # plain floats (a handful of bodies: cheaper than numpy's per-call cost).
            gx, gy = g_space
            magnitude = math.hypot(gx, gy)
            for body_id, rule in self._rules.items():
                body = self._bodies[self._names[body_id]]
                if rule.direction is None:
                    rx, ry = rule.scale * gx, rule.scale * gy
                else:
                    rx = rule.scale * magnitude * rule.direction[0]
                    ry = rule.scale * magnitude * rule.direction[1]
                m = body.mass
                self.ledger.add(body, (m * (rx - gx), m * (ry - gy)), category=Category.PASSIVE)
            return
        # A field that varies in space: one vectorised evaluation at every dynamic body.
        ids, pos = read_positions(self.space, self._pos_buffer)
        cache = self._field_rows
        if cache is None or not np.array_equal(cache[0], ids):
            # Row order only changes when bodies are added, removed, sleep or wake.
            reg = lookup(self._reg_ids, ids)
            rows = np.nonzero(reg >= 0)[0]
            idx = reg[rows]
            mass = np.repeat(self._reg_mass[idx], 2).reshape(-1, 2)  # contiguous [m, m] rows
            cache = (ids, rows, mass, self._reg_scale[idx], self._reg_dir[idx])
            self._field_rows = cache
        _, rows, mass, scale, direction = cache
        g = self._field.at(np.take(pos, rows, axis=0), self.time)
        if self._rules:
            g = apply_rules(g, scale, direction)
        # One row per body of the read (zero for static, kinematic and unnamed bodies).
        force = np.zeros((len(ids), 2))
        force[rows] = g * mass
        self._field_ids = ids
        self._field_force = force

    def _drive_movers(self) -> None:
        for mover in self._movers:
            mover.drive(self.time, self.config.dt)

    def _physics(self) -> None:
        cfg = self.config
        n = cfg.substeps
        h = cfg.dt / n
        self.ledger.flush()
        field_force = self._field_force
        # Forces set straight on a body (``body.force``) are re-applied with the ledger's before
        # every substep, tracked or not (see WorldConfig.substeps): with substeps, read them all.
        scalar = self._scalar_on
        batched = field_force is not None or (bool(self._solver.bodies) and not scalar) or n > 1
        if batched:
            self._rows.read(self.space)
            if field_force is not None and np.array_equal(self._field_ids, self._rows.ids):
                field_rows = field_force  # same read order (the usual case): no re-keying
                self._rows.state[:, 3:5] += field_rows
                self._write_forces()
            elif field_force is not None:
                at = lookup(np.sort(self._field_ids), self._rows.ids)
                order = np.argsort(self._field_ids)
                hit = np.nonzero(at >= 0)[0]
                field_rows = np.zeros((len(self._rows.ids), 2))
                field_rows[hit] = field_force[order[at[hit]]]
                self._rows.state[:, 3:5] += field_rows
                self._write_forces()
            else:
                field_rows = None
            if self._solver.bodies and not scalar:
                self._solver.before_step(self._rows.ids, self._rows.state, field_rows)
        if scalar:
            self._scalar.before_step()
            self._scalar_synced = False
        for k in range(n):
            if k > 0:
                self._write_forces()
            # Chipmunk rescales warm starts by h / (its last step) when the length changes.
            rescaled = self._config.contact_split and self.space.current_time_step != h
            self.space.step(h)
            self._space_steps += 1
            if scalar:
                self._scalar.after_substep(check_sleep=self._solver.check_sleep)
            elif self._solver.bodies:
                ids, vel = self._rows.read_velocities(self.space)
                self._solver.after_substep(
                    self.space,
                    ids,
                    vel,
                    last=k == n - 1,
                    stamp=self._space_steps,
                    rescaled=rescaled,
                )

    def _write_forces(self) -> None:
        """Write the forces of the last batch read back, in one batch or per body if sleeping."""
        if math.isfinite(self.config.sleep_time):
            by_id = {b.id: b for b in self.space.bodies}
            for body_id, row in zip(self._rows.ids, self._rows.state, strict=True):
                body = by_id.get(int(body_id))
                # Setting a force wakes a body and restarts its idle clock: write only non-zero
                # forces (pymunk cleared the rest after the last substep).
                if (
                    body is not None
                    and body.body_type == pymunk.Body.DYNAMIC
                    and (row[3] != 0.0 or row[4] != 0.0 or row[5] != 0.0)
                ):
                    body.force = (row[3], row[4])
                    body.torque = row[5]
        else:
            self._rows.write_forces(self.space, self._rows.state[:, 3:6])

    def _solve_forces(self) -> None:
        if self._scalar_on:
            g = self.space.gravity
            self._scalar.finish(
                dt=self.config.dt, damping=self.config.damping, space_gravity=(g.x, g.y),
                ledger=self.ledger,
            )  # fmt: skip
            return
        self._solver.finish(
            dt=self.config.dt,
            substeps=self.config.substeps,
            damping=self.config.damping,
            space_gravity=(self.space.gravity.x, self.space.gravity.y),
            ledger=self.ledger,
        )

    def _filter(self) -> None:
        if self._scalar_on:
            self._scalar.filter(self.config.dt, self._perceived.config.up_threshold, self._up_at)
            return
        self._perceived.update(self._solver.specific, self._solver.valid, self.config.dt)
        if self._perceived.up_complete:
            return
        # Until a body has felt anything, its up is against the gravity field at it.
        for row in np.nonzero(~np.isfinite(self._perceived.up).all(axis=1))[0]:
            self._perceived.up[row] = self._up_at(self._solver.bodies[row])

    def _up_at(self, body: pymunk.Body) -> Vec:
        """The unit vector against the gravity field at a body: its up until it feels one."""
        g = self.gravity_at(self._names[body.id])
        n = math.hypot(*g)
        return (-g[0] / n, -g[1] / n) if n > 0 else (0.0, 1.0)


# -- argument checks -----------------------------------------------------------------------------


def _check_surface(prefix: str, friction: float, elasticity: float) -> None:
    in_range(f"{prefix}friction", friction, 0.0, 1e3, "(Coulomb coefficient)")
    in_range(f"{prefix}elasticity", elasticity, 0.0, 1.0, "(restitution)")


def _check_size(name: str, size: Sequence[float]) -> None:
    bounded_vec(name, size, MAX_LENGTH, "m")
    for i, v in enumerate(size):
        if v <= 0.0:
            raise ValueError(f"{name}[{i}]: expected a length > 0 m, got {v!r}")


def _check_body(name: str, body: pymunk.Body, shapes: Sequence[pymunk.Shape]) -> None:
    """Refuse what pymunk asserts on, aborts on or turns into NaN, before it sees it."""
    if not isinstance(body, pymunk.Body):
        raise ValueError(f"{name}: expected a pymunk.Body, got {body!r}")
    if body.space is not None:
        raise ValueError(f"{name}: the body is already in a space")
    if body.body_type == pymunk.Body.DYNAMIC:
        in_range(f"{name}.mass", body.mass, MIN_MASS, MAX_MASS, "kg")
        if body.moment != math.inf:
            in_range(f"{name}.moment", body.moment, MIN_MOMENT, MAX_MOMENT, "kg·m²")
    bounded_vec(f"{name}.position", tuple(body.position), MAX_COORDINATE, "m")
    bounded(f"{name}.angle", body.angle, MAX_ANGLE, "rad")
    bounded_vec(f"{name}.velocity", tuple(body.velocity), MAX_SPEED, "m/s")
    bounded(f"{name}.angular_velocity", body.angular_velocity, MAX_ANGULAR_SPEED, "rad/s")
    bounded_vec(f"{name}.force", tuple(body.force), MAX_FORCE, "N")
    for i, shape in enumerate(shapes):
        where = f"{name}.shapes[{i}]"
        if not isinstance(shape, pymunk.Shape) or shape.body is not body:
            raise ValueError(f"{where}: expected a shape of this body, got {shape!r}")
        if shape.space is not None:
            raise ValueError(f"{where}: the shape is already in a space")
        _check_surface(f"{where}.", shape.friction, shape.elasticity)
        in_range(f"{where}.radius", _radius(shape), 0.0, MAX_LENGTH, "m")
        for j, point in enumerate(_points(shape)):
            bounded_vec(f"{where}.points[{j}]", tuple(point), MAX_COORDINATE, "m (body frame)")


def _radius(shape: pymunk.Shape) -> float:
    if isinstance(shape, pymunk.Circle | pymunk.Segment | pymunk.Poly):
        return float(shape.radius)
    return 0.0


def _points(shape: pymunk.Shape) -> list[pymunk.Vec2d]:
    """A shape's defining points in the body's frame."""
    if isinstance(shape, pymunk.Circle):
        return [shape.offset]
    if isinstance(shape, pymunk.Segment):
        return [shape.a, shape.b]
    if isinstance(shape, pymunk.Poly):
        return list(shape.get_vertices())
    return []


def _group(body: pymunk.Body) -> list[pymunk.Body]:
    """The dynamic bodies connected to ``body`` by contacts or joints, ``body`` first (static and
    kinematic bodies do not connect, as in Chipmunk's own sleeping)."""
    group = [body]
    seen = {body.id}
    k = 0
    while k < len(group):
        current = group[k]
        k += 1
        neighbours = _touching(current)
        neighbours.extend(b for c in current.constraints for b in (c.a, c.b))
        for other in neighbours:
            if other.body_type == pymunk.Body.DYNAMIC and other.id not in seen:
                seen.add(other.id)
                group.append(other)
    return group


def _touching(body: pymunk.Body) -> list[pymunk.Body]:
    """The bodies of every arbiter of ``body`` (itself included)."""
    out: list[pymunk.Body] = []
    body.each_arbiter(lambda arb: out.extend(shape.body for shape in arb.shapes))
    return out
