"""Feasibility: what no single key of a level can show, found once its scene is built.

A spring unstable at the level's step, a mass ratio across a joint or a contact that no iteration
count holds, a body spawned inside another, a probe longer than the room: each is refused with a
:class:`~playground.level.errors.Problem` at the key to change, saying what to change
(:func:`playground.scene.build` raises them as a ``LevelError``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import pymunk

from playground.gravity import GravityRule, Uniform
from playground.level.derive import to_core
from playground.level.document import Level
from playground.level.errors import Problem
from playground.level.gravity import UniformGravity
from playground.level.timeline import BodyGravity, FlipGravity, SetGravity
from playground.limits import (
    MAX_COORDINATE,
    MAX_IMPULSE,
    MAX_MASS_RATIO,
    MAX_OVERLAP,
    SPRING_LIMIT,
)
from playground.world.world import World

__all__ = ["derived_problems", "physical_problems"]


def physical_problems(
    level: Level, world: World, joints: list[pymunk.Constraint]
) -> Iterator[Problem]:
    """Refuse a scene no setting can simulate: a spring unstable at this dt, a mass ratio across a
    joint or a contact that no iteration count holds, a body spawned inside another, a probe
    longer than the room. Each problem says what to change."""
    h = level.settings.dt / level.settings.substeps
    for i, (model, joint) in enumerate(zip(level.joints, joints, strict=True)):
        a, b = joint.a, joint.b
        if isinstance(joint, pymunk.DampedSpring | pymunk.DampedRotarySpring):
            rotary = isinstance(joint, pymunk.DampedRotarySpring)
            inertia = _reduced(*((x.moment if rotary else x.mass) for x in (a, b) if _moves(x)))
            if inertia > 0.0:
                omega_h = math.sqrt(joint.stiffness / inertia) * h
                if omega_h >= SPRING_LIMIT:
                    k_max = inertia * (SPRING_LIMIT / h) ** 2
                    yield Problem(
                        f"joints.{i}.stiffness",
                        f"2πf·dt = {omega_h:.3g} at dt/substeps = {h:.3g} s: the spring gains "
                        f"energy every step (stable below {SPRING_LIMIT:g}); lower the stiffness "
                        f"below {k_max:.3g}, or dt, or raise substeps",
                    )
        ratio = _ratio(a, b)
        if ratio > MAX_MASS_RATIO:
            yield Problem(
                f"joints.{i}",
                f"{model.a!r} and {model.b!r} differ in mass {ratio:.3g}-fold: no iteration "
                f"count holds a joint beyond {MAX_MASS_RATIO:g}; bring their masses closer",
            )
    seen: set[tuple[int, int]] = set()
    for name in world.names:
        body = world.body(name)
        for shape in body.shapes:
            for hit in world.space.shape_query(shape):
                other = hit.shape.body if hit.shape is not None else None
                if other is None or other is body:
                    continue
                pair = (min(body.id, other.id), max(body.id, other.id))
                if pair in seen:
                    continue
                seen.add(pair)
                other_name = world.name_of(other) or "the static geometry"
                depth = -min(p.distance for p in hit.contact_point_set.points)
                if depth > MAX_OVERLAP and _moves(body):
                    yield Problem(
                        _where(level, name),
                        f"starts {depth:.3g} m inside {other_name!r} (more than "
                        f"{MAX_OVERLAP:g} m): move it out so the solver does not push them apart "
                        "at once",
                    )
                ratio = _ratio(body, other)
                if ratio > MAX_MASS_RATIO:
                    yield Problem(
                        _where(level, name),
                        f"rests on {other_name!r} at a mass ratio of {ratio:.3g} (more than "
                        f"{MAX_MASS_RATIO:g}: no iteration count holds it); bring the masses "
                        "closer",
                    )
    yield from _probe_problems(level, world)


def _probe_problems(level: Level, world: World) -> Iterator[Problem]:
    """A probe longer than the room sees through its walls."""
    boxes = [s.cache_bb() for s in world.space.shapes if not _moves(s.body)]
    if not boxes:
        return
    size = max(
        max(bb.right for bb in boxes) - min(bb.left for bb in boxes),
        max(bb.top for bb in boxes) - min(bb.bottom for bb in boxes),
    )
    for i, actor in enumerate(level.actors):
        length = to_core(actor.controller).probe_length
        if length > size:
            yield Problem(
                f"actors.{i}.controller.probe_length",
                f"{length:g} m is longer than the room ({size:.3g} m across): the probe would "
                "see through it; shorten the probe",
            )


def _moves(body: pymunk.Body | None) -> bool:
    return body is not None and body.body_type == pymunk.Body.DYNAMIC


def _reduced(*masses: float) -> float:
    """The reduced mass (or moment) of the moving ends of a joint: m for one, m₁m₂/(m₁+m₂) for two;
    an end with an infinite moment (locked rotation) counts as fixed."""
    finite = [m for m in masses if math.isfinite(m)]
    if not finite:
        return 0.0
    if len(finite) == 1:
        return finite[0]
    return finite[0] * finite[1] / (finite[0] + finite[1])


def _ratio(a: pymunk.Body, b: pymunk.Body) -> float:
    """Mass ratio of two dynamic bodies (≥ 1), 1 when either does not move."""
    if not (_moves(a) and _moves(b)):
        return 1.0
    return max(a.mass, b.mass) / min(a.mass, b.mass)


def _where(level: Level, name: str) -> str:
    for i, prop in enumerate(level.props):
        if prop.name == name:
            return f"props.{i}.position"
    for i, actor in enumerate(level.actors):
        if actor.name == name:
            return f"actors.{i}.position"
    return name


def derived_problems(level: Level) -> Iterator[Problem]:
    """Values the run derives from several keys, checked against the same bounds the run
    applies: the field after each gravity event, in run order; each body's gravity rule; an
    actor's jump impulse; how far its probe and hands reach from where it starts."""
    yield from _gravity_problems(level)
    for i, actor in enumerate(level.actors):
        cfg = to_core(actor.controller)
        impulse = cfg.mass * cfg.jump_speed
        if impulse > MAX_IMPULSE:
            yield Problem(
                f"actors.{i}.controller.jump_speed",
                f"a jump of {cfg.mass:g} kg at {cfg.jump_speed:g} m/s needs {impulse:.4g} N·s, "
                f"more than {MAX_IMPULSE:g} N·s; lower the jump speed or the mass",
            )
        reach = cfg.height + max(cfg.probe_length, cfg.grab_reach, cfg.push_reach)
        far = max(abs(v) for v in actor.position) + reach
        if far > MAX_COORDINATE:
            yield Problem(
                f"actors.{i}.position",
                f"its probe and hands reach {far:.6g} m from the origin, past "
                f"{MAX_COORDINATE:g} m; move it closer to the origin",
            )


def _gravity_problems(level: Level) -> Iterator[Problem]:
    """Each gravity event's field or rule, made as the run makes it (the core refuses what the
    run would refuse), in the order the run applies them."""
    field = level.gravity
    g = field.g if isinstance(field, UniformGravity) else None
    for i in sorted(range(len(level.events)), key=lambda k: (level.events[k].t, k)):
        event = level.events[i]
        try:
            if isinstance(event, SetGravity):
                g = event.g
            elif isinstance(event, FlipGravity) and g is not None:
                c, s = math.cos(event.angle), math.sin(event.angle)
                g = (c * g[0] - s * g[1], s * g[0] + c * g[1])
                Uniform(g)
            elif isinstance(event, BodyGravity):
                GravityRule(event.scale, event.direction)
        except ValueError as exc:
            key = "direction" if isinstance(event, BodyGravity) else "angle"
            yield Problem(f"events.{i}.{key}", f"{exc}")
            return
