"""Cross-references: the names a level uses must exist, be unique and be of the right kind."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from playground.level.document import Level
from playground.level.errors import Problem, suggest
from playground.level.expect_rules import Context, check_expectation
from playground.level.gravity import UniformGravity
from playground.level.joints import STATIC
from playground.level.shapes import Ring
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
    for i, joint in enumerate(level.joints):
        for end in ("a", "b"):
            yield from known(f"joints.{i}.{end}", getattr(joint, end), [*names, STATIC], "body")
        if joint.a == joint.b:
            yield Problem(f"joints.{i}", "a joint needs two different bodies")
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


def _check_catches(level: Level) -> Iterator[Problem]:
    """Every declared break exists, once; and there are checks to catch it."""
    if not level.catches:
        return
    from playground.faults.catalog import names as break_names

    valid = break_names()
    seen: set[str] = set()
    for i, name in enumerate(level.catches):
        if name not in valid:
            yield Problem(
                f"catches.{i}",
                f"no break named {name!r}{suggest(name, valid)} (valid: {', '.join(valid)})",
            )
        elif name in seen:
            yield Problem(f"catches.{i}", f"break {name!r} is declared twice")
        seen.add(name)
    if not level.expect:
        yield Problem("catches", "a level without expectations cannot catch a break")
