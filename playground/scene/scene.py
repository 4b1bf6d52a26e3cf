"""A scene: the world built from a validated level, with its controllers and timelines.

:func:`build` turns a :class:`playground.level.Level` into a :class:`Scene` — settings, gravity,
static geometry, props, movers, joints, actors, tracking, events and scripted inputs — ready to
step. Its quantities are read by :mod:`playground.scene.readings`.

>>> from playground.level import find, load
>>> scene = build(load(find("incline")))
>>> scene.world.config.contact_split
True
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import pymunk

from playground import movers as movers_mod
from playground.gravity import GravityRule, Uniform
from playground.level.bodies import Actor, MoverModel, Prop
from playground.level.derive import to_core
from playground.level.document import Level
from playground.level.errors import LevelError, Problem
from playground.level.joints import STATIC
from playground.level.joints import Joint as JointModel
from playground.level.shapes import Box, Capsule, CircleShape, Polygon, Ring, Segment, Shape
from playground.level.timeline import (
    BodyGravity,
    Event,
    FlipGravity,
    Impulse,
    Nullify,
    Remove,
    RestoreGravity,
    SetGravity,
    Spawn,
)
from playground.scene.feasibility import derived_problems, physical_problems
from playground.vec import Vec
from playground.world import one_way
from playground.world.config import WorldConfig
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["Scene", "build"]


class Scene:
    """A built level: the world, its controllers by actor name, and readers for its bodies."""

    def __init__(self, level: Level, world: World) -> None:
        self.level = level
        self.world = world
        self.controllers: dict[str, Controller] = {}

    @property
    def tracked(self) -> list[str]:
        """Tracked bodies present now (actors first, then tracked props, in level order)."""
        present = set(self.world.names)
        return [n for n in self.level.tracked() if n in present]

    def state(self, name: str) -> str | None:
        """The controller state of an actor (``"grounded"``, …), None for other bodies."""
        ctrl = self.controllers.get(name)
        return None if ctrl is None else str(ctrl.state.value)

    def up(self, name: str) -> Vec:
        """The body's up: its controller's up, else its perceived up (unit vector)."""
        ctrl = self.controllers.get(name)
        if ctrl is not None:
            u = ctrl.up
            return (float(u[0]), float(u[1]))
        return self.world.perceived_up(name)

    def tilt(self, name: str) -> float:
        """Angle between the body's axis (its local +y) and its up, rad in [0, π]."""
        a = self.world.body(name).angle
        ux, uy = self.up(name)
        cos = -math.sin(a) * ux + math.cos(a) * uy
        return math.acos(max(-1.0, min(1.0, cos)))

    def support_filtered(self, name: str) -> Vec:
        """The filtered support force, N: −m · perceived gravity."""
        m = self.world.body(name).mass
        gx, gy = self.world.perceived_gravity(name)
        return (-m * gx, -m * gy)

    def run(self, seconds: float) -> None:
        """Step for ``seconds`` of simulated time."""
        self.world.run(seconds)


# -- building ------------------------------------------------------------------------------------


def build(level: Level, source: str | None = None) -> Scene:
    """Build the world a level describes; ``source`` (its file) is what a refusal names
    (default: the level's title).

    Order: settings and gravity, static geometry, movers, props, actors, joints, tracking, events,
    scripted inputs. Problems only the engine can see are raised as :class:`LevelError`, each at
    its key: ``playground check`` builds the scene too, so what it accepts, ``run`` runs.
    """
    where = level.title if source is None else source
    try:
        return _build(level, where)
    except (ValueError, KeyError, TypeError) as exc:
        raise LevelError(where, [Problem("", f"cannot build the scene: {exc}")]) from None


