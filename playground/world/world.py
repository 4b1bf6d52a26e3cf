"""The world: a pymunk space in SI units, its named bodies, and the fixed step that runs every
stage top-down.

The stages (docs/design.md §4) are named by :class:`~playground.world.schedule.Stage`; a stage the
scene does not need is skipped without cost (uniform gravity is ``space.gravity``; no tracked
body, no solver; no perceiver, no filter). Each stage can be timed. The world keeps the step
and the plan, and holds its parts, each of its own module, delegating to them: the named bodies
(:mod:`~playground.world.registry`), the schedule (:mod:`~playground.world.schedule`), the
gravity stage (:mod:`~playground.world.gravity_stage`), the forces put on bodies
(:mod:`~playground.world.force_input`, into the ledger) and the physics stage with the tracked
bodies (:mod:`~playground.world.physics`).

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
from typing import Literal

import numpy as np
import pymunk
import pymunk.batch as batch
from numpy.typing import NDArray

from playground._engine.space import CountingSpace
from playground.forces.ledger import Category, ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.tracked import SCALAR_MAX_BODIES
from playground.gravity import GravityField, GravityRule, Perception, Uniform
from playground.limits import (
    MAX_GRAVITY,
    MAX_MASS,
    MAX_MOMENT,
    MIN_MASS,
    MIN_MOMENT,
    RUNAWAY_FORCE,
)
from playground.movers import Mover, Path
from playground.params import bounded_vec, in_range
from playground.vec import Vec
from playground.world.config import WorldConfig
from playground.world.errors import WorldUsageError
from playground.world.force_input import ForceInput
from playground.world.gravity_stage import GravityStage
from playground.world.guard import FORCE_COLUMNS, GUARD_EVERY, RunawayError, state_runaway
from playground.world.physics import PhysicsStage
from playground.world.registry import BodyRegistry
from playground.world.schedule import (
    EVENT_EARLY,
    Hook,
    Schedule,
    Stage,
    StageTiming,
    run_hooks,
)

__all__ = ["World"]

# The stages bound to names once: reading a member off an Enum class costs many times a global's
# read, and the step names one per stage it runs (docs/performance.md, "The small costs the code
# is shaped by", row enum_member).
INPUTS, EVENTS, GRAVITY, MOVERS, CONTROL, PHYSICS, FORCES, FILTER, OBSERVE = Stage

_NEVER = 2**62
"""A step number no run reaches: the guard's next check when the guard is off."""


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
    :class:`~playground.forces.solver.ForceSolver`).

    >>> world = World(gravity=(0.0, -9.81))                 # m/s²; dt = 1/120 s by default
    >>> ball = world.add_box("ball", mass=2.0, size=(0.2, 0.2), position=(0.0, 10.0))
    >>> world.run(1.0)                                     # s: 120 steps of free fall
    >>> round(world.time, 6), round(ball.velocity.y, 6)    # s, m/s: g·t
    (1.0, -9.81)
    """

    def __init__(
        self,
        config: WorldConfig | None = None,
        gravity: GravityField | Sequence[float] | None = None,
    ) -> None:
        self._config = config if config is not None else WorldConfig()
        self._registry = BodyRegistry(added=self._added, removed=self._removed)
        self.space: CountingSpace = self._registry.space
        """The pymunk space (m, kg, s; a :class:`pymunk.Space` that counts its removals). A body
        added to it straight (``space.add``) acts like any other; :meth:`adopt` names it,
        :meth:`track` tracks it; one taken out with ``space.remove`` leaves the world at the next
        step (see :meth:`track`)."""
        # Chipmunk keeps an arbiter 3 steps after its contact ends by default; a contact made
        # again from it starts from the old accumulated impulse without applying it, so the
        # arbiter reports an impulse the bodies never received (see ForceSolver). Dropping
        # arbiters at once loses no warm start (such a first contact is never warm-started), and
        # the new contact no longer starts from an impulse that lets it pull, or grip beyond its
        # own normal impulse.
        self.space.collision_persistence = 1
        self._bare = False
        # Whether the step has nothing to do but what the ledger may hold (see _plan).
        self._idle = False
        self._lap_start = 0.0  # perf_counter at the start of the stage being timed
        # Whether the next step must decide again what it runs: written by _replan and _plan only.
        self._plan_dirty = True
        self.time = 0.0
        self._epoch = (0, 0.0)  # (steps, time) when dt last changed
        self.steps = 0
        self.ledger = ForceLedger(on_first=self._ledger_filled)
        """The forces put on bodies for the coming step, by category (emptied by each step)."""
        self._forces_in = ForceInput(self.ledger, self._registry.own, self._config.guard)
        self._scalar_max_bodies = SCALAR_MAX_BODIES
        self.timings: dict[Stage, StageTiming] = {s: StageTiming() for s in Stage}
        self._movers: list[Mover] = []
        # Tracked bodies the world has no name for (added with space.add): a step after a
        # space.remove checks that they are still in the space (see track).
        self._anonymous: list[pymunk.Body] = []
        self._stepping = False
        self._schedule = Schedule(self._replan)
        registry = self._registry
        self._gravity = GravityStage(
            self.space, registry.by_name, registry.name_by_id, self.ledger, self._replan
        )
        self._physics = PhysicsStage(
            self.space, self._config, self.ledger, self._replan, self._up_at
        )
        self._guard_next = GUARD_EVERY if self._config.guard else _NEVER
        self._state_buffer = batch.Buffer()
        self.crowd: object = None
        """The crowd of the world's controllers (``playground.controller.crowd.Crowd``, made by
        the first controller), which runs them as one when they are many."""
        self.config = self._config
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
        self._physics.configure(config)
        self._forces_in.guard = config.guard
        self._guard_next = self.steps + GUARD_EVERY if config.guard else _NEVER
        self._replan()

    @property
    def scalar_max_bodies(self) -> int:
        """Most tracked bodies the scalar implementation serves, in plain floats (0: never); the
        batch implementation serves more. A change takes effect from the next step."""
        return self._scalar_max_bodies

    @scalar_max_bodies.setter
    def scalar_max_bodies(self, most: int) -> None:
        self._scalar_max_bodies = most
        self._replan()

    def set_perception(self, perception: Perception) -> None:
        """Re-tune how perceived gravity is filtered (1€ parameters, up threshold) from the next
        step on, keeping the filter's state; the spike stage is fixed when the world is built."""
        if not isinstance(perception, Perception):
            raise ValueError(f"perception: expected a Perception, got {perception!r}")
        self._physics.tracked.tune(perception)
        self._config = dataclasses.replace(self._config, perception=perception)

    def _replan(self) -> None:
        """Plan the next step again (something it must or need not do has changed)."""
        self._plan_dirty = True

    def _ledger_filled(self) -> None:
        """The ledger got its first force since it was last empty: the next step is not bare."""
        self._bare = False

    def _plan(self) -> None:
        """Decide whether the next steps are bare (nothing but ``space.step``), and which
        implementation serves the tracked bodies (:meth:`TrackedSet.plan
        <playground.forces.tracked.TrackedSet.plan>`).

        The ledger is not part of the plan: it fills and empties every step of a level with a
        controller. A step that is idle but for the ledger's forces is bare once they are
        flushed (:meth:`step` sets that), until the ledger fills again (:meth:`_ledger_filled`).
        """
        cfg = self._config
        gravity = self._gravity
        physics = self._physics
        schedule = self._schedule
        tracked = physics.tracked
        most = self._scalar_max_bodies
        tracked.plan(most, gravity.plain_ready(most), cfg.substeps)
        gravity.use_plain(tracked.active.takes_field_by_body)
        self._idle = not (
            schedule.inputs
            or schedule.events
            or schedule.event_hooks
            or gravity.active
            or self._movers
            or schedule.controls
            or tracked.bodies
            or tracked.perceivers
            or schedule.observers
            or cfg.timing
            or cfg.substeps != 1
        )
        self._bare = self._idle and not len(self.ledger)
        self._plan_dirty = False

    # -- gravity ---------------------------------------------------------------------------------

    @property
    def gravity(self) -> GravityField:
        """The gravity field (m/s²). A plain (gx, gy) is accepted and becomes :class:`Uniform`."""
        return self._gravity.field

    @gravity.setter
    def gravity(self, value: GravityField | Sequence[float]) -> None:
        if not isinstance(value, GravityField):
            bounded_vec("gravity", tuple(value), MAX_GRAVITY, "m/s²")
            value = Uniform((float(value[0]), float(value[1])))
        self._gravity.set_field(value, self.time)

    @property
    def gravity_version(self) -> int:
        """A count that changes whenever the field or a body's rule does: a caller keeping
        :attr:`gravity` or a :meth:`gravity_rule` between steps reads them again when it has
        changed (a controller reads its rule every step otherwise)."""
        return self._gravity.version

    def set_gravity_rule(self, name: str, rule: GravityRule | None) -> None:
        """Give one body its own gravity: a scale (0 nullifies it) or its own direction.

        ``None`` restores the field.
        """
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only dynamic bodies feel gravity")
        self._gravity.set_rule(body.id, rule)

    def gravity_rule(self, name: str) -> GravityRule:
        """The body's rule (the default rule if it has none)."""
        self.body(name)  # KeyError naming the known bodies
        return self._gravity.rule(self._registry.id_by_name[name])

    def gravity_at(self, name: str) -> Vec:
        """The gravity this body feels now (field and rule), m/s²."""
        return self._gravity.at(self.body(name), self.time)

    def _up_at(self, body: pymunk.Body) -> Vec:
        """The unit vector against the gravity field at a body: its up until it feels one."""
        g = self._gravity.at(body, self.time)
        n = math.hypot(*g)
        return (-g[0] / n, -g[1] / n) if n > 0 else (0.0, 1.0)

    # -- bodies (the registry) -------------------------------------------------------------------

    @property
    def locked(self) -> bool:
        """Whether the world is inside a step (from its gravity stage on): then bodies, static
        shapes, tracking and hooks added or removed wait for the step's end."""
        return self._registry.locked

    def later(self, action: Callable[[World], object]) -> None:
        """Run ``action(world)`` when the step ends, after the changes asked for before it (at
        once if the world is not :attr:`locked`): for a change the world does not defer itself,
        such as building a controller from a hook."""
        self._registry.later(lambda: action(self))

    def add(self, name: str, body: pymunk.Body, *shapes: pymunk.Shape) -> pymunk.Body:
        """Add a named body and its shapes (see :meth:`BodyRegistry.add
        <playground.world.registry.BodyRegistry.add>`: names are unique, values are checked
        against :mod:`playground.limits`); returns the body.

        >>> world = World()
        >>> ball = pymunk.Body(2.0, pymunk.moment_for_circle(2.0, 0.0, 0.25))  # kg, kg·m²
        >>> ball.position = (0.0, 3.0)                                         # m
        >>> world.add("ball", ball, pymunk.Circle(ball, 0.25)) is ball          # 0.25 m radius
        True
        >>> world.body("ball") is ball, world.names
        (True, ['ball'])
        """
        return self._registry.add(name, body, *shapes)

    def adopt(self, name: str, body: pymunk.Body) -> pymunk.Body:
        """Name a body the game added straight to :attr:`space` (``space.add``): from then on it
        is a body of the world like one added with :meth:`add` (found, tracked and given a
        gravity rule by name; a field that varies in space acts on it; :meth:`remove` takes it
        out with its shapes and joints)."""
        return self._registry.adopt(name, body)

    def remove(self, item: str | pymunk.Constraint) -> None:
        """Remove a body by name, with its shapes and joints, and stop tracking it; or remove a
        joint added with :meth:`add_constraint`."""
        self._registry.remove(item)

    def add_constraint(self, constraint: pymunk.Constraint) -> pymunk.Constraint:
        """Add a joint between bodies of this world (or the space's static body)."""
        return self._registry.add_constraint(constraint)

    def add_static(self, *shapes: pymunk.Shape) -> None:
        """Add shapes of the space's static body: fixed geometry (m), checked like a body's.

        >>> world = World()
        >>> ground = pymunk.Circle(world.space.static_body, 10.0)   # m: a small planet's surface
        >>> world.add_static(ground)
        >>> ground in world.space.shapes
        True
        """
        self._registry.add_static(*shapes)

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
        """A dynamic box of ``size`` (w, h in m) and ``mass`` (kg) at ``position`` (m), turned
        by ``angle`` (rad)."""
        return self._registry.add_box(
            name,
            mass=mass,
            size=size,
            position=position,
            angle=angle,
            friction=friction,
            elasticity=elasticity,
        )

    def add_static_segment(
        self,
        a: Vec,
        b: Vec,
        radius: float = 0.05,
        *,
        friction: float = 1.0,
        elasticity: float = 0.0,
    ) -> pymunk.Segment:
        """A static segment from ``a`` to ``b`` (m), ``radius`` thick (m), with its
        ``friction`` and ``elasticity`` (coefficients, no unit); returns the shape.

        >>> world = World()
        >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))   # m: a 10 m floor at y = 0
        >>> floor.radius, floor.friction                                # m; no unit
        (0.05, 1.0)
        """
        return self._registry.add_static_segment(
            a, b, radius, friction=friction, elasticity=elasticity
        )

    def body(self, name: str) -> pymunk.Body:
        """The body called ``name`` (KeyError naming the known bodies otherwise)."""
        return self._registry.body(name)

    def body_at(self, point: Vec, radius: float = 0.0) -> str | None:
        """The named body with a shape at world ``point`` (m) or within ``radius`` (m) of it (the
        nearest if several), or None (unnamed bodies such as static ground do not count)."""
        return self._registry.body_at(point, radius)

    def name_of(self, body: pymunk.Body) -> str | None:
        """The body's name, or None for a body the world does not know by name."""
        return self._registry.name_of(body)

    @property
    def names(self) -> list[str]:
        """The names of the bodies, in the order they were added."""
        return self._registry.names

    def sleep(self, name: str) -> None:
        """Put a body to sleep now, with every dynamic body it touches or is jointed to (see
        :meth:`BodyRegistry.sleep <playground.world.registry.BodyRegistry.sleep>`)."""
        self._registry.sleep(name)

    def wake(self, name: str) -> None:
        """Wake a sleeping body and its group (nothing happens to an awake one)."""
        self._registry.wake(name)

    # -- forces in (the ledger) ------------------------------------------------------------------

    def apply_force(
        self,
        body: pymunk.Body | str,
        force: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Apply ``force`` (N, world frame) at world ``point`` (m; default: the centre of
        gravity) during the coming step."""
        self._forces_in.apply_force(body, force, point=point, category=category)

    def apply_forces(
        self,
        body: pymunk.Body,
        forces: list[tuple[float, float, Category]],
        torque: float | None = None,
        *,
        point: Vec | None = None,
    ) -> None:
        """Apply several forces ``(fx, fy, category)`` (N, world frame, at world ``point``, m;
        default: the centre of gravity) and a pure ``torque`` (N·m, counter-clockwise) to one
        body of this world during the coming step: one call and one check of each, for a
        controller's forces on its own body and their reactions on its ground; the totals are
        those of one :meth:`apply_force` call each, in order, then one :meth:`apply_torque`,
        bit for bit."""
        self._forces_in.apply_forces(body, forces, torque, point=point)

    def apply_torque(
        self, body: pymunk.Body | str, torque: float, *, category: Category = Category.APPLIED
    ) -> None:
        """Apply a pure ``torque`` (N·m, counter-clockwise) during the coming step."""
        self._forces_in.apply_torque(body, torque, category=category)

    def apply_impulse(
        self,
        body: pymunk.Body | str,
        impulse: Vec,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Apply ``impulse`` (N·s) spread over the coming step, as the force impulse/dt."""
        self._forces_in.apply_impulse(
            body, impulse, self._config.dt, point=point, category=category
        )

    # -- the tracked bodies (the physics stage's) ------------------------------------------------

    def track(self, *bodies: str | pymunk.Body, perceive: bool = True) -> None:
        """Recover engine forces for these dynamic bodies every step, by name or as bodies of
        :attr:`space` (a body the game added with ``space.add`` too, named or not);
        ``perceive`` also filters their perceived gravity. From the next step on if the world
        is :attr:`locked`.

        A body may leave the way it came, with ``space.remove``: the next step untracks it
        before its gravity stage (a body removed by an INPUTS or EVENTS hook is untracked in that
        step, one removed later in the step in the next), and reading it then raises a
        ``KeyError`` that says it left. A named body leaves the world then too, as with
        :meth:`remove` (its name, tracking, gravity rule and mover go; its shapes and joints are
        left as the game left them); :meth:`remove` takes it out with its shapes and joints.

        >>> world = World()
        >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))          # m
        >>> crate = pymunk.Body(10.0, pymunk.moment_for_box(10.0, (1.0, 1.0)))  # kg, kg·m²
        >>> crate.position = (0.0, 0.55)                                        # m
        >>> box = pymunk.Poly.create_box(crate, (1.0, 1.0))                     # m
        >>> world.space.add(crate, box)
        >>> world.track(crate)
        >>> world.run(1.0)                                                      # s
        >>> round(world.forces(crate).support[1], 6)                            # N: m·g
        98.1
        >>> world.space.remove(crate, box)
        >>> world.step()
        >>> world.tracked_bodies
        []
        """
        registry = self._registry
        for item in bodies:
            if isinstance(item, str):
                registry.require(item)  # KeyError naming the known bodies, now
            else:
                self._in_space(item)
        if registry.locked:
            registry.later(lambda: self.track(*bodies, perceive=perceive))
            return
        tracked = self._physics.tracked
        for item in bodies:
            if isinstance(item, str):
                tracked.track(registry.body(item), perceive)
                continue
            tracked.track(item, perceive)
            if registry.name_of(item) is None and item not in self._anonymous:
                self._anonymous.append(item)

    def untrack(self, *bodies: str | pymunk.Body) -> None:
        """Stop tracking these bodies (by name or as bodies; one not tracked is left alone): for
        a body the game is about to take out of :attr:`space` itself. From the next step on if
        the world is :attr:`locked`."""
        registry = self._registry
        items = [registry.body(b) if isinstance(b, str) else self._in_space(b) for b in bodies]
        if registry.locked:
            registry.later(lambda: self.untrack(*items))
            return
        tracked = self._physics.tracked
        for body in items:
            if tracked.row_of(body) is not None:
                tracked.untrack(body)
        self._anonymous = [b for b in self._anonymous if b not in items]

    def _departed(self) -> None:
        """Something was taken out of :attr:`space` with ``space.remove`` since the last look:
        the named bodies among it leave the world, the nameless tracked ones are untracked (see
        :meth:`track`)."""
        self._registry.forget_departed()
        if self._anonymous:
            self._untrack_departed()

    def _untrack_departed(self) -> None:
        """Untrack the nameless tracked bodies the game took out of :attr:`space` (see
        :meth:`track`); forget those named since (:meth:`remove` takes care of them)."""
        in_space = self.space.bodies  # a live view: membership is a dict look-up
        name_of = self._registry.name_of
        tracked = self._physics.tracked
        staying = []
        for body in self._anonymous:
            if body not in in_space:
                if tracked.row_of(body) is not None:
                    tracked.untrack(body)
            elif name_of(body) is None:
                staying.append(body)
        self._anonymous = staying

    def _in_space(self, body: object) -> pymunk.Body:
        """``body`` if it is a dynamic body of :attr:`space` (``ValueError`` otherwise)."""
        if not isinstance(body, pymunk.Body) or body.space is not self.space:
            raise ValueError(f"body: expected a body name or a body of this world, got {body!r}")
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{body!r}: only dynamic bodies have engine forces to recover")
        return body

    @property
    def tracked_bodies(self) -> list[pymunk.Body]:
        """The tracked bodies, in the order they were tracked (a copy)."""
        return list(self._physics.tracked.bodies)

    def is_tracked(self, name: str) -> bool:
        """Whether the body ``name`` is tracked (KeyError naming the known bodies if there is
        no such body)."""
        registry = self._registry
        body = registry.body(name)
        return self._physics.tracked.row_of(body, registry.id_by_name[name]) is not None

    def readings(self) -> TrackedReadings:
        """Every tracked body's last readings and perceived gravity, as arrays (copies), one row
        each in :attr:`tracked_bodies` order."""
        return self._physics.tracked.active.table()

    @property
    def tracked_kind(self) -> Literal["scalar", "batch"]:
        """Which implementation serves the tracked bodies in the coming steps, as last planned:
        ``"scalar"`` (plain floats, for few bodies) or ``"batch"`` (numpy and
        ``pymunk.batch``, for many). Benchmarks report it; nothing else needs it."""
        return self._physics.tracked.active.kind

    def forces(self, body: str | pymunk.Body) -> BodyForces:
        """The last readings of a tracked body (by name, or the body): forces in N, what an
        accelerometer on it reads in m/s² (:class:`~playground.forces.readings.BodyForces`).

        >>> world = World()
        >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))                 # m
        >>> _ = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.55))  # kg, m
        >>> world.track("crate")
        >>> world.run(1.0)                                                             # s
        >>> readings = world.forces("crate")
        >>> round(readings.support[1], 6), round(readings.specific[1], 6)  # N: m·g; m/s²: g
        (98.1, 9.81)
        """
        return self._physics.tracked.active.reading(self._tracked_row(body))

    def perceived_gravity(self, body: str | pymunk.Body) -> Vec:
        """The filtered perceived gravity of a tracked body (by name, or the body), m/s²."""
        return self._physics.tracked.active.perceived_gravity(self._tracked_row(body))

    def perceived_up(self, body: str | pymunk.Body) -> Vec:
        """The unit vector (no unit) opposite the perceived gravity of a tracked body (by name,
        or the body), held through weak readings: the up a camera turns with.

        >>> world = World(gravity=(-9.81, 0.0))                   # m/s²: gravity to the left
        >>> wall = world.add_static_segment((-0.3, -5.0), (-0.3, 5.0))                   # m
        >>> _ = world.add_box("crate", mass=1.0, size=(0.5, 0.5), position=(0.0, 0.0))  # kg, m
        >>> world.track("crate")
        >>> world.run(1.0)                                                               # s
        >>> tuple(round(c, 6) + 0.0 for c in world.perceived_up("crate"))  # away from the wall
        (1.0, 0.0)
        """
        return self._physics.tracked.active.perceived_up(self._tracked_row(body))

    def perceived_up_and_gravity(self, body: str | pymunk.Body) -> tuple[Vec, Vec]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of a tracked body in one call (a
        controller reads both every step; the row is looked up once)."""
        row = self._tracked_row(body)
        return self._physics.tracked.active.perceived_up_and_gravity(row)

    @property
    def tracked_version(self) -> int:
        """Counts the changes of the tracked rows: rows from :meth:`tracked_rows` hold while it
        stays the same."""
        return self._physics.tracked.version

    def tracked_rows(self, names: Sequence[str]) -> NDArray[np.intp]:
        """The tracked rows of the bodies ``names`` (KeyError for one not tracked), for
        :meth:`perceived_block`."""
        return np.array([self._tracked_row(n) for n in names], dtype=np.intp)

    def perceived_block(
        self, rows: NDArray[np.intp]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of many tracked bodies at once, by
        their :meth:`tracked_rows`: (k, 2) arrays of the same values (a crowd of controllers
        reads them every step)."""
        return self._physics.tracked.perceived_block(rows)

    def _tracked_row(self, item: str | pymunk.Body) -> int:
        if type(item) is str:
            registry = self._registry
            row = self._physics.tracked.row_of(registry.body(item), registry.id_by_name[item])
        elif isinstance(item, pymunk.Body):
            row = self._physics.tracked.row_of(item)
        else:
            raise ValueError(f"body: expected a body name or a body of this world, got {item!r}")
        if row is None:
            if isinstance(item, pymunk.Body) and item.space is not self.space:
                raise KeyError(
                    f"{item!r}: not tracked, it is not in the world's space (a tracked body "
                    "taken out with space.remove is untracked at the next step)"
                )
            raise KeyError(f"{item}: not tracked (call world.track({item!r}) first)")
        return row

    # -- the world's own bookkeeping of bodies -------------------------------------------------

    def _added(self, body: pymunk.Body) -> None:
        """A named body joined (the registry calls this)."""
        self._gravity.bodies_changed()

    def _removed(self, body: pymunk.Body) -> None:
        """A named body left the registry (the registry calls this), still in the space unless
        the game took it out with ``space.remove``."""
        self._gravity.forget(body.id)
        tracked = self._physics.tracked
        if tracked.row_of(body) is not None:
            tracked.untrack(body)
        self._movers = [m for m in self._movers if m.body is not body]
        self._replan()

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
        self._physics.tracked.refresh_masses()
        self._gravity.bodies_changed()

    def add_mover(self, name: str, path: Path) -> Mover:
        """Drive the kinematic body ``name`` along ``path`` (placed at its pose now): each step
        gives it the velocity (m/s, rad/s) that reaches the path's next pose.

        >>> from playground import Waypoints
        >>> world = World()
        >>> lift = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        >>> _ = world.add("lift", lift, pymunk.Segment(lift, (-1.0, 0.0), (1.0, 0.0), 0.1))  # m
        >>> path = Waypoints(((0.0, 0.0), (0.0, 2.0)), speed=0.5)    # m, m/s
        >>> _ = world.add_mover("lift", path)
        >>> world.run(2.0)                                           # s
        >>> round(lift.position.y, 6), round(lift.velocity.y, 6)     # m: 0.5 m/s × 2 s; m/s
        (1.0, 0.5)
        """
        mover = Mover(self.body(name), path)
        mover.place(self.time)
        self._movers.append(mover)
        self._replan()
        return mover

    # -- hooks and events ------------------------------------------------------------------------

    def on(self, stage: Stage, hook: Hook) -> None:
        """Run ``hook(world)`` every step in ``stage`` (INPUTS, EVENTS, CONTROL or OBSERVE); from
        the next step on if the world is :attr:`locked`."""
        self._schedule.check(stage)
        self._registry.later(lambda: self._schedule.on(stage, hook))

    def off(self, stage: Stage, hook: Hook) -> None:
        """Stop running ``hook`` in ``stage``: the opposite of :meth:`on`. Safe from inside a
        step: the stage that is running finishes with the hooks it started with."""
        self._schedule.off(stage, hook)

    def replace_hooks(self, stage: Stage, old: Sequence[Hook], new: Sequence[Hook]) -> bool:
        """Put the hooks ``new`` in the place of ``old``, hooks of ``stage`` that run one right
        after another in that order; False, and nothing changes, if they do not
        (:meth:`Schedule.replace <playground.world.schedule.Schedule.replace>`). Safe from inside
        a step, as :meth:`off` is."""
        return self._schedule.replace(stage, old, new)

    def at(self, t: float, event: Hook) -> None:
        """Run ``event(world)`` once, in the EVENTS stage of the first step starting at or after
        ``t`` (s). Events at the same time run in the order they were scheduled."""
        self._schedule.at(t, event)

    def on_substep(self, reader: Callable[[], None]) -> None:
        """Call ``reader()`` in the PHYSICS stage after each substep of a step but the last
        (never with ``config.substeps`` 1): a reading that is to be the step's mean over its
        substeps adds up there what pymunk keeps only for the substep just run (a contact's
        impulse; the last substep's is still there after the step). It reads the engine and
        changes nothing: no world call, no body or force written."""
        self._physics.substep_readers.append(reader)

    def off_substep(self, reader: Callable[[], None]) -> None:
        """Stop calling ``reader``: the opposite of :meth:`on_substep` (ValueError if it is not
        called)."""
        readers = self._physics.substep_readers
        if reader not in readers:
            name = getattr(reader, "__name__", repr(reader))
            raise ValueError(f"reader: {name} is not called after substeps")
        kept = list(readers)  # a new list: a step calling the old one is not disturbed
        kept.remove(reader)
        self._physics.substep_readers = kept

    # -- the step --------------------------------------------------------------------------------

    def step(self) -> None:
        """Advance one fixed step of ``config.dt`` seconds through the stages, top-down.

        A hook cannot step the world it runs in (:class:`WorldUsageError`): the step it is in
        would go on with the state of a step after it.

        >>> world = World()                                                  # dt = 1/120 s
        >>> ball = world.add_box("ball", mass=1.0, size=(0.2, 0.2), position=(0.0, 5.0))  # kg, m
        >>> world.step()
        >>> world.steps, round(world.time, 6), round(ball.velocity.y, 6)    # s; m/s: −g·dt
        (1, 0.008333, -0.08175)
        """
        if self._stepping:
            raise WorldUsageError(
                "step: the world is already stepping (called from a hook or event of a step); "
                "change the world from the hook and let the step run on"
            )
        # The game took something out of the space (space.remove): before anything reads a body.
        if self.space.removals != self._registry.removals_seen:
            self._departed()
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
        # Each stage ends with lap(its name): it times the stage when config.timing is on.
        lap = self._start_laps() if self._config.timing else _no_lap
        schedule = self._schedule
        gravity = self._gravity
        physics = self._physics
        tracked = physics.tracked
        registry = self._registry
        # A bare step runs no hook, so only this path can be entered again from inside.
        self._stepping = True
        try:
            # 1. inputs: scripts and keyboards turn into intents
            if schedule.inputs:
                run_hooks(schedule.inputs, self)
                lap(INPUTS)
            # 2. events: scheduled scene changes
            events = schedule.events
            if (events and events[0][0] <= self.time + EVENT_EARLY) or schedule.event_hooks:
                schedule.run_events(self)
                lap(EVENTS)
            # A body an input or event took out of the space leaves now, before any stage
            # reads it.
            if self.space.removals != registry.removals_seen:
                self._departed()
            # An input or event that tracked or untracked a body changed which implementation
            # serves the tracked bodies: plan again, so the gravity stage hands its field in the
            # form the physics stage now takes.
            if self._plan_dirty:
                self._plan()
            # From here to the step's end the world is locked: what a hook adds or removes waits
            # for the end, so every stage of this step sees the same bodies.
            registry.lock()
            # 3. gravity: space.gravity for a uniform field, per-body forces for anything else
            field = None
            if gravity.active:
                field = gravity.apply(self.time)
                lap(GRAVITY)
            # 4. movers: kinematic bodies get the velocity that reaches their next pose
            if self._movers:
                self._drive_movers()
                lap(MOVERS)
            # 5. control: controllers sense and put their forces in the ledger
            if schedule.controls:
                run_hooks(schedule.controls, self)
                lap(CONTROL)
            # 6. physics: flush forces, step the space (re-applying forces every substep)
            physics.step(field)
            lap(PHYSICS)
            # 7. forces: reverse integration for tracked bodies
            if tracked.bodies:
                physics.solve()
                lap(FORCES)
            # 8. filter: perceived gravity for the bodies that perceive
            if tracked.perceivers:
                physics.filter()
                lap(FILTER)
            # The forces are spent: a step with nothing else to do is bare again.
            self.ledger.clear()
            self._bare = self._idle
            self.steps += 1
            # Not a running sum: no drift over long runs (the epoch moves only when dt changes).
            self.time = self._epoch[1] + (self.steps - self._epoch[0]) * self._config.dt
            # the guard: nothing non-finite or runaway reaches the observers
            if tracked.bodies and self._config.guard:
                bad = tracked.active.runaway(RUNAWAY_FORCE)
                if bad is not None:
                    body_id, column, value = bad
                    self._runaway(body_id, FORCE_COLUMNS[column], value, RUNAWAY_FORCE)
            if self.steps >= self._guard_next:
                self._guard_all()
            # 9. observe: recorders, checks, views — read-only
            if schedule.observers:
                lap(None)  # the bookkeeping above is no stage's
                run_hooks(schedule.observers, self)
                lap(OBSERVE)
        finally:
            registry.unlock()
            self._stepping = False
        registry.run_pending()

    def run(self, seconds: float) -> None:
        """Step for ``seconds`` of simulated time (rounded to whole steps)."""
        steps = seconds / self.config.dt
        if not (math.isfinite(steps) and steps >= 0.0):
            raise ValueError(f"seconds: expected a finite number of seconds >= 0, got {seconds!r}")
        for _ in range(round(steps)):
            self.step()

    def _start_laps(self) -> Callable[[Stage | None], None]:
        """Start timing this step's stages: :meth:`_lap` ends each."""
        self._lap_start = time.perf_counter()
        return self._lap

    def _lap(self, stage: Stage | None) -> None:
        """Charge the time since the last lap to ``stage`` (None: to no stage)."""
        if stage is not None:
            elapsed = time.perf_counter() - self._lap_start
            timing = self.timings[stage]
            timing.total += elapsed
            timing.calls += 1
            timing.last = elapsed
        # Read after the bookkeeping, which is no stage's.
        self._lap_start = time.perf_counter()

    def _drive_movers(self) -> None:
        t, dt = self.time, self._config.dt
        for mover in self._movers:
            mover.drive(t, dt)

    def _guard_all(self) -> None:
        """Stop if any body's position, angle or velocity is not finite or runs away."""
        self._guard_next = self.steps + GUARD_EVERY
        bad = state_runaway(self.space, self._state_buffer)
        if bad is not None:
            self._runaway(*bad)

    def _runaway(
        self, body_id: int, column: tuple[str, str, str], value: float, bound: float
    ) -> None:
        name = self._registry.name_by_id.get(body_id)
        who = repr(name) if name is not None else f"an unnamed body (id {body_id})"
        raise RunawayError(who, self.steps, self.time, column, value, float(bound))


def _no_lap(stage: Stage | None) -> None:
    """The lap of a step whose stages are not timed."""
