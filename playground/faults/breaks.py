"""The breaks: each one breaks one feature of the playground — the controller's force laws and
readings, gravity rules, perception, movers — and registers itself in the catalogue by name.

>>> from playground.faults.catalog import BREAKS
>>> BREAKS["balance_off"].doc
'No balance torque: the capsule no longer keeps itself upright.'
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Iterator
from typing import Any

import pymunk

from playground import movers as movers_mod
from playground.controller import decision as decision_mod
from playground.controller import ledge as ledge_mod
from playground.controller import sensing as sensing_mod
from playground.controller import stairs as stairs_mod
from playground.controller import switches
from playground.controller._vec import ZERO
from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.grab import Grip
from playground.controller.laws import Laws, Reacting
from playground.controller.ledge import Ledge
from playground.controller.sensing import GroundHit, Sensed
from playground.controller.states import State
from playground.faults.catalog import register
from playground.faults.patching import (
    after,
    argument_changed,
    controller_config,
    controller_laws,
    parameter,
    replaced,
    rotate,
    with_argument,
)
from playground.gravity import GravityRule
from playground.gravity import perception as perception_mod
from playground.vec import Vec
from playground.world import gravity_stage
from playground.world import one_way as one_way_mod
from playground.world import world as world_mod

HOVER_REACTION_SCALE = 0.05
"""What is left of the hover's reaction on the ground under ``hover_reaction`` (5 %)."""
DRIVE_SLOWDOWN = 2.0
"""``drive_slowed`` multiplies the drive's time constant by this (half as fast)."""
TRACTION_FREE_HOVER = math.inf
"""``traction_unbounded`` tells the drive the hover pushes with this much (no traction bound)."""
GRIP_READING_SCALE = 0.5
"""``grip_reading`` scales the controller's grip reading by this."""
HOVER_READING_SCALE = 0.5
"""``hover_reading`` scales the controller's hover reading by this."""
GRIP_FORCE = 700.0
"""``grip_weakened`` sets the grip budget to this, N: above a 70 kg player's weight (686.7 N),
below what a climb at 1 m/s² needs (756.7 N)."""
NULLIFY_LEFT = 0.03
"""``nullify_leaks`` leaves this fraction of gravity on a nullified body."""
PERCEIVED_ROTATION = math.radians(30.0)
"""``perceived_gravity_rotated`` turns the perceived gravity and up by this, rad (CCW)."""
BYPASS_CUTOFF = 1e9
"""``filter_bypassed`` sets the 1€ minimum cutoff to this, Hz: the filter passes every sample."""


@register("hover_reaction")
def _hover_reaction() -> Iterator[None]:
    """The hover's reaction on the ground is cut to 5 % (Newton's third law broken): a plank,
    a crate or a raft no longer feels the player standing on it."""

    def make(original: Callable[[Reacting, Vec], Vec]) -> Callable[[Reacting, Vec], Vec]:
        def reaction(law: Reacting, force: Vec) -> Vec:
            rx, ry = original(law, force)
            keep = HOVER_REACTION_SCALE if law == "hover" else 1.0
            return (keep * rx, keep * ry)

        return reaction

    with controller_laws(reaction=make):
        yield


@register("hover_removed")
def _hover_removed() -> Iterator[None]:
    """No hover spring at all: the capsule stands on its own end cap, and with no hover force
    the drive has no traction."""
    with controller_laws(hover=lambda _: lambda *a, **k: 0.0):
        yield


@register("hover_reading")
def _hover_reading() -> Iterator[None]:
    """The controller's own hover reading is halved (the force it applies is unchanged)."""

    def then(a: dict[str, Any], result: None) -> None:
        me = a["self"]
        hx, hy = me.last_forces.hover
        k = HOVER_READING_SCALE
        me.last_forces = dataclasses.replace(me.last_forces, hover=(k * hx, k * hy))

    with after(Controller, "step", ("self",), then):
        yield


def _still(hit: Any) -> Any:
    """The ground ``hit`` as if it stood still in the world."""
    motion = {
        f.name: (0.0, 0.0)
        for f in dataclasses.fields(hit)
        if f.name.endswith(("velocity", "acceleration"))
    }
    return dataclasses.replace(hit, **motion)


@register("drive_world_frame")
def _drive_world_frame() -> Iterator[None]:
    """The drive works relative to the world instead of the ground under the feet: standing still
    means standing still in the world, so a platform slides away under the player."""
    with controller_laws(drive=argument_changed(Laws, "hit", _still)):
        yield


@register("drive_slowed")
def _drive_slowed() -> Iterator[None]:
    """The drive closes the gap to its goal velocity half as fast (its time constant doubled)."""
    with controller_config(drive_time=lambda t: t * DRIVE_SLOWDOWN):
        yield