def _build(level: Level, where: str) -> Scene:
    settings = to_core(level.settings)
    config = dataclasses.replace(settings, perception=to_core(level.tracking.perception))
    world = World(config, gravity=to_core(level.gravity))
    one_way.install(world.space)
    scene = Scene(level, world)
    static = world.space.static_body
    for shape in level.geometry:
        world.add_static(*_shapes(static, shape))
    for mover in level.movers:
        _add_mover(world, mover)
    problems: list[Problem] = []
    for i, prop in enumerate(level.props):
        try:
            make_prop(world, prop)
        except ValueError as exc:
            problems.append(Problem(f"props.{i}", str(exc)))
    if problems:
        raise LevelError(where, problems)
    for actor in level.actors:
        scene.controllers[actor.name] = _add_actor(world, level, actor)
    joints = [world.add_constraint(_joint(world, joint)) for joint in level.joints]
    if level.tracking.bodies:
        present = [n for n in level.tracking.bodies if n in world.names]
        if present:
            world.track(*present, perceive=level.tracking.perceive)
    for event in level.events:
        world.at(event.t, _event(level, event, scene.controllers))
    problems = list(physical_problems(level, world, joints))
    problems += _spawn_problems(level, config)
    problems += derived_problems(level)
    if problems:
        raise LevelError(where, problems)
    return scene


def _spawn_problems(level: Level, config: WorldConfig) -> list[Problem]:
    """A spawned prop gets every check a prop of the setup gets, before the run: each is made in
    a world of its own, as the spawn will make it (after the scene is built, so the bodies and
    shapes of the setup are numbered as before)."""
    problems: list[Problem] = []
    spawns = [(i, e.prop) for i, e in enumerate(level.events) if isinstance(e, Spawn)]
    if not spawns:
        return problems
    scratch = World(config)
    for i, spawned in spawns:
        try:
            make_prop(scratch, spawned)
        except ValueError as exc:
            problems.append(Problem(f"events.{i}.prop", str(exc)))
    return problems


def _shapes(body: pymunk.Body, model: Shape) -> list[pymunk.Shape]:
    """The pymunk shapes of one shape table, in the body's frame (not yet added)."""
    out: list[pymunk.Shape]
    if isinstance(model, Segment):
        out = [pymunk.Segment(body, model.a, model.b, model.radius)]
    elif isinstance(model, Box):
        w, h = model.size
        corners = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
        t = pymunk.Transform.translation(*model.center).rotated(model.angle)
        out = [pymunk.Poly(body, corners, t, model.radius)]
    elif isinstance(model, Polygon):
        out = [pymunk.Poly(body, list(model.points), None, model.radius)]
    elif isinstance(model, CircleShape):
        out = [pymunk.Circle(body, model.radius, model.center)]
    elif isinstance(model, Capsule):
        cx, cy = model.center
        half = model.length / 2
        out = [pymunk.Segment(body, (cx, cy - half), (cx, cy + half), model.radius)]
    else:
        return _ring(body, model)
    for shape in out:
        shape.friction = model.friction
        shape.elasticity = model.elasticity
        if model.one_way:
            shape.collision_type = one_way.ONE_WAY
    return out


def _ring(body: pymunk.Body, model: Ring) -> list[pymunk.Shape]:
    segments = movers_mod.ring_room(
        body,
        model.radius,
        segments=model.segments,
        thickness=model.thickness,
        friction=model.friction,
    )
    for seg in segments:
        seg.elasticity = model.elasticity
        if model.one_way:
            seg.collision_type = one_way.ONE_WAY
    return list(segments)


def _add_mover(world: World, model: MoverModel) -> None:
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shapes = [s for m in model.shapes for s in _shapes(body, m)]
    world.add(model.name, body, *shapes)
    world.add_mover(model.name, to_core(model.path))


def _moment(model: Shape, mass: float) -> float:
    """Moment of inertia (kg·m²) of one shape of ``mass`` about the body's origin."""
    if isinstance(model, Segment):
        return float(pymunk.moment_for_segment(mass, model.a, model.b, model.radius))
    if isinstance(model, Box):
        w, h = model.size
        c = math.hypot(*model.center)
        return float(pymunk.moment_for_box(mass, (w, h)) + mass * c * c)
    if isinstance(model, Polygon):
        return float(pymunk.moment_for_poly(mass, list(model.points), (0, 0), model.radius))
    if isinstance(model, CircleShape):
        return float(pymunk.moment_for_circle(mass, 0.0, model.radius, model.center))
    if isinstance(model, Capsule):
        cx, cy = model.center
        half = model.length / 2
        return float(
            pymunk.moment_for_segment(mass, (cx, cy - half), (cx, cy + half), model.radius)
        )
    raise ValueError("a ring cannot be part of a dynamic body")


