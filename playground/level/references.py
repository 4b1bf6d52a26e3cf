"""Cross-references: the names a level uses must exist, be unique and be of the right kind."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from playground.level.document import Level
from playground.level.errors import Problem, suggest
from playground.level.expect_rules import Context, check_expectation
from playground.level.gravity import UniformGravity
from playground.level.joints import STATIC
from playground.level.lifetimes import lifetime_problems
from playground.level.naming import check_names
from playground.level.shapes import Ring
from playground.level.support import support_problems
from playground.level.timeline import FlipGravity, Remove, Spawn


def references(level: Level, assumed: frozenset[str] = frozenset()) -> Iterator[Problem]:
    """Names that must exist, be unique, or be of the right kind.

    ``assumed`` are names of bodies left out of ``level`` because their tables are invalid
    (see :func:`validate`): references to them are not reported.
    """
    names = level.body_names()
    seen: set[str] = set()
    for name in names:
        if name == STATIC:
            yield Problem("", f"{STATIC!r} is reserved for the fixed world; rename the body")
        if name in seen:
            yield Problem("", f"body name {name!r} is used twice; names must be unique")
        seen.add(name)
    actors = [a.name for a in level.actors]
    dynamic = [*(p.name for p in level.props), *actors]
    dynamic += [e.prop.name for e in level.events if isinstance(e, Spawn)]

    def known(path: str, name: str, pool: Sequence[str], what: str) -> Iterator[Problem]:
        if name not in pool and name not in assumed:
            listing = ", ".join(pool) or "none"
            yield Problem(path, f"no {what} named {name!r}{suggest(name, pool)} (known: {listing})")

    for i, prop in enumerate(level.props):
        for j, shape in enumerate(prop.shapes):
            if isinstance(shape, Ring):
                yield Problem(f"props.{i}.shapes.{j}", "a ring belongs to a mover or geometry")
    for i, name in enumerate(level.tracking.bodies):
        yield from known(f"tracking.bodies.{i}", name, dynamic, "dynamic body")
    spawned = {e.prop.name for e in level.events if isinstance(e, Spawn)}
    at_setup = [n for n in names if n not in spawned]
    setup_dynamic = {*(p.name for p in level.props), *actors}
    for i, joint in enumerate(level.joints):
        for end in ("a", "b"):
            name = getattr(joint, end)
            if name in spawned:
                yield Problem(
                    f"joints.{i}.{end}",
                    f"{name!r} is spawned during the run; a joint is made at setup, between "
                    "bodies of the setup",
                )
            else:
                yield from known(f"joints.{i}.{end}", name, [*at_setup, STATIC], "body")
        if joint.a == joint.b:
            yield Problem(f"joints.{i}", "a joint needs two different bodies")
        ends = (joint.a, joint.b)
        if all(n in at_setup or n == STATIC for n in ends) and not setup_dynamic & set(ends):
            # Chipmunk solves a joint on the bodies it can move: with neither end dynamic it
            # fails its own assertion at the first step.
            yield Problem(
                f"joints.{i}",
                f"a joint needs a dynamic body (a prop or an actor) at one end at least; "
                f"{joint.a!r} and {joint.b!r} are {_kind(level, joint.a)} and "
                f"{_kind(level, joint.b)}",
            )
    for i, inp in enumerate(level.inputs):
        yield from known(f"inputs.{i}.actor", inp.actor, actors, "actor")
        if inp.nullify is not None:
            yield from known(f"inputs.{i}.nullify", inp.nullify, dynamic, "dynamic body")
    for i, actor in enumerate(level.actors):
        if actor.patrol is not None and any(inp.actor == actor.name for inp in level.inputs):
            yield Problem(
                f"actors.{i}.patrol", "an actor has a patrol or scripted inputs, not both"
            )
    for i, event in enumerate(level.events):
        body = getattr(event, "body", None)
        if body is not None:
            pool = names if isinstance(event, Remove) else dynamic
            yield from known(f"events.{i}.body", body, pool, "body")
        if isinstance(event, FlipGravity) and not isinstance(level.gravity, UniformGravity):
            yield Problem(f"events.{i}", "flip_gravity turns a uniform field; use rotating turns")
    follow = level.view.follow
    if follow is not None and follow not in names and follow not in assumed:
        yield from known("view.follow", follow, names, "body")
    context = Context(level, names, actors, level.tracked())
    for i, exp in enumerate(level.expect):
        if exp.body in assumed or exp.relative_to in assumed:
            continue
        yield from check_expectation(f"expect.{i}", exp, context)
    yield from _check_catches(level)
    if any(u.checks for u in level.variants.unsupported):
        # A check's default name needs a valid expectation: named only where one is used.
        yield from support_problems(level, assumed, check_names(level))
    else:
        yield from support_problems(level, assumed)
    yield from lifetime_problems(level)


def _kind(level: Level, name: str) -> str:
    """What kind of body ``name`` is, in words."""
    if name == STATIC:
        return "the fixed world"
    if any(m.name == name for m in level.movers):
        return "a mover (kinematic)"
    return "dynamic"


def _check_catches(level: Level) -> Iterator[Problem]:
    """Every declared break is declared once, and there are checks to catch it. Which names are
    breaks is the faults layer's to say (:func:`playground.faults.catalog.catch_problems`, run by
    ``playground check`` and ``playground faults``): the level format does not import it."""
    if not level.catches:
        return
    seen: set[str] = set()
    for i, name in enumerate(level.catches):
        if name in seen:
            yield Problem(f"catches.{i}", f"break {name!r} is declared twice")
        seen.add(name)
    if not level.expect:
        yield Problem("catches", "a level without expectations cannot catch a break")
