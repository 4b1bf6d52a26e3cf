"""Acting, the last phase of a controller's step: :func:`act` turns what was sensed and decided
into the forces of the state (:class:`ControllerForces`) through the controller's
:class:`~playground.controller.laws.Laws`, each within its budget and with its reaction
(Newton's third law); :func:`exert` puts them into the world.

>>> ControllerForces().hover
(0.0, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import pymunk

from playground.controller._vec import ZERO, scaled
from playground.controller.config import ControllerConfig
from playground.controller.laws import Laws
from playground.controller.sensing import GroundHit, Sensed
from playground.controller.states import (
    AIRBORNE,
    CLIMBING,
    CRUSHED,
    GETTING_UP,
    GROUNDED,
    OFF_BALANCE,
    SLIDING,
    ControllerState,
)
from playground.forces.ledger import Category
from playground.intents import Intent
from playground.vec import Vec
from playground.world.world import World

# Enum members read once (``Category.X`` goes through the enum's metaclass).
SUPPORT = Category.SUPPORT
APPLIED = Category.APPLIED

__all__ = ["NO_FORCES", "ControllerForces", "act", "exert"]

Forces = list[tuple[float, float, Category]]
"""Forces ``(fx, fy, category)`` on one body, N, in the order they act."""


@dataclass(slots=True)
class ControllerForces:
    """The forces of one controller step (N, N·m, N·s): what it puts on its own body and what
    goes back onto others. Read-only by convention, not frozen (a frozen dataclass costs
    several times more to build, and one is built every step; a changed copy is made with
    ``dataclasses.replace``).

    The readings — ``hover``, ``drive`` (or the air steering), ``grip``, ``push`` (its reaction
    on us) and ``balance_torque`` — are the forces on our own body; ``grip`` is the joint force
    of the step before (a joint's force is known only after the step it acts in).

    Attributes:
        own: the forces on our body in the order they act, written with ``torque``.
        torque: the balance torque written on our body (None: no balance acts).
        ground: the ground that takes ``reactions`` and ``reaction_torque`` at its hit point
            (None: no dynamic ground under a grounded controller).
        reactions: hover's and drive's reactions on ``ground``.
        reaction_torque: the balance torque's reaction on ``ground`` (None: none).
        take_off: the dynamic ground a take-off pushes off and the impulse it gets (None:
            none).
        pushed: the pushed body, where the push acts on it and the force on it (None: no push).
        balance_short: the balance needed more than its budget while touching (None: no
            balance acted); the next step's state machine counts how long.
        climb: the climb's force onto a ledge on our body (a reading, in ``own`` too).
        climbed: the dynamic ledge climbed, where the climb's reaction acts on it (its edge)
            and that reaction (None: none).
    """

    hover: Vec = ZERO
    drive: Vec = ZERO
    grip: Vec = ZERO
    push: Vec = ZERO
    balance_torque: float = 0.0
    own: Forces = field(default_factory=list)
    torque: float | None = None
    ground: GroundHit | None = None
    reactions: Forces = field(default_factory=list)
    reaction_torque: float | None = None
    take_off: tuple[GroundHit, Vec] | None = None
    pushed: tuple[pymunk.Body, Vec, Vec] | None = None
    balance_short: bool | None = None
    climb: Vec = ZERO
    climbed: tuple[pymunk.Body, Vec, Vec] | None = None


NO_FORCES = ControllerForces()
"""No force at all (off balance, or before the first step)."""


def act(
    sensed: Sensed,
    state: ControllerState,
    intent: Intent,
    config: ControllerConfig,
    laws: Laws,
) -> ControllerForces:
    """The forces of the state just decided (none while off balance), through ``laws``.

    Hover and drive act while grounded, getting up or crushed (the drive not while crushed), on
    walkable ground; the slide's hover alone on ground too steep to stand on; air steering
    while airborne; the climb onto a ledge while climbing (its reaction on a dynamic ledge at
    the edge); the take-off's impulse as a force over the step; the push; the balance torque
    unless the capsule's rotation is locked. Only a dynamic ground (or ledge) takes reactions
    (the world drops forces on static and kinematic bodies), as SUPPORT forces because they
    stand in for a contact on both sides.
    """
    # The take-off step still carries the weight: the forces follow the state it leaves.
    footing = state.footing
    if footing is OFF_BALANCE:
        return NO_FORCES
    hit = sensed.ground
    dt = sensed.dt
    hover = drive = push = climb = ZERO
    hover_f = 0.0
    climbed: tuple[pymunk.Body, Vec, Vec] | None = None
    balance_torque = 0.0
    own: Forces = []
    reactions: Forces = []
    take_off: tuple[GroundHit, Vec] | None = None
    pushed: tuple[pymunk.Body, Vec, Vec] | None = None
    grounded = footing in (GROUNDED, GETTING_UP, CRUSHED, SLIDING)
    reacting = grounded and hit is not None and hit.dynamic
    # On ground it may not stand on: sliding, or about to (GROUNDED until footing_time; within
    # SLOPE_BAND of max_slope it still stands, decide said so).
    slipping = (
        hit is not None
        and not hit.walkable
        and (footing is SLIDING or (footing is GROUNDED and state.footing_lost > 0.0))
        and hit.normal[0] * sensed.level[0] + hit.normal[1] * sensed.level[1] > 0.0
    )
    react = laws.reaction
    jumped = state.take_off_from is not None
    if jumped:
        # The body leaves at exactly jump_speed relative to the ground.
        ground = hit if hit is not None else state.last_ground
        jx, jy = laws.jump(sensed, ground, config)
        own.append((jx / dt, jy / dt, SUPPORT))
        if ground is not None and ground.dynamic:
            take_off = (ground, react("jump", (jx, jy)))

    if slipping:
        assert hit is not None
        hover_f = laws.slide(sensed, state, hit, config)
        hover = (hover_f * hit.normal[0], hover_f * hit.normal[1])
        if hover_f > 0.0:
            own.append((hover[0], hover[1], SUPPORT))
            if reacting:
                rx, ry = react("hover", hover)
                reactions.append((rx, ry, SUPPORT))
    elif grounded and hit is not None and (hit.walkable or footing is GROUNDED):
        hover_f = laws.hover(sensed, state, hit, config)
        hover = (hover_f * hit.normal[0], hover_f * hit.normal[1])
        if hover_f > 0.0:
            own.append((hover[0], hover[1], SUPPORT))
            if reacting:
                rx, ry = react("hover", hover)
                reactions.append((rx, ry, SUPPORT))
        if footing is not CRUSHED:
            drive = laws.drive(sensed, hit, intent.move, hover_f, config)
            if drive is not ZERO:
                own.append((drive[0], drive[1], SUPPORT))
                if reacting:
                    rx, ry = react("drive", drive)
                    reactions.append((rx, ry, SUPPORT))
    elif footing is AIRBORNE and intent.move != 0.0 and not jumped:
        drive = laws.steer(sensed, intent.move, config)
        if drive is not ZERO:
            own.append((drive[0], drive[1], APPLIED))
    elif footing is CLIMBING and sensed.ledge is not None:
        held = sensed.ledge
        climb = laws.climb(sensed, held, config)
        own.append((climb[0], climb[1], SUPPORT))
        if held.dynamic:
            climbed = (held.ledge.body, held.edge, react("climb", climb))

    target = sensed.push_target
    if intent.push and target is not None:
        on_it = laws.push(sensed, target, config)
        pushed = (target.body, target.point, on_it)
        push = react("push", on_it)
        own.append((push[0], push[1], SUPPORT))

    torque: float | None = None
    short: bool | None = None
    if not config.lock_rotation:
        need = laws.balance(sensed, hit if grounded else None, config)
        budget = config.balance_budget(sensed.body.mass)
        # The feet twist a loose ground only as hard as the load on it holds it down: past that
        # it tips and flips under them instead of holding the body up (a 3 kg, 25 × 4 cm tile
        # stepped on near its edge spun at 350 rad/s under the 150-600 N·m the balance asked).
        # Through a dynamic ground the torque is at most the hover's force times its lever
        # (sensing.footing); with the legs slack, none. A static, kinematic or jointed ground
        # takes any torque, and the balance falls short, to lose balance, only past its own
        # budget.
        limit = budget
        if reacting and hit is not None and hit.lever != math.inf:
            limit = min(budget, hover_f * hit.lever)
        torque = balance_torque = max(-limit, min(limit, need))
        touching = (grounded and hit is not None) or sensed.touching
        short = abs(need) > budget and touching and state.state is not GETTING_UP

    grip = ZERO
    if state.grip is not None:
        grip = scaled(sensed.engine, laws.grip(sensed.grip_impulse, dt))
    ground = hit if reacting else None
    reaction_torque = -torque if reacting and torque is not None else None
    # Positionally, in the order of the fields: building one with keywords is dearer
    # (docs/performance.md, row positional), and one is built every step.
    return ControllerForces(
        hover, drive, grip, push, balance_torque, own, torque, ground, reactions, reaction_torque,
        take_off, pushed, short, climb, climbed,
    )  # fmt: skip


def exert(world: World, body: pymunk.Body, forces: ControllerForces) -> None:
    """Put one step's ``forces`` into ``world``: the take-off's reaction on the ground, the
    push on the pushed body, the climb's reaction on the ledge, the reactions on the ground (at
    the hit point), then our own forces and torque, each written once (see
    :meth:`World.apply_forces`)."""
    if forces.take_off is not None:
        pushed_off, impulse = forces.take_off
        world.apply_impulse(pushed_off.body, impulse, point=pushed_off.point, category=SUPPORT)
    if forces.pushed is not None:
        pushed, point, force = forces.pushed
        world.apply_force(pushed, force, point=point, category=SUPPORT)
    if forces.climbed is not None:
        ledge, point, force = forces.climbed
        world.apply_force(ledge, force, point=point, category=SUPPORT)
    ground = forces.ground
    if ground is not None and (forces.reactions or forces.reaction_torque is not None):
        world.apply_forces(
            ground.body, forces.reactions, forces.reaction_torque, point=ground.point
        )
    if forces.own or forces.torque is not None:
        world.apply_forces(body, forces.own, forces.torque)