def make_prop(world: World, model: Prop) -> pymunk.Body:
    """A dynamic body for a prop: its mass spread over its shapes by area; the body turns about
    its position (its origin), which is the centre of gravity for symmetric shapes."""
    body = pymunk.Body()
    shapes = [s for m in model.shapes for s in _shapes(body, m)]
    areas = [s.area for s in shapes]
    total = sum(areas)
    if not total > 0.0:
        raise ValueError(f"{model.name}: its shapes have no area to carry its mass")
    moment = sum(
        _moment(m, model.mass * a / total) for m, a in zip(model.shapes, areas, strict=True)
    )
    body.mass = model.mass
    body.moment = model.moment if model.moment is not None else moment
    body.position = model.position
    body.angle = model.angle
    body.velocity = model.velocity
    body.angular_velocity = model.angular_velocity
    world.add(model.name, body, *shapes)
    return body


def _add_actor(world: World, level: Level, actor: Actor) -> Controller:
    from playground.controller.controller import Controller
    from playground.intents import Script

    source: Any = None
    timeline = [inp for inp in level.inputs if inp.actor == actor.name]
    if timeline:
        source = Script(
            timeline=tuple((inp.t, inp.intent()) for inp in sorted(timeline, key=lambda i: i.t))
        )
    elif actor.patrol is not None:
        source = to_core(actor.patrol)
    controller = Controller(
        world,
        actor.name,
        actor.position,
        config=to_core(actor.controller),
        source=source,
        angle=actor.angle,
    )
    controller.body.velocity = actor.velocity
    controller.body.angular_velocity = actor.angular_velocity
    return controller


def _body(world: World, name: str) -> pymunk.Body:
    return world.space.static_body if name == STATIC else world.body(name)


def _joint(world: World, model: JointModel) -> pymunk.Constraint:
    a, b = _body(world, model.a), _body(world, model.b)
    joint: pymunk.Constraint
    if model.kind == "pivot":
        joint = pymunk.PivotJoint(a, b, model.anchor)
    elif model.kind == "pin":
        joint = pymunk.PinJoint(
            a, b, a.world_to_local(model.anchor_a), b.world_to_local(model.anchor_b)
        )
    elif model.kind == "spring":
        rest = (
            math.dist(model.anchor_a, model.anchor_b)
            if model.rest_length is None
            else model.rest_length
        )
        joint = pymunk.DampedSpring(
            a,
            b,
            a.world_to_local(model.anchor_a),
            b.world_to_local(model.anchor_b),
            rest,
            model.stiffness,
            model.damping,
        )
    elif model.kind == "rotary_spring":
        joint = pymunk.DampedRotarySpring(a, b, model.rest_angle, model.stiffness, model.damping)
    else:
        joint = pymunk.RotaryLimitJoint(a, b, model.min, model.max)
    if model.max_force is not None:
        joint.max_force = model.max_force
    joint.collide_bodies = model.collide
    return joint


def _event(
    level: Level, event: Event, controllers: dict[str, Controller]
) -> Callable[[World], None]:
    """The world event for one entry of the level's timeline."""

    def run(world: World) -> None:
        if isinstance(event, SetGravity):
            world.gravity = Uniform(event.g)
        elif isinstance(event, FlipGravity):
            field = world.gravity
            assert isinstance(field, Uniform)
            gx, gy = field.g
            c, s = math.cos(event.angle), math.sin(event.angle)
            world.gravity = Uniform((c * gx - s * gy, s * gx + c * gy))
        elif isinstance(event, Nullify):
            world.set_gravity_rule(event.body, GravityRule(scale=0.0))
        elif isinstance(event, RestoreGravity):
            world.set_gravity_rule(event.body, None)
        elif isinstance(event, BodyGravity):
            world.set_gravity_rule(event.body, GravityRule(event.scale, event.direction))
        elif isinstance(event, Impulse):
            world.apply_impulse(event.body, event.impulse, point=event.point)
        elif isinstance(event, Spawn):
            make_prop(world, event.prop)
            if event.prop.name in level.tracking.bodies:
                world.track(event.prop.name, perceive=level.tracking.perceive)
        elif isinstance(event, Remove):
            # An actor goes with its controller (which then does nothing), not from under it.
            ctrl = controllers.get(event.body)
            if ctrl is not None:
                ctrl.remove()
            else:
                world.remove(event.body)

    return run
