"""Deciding, the middle phase of a controller's step: the state machine. :func:`decide` takes
what was sensed, the state and the intent and returns the next
:class:`~playground.controller.states.ControllerState` — the jump press, the take-off, the grip
taken or let go, how long the balance has fallen short, and which :class:`State` acts.

It reads no world and writes nothing: the grip's joint enters or leaves the world afterwards
(:func:`~playground.controller.grab.hold`). Times in s of world time.
"""

from __future__ import annotations

import math

from playground.controller import ledge as ledges
from playground.controller.config import ControllerConfig
from playground.controller.sensing import GroundHit, Sensed, height, up_speed
from playground.controller.states import (
    AIRBORNE,
    CLIMBING,
    CRUSHED,
    GETTING_UP,
    GROUNDED,
    HANGING,
    OFF_BALANCE,
    SLIDING,
    SLOPE_BAND,
    ControllerState,
    State,
)
from playground.intents import Intent

__all__ = ["crush_limit", "decide", "footing", "is_still", "steady"]

# The footings in order, worst first: a better one is taken at once, a worse one once it lasts.
_RANK = {AIRBORNE: 0, SLIDING: 1, GROUNDED: 2}


def decide(
    sensed: Sensed, state: ControllerState, intent: Intent, config: ControllerConfig
) -> ControllerState:
    """The state after this step's decisions (a new value; ``state`` is left as it was).

    In order: a new jump press is remembered; a take-off ends once it stops rising; the
    balance's shortfall of the last step is counted; the grip is kept, let go (grab released,
    or the anchors slipped beyond ``grip_slip``) or taken (grab held and a hold within reach);
    a ledge held by its edge is climbed (its grip let go, the climb's force takes over) on a
    climb up, until it is up on walkable ground (:func:`~playground.controller.ledge.up`),
    or the grab is released;
    then the state machine moves on (between GROUNDED, SLIDING and AIRBORNE by
    :func:`footing`, a worse footing once it has lasted ``footing_time``), and a buffered
    jump takes off if the state allows it (grounded, or airborne within ``coyote_time`` of the
    ground).
    """
    t = sensed.time
    dt = sensed.dt
    hit = sensed.ground
    current: State = state.state

    jump_pressed_at = state.jump_pressed_at
    if intent.jump and not state.jump_held:
        jump_pressed_at = t
    rising = state.rising
    if rising and up_speed(sensed, hit) <= 0.0:
        # Relative to the ground, or to the world out of its reach: a jump up through a
        # one-way platform is still rising when the platform comes into reach.
        rising = False

    saturated = state.saturated
    if sensed.balance_short is not None:
        saturated = saturated + dt if sensed.balance_short else 0.0

    grip = state.grip
    if grip is not None:
        if not intent.grab or sensed.slip > config.grip_slip:
            grip = None
    elif sensed.handhold is not None:
        grip = sensed.handhold
        current = HANGING
    ledge = state.ledge if current is CLIMBING and intent.grab else None
    if grip is not None and grip.ledge is not None:
        ledge = grip.ledge
        if intent.climb > 0.0:
            # Up onto the ledge: the hands let go of the joint, the climb's force takes over.
            grip = None
            current = CLIMBING

    grounded_at = state.grounded_at
    still = state.still
    relieved = 0.0
    footing_lost = 0.0
    getup_at = state.getup_at
    getup_from = state.getup_from
    on_ground = hit is not None and hit.walkable and not rising
    climbing = False
    if ledge is not None and grip is None:
        # Sensing read the ledge held or about to be climbed (sensed.ledge).
        hold = sensed.ledge
        climbing = hold is not None and not (on_ground and ledges.up(sensed.body, hold, config))
        if not climbing:
            ledge = None
    last_ground = hit if on_ground else state.last_ground
    if current is OFF_BALANCE:
        still = still + dt if is_still(sensed, hit, config) else 0.0
        if still >= config.settle_time and hit is not None:
            current = GETTING_UP
            getup_at = t
            getup_from = height(sensed, hit)
            saturated = 0.0
    elif current is GETTING_UP:
        if hit is None:
            current = AIRBORNE
        elif t - getup_at >= config.getup_time and steady(sensed, config):
            current = GROUNDED
            grounded_at = t
    elif saturated > config.balance_loss_time:
        # Off balance: let go of any grip; hover, drive and balance stop until it is still.
        grip = None
        ledge = None
        current = OFF_BALANCE
        still = 0.0
        saturated = 0.0
    elif grip is not None:
        current = HANGING
    elif climbing:
        current = CLIMBING
    else:
        # The contact load first: it is zero while hovering, and the threshold is a call.
        pressed = sensed.contact_load > 0.0
        if pressed and sensed.load > crush_limit(current, sensed.body.mass, config):
            # Crushed: bearing more than crush_force from above with the load still on us (a
            # crusher held off at arm's length by the push no longer pins us); once crushed,
            # more than crush_release of it.
            current = CRUSHED
        elif current is CRUSHED and state.relieved + dt < config.crush_release_time:
            # Relieved only for a moment: a rocking or bouncing load swings around the
            # threshold (and off and on again), and a state that followed it would flicker.
            relieved = state.relieved + dt
        else:
            found = footing(sensed, hit, rising, current, config)
            rank = _RANK.get(current)
            if rank is None or _RANK[found] >= rank:
                current = found
            elif state.footing_lost + dt < config.footing_time:
                # Worse footing only for a moment: the ground at the edge of the probe's reach,
                # a crest crossed at speed, one odd reading where two facets meet.
                footing_lost = state.footing_lost + dt
            else:
                current = found
        if current is not AIRBORNE and on_ground:
            grounded_at = t

    take_off_from: State | None = None
    may_jump = current is GROUNDED or (
        current is AIRBORNE and t - grounded_at <= config.coyote_time
    )
    if may_jump and t - jump_pressed_at <= config.jump_buffer:
        ground = hit if hit is not None else last_ground
        jump_pressed_at = -math.inf
        grounded_at = -math.inf
        if config.jump_speed - up_speed(sensed, ground) > 0.0:
            take_off_from = current
            current = AIRBORNE
            rising = True
            footing_lost = 0.0

    # Positionally, in the order of the fields: building one with keywords is dearer
    # (docs/performance.md, row positional), and one is built every step.
    return ControllerState(
        current, intent.jump, jump_pressed_at, grounded_at, rising, last_ground, saturated,
        still, relieved, getup_at, getup_from, grip, take_off_from, intent.gravity,
        intent.nullify, ledge, footing_lost, t if sensed.touching else state.touched_at,
    )  # fmt: skip


