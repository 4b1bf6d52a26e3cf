"""The capsule player controller: hover, drive, balance, jump, grab, push — all relative to up.

A :class:`Controller` is a dynamic capsule that moves only through forces, within budgets. Its
"up" is the filtered perceived gravity while it is supported and the gravity field at the body
while airborne, so the same code works on a floor, a ceiling, a planet or inside a spinning ring.
Every force goes through ``world.apply_forces`` with its category, so the solver's support force
and perceived gravity stay right. An enemy is the same controller with another intent source.

Each step reads sense → decide → act: :mod:`~playground.controller.sensing` (:class:`Sensed`),
:mod:`~playground.controller.decision` (:class:`ControllerState`, in
:mod:`~playground.controller.states`), :mod:`~playground.controller.action`
(:class:`ControllerForces`) through the force laws of :mod:`~playground.controller.laws`
(:class:`Laws`); :mod:`~playground.controller.grab` and :mod:`~playground.controller.switches`
put grips and gravity switches into the world; :mod:`~playground.controller.config` holds the
configuration and :mod:`~playground.controller.spring` the hover spring's maths.

>>> from playground.world import World
>>> world = World()
>>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
>>> player = Controller(world, "player", position=(0.0, 1.0))
>>> world.run(2.0)
>>> player.state.value, round(player.probe.distance, 3)
('grounded', 0.95)
"""

from playground.controller.action import ControllerForces
from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.laws import Laws
from playground.controller.sensing import GroundHit, Sensed
from playground.controller.spring import hover_limit, hover_spring
from playground.controller.states import ControllerState, State, Transition

__all__ = [
    "Controller",
    "ControllerConfig",
    "ControllerForces",
    "ControllerState",
    "GroundHit",
    "Laws",
    "Sensed",
    "State",
    "Transition",
    "hover_limit",
    "hover_spring",
]