def _without_own_acceleration(hit: Any) -> Any:
    """The ground ``hit`` with its own acceleration left out of its frame's."""
    (fx, fy), (ox, oy) = hit.frame_acceleration, hit.own_acceleration
    return dataclasses.replace(
        hit, frame_acceleration=(fx - ox, fy - oy), own_acceleration=(0.0, 0.0)
    )


@register("ground_acceleration_ignored")
def _ground_acceleration_ignored() -> Iterator[None]:
    """The drive and the hover no longer feed the ground's own acceleration forward: on an
    accelerating platform the player lags behind it by its acceleration × the drive's time
    constant."""
    without = argument_changed(Laws, "hit", _without_own_acceleration)
    with controller_laws(hover=without, drive=without):
        yield


@register("traction_unbounded")
def _traction_unbounded() -> Iterator[None]:
    """The drive is no longer bounded by traction × hover force (only by its budget): a body
    with no weight on its feet still pushes itself along the ground."""
    with controller_laws(drive=argument_changed(Laws, "hover", lambda _: TRACTION_FREE_HOVER)):
        yield


@register("balance_off")
def _balance_off() -> Iterator[None]:
    """No balance torque: the capsule no longer keeps itself upright."""
    with controller_laws(balance=lambda _: lambda *a, **k: 0.0):
        yield


@register("balance_absolute_spin")
def _balance_absolute_spin() -> Iterator[None]:
    """The balance damps the body's absolute spin instead of its spin relative to the ground:
    on a turning floor (inside a spinning ring) the capsule lags behind its up."""
    with controller_laws(balance=argument_changed(Laws, "hit", lambda hit: None)):
        yield


@register("footing_unbounded")
def _footing_unbounded() -> Iterator[None]:
    """The balance torque through a loose ground is no longer held to what the load on it holds
    down: stepping onto a loose tile near its edge, the feet flip it and it spins away under
    them."""
    with replaced(sensing_mod, "footing", lambda _: lambda *a, **k: math.inf):
        yield


@register("grip_reading")
def _grip_reading() -> Iterator[None]:
    """The controller's own grip reading is halved (the joint itself is unchanged)."""

    def make(original: Callable[[float, float], float]) -> Callable[[float, float], float]:
        return lambda impulse, dt: GRIP_READING_SCALE * original(impulse, dt)

    with controller_laws(grip=make):
        yield


@register("grip_weakened")
def _grip_weakened() -> Iterator[None]:
    """The grip joint's force budget drops to 700 N: it holds a 70 kg player's weight but not
    the extra a climbing flyer asks of it."""
    with controller_config(grip_force=lambda _: GRIP_FORCE):
        yield


@register("ledge_grab_off")
def _ledge_grab_off() -> Iterator[None]:
    """The hands no longer find a ledge's edge: a grab next to a wall holds its face wherever it
    touches, and there is no ledge to climb onto."""
    with replaced(ledge_mod, "find", lambda _: lambda *a, **k: None):
        yield


@register("ledge_climb_off")
def _ledge_climb_off() -> Iterator[None]:
    """No climb force: a climb up lets go of the ledge's edge and nothing lifts the body."""
    with controller_laws(climb=lambda _: lambda *a, **k: ZERO):
        yield


@register("ledge_climb_reaction_off")
def _ledge_climb_reaction_off() -> Iterator[None]:
    """The climb's reaction on the ledge is lost (Newton's third law broken): a loose crate no
    longer feels the player pulling itself up onto it."""

    def make(original: Callable[[Reacting, Vec], Vec]) -> Callable[[Reacting, Vec], Vec]:
        return lambda law, force: (0.0, 0.0) if law == "climb" else original(law, force)

    with controller_laws(reaction=make):
        yield


@register("jump_reaction_off")
def _jump_reaction_off() -> Iterator[None]:
    """The take-off's reaction on a dynamic ground is lost (Newton's third law broken): a free
    plank, a crate or a raft no longer feels the player jump off it."""

    def make(original: Callable[[Reacting, Vec], Vec]) -> Callable[[Reacting, Vec], Vec]:
        return lambda law, force: (0.0, 0.0) if law == "jump" else original(law, force)

    with controller_laws(reaction=make):
        yield


@register("ledge_held_in_world")
def _ledge_held_in_world() -> Iterator[None]:
    """A ledge's edge is held fixed in the world instead of on the ledge's own body: a moving
    pillar leaves its player hanging in the air, a loose crate no longer feels its weight."""

    def make(
        original: Callable[[pymunk.Body, Ledge, ControllerConfig], Grip],
    ) -> Callable[[pymunk.Body, Ledge, ControllerConfig], Grip]:
        def grip(body: pymunk.Body, ledge: Ledge, config: ControllerConfig) -> Grip:
            held = original(body, ledge, config)
            joint, space = held.joint, ledge.body.space
            if space is None:
                return held
            where = joint.b.local_to_world(joint.anchor_b)
            pinned = pymunk.PivotJoint(joint.a, space.static_body, joint.anchor_a, where)
            pinned.max_force = joint.max_force
            pinned.collide_bodies = False
            pinned.post_solve = held.impulses.add
            return dataclasses.replace(held, joint=pinned)

        return grip

    with replaced(ledge_mod, "grip", make):
        yield


