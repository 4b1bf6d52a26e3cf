"""The forces put on the world's bodies for the coming step: forces, torques and impulses,
checked, into the world's :class:`~playground.forces.ForceLedger`.

A runaway force is refused here, naming the argument, rather than blowing the step up later; a
force on a body that is not dynamic is dropped (the engine would not integrate it).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable

import pymunk

from playground._engine import raw
from playground.forces.ledger import Category, ForceLedger
from playground.limits import MAX_COORDINATE, MAX_IMPULSE, RUNAWAY_FORCE
from playground.params import bounded, bounded_vec
from playground.vec import Vec

__all__ = ["ForceInput"]

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


class ForceInput:
    """Forces in, by body (a body of the world or its name, as ``own`` resolves it), into
    ``ledger``; ``guard`` bounds them (off: any finite value)."""

    def __init__(
        self, ledger: ForceLedger, own: Callable[[pymunk.Body | str], pymunk.Body], guard: bool
    ) -> None:
        self.ledger = ledger
        self._own = own
        self.guard = guard
        """Whether forces and torques beyond the runaway bounds are refused."""

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
        guard = self.guard
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
        """Apply several forces ``(fx, fy, category)`` and a pure ``torque`` to one body (see
        :meth:`World.apply_forces <playground.world.World.apply_forces>`)."""
        if point is not None and not _plain_within(point, MAX_COORDINATE):
            bounded_vec("point", point, MAX_COORDINATE, "m")
        guard = self.guard
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
        guard = self.guard
        cap = _RUNAWAY_TORQUE if guard else _LARGEST
        if not (type(torque) is float and -cap <= torque <= cap):
            bounded("torque", torque, _RUNAWAY_TORQUE if guard else math.inf, "N·m")
        if raw.body_type(raw.handle(b)) == pymunk.Body.DYNAMIC:
            self.ledger.add_torque(b, torque, category)

    def apply_impulse(
        self,
        body: pymunk.Body | str,
        impulse: Vec,
        dt: float,
        *,
        point: Vec | None = None,
        category: Category = Category.APPLIED,
    ) -> None:
        """Apply ``impulse`` (N·s) spread over the coming step of ``dt`` (s), as the force
        impulse/dt."""
        bounded_vec("impulse", impulse, MAX_IMPULSE, "N·s")
        self.apply_force(body, (impulse[0] / dt, impulse[1] / dt), point=point, category=category)
