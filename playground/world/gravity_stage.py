"""The gravity stage: the field, each body's own rule, and how the two reach the bodies.

A field uniform in space is ``space.gravity`` (pymunk integrates it at no cost); a body with its
own rule then gets one correction force, m·(g_rule − g_space), in plain floats. A field that
varies in space is evaluated once per step at every dynamic body, vectorised, at the positions of
the batch implementation's one read of every body (:meth:`GravityStage.forces_at`); while the
scalar implementation serves the tracked bodies and the named dynamic bodies are few, it is
evaluated body by body in plain floats instead (:mod:`playground.gravity.plain`). The stage
runs only when one of the two is needed.

>>> import pymunk
>>> from playground.forces import ForceLedger
>>> space = pymunk.Space()
>>> stage = GravityStage(space, {}, {}, ForceLedger(), replan=lambda: None)
>>> stage.set_field(Uniform((0.0, -9.81)), 0.0)
>>> stage.active, space.gravity
(False, Vec2d(0.0, -9.81))
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine import raw
from playground._engine.batch import lookup
from playground.forces.ledger import Category, ForceLedger
from playground.forces.tracked import FieldForces, FieldOnBodies
from playground.gravity import GravityField, GravityRule, RotatingRoom, Uniform, apply_rules
from playground.gravity.plain import PlainField, PointField, point_field
from playground.gravity.rule import ruled
from playground.vec import Vec

__all__ = ["GravityStage"]

_PASSIVE = Category.PASSIVE
"""Read once: reading a member off an Enum class costs many times a global's read
(docs/performance.md, "The small costs the code is shaped by", row enum_member)."""

_DEFAULT_RULE = GravityRule()
"""The rule of a body that has none (frozen, so one instance serves every read)."""


class GravityStage:
    """The gravity field and per-body rules of one world (``bodies`` and ``names`` are the
    world's registry, shared, not copied). ``replan`` is called when the stage starts or stops
    being needed."""

    def __init__(
        self,
        space: pymunk.Space,
        bodies: dict[str, pymunk.Body],
        names: dict[int, str],
        ledger: ForceLedger,
        replan: Callable[[], None],
    ) -> None:
        self.space = space
        self._space_h = raw.space_handle(space)
        self._bodies = bodies
        self._names = names
        self.ledger = ledger
        self._replan = replan
        self.field: GravityField = Uniform()
        self._rules: dict[int, GravityRule] = {}
        self.version = 0
        """Counts the changes of the field and of the rules (see :attr:`World.gravity_version`)."""
        self.active = False
        """Whether the stage runs: a field that is not constant, or bodies with their own rule."""
        self._t = 0.0  # s: the time of the last apply, for forces_at
        self._plain_on = False
        self._point: PointField | None = point_field(self.field)
        self._plain: PlainField | None = None
        self._reg_bodies: list[tuple[pymunk.Body, float, GravityRule]] = []
        self._registry_dirty = True
        self._reg_ids = np.zeros(0, dtype=np.uintp)
        self._reg_mass = np.zeros(0)
        self._reg_scale = np.zeros(0)
        self._reg_dir = np.zeros((0, 2))
        self._field_rows: (
            tuple[
                NDArray[np.uintp],
                NDArray[np.intp] | slice,
                NDArray[np.float64],
                NDArray[np.float64],
                NDArray[np.float64],
            ]
            | None
        ) = None

    # -- the field and the rules -----------------------------------------------------------------

    def set_field(self, field: GravityField, t: float) -> None:
        """Use ``field`` from time ``t`` (s) on."""
        self.field = field
        self.version += 1
        self._point = point_field(field)
        self._plain = None
        self.space.gravity = self.space_gravity(t)
        self._update_active()

    def space_gravity(self, t: float) -> Vec:
        """What ``space.gravity`` holds: the field if uniform, else zero (forces do the work)."""
        f = self.field
        if isinstance(f, Uniform):
            return f.g
        if isinstance(f, RotatingRoom):
            return f.vector(t)
        if f.uniform:
            g = f.at(np.zeros((1, 2)), t)[0]
            return (float(g[0]), float(g[1]))
        return (0.0, 0.0)

    def set_rule(self, body_id: int, rule: GravityRule | None) -> None:
        """Give the body ``body_id`` its own rule (``None`` or the default rule: the field's)."""
        if rule is None or rule.is_default:
            self._rules.pop(body_id, None)
        else:
            self._rules[body_id] = rule
        self.version += 1
        self._registry_dirty = True
        self._update_active()

    def rule(self, body_id: int) -> GravityRule:
        """The body's rule (the default rule if it has none)."""
        return self._rules.get(body_id, _DEFAULT_RULE)

    def at(self, body: pymunk.Body, t: float) -> Vec:
        """The gravity ``body`` feels at time ``t`` (field and rule), m/s²: in plain floats for
        the kinds of field that have that form (the same numbers; numpy costs far more for one
        body)."""
        point = self._point
        if point is not None:
            rule = self._rules.get(body.id, _DEFAULT_RULE)
            x, y = body.position
            gx, gy = point(x, y, t)
            return rule.apply(gx, gy)
        g = self.field.at(np.array([[body.position.x, body.position.y]]), t)
        rule = self._rules.get(body.id, _DEFAULT_RULE)
        d = np.array([rule.direction if rule.direction is not None else (np.nan, np.nan)])
        out = apply_rules(g, np.array([rule.scale]), d)[0]
        return (float(out[0]), float(out[1]))

    def bodies_changed(self) -> None:
        """A body was added or removed or its mass changed: rebuild the registry before the next
        evaluation (and plan again: a field is handed body by body for a few bodies only)."""
        self._registry_dirty = True
        self._replan()

    def forget(self, body_id: int) -> None:
        """The body left the world: drop its rule."""
        self._rules.pop(body_id, None)
        self.version += 1
        self._registry_dirty = True
        self._update_active()

    def _update_active(self) -> None:
        self.active = bool(self._rules) or not isinstance(self.field, Uniform)
        self._replan()

    # -- the stage -------------------------------------------------------------------------------

    def plain_ready(self, max_bodies: int) -> bool:
        """Whether the stage can hand its forces body by body (:data:`FieldOnBodies
        <playground.forces.tracked.FieldOnBodies>`): no field force per body (a field uniform in
        space), or one it evaluates in plain floats at no more than ``max_bodies`` named dynamic
        bodies."""
        if not self.active or self.field.uniform:
            return True
        if self._registry_dirty:
            self._refresh_registry()
        return len(self._reg_bodies) <= max_bodies and self._point is not None

    def use_plain(self, on: bool) -> None:
        """Hand a field that varies in space body by body (``on``, the form the scalar
        implementation of the tracked bodies takes), or as batch rows."""
        self._plain_on = on

    def apply(self, t: float) -> FieldForces | FieldOnBodies | None:
        """The stage at time ``t`` (s): set ``space.gravity`` and put the rules' corrections in
        the ledger; for a field that varies in space return its force on every body (body by
        body while :meth:`use_plain` is on), or :meth:`forces_at` for the batch
        implementation's read."""
        if self._registry_dirty:
            self._refresh_registry()
        g_space = self.space_gravity(t)
        if raw.gravity(self._space_h) != g_space:
            self.space.gravity = g_space  # setting it wakes every body: only when it changes
        if self.field.uniform:
            # Only bodies with their own rule need a correction force: m·(g_rule − g_space), in
            # plain floats (a handful of bodies: cheaper than numpy's per-call cost), by the
            # rule's one formula as every other path (a copy of it here could drop the scale of
            # a rule with its own direction unseen: a review's mutation did).
            gx, gy = g_space
            bodies, names, add = self._bodies, self._names, self.ledger.add
            for body_id, rule in self._rules.items():
                body = bodies[names[body_id]]
                rx, ry = ruled(gx, gy, rule.scale, rule.direction)
                m = raw.mass(raw.handle(body))
                add(body, (m * (rx - gx), m * (ry - gy)), category=_PASSIVE)
            return None
        if self._plain_on:
            if self._plain is None:
                assert self._point is not None
                self._plain = PlainField(self._point, self._reg_bodies)
            return self._plain.forces(t)
        # A field that varies in space: one vectorised evaluation at every dynamic body, at the
        # positions of the physics stage's batch read (one read for positions, velocities and
        # forces, after the controllers).
        self._t = t
        return self.forces_at

    def forces_at(
        self, ids: NDArray[np.uintp], pos: NDArray[np.float64]
    ) -> tuple[NDArray[np.intp] | slice, NDArray[np.float64]]:
        """The field's force (N) on the named dynamic bodies among ``ids`` at ``pos`` (m) at the
        time of the last :meth:`apply`: their rows in the read, and one (fx, fy) row each."""
        t = self._t
        cache = self._field_rows
        if cache is None or not (cache[0] is ids or np.array_equal(cache[0], ids)):
            # Row order only changes when bodies are added, removed, sleep or wake.
            reg = lookup(self._reg_ids, ids)
            hit = np.nonzero(reg >= 0)[0]
            idx = reg[hit]
            mass = np.repeat(self._reg_mass[idx], 2).reshape(-1, 2)  # contiguous [m, m] rows
            # The named dynamic bodies are usually one run of rows (the static body comes
            # last): a slice then, cheaper to index than the rows one by one.
            run = len(hit) > 0 and int(hit[-1]) - int(hit[0]) == len(hit) - 1
            rows = slice(int(hit[0]), int(hit[-1]) + 1) if run else hit
            cache = (ids, rows, mass, self._reg_scale[idx], self._reg_dir[idx])
            self._field_rows = cache
        _, rows, mass, scale, direction = cache
        points = pos[rows] if isinstance(rows, slice) else np.take(pos, rows, axis=0)
        g = self.field.at(points, t)
        if self._rules:
            g = apply_rules(g, scale, direction)
        return rows, g * mass

    def _refresh_registry(self) -> None:
        """Sorted ids, masses and rules of every named dynamic body, for vectorised gravity."""
        dyn = [b for b in self._bodies.values() if b.body_type == pymunk.Body.DYNAMIC]
        dyn.sort(key=lambda b: b.id)
        self._reg_ids = np.array([b.id for b in dyn], dtype=np.uintp)
        self._reg_mass = np.array([b.mass for b in dyn], dtype=np.float64)
        rules = [self._rules.get(b.id, GravityRule()) for b in dyn]
        self._reg_bodies = [(b, b.mass, rule) for b, rule in zip(dyn, rules, strict=True)]
        self._plain = None
        self._reg_scale = np.array([r.scale for r in rules], dtype=np.float64)
        self._reg_dir = np.array(
            [r.direction if r.direction is not None else (np.nan, np.nan) for r in rules],
            dtype=np.float64,
        ).reshape(-1, 2)
        self._registry_dirty = False
        self._field_rows = None