def crush_limit(state: State, mass: float, config: ControllerConfig) -> float:
    """The load from above (N) beyond which a body of ``mass`` (kg) in ``state`` is crushed:
    the crush threshold, and once crushed ``crush_release`` of it, so that a load swinging a
    little around the threshold crushes once instead of making the state flicker.

    >>> config = ControllerConfig()
    >>> round(crush_limit(GROUNDED, 70.0, config), 1), round(crush_limit(CRUSHED, 70.0, config), 1)
    (1500.0, 1200.0)
    """
    threshold = config.crush_threshold(mass)
    return threshold * config.crush_release if state is CRUSHED else threshold


def footing(
    sensed: Sensed, hit: GroundHit | None, rising: bool, current: State, config: ControllerConfig
) -> State:
    """The footing the probe's ``hit`` gives: GROUNDED on walkable ground (for a controller
    already ``current``-ly GROUNDED, up to :data:`SLOPE_BAND` steeper than ``max_slope``),
    SLIDING on ground too steep to stand on, AIRBORNE over none (or while ``rising``)."""
    if hit is None or rising:
        return AIRBORNE
    if hit.walkable:
        return GROUNDED
    nx, ny = hit.normal
    ux, uy = sensed.level
    cos_up = nx * ux + ny * uy
    if current is GROUNDED and cos_up >= math.cos(config.max_slope + SLOPE_BAND):
        return GROUNDED
    return SLIDING if cos_up > 0.0 else AIRBORNE


def steady(sensed: Sensed, config: ControllerConfig) -> bool:
    """Up again: the axis and the perceived up both within max_slope of the up used while
    getting up (after a fall the inner ear needs a moment before it is trusted again)."""
    ux, uy = sensed.up
    ax, ay = -sensed.body.sin, sensed.body.cos
    tilt = math.atan2(ax * uy - ay * ux, ax * ux + ay * uy)
    perceived = sensed.perceived_up
    if perceived is None:
        return False
    px, py = perceived
    return abs(tilt) < config.max_slope and px * ux + py * uy >= math.cos(config.max_slope)


def is_still(sensed: Sensed, hit: GroundHit | None, config: ControllerConfig) -> bool:
    """The body rests on the ground: slower than ``settle_speed`` and ``settle_spin``
    relative to it."""
    body = sensed.body
    gx, gy = hit.frame_velocity if hit is not None else (0.0, 0.0)
    spin = body.spin - (hit.spin if hit is not None else 0.0)
    return (
        math.hypot(body.vx - gx, body.vy - gy) < config.settle_speed
        and abs(spin) < config.settle_spin
    )
