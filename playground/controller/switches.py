"""Gravity switches: an intent turns the controller's own gravity to a direction, restores it,
or nullifies another body's, each acting once per new intent value from the next step on.

:func:`switch` compares the intent with the values it asked for last step (kept in the
controller's :class:`~playground.controller.states.ControllerState`).
"""

from __future__ import annotations

from collections.abc import Callable

from playground.gravity import GravityRule
from playground.intents import Intent
from playground.vec import Vec
from playground.world.world import World

__all__ = ["next_step", "switch"]


def switch(
    world: World,
    name: str,
    intent: Intent,
    gravity_wish: Vec | None,
    nullify_wish: str | None,
) -> None:
    """Act on the gravity switches of ``intent`` for the body ``name``: a new value (a held
    intent acts once; ``gravity_wish`` and ``nullify_wish`` are last step's values) changes a
    rule from the next step on. This step's gravity was applied before the controllers run,
    and every controller (the nullified one included, whether it runs before or after us)
    must read the gravity that acts in its step."""
    if intent.restore_gravity:
        if not world.gravity_rule(name).is_default:
            next_step(world, lambda w: w.set_gravity_rule(name, None))
    elif intent.gravity is not None and intent.gravity != gravity_wish:
        rule = GravityRule(direction=intent.gravity)
        next_step(world, lambda w: w.set_gravity_rule(name, rule))
    target = intent.nullify
    if target is not None and target != nullify_wish:
        next_step(world, lambda w: w.set_gravity_rule(target, GravityRule(scale=0.0)))


def next_step(world: World, change: Callable[[World], None]) -> None:
    """Run ``change`` in the EVENTS stage of the next step, before its gravity is applied."""
    world.at(world.time + 0.5 * world.config.dt, change)
