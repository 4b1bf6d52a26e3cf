"""The capsule player controller: hover, drive, balance, jump, grab, push — all relative to up.

A :class:`Controller` is a dynamic capsule that moves only through forces, within budgets. Its
"up" is the filtered perceived gravity while it is supported and the gravity field at the body
while airborne, so the same code works on a floor, a ceiling, a planet or inside a spinning ring.
Every force goes through ``world.apply_force`` with its category, so the solver's support force and
perceived gravity stay right. An enemy is the same controller with another intent source.

Each step reads sense → decide → act: :mod:`~playground.controller.sensing`,
:mod:`~playground.controller.states` and :mod:`~playground.controller.grab`, then
:mod:`~playground.controller.laws` and :mod:`~playground.controller.switches`;
:mod:`~playground.controller.config` holds the configuration and
:mod:`~playground.controller.spring` the hover spring's maths.

>>> from playground.world import World
>>> world = World()
>>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
>>> player = Controller(world, "player", position=(0.0, 1.0))
>>> world.run(2.0)
>>> player.state.value, round(player.probe.distance, 3)
('grounded', 0.95)
"""

from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.laws import ControllerForces
from playground.controller.sensing import GroundHit
from playground.controller.spring import hover_limit, hover_spring
from playground.controller.states import State

__all__ = [
    "Controller",
    "ControllerConfig",
    "ControllerForces",
    "GroundHit",
    "State",
    "hover_limit",
    "hover_spring",
]
