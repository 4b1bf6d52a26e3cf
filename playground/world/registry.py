"""The named bodies of one space: adding, looking up and removing them and their joints, and
putting them to sleep.

:class:`BodyRegistry` is the part of :class:`~playground.world.world.World` that keeps the space
and the names of its bodies; the world learns of each change through the ``added`` and
``removed`` callbacks it passes in (its stages follow: gravity registry, tracking, movers). A body
added straight to the space (``space.add``) is unnamed until :meth:`BodyRegistry.adopt` names it;
a named body the game takes out of the space itself (``space.remove``) leaves the registry at
:meth:`BodyRegistry.forget_departed`, which the world calls before each step.

While the world is *locked* (from its gravity stage to the end of a step, see
:meth:`BodyRegistry.lock`), bodies and static shapes added or removed by a hook join or leave
when the step ends, as pymunk and Box2D defer changes made from inside their step: every stage of
one step sees the same bodies. A joint is added or removed at once (the world keeps nothing per
step about joints, and a controller's grab acts in the step it grabs) unless one of its bodies is
itself waiting to join.

>>> registry = BodyRegistry()
>>> _ = registry.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
>>> registry.names, registry.name_of(registry.body("crate"))
(['crate'], 'crate')
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pymunk

from playground._engine.space import CountingSpace
from playground.limits import (
    MAX_ANGLE,
    MAX_COORDINATE,
    MAX_LENGTH,
    MAX_MASS,
    MAX_STIFFNESS,
    MIN_MASS,
)
from playground.params import bounded, bounded_vec, finite, in_range
from playground.vec import Vec
from playground.world.bodies import (
    check_body,
    check_shapes,
    check_size,
    check_surface,
    group,
    surfaced,
)
from playground.world.errors import WorldUsageError

__all__ = ["DEPARTED_REMEMBERED", "BodyRegistry"]

DEPARTED_REMEMBERED = 256
"""How many names of bodies taken out with ``space.remove`` the registry remembers, newest
first, to say so when one is looked up (a bound: a game may spawn and drop bodies by the
thousand, each with a name of its own)."""


def _nothing(body: pymunk.Body) -> None:
    """A change nobody follows."""


class BodyRegistry:
    """A pymunk space and its bodies by name (unique names; unnamed static shapes allowed).

    ``added(body)`` runs after a named body joined (or was adopted), ``removed(body)`` after one
    left the registry (still in the space, unless the game took it out with ``space.remove``).
    """

    def __init__(
        self,
        added: Callable[[pymunk.Body], None] = _nothing,
        removed: Callable[[pymunk.Body], None] = _nothing,
    ) -> None:
        self.space = CountingSpace()
        self.removals_seen = 0
        """``space.removals`` when the registry last looked for bodies the game took out of the
        space (:meth:`forget_departed`): a step compares the two before it reads any body."""
        # The names of bodies that left by space.remove, newest last, to say so when looked up.
        self._departed: dict[str, None] = {}
        self._added = added
        self._removed = removed
        self.by_name: dict[str, pymunk.Body] = {}
        """The named bodies (the dict itself, shared with the gravity stage: read it only)."""
        # Each body's id by name: ``body.id`` is a call into chipmunk, and controllers look up
        # their rule and tracked row by name every step.
        self.id_by_name: dict[str, int] = {}
        """Each named body's ``body.id`` (read it only)."""
        self.name_by_id: dict[int, str] = {}
        """Each named body's name by ``body.id`` (read it only)."""
        self._locked = False
        # What a hook changed while the world was locked, in call order, run at the step's end;
        # the names and the bodies and joints waiting to join, and the names about to leave.
        self._pending: list[Callable[[], object]] = []
        self._arriving: set[object] = set()
        self._leaving: set[str] = set()

    @property
    def locked(self) -> bool:
        """Whether the world is inside a step (from its gravity stage on): then bodies, static
        shapes, tracking and hooks added or removed wait for the step's end."""
        return self._locked

    def lock(self) -> None:
        """The step's locked part begins: changes wait until :meth:`unlock` and
        :meth:`run_pending`."""
        self._locked = True

    def unlock(self) -> None:
        """The step's locked part ends (the changes asked for meanwhile are still pending)."""
        self._locked = False

    def run_pending(self) -> None:
        """Make the changes asked for while locked, in order."""
        if self._pending:
            pending, self._pending = self._pending, []
            for change in pending:
                change()

    def _defer(self, change: Callable[[], object]) -> None:
        self._pending.append(change)

    def later(self, change: Callable[[], object]) -> None:
        """Run ``change()`` when the step ends, after the changes asked for before it (at once
        if the registry is not :attr:`locked`)."""
        if self._locked:
            self._defer(change)
        else:
            change()

    def require(self, name: str) -> None:
        """KeyError naming the known bodies unless ``name`` is a body's, or one waiting to join."""
        if name not in self._arriving:
            self.body(name)

    def add(self, name: str, body: pymunk.Body, *shapes: pymunk.Shape) -> pymunk.Body:
        """Add a named body and its shapes. Names are unique.

        Its mass, state and shapes must lie in the ranges of :mod:`playground.limits`
        (``ValueError`` naming the attribute otherwise): pymunk aborts the process on some
        absurd values and carries NaN through every later step on others.
        """
        if not isinstance(name, str) or not name:
            raise ValueError(f"name: expected a non-empty string, got {name!r}")
        if name in self.by_name or name in self._arriving:
            raise ValueError(f"{name}: a body with this name already exists")
        check_body(name, body, shapes)
        self._departed.pop(name, None)
        if self._locked:
            if body in self._arriving:
                raise ValueError(f"{name}: the body is already waiting to join this world")
            self._arriving.update((name, body))
            self._defer(lambda: self._join(name, body, shapes))
            return body
        self.space.add(body, *shapes)
        self.by_name[name] = body
        self.id_by_name[name] = body.id
        self.name_by_id[body.id] = name
        self._added(body)
        return body

    def adopt(self, name: str, body: pymunk.Body) -> pymunk.Body:
        """Name a body that was added straight to this space (``space.add``): from then on it is
        a body of the registry like one added with :meth:`add` (found, tracked and given a
        gravity rule by name, removed with its shapes and joints). Names are unique; a body has
        one name. While :attr:`locked`, the name is given when the step ends.

        >>> registry = BodyRegistry()
        >>> crate = pymunk.Body(10.0, 1.0)
        >>> registry.space.add(crate, pymunk.Poly.create_box(crate, (1.0, 1.0)))
        >>> registry.adopt("crate", crate) is registry.body("crate")
        True
        """
        if not isinstance(name, str) or not name:
            raise ValueError(f"name: expected a non-empty string, got {name!r}")
        if name in self.by_name or name in self._arriving:
            raise ValueError(f"{name}: a body with this name already exists")
        if not isinstance(body, pymunk.Body) or body.space is not self.space:
            raise ValueError(
                f"{name}: expected a body in this world's space (added with space.add), "
                f"got {body!r}"
            )
        known = self.name_by_id.get(body.id)
        if known is not None:
            raise ValueError(f"{name}: the body is already called {known!r}")
        self._departed.pop(name, None)
        if self._locked:
            self._arriving.add(name)
            self._defer(lambda: self._adopted(name, body))
            return body
        self.by_name[name] = body
        self.id_by_name[name] = body.id
        self.name_by_id[body.id] = name
        self._added(body)
        return body

    def _adopted(self, name: str, body: pymunk.Body) -> None:
        self._arriving.discard(name)
        self.adopt(name, body)

    def _join(self, name: str, body: pymunk.Body, shapes: tuple[pymunk.Shape, ...]) -> None:
        self._arriving.difference_update((name, body))
        self.add(name, body, *shapes)

    def remove(self, item: str | pymunk.Constraint) -> None:
        """Remove a body by name, with its shapes and joints, and stop tracking it; or remove a
        joint added with :meth:`add_constraint`."""
        if isinstance(item, pymunk.Constraint):
            self._remove_constraint(item)
            return
        if item in self._leaving or (item not in self._arriving and item not in self.by_name):
            self.body(item)  # KeyError naming the known bodies
            raise KeyError(f"{item}: already removed in this step")
        if self._locked:
            self._leaving.add(item)
            self._defer(lambda: self._leave(item))
            return
        body = self.by_name.pop(item)
        del self.id_by_name[item]
        del self.name_by_id[body.id]
        self._removed(body)
        space = self.space
        # Only what is in the space: a joint made on the body but never added is not, nor what
        # the game took out itself (space.remove) since the last step.
        joints = set(space.constraints).intersection(body.constraints)
        parts: list[pymunk.Body | pymunk.Shape | pymunk.Constraint] = [
            s for s in body.shapes if s.space is space
        ]
        parts.extend(joints)
        if body.space is space:
            parts.append(body)
        if parts:
            self._take_out(*parts)

    def _take_out(self, *parts: pymunk.Body | pymunk.Shape | pymunk.Constraint) -> None:
        """``space.remove(*parts)``, the registry's own: not a removal for
        :meth:`forget_departed` to look into (unless the game made one since it last looked)."""
        space = self.space
        in_sync = space.removals == self.removals_seen
        space.remove(*parts)
        if in_sync:
            self.removals_seen = space.removals

    def forget_departed(self) -> list[str]:
        """Forget the named bodies the game took out of the space itself (``space.remove``)
        since the last call, as :meth:`remove` forgets them (their tracking, gravity rule and
        mover go; the shapes and joints are the game's, left as it left them); the names, in the
        order they were added. Looking one up later raises a ``KeyError`` that says it left.

        >>> registry = BodyRegistry()
        >>> crate = registry.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
        >>> registry.space.remove(crate, *crate.shapes)
        >>> registry.forget_departed(), registry.names
        (['crate'], [])
        >>> try:
        ...     registry.body("crate")
        ... except KeyError as error:
        ...     print(error.args[0])
        no body named 'crate': it was taken out of the space with space.remove (known: none)
        """
        space = self.space
        self.removals_seen = space.removals
        gone = [name for name, body in self.by_name.items() if body.space is not space]
        departed = self._departed
        for name in gone:
            body = self.by_name.pop(name)
            del self.id_by_name[name]
            del self.name_by_id[body.id]
            departed[name] = None
            if len(departed) > DEPARTED_REMEMBERED:
                del departed[next(iter(departed))]
            self._removed(body)
        return gone

    def _leave(self, name: str) -> None:
        self._leaving.discard(name)
        self.remove(name)

    def add_constraint(self, constraint: pymunk.Constraint) -> pymunk.Constraint:
        """Add a joint between bodies of this world (or the space's static body).

        >>> registry = BodyRegistry()
        >>> a = registry.add_box("a", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
        >>> pin = registry.add_constraint(pymunk.PinJoint(a, registry.space.static_body))
        >>> list(registry.space.constraints) == [pin]
        True
        >>> registry.remove(pin)
        >>> list(registry.space.constraints)
        []
        """
        if not isinstance(constraint, pymunk.Constraint):
            raise ValueError(f"constraint: expected a pymunk.Constraint, got {constraint!r}")
        waits = False
        for end, body in (("a", constraint.a), ("b", constraint.b)):
            if body in self._arriving:
                waits = True
            elif body is not self.space.static_body and body.space is not self.space:
                raise ValueError(f"constraint.{end}: expected a body of this world, got {body!r}")
        if constraint in self._arriving or constraint in self.space.constraints:
            raise ValueError("constraint: the joint is already in this world")
        unsolvable(constraint)
        if waits:
            self._arriving.add(constraint)
            self._defer(lambda: self._arrive(constraint))
        else:
            self.space.add(constraint)
        return constraint

    def _arrive(self, constraint: pymunk.Constraint) -> None:
        self._arriving.discard(constraint)
        self.space.add(constraint)

    def _remove_constraint(self, constraint: pymunk.Constraint) -> None:
        if constraint in self._arriving:
            self._defer(lambda: self._take_out(constraint))
        elif constraint in self.space.constraints:
            self._take_out(constraint)
        else:
            raise ValueError(f"constraint: {constraint!r} is not in this world")

    def add_static(self, *shapes: pymunk.Shape) -> None:
        """Add shapes of the space's static body: fixed geometry (m), checked like a body's."""
        check_shapes("static", self.space.static_body, shapes)
        if self._locked:
            self._defer(lambda: self.space.add(*shapes))
        else:
            self.space.add(*shapes)

    def body(self, name: str) -> pymunk.Body:
        """The body called ``name`` (KeyError naming the known bodies otherwise)."""
        try:
            return self.by_name[name]
        except KeyError:
            if name in self._arriving:
                raise KeyError(
                    f"{name}: added during this step; it joins when the step ends"
                ) from None
            known = ", ".join(sorted(self.by_name)) or "none"
            if name in self._departed:
                raise KeyError(
                    f"no body named {name!r}: it was taken out of the space with space.remove "
                    f"(known: {known})"
                ) from None
            raise KeyError(f"no body named {name!r} (known: {known})") from None

    def body_at(self, point: Vec, radius: float = 0.0) -> str | None:
        """The named body with a shape at world ``point`` (m) or within ``radius`` (m) of it (the
        nearest if several), or None (unnamed bodies such as static ground do not count).

        >>> registry = BodyRegistry()
        >>> _ = registry.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
        >>> registry.body_at((0.2, 0.7)), registry.body_at((2.0, 0.5))
        ('crate', None)
        >>> registry.body_at((0.6, 0.5), 0.2)
        'crate'
        """
        bounded_vec("point", point, MAX_COORDINATE, "m")
        finite("radius", radius)
        info = self.space.point_query_nearest(point, max(radius, 0.0), pymunk.ShapeFilter())
        if info is None or info.shape is None or info.shape.body is None:
            return None
        return self.name_by_id.get(info.shape.body.id)

    def name_of(self, body: pymunk.Body) -> str | None:
        """The body's name, or None for a body the registry does not know by name."""
        return self.name_by_id.get(body.id)

    @property
    def names(self) -> list[str]:
        """The names of the bodies, in the order they were added."""
        return list(self.by_name)

    def own(self, body: pymunk.Body | str) -> pymunk.Body:
        """The body by name, or a body object that is in this space (``ValueError`` otherwise)."""
        if isinstance(body, str):
            return self.body(body)
        if not isinstance(body, pymunk.Body) or body.space is not self.space:
            raise ValueError(f"body: expected a body name or a body of this world, got {body!r}")
        return body

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
        check_size("size", size)
        bounded_vec("position", position, MAX_COORDINATE, "m")
        bounded("angle", angle, MAX_ANGLE, "rad")
        check_surface("", friction, elasticity)
        body = pymunk.Body(mass, pymunk.moment_for_box(mass, size))
        body.position = position
        body.angle = angle
        return self.add(
            name, body, surfaced(pymunk.Poly.create_box(body, size), friction, elasticity)
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
        """A static segment from ``a`` to ``b`` (m) on the space's static body."""
        bounded_vec("a", a, MAX_COORDINATE, "m")
        bounded_vec("b", b, MAX_COORDINATE, "m")
        in_range("radius", radius, 0.0, MAX_LENGTH, "m")
        check_surface("", friction, elasticity)
        seg = surfaced(pymunk.Segment(self.space.static_body, a, b, radius), friction, elasticity)
        self.add_static(seg)
        return seg

    def sleep(self, name: str) -> None:
        """Put a body to sleep now, with every dynamic body it touches or is jointed to.

        Chipmunk sleeps and wakes such a group together; a body put to sleep alone while it
        touches an awake one corrupts its memory, and one put to sleep twice aborts the process.
        So the whole group is woken, then put to sleep around ``name``; a sleeping body is left
        as it is. Any force, contact or change of gravity wakes the group again.
        """
        if not math.isfinite(self.space.sleep_time_threshold):
            raise ValueError(
                f"{name}: sleeping is off in this world (WorldConfig.sleep_time = inf); "
                "give the world a finite sleep_time to put bodies to sleep"
            )
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only a dynamic body can sleep")
        if body.space is not self.space:
            raise WorldUsageError(
                f"{name}: the body joins the space at the end of this step; put it to sleep "
                "from the next step on"
            )
        if body.is_sleeping:
            return
        members = group(body)
        for other in members:
            other.activate()
        body.sleep()
        for other in members:
            if other is not body:
                other.sleep_with_group(body)

    def wake(self, name: str) -> None:
        """Wake a sleeping body and its group (nothing happens to an awake one)."""
        body = self.body(name)
        if body.body_type != pymunk.Body.DYNAMIC:
            raise ValueError(f"{name}: only a dynamic body sleeps or wakes")
        body.activate()


def unsolvable(constraint: pymunk.Constraint) -> None:
    """Refuse a joint the engine cannot solve (ValueError naming why): one with no dynamic body
    at either end (Chipmunk asserts at the first step), a gear of ratio 0 (its bodies' moments are
    divided by it: NaN from the next step) and a parameter that is not a finite number."""
    if all(b.body_type != pymunk.Body.DYNAMIC for b in (constraint.a, constraint.b)):
        raise ValueError(
            "constraint: a joint needs a dynamic body at one end at least (both ends are static "
            "or kinematic, which the engine cannot move)"
        )
    for key in _JOINT_NUMBERS:
        value = getattr(constraint, key, None)
        if not isinstance(value, float | int):
            continue
        # The bounds on force and bias are infinite by default: only NaN is refused there.
        if math.isnan(value) if key in _UNBOUNDED else not math.isfinite(value):
            raise ValueError(f"constraint.{key}: expected a finite number, got {value!r}")
    for key in ("stiffness", "damping"):
        value = getattr(constraint, key, None)
        if isinstance(value, float | int) and abs(value) > MAX_STIFFNESS:
            raise ValueError(
                f"constraint.{key}: expected at most {MAX_STIFFNESS:g} (N/m or N·m/rad, and per "
                f"second for damping), got {value!r}: the spring's force overflows at once"
            )
    if isinstance(constraint, pymunk.GearJoint) and constraint.ratio == 0.0:
        raise ValueError(
            "constraint.ratio: a gear's ratio must not be 0 (the engine divides by it)"
        )


_JOINT_NUMBERS = (
    "ratio",
    "phase",
    "rate",
    "stiffness",
    "damping",
    "rest_length",
    "rest_angle",
    "distance",
    "min",
    "max",
    "ratchet",
    "max_force",
    "max_bias",
    "error_bias",
)
"""Numeric parameters of pymunk's joints (each kind has some of them)."""
_UNBOUNDED = frozenset({"max_force", "max_bias"})
