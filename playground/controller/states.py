"""Deciding, the second part of a controller's step: the jump press, the grip, and the state
machine (:class:`State`) that says which forces act.

The functions here are the :class:`~playground.controller.controller.Controller`'s methods (it
binds them by name).

>>> State.GROUNDED.value
'grounded'
"""

from __future__ import annotations

import math
from enum import Enum
from typing import TYPE_CHECKING

from playground.controller._vec import ZERO
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller
    from playground.controller.sensing import GroundHit

__all__ = [
    "AIRBORNE",
    "CRUSHED",
    "GETTING_UP",
    "GROUNDED",
    "HANGING",
    "OFF_BALANCE",
    "State",
    "decide",
    "is_still",
    "lose_balance",
    "steady",
    "update_state",
]


class State(Enum):
    """What the controller is doing; the world, the view and tests read it."""

    GROUNDED = "grounded"
    AIRBORNE = "airborne"
    HANGING = "hanging"
    OFF_BALANCE = "off_balance"
    GETTING_UP = "getting_up"
    CRUSHED = "crushed"


# The members as module names, for the step: reading ``State.X`` goes through the enum's
# metaclass (~90 ns in Python 3.11, a module name ~10 ns), and a step reads a dozen of them.
GROUNDED = State.GROUNDED
AIRBORNE = State.AIRBORNE
HANGING = State.HANGING
OFF_BALANCE = State.OFF_BALANCE
GETTING_UP = State.GETTING_UP
CRUSHED = State.CRUSHED


def decide(self: Controller, world: World) -> None:
    """Register a new jump press, end the take-off once it stops rising, take or let go of a
    grip, and move the state machine on, from what :func:`~playground.controller.sensing.sense`
    has just read."""
    it = self.intent
    hit = self.probe
    ux, uy = self.up
    if it.jump and not self._jump_held:
        self._jump_pressed_at = world.time
    self._jump_held = it.jump

    gvx, gvy = hit.frame_velocity if hit is not None else ZERO
    v_up = (self._vx - gvx) * ux + (self._vy - gvy) * uy
    if self._rising and (v_up <= 0.0 or hit is None):
        self._rising = False

    self._update_grip(world, it)
    self._update_state(world, hit)


def update_state(self: Controller, world: World, hit: GroundHit | None) -> None:
    """Move the state machine on from what was sensed this step (``hit``: the probe's ground)."""
    cfg = self.config
    t = world.time
    state = self.state
    on_ground = hit is not None and hit.walkable and not self._rising
    if on_ground:
        self._last_ground = hit
    if state is OFF_BALANCE:
        if self._is_still(hit):
            self._still += world.config.dt
        else:
            self._still = 0.0
        if self._still >= cfg.settle_time and hit is not None:
            self.state = GETTING_UP
            self._getup_at = t
            self._getup_from = self._height(hit)
            self._saturated = 0.0
        return
    if state is GETTING_UP:
        if hit is None:
            self.state = AIRBORNE
        elif t - self._getup_at >= cfg.getup_time and self._steady(world):
            self.state = GROUNDED
            self._grounded_at = t
        return
    if self._saturated > cfg.balance_loss_time:
        self._lose_balance(world)
        return
    if self.joint is not None:
        self.state = HANGING
        return
    if self.load > cfg.crush_force and self.contact_load > 0.0:
        # Crushed: bearing more than crush_force from above with the load still on us (a
        # crusher held off at arm's length by the push no longer pins us).
        self.state = CRUSHED
    elif on_ground:
        self.state = GROUNDED
    else:
        self.state = AIRBORNE
    if self.state is not AIRBORNE and on_ground:
        self._grounded_at = t


def steady(self: Controller, world: World) -> bool:
    """Up again: the axis and the perceived up both within max_slope of the up used while
    getting up (after a fall the inner ear needs a moment before it is trusted again)."""
    ux, uy = self.up
    px, py = world.perceived_up(self.name)
    return abs(self.tilt) < self.config.max_slope and px * ux + py * uy >= self._cos_slope


def is_still(self: Controller, hit: GroundHit | None) -> bool:
    """The body rests on the ground: slower than ``settle_speed`` and ``settle_spin``
    relative to it."""
    cfg = self.config
    vx, vy = self._vx, self._vy
    gx, gy = hit.frame_velocity if hit is not None else ZERO
    spin = self.body.angular_velocity - (hit.body.angular_velocity if hit is not None else 0.0)
    return math.hypot(vx - gx, vy - gy) < cfg.settle_speed and abs(spin) < cfg.settle_spin


def lose_balance(self: Controller, world: World) -> None:
    """Fall over: let go of any grip; hover, drive and balance stop until it is still."""
    self._release(world)
    self.state = OFF_BALANCE
    self._still = 0.0
    self._saturated = 0.0
