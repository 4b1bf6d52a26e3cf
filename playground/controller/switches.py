"""Gravity switches: an intent turns the controller's own gravity to a direction, restores it,
or nullifies another body's, each acting once per new intent value from the next step on.

:func:`gravity_actions` is the :class:`~playground.controller.controller.Controller`'s method
``_gravity_actions`` (it binds it by name).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from playground.gravity import GravityRule
from playground.intents import Intent
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["gravity_actions", "next_step"]


def gravity_actions(self: Controller, world: World, it: Intent) -> None:
    """Gravity switches act on a new intent value (a held intent acts once), from the next
    step on: this step's gravity was applied before the controllers run, and every controller
    (the nullified one included, whether it runs before or after us) must read the gravity
    that acts in its step."""
    name = self.name
    if it.restore_gravity:
        if not world.gravity_rule(name).is_default:
            next_step(world, lambda w: w.set_gravity_rule(name, None))
    elif it.gravity is not None and it.gravity != self._gravity_wish:
        rule = GravityRule(direction=it.gravity)
        next_step(world, lambda w: w.set_gravity_rule(name, rule))
    self._gravity_wish = it.gravity
    target = it.nullify
    if target is not None and target != self._nullify_wish:
        next_step(world, lambda w: w.set_gravity_rule(target, GravityRule(scale=0.0)))
    self._nullify_wish = it.nullify


def next_step(world: World, change: Callable[[World], None]) -> None:
    """Run ``change`` in the EVENTS stage of the next step, before its gravity is applied."""
    world.at(world.time + 0.5 * world.config.dt, change)
