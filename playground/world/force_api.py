"""The world's force API: forces, torques and impulses put on bodies, and the readings of the
tracked bodies (engine forces, perceived gravity, perceived up).

Forces go into the world's :class:`~playground.forces.ForceLedger` after a check of their size
(a runaway force is refused here, naming the argument, rather than blowing the step up later);
readings come from the tracked bodies (:class:`~playground.forces.tracked.TrackedSet`), whichever
implementation serves them; reading changes nothing.
"""

from __future__ import annotations

import math
import sys

import pymunk

from playground._engine import raw
from playground.forces.ledger import Category, ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.limits import MAX_COORDINATE, MAX_IMPULSE, RUNAWAY_FORCE
from playground.params import bounded, bounded_vec
from playground.vec import Vec
from playground.world.config import WorldConfig
from playground.world.physics import PhysicsStage
from playground.world.registry import BodyRegistry

__all__ = ["ForceAPI"]

_LARGEST = sys.float_info.max
"""The bound of the quick checks when the guard is off: any finite number (∞ fails
``x <= _LARGEST``, NaN every comparison)."""
_RUNAWAY_TORQUE = RUNAWAY_FORCE * MAX_COORDINATE
"""A torque is a force times a lever of at most the world's size: the same runaway bound, N·m."""


def _plain_within(v: object, limit: float) -> bool:
    """Whether ``v`` is a pair of floats within ±``limit`` (NaN fails the comparisons): the
    common case, checked in a few comparisons. Anything else (ints, numpy numbers, a wrong
    length, a value out of bounds) goes to the full check, which accepts it or names what is
    wrong, so this changes only the cost, never what is accepted."""
    if type(v) is not tuple or len(v) != 2:
        return False
    x, y = v
    return type(x) is float and type(y) is float and -limit <= x <= limit and -limit <= y <= limit


class ForceAPI(BodyRegistry):
    """Forces in, readings out, by body name (the part of :class:`~playground.world.World` that
    users and controllers call every step)."""

    ledger: ForceLedger
    _config: WorldConfig
    _physics: PhysicsStage

    def track(self, *names: str, perceive: bool = True) -> None:
        """Recover engine forces for these dynamic bodies every step; ``perceive`` also filters
        their perceived gravity. From the next step on if the world is :attr:`locked`."""
        if self._locked:
            for name in names:
                if name not in self._arriving:
                    self.body(name)  # KeyError naming the known bodies, now
            self._defer(lambda: self.track(*names, perceive=perceive))
            return
        for name in names:
            self._physics.tracked.track(self.body(name), perceive)

    @property
    def tracked_bodies(self) -> list[pymunk.Body]:
        """The tracked bodies, in the order they were tracked (a copy)."""
        return list(self._physics.tracked.bodies)

    def is_tracked(self, name: str) -> bool:
        """Whether the body ``name`` is tracked (KeyError naming the known bodies if there is
        no such body)."""
        return self._physics.tracked.row_of(self.body(name), self._ids[name]) is not None

    def readings(self) -> TrackedReadings:
        """Every tracked body's last readings and perceived gravity, as arrays (copies), one row
        each in :attr:`tracked_bodies` order."""
        return self._physics.tracked.active.table()

    @property
    def tracked_kind(self) -> str:
        """Which implementation serves the tracked bodies in the coming steps, as last planned:
        ``"scalar"`` (plain floats, for few bodies) or ``"batch"`` (numpy and
        ``pymunk.batch``, for many). Benchmarks report it; nothing else needs it."""
        return self._physics.tracked.active.kind

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
        guard = self._config.guard
        if not _plain_within(force, RUNAWAY_FORCE if guard else _LARGEST):
            bounded_vec("force", force, RUNAWAY_FORCE if guard else math.inf, "N")
        if point is not None and not _plain_within(point, MAX_COORDINATE):
            bounded_vec("point", point, MAX_COORDINATE, "m")
        if raw.body_type(raw.handle(b)) == pymunk.Body.DYNAMIC:
            # The ledger's first entry replans the step (its on_first).
            self.ledger.add(b, force, point=point, category=category)

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
        if point is not None and not _plain_within(point, MAX_COORDINATE):
            bounded_vec("point", point, MAX_COORDINATE, "m")
        guard = self._config.guard
        cap = RUNAWAY_FORCE if guard else _LARGEST
        for fx, fy, _ in forces:
            # Within ±cap (finite), NaN refused by the comparisons themselves.
            if not (-cap <= fx <= cap and -cap <= fy <= cap):
                bounded_vec("force", (fx, fy), RUNAWAY_FORCE if guard else math.inf, "N")
        if torque is not None:
            # A torque is a force times a lever of at most the world's size (apply_torque).
            t_cap = _RUNAWAY_TORQUE if guard else _LARGEST
            if not -t_cap <= torque <= t_cap:
                bounded("torque", torque, _RUNAWAY_TORQUE if guard else math.inf, "N·m")
        if raw.body_type(raw.handle(body)) == pymunk.Body.DYNAMIC:
            self.ledger.add_all(self._own(body), forces, torque, point)

    def apply_torque(
        self, body: pymunk.Body | str, torque: float, *, category: Category = Category.APPLIED
    ) -> None:
        """Apply a pure ``torque`` (N·m, counter-clockwise) during the coming step."""
        b = self._own(body)
        guard = self._config.guard
        cap = _RUNAWAY_TORQUE if guard else _LARGEST
        if not (type(torque) is float and -cap <= torque <= cap):
            bounded("torque", torque, _RUNAWAY_TORQUE if guard else math.inf, "N·m")
        if raw.body_type(raw.handle(b)) == pymunk.Body.DYNAMIC:
            self.ledger.add_torque(b, torque, category)

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
        dt = self._config.dt
        self.apply_force(body, (impulse[0] / dt, impulse[1] / dt), point=point, category=category)

    def forces(self, name: str) -> BodyForces:
        """The last readings of a tracked body."""
        return self._physics.tracked.active.reading(self._tracked_row(name))

    def perceived_gravity(self, name: str) -> Vec:
        """The filtered perceived gravity of a tracked body, m/s²."""
        return self._physics.tracked.active.perceived_gravity(self._tracked_row(name))

    def perceived_up(self, name: str) -> Vec:
        """Unit vector opposite the perceived gravity, held through weak readings."""
        return self._physics.tracked.active.perceived_up(self._tracked_row(name))

    def perceived_up_and_gravity(self, name: str) -> tuple[Vec, Vec]:
        """:meth:`perceived_up` and :meth:`perceived_gravity` of a tracked body in one call (a
        controller reads both every step; the row is looked up once)."""
        row = self._tracked_row(name)
        return self._physics.tracked.active.perceived_up_and_gravity(row)

    def _tracked_row(self, name: str) -> int:
        row = self._physics.tracked.row_of(self.body(name), self._ids[name])
        if row is None:
            raise KeyError(f"{name}: not tracked (call world.track({name!r}) first)")
        return row