@register("one_way_solid")
def _one_way_solid() -> Iterator[None]:
    """One-way shapes are solid from every side: a player jumping up under a platform hits its
    head on it."""

    def make(original: Callable[..., None]) -> Callable[..., None]:
        parameter(original, one_way_mod, "arbiter")

        def begin(arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
            arbiter.process_collision = True

        return begin

    with replaced(one_way_mod, "_begin", make):
        yield


@register("one_way_probe_below")
def _one_way_probe_below() -> Iterator[None]:
    """The ground probe takes a one-way shape for ground from below and from inside it: a jump
    that leaves the centre inside a platform is held up there by its hover."""
    with replaced(one_way_mod, "passes", lambda _: lambda *a, **k: False):
        yield


@register("push_reaction_off")
def _push_reaction_off() -> Iterator[None]:
    """The push's reaction on the pusher is lost (the pushed body still gets its push)."""

    def make(original: Callable[[Reacting, Vec], Vec]) -> Callable[[Reacting, Vec], Vec]:
        return lambda law, force: (0.0, 0.0) if law == "push" else original(law, force)

    with controller_laws(reaction=make):
        yield


@register("nullify_leaks")
def _nullify_leaks() -> Iterator[None]:
    """Nullifying a body's gravity leaves 3 % of it on."""

    def leak(rule: GravityRule | None) -> GravityRule | None:
        if rule is not None and rule.scale == 0.0:
            return GravityRule(scale=NULLIFY_LEFT, direction=rule.direction)
        return rule

    with with_argument(world_mod.World, "set_gravity_rule", "rule", leak):
        yield


@register("own_gravity_ignored")
def _own_gravity_ignored() -> Iterator[None]:
    """The controller ignores its own-gravity switch (the intent's ``gravity``)."""
    with with_argument(
        switches, "switch", "intent", lambda it: dataclasses.replace(it, gravity=None)
    ):
        yield


@register("perceived_gravity_rotated")
def _perceived_gravity_rotated() -> Iterator[None]:
    """The inner ear is turned by 30°: perceived gravity and perceived up, as the world reports
    them to controllers and checks, are rotated counter-clockwise."""

    def turned(original: Callable[..., tuple[float, float]]) -> Callable[..., tuple[float, float]]:
        return lambda self, name: rotate(original(self, name), PERCEIVED_ROTATION)

    def both_turned(original: Callable[..., tuple[Vec, Vec]]) -> Callable[..., tuple[Vec, Vec]]:
        def read(self: Any, name: str) -> tuple[Vec, Vec]:
            up, gravity = original(self, name)
            return rotate(up, PERCEIVED_ROTATION), rotate(gravity, PERCEIVED_ROTATION)

        return read

    with (
        replaced(world_mod.World, "perceived_gravity", turned),
        replaced(world_mod.World, "perceived_up", turned),
        replaced(world_mod.World, "perceived_up_and_gravity", both_turned),
    ):
        yield


@register("filter_bypassed")
def _filter_bypassed() -> Iterator[None]:
    """Perceived gravity is not filtered: no median-of-3 stage and a 1€ cutoff so high that every
    raw sample (every bounce's spike) passes straight through."""
    with with_argument(
        perception_mod.PerceivedGravity,
        "__init__",
        "config",
        lambda c: dataclasses.replace(c, min_cutoff=BYPASS_CUTOFF, spike_filter=False),
    ):
        yield


@register("mover_velocity_late")
def _mover_velocity_late() -> Iterator[None]:
    """Movers set the velocity of the step before: each kinematic body trails its path by one
    step (it starts a step late and never catches up)."""

    def make(original: Callable[..., None]) -> Callable[..., None]:
        parameter(original, movers_mod.Mover, "t")
        parameter(original, movers_mod.Mover, "dt")

        def drive(self: Any, t: float, dt: float) -> None:
            original(self, t=t - dt, dt=dt)

        return drive

    with replaced(movers_mod.Mover, "drive", make):
        yield


@register("own_gravity_scale_ignored")
def _own_gravity_scale_ignored() -> Iterator[None]:
    """In a uniform field the gravity stage drops the scale of a rule with its own direction:
    such a body falls at the field's |g| along its direction, while the world still reports the
    rule's gravity (so a controller believes it)."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        def unscaled(gx: float, gy: float, scale: float, direction: Vec | None) -> Vec:
            return original(gx, gy, scale if direction is None else 1.0, direction)  # type: ignore[no-any-return]

        return unscaled

    with replaced(gravity_stage, "ruled", make):
        yield


@register("gravity_rule_ignored")
def _gravity_rule_ignored() -> Iterator[None]:
    """The gravity stage ignores per-body rules (nullified, scaled or own gravity): every body
    falls in the field, while the world still reports each body's rule (so its controller
    believes it)."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        def without_rules(self: Any, *args: Any) -> Any:
            rules, self._rules = self._rules, {}
            try:
                return original(self, *args)
            finally:
                self._rules = rules

        return without_rules

    # apply: the corrections in a uniform field; forces_at: a field that varies in space, which
    # the physics stage evaluates after the gravity stage.
    with (
        replaced(gravity_stage.GravityStage, "apply", make),
        replaced(gravity_stage.GravityStage, "forces_at", make),
    ):
        yield


@register("ring_spin_stopped")
def _ring_spin_stopped() -> Iterator[None]:
    """Spinning movers stand still: a ``spin`` path keeps its starting angle."""
    with replaced(movers_mod.Spin, "pose", lambda _: lambda self, t: (self.position, self.angle)):
        yield


@register("stairs_no_step_up")
def _stairs_no_step_up() -> Iterator[None]:
    """The probe never looks ahead for a tread: a walking player finds a riser only once its
    centre is over it, and its cap strikes the nosing first."""
    with replaced(stairs_mod, "ahead", lambda _: lambda *a, **k: None):
        yield


@register("stairs_no_step_down")
def _stairs_no_step_down() -> Iterator[None]:
    """No step down: a grounded player whose probe loses the ground goes AIRBORNE, however
    near the tread below."""
    with replaced(stairs_mod, "below", lambda _: lambda *a, **k: None):
        yield


@register("slope_speed_horizontal")
def _slope_speed_horizontal() -> Iterator[None]:
    """The drive's goal is move·max_speed measured horizontally (along up's tangent), not
    along the ground: up or down a slope θ it walks at max_speed·cosθ along it (2.83 m/s of
    4 m/s at 45°)."""

    def make(
        original: Callable[[Sensed, GroundHit, float, float, ControllerConfig], Vec],
    ) -> Callable[[Sensed, GroundHit, float, float, ControllerConfig], Vec]:
        parameter(original, Laws, "move")

        def drive(
            sensed: Sensed, hit: GroundHit, move: float, hover: float, config: ControllerConfig
        ) -> Vec:
            nx, ny = hit.normal
            ux, uy = sensed.up
            return original(sensed, hit, move * abs(nx * ux + ny * uy), hover, config)

        return drive

    with controller_laws(drive=make):
        yield


@register("slope_hold_in_budget")
def _slope_hold_in_budget() -> Iterator[None]:
    """The drive holds a slope out of the legs' budget (within ±ground_force, not within the
    hold ± ground_force): no slope steeper than asin(ground_weights), 31°, is held, and up a
    45° slope the player slides back."""

    def make(
        original: Callable[[Sensed, GroundHit, float, float, ControllerConfig], Vec],
    ) -> Callable[[Sensed, GroundHit, float, float, ControllerConfig], Vec]:
        parameter(original, Laws, "hover")

        def drive(
            sensed: Sensed, hit: GroundHit, move: float, hover: float, config: ControllerConfig
        ) -> Vec:
            fx, fy = original(sensed, hit, move, hover, config)
            nx, ny = hit.normal
            along = fx * ny - fy * nx  # along the tangent (ny, −nx), N
            budget = config.ground_budget(sensed.body.mass)
            f = max(-budget, min(budget, along))
            return ZERO if f == 0.0 else (f * ny, -f * nx)

        return drive

    with controller_laws(drive=make):
        yield


@register("sliding_removed")
def _sliding_removed() -> Iterator[None]:
    """Ground too steep to stand on counts as none: the controller is AIRBORNE over it (its up
    the field's, no hover) instead of SLIDING down it on its hover."""

    def make(original: Callable[..., State]) -> Callable[..., State]:
        parameter(original, decision_mod, "rising")

        def footing(*args: Any, **kwargs: Any) -> State:
            found = original(*args, **kwargs)
            return State.AIRBORNE if found is State.SLIDING else found

        return footing

    with replaced(decision_mod, "footing", make):
        yield


@register("wall_push_as_support")
def _wall_push_as_support() -> Iterator[None]:
    """The controller's up is the perceived one whatever pushes it: pressed against a wall or
    a slope too steep to stand on, their push tips its up (and its balance leans it) toward
    their normal."""

    def make(original: Callable[..., Vec]) -> Callable[..., Vec]:
        parameter(original, sensing_mod, "perceived")

        def lean(perceived: Vec, *args: Any, **kwargs: Any) -> Vec:
            return perceived

        return lean

    with replaced(sensing_mod, "lean", make):
        yield
