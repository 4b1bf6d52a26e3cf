"""The controller's state between steps: what its state machine is doing (:class:`State`), its
timers, the grip it holds, the ground it last stood on (:class:`ControllerState`), and a change
of state as a value (:class:`Transition`).

:func:`~playground.controller.decision.decide` takes one :class:`ControllerState` and returns
the next; nothing else writes one.

>>> State.GROUNDED.value
'grounded'
>>> ControllerState().state
<State.AIRBORNE: 'airborne'>
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum
from typing import TYPE_CHECKING

from playground.vec import Vec

if TYPE_CHECKING:
    from playground.controller.grab import Grip
    from playground.controller.sensing import GroundHit

__all__ = [
    "AIRBORNE",
    "CRUSHED",
    "GETTING_UP",
    "GROUNDED",
    "HANGING",
    "OFF_BALANCE",
    "ControllerState",
    "State",
    "Transition",
]


class State(Enum):
    """What the controller is doing; the world, the view and tests read it.

    >>> State("grounded") is State.GROUNDED, State.CRUSHED.value
    (True, 'crushed')
    """

    GROUNDED = "grounded"
    AIRBORNE = "airborne"
    HANGING = "hanging"
    OFF_BALANCE = "off_balance"
    GETTING_UP = "getting_up"
    CRUSHED = "crushed"


# The members as module names, for the step: reading ``State.X`` goes through the enum's
# metaclass, a module name does not, and a step reads a dozen of them.
GROUNDED = State.GROUNDED
AIRBORNE = State.AIRBORNE
HANGING = State.HANGING
OFF_BALANCE = State.OFF_BALANCE
GETTING_UP = State.GETTING_UP
CRUSHED = State.CRUSHED


@dataclass(slots=True)
class ControllerState:
    """What a controller carries from one step to the next (times in s of world time).

    A plain value, read-only by convention: :func:`~playground.controller.decision.decide`
    builds a new one every step (not frozen: a frozen dataclass is dearer to build, through
    ``object.__setattr__`` per field; docs/performance.md, plain_dataclass).

    Attributes:
        state: what the state machine is doing.
        jump_held: the jump intent was held last step (a press is its rising edge).
        jump_pressed_at: when the jump was last pressed and not yet used (−∞: none).
        grounded_at: when the controller last stood on walkable ground (−∞: it jumped since).
        rising: taking off, until it stops rising relative to the ground or loses it.
        last_ground: the walkable ground it last stood on (a coyote jump pushes off it).
        saturated: how long the balance has needed more than its budget while touching.
        still: how long it has lain still while off balance.
        relieved: how long a crushed controller's load has stayed at most ``crush_force``.
        getup_at: when it started getting up.
        getup_from: its height over the ground then, m.
        grip: the grip held (None: none).
        take_off_from: the state a take-off this step leaves (None: no take-off). The take-off
            step still carries the weight: its forces follow this state, not ``state``.
        gravity_wish: the own-gravity direction the intent asked for last step.
        nullify_wish: the body whose gravity the intent nullified last step.
    """

    state: State = AIRBORNE
    jump_held: bool = False
    jump_pressed_at: float = -math.inf
    grounded_at: float = -math.inf
    rising: bool = False
    last_ground: GroundHit | None = None
    saturated: float = 0.0
    still: float = 0.0
    relieved: float = 0.0
    getup_at: float = 0.0
    getup_from: float = 0.0
    grip: Grip | None = None
    take_off_from: State | None = None
    gravity_wish: Vec | None = None
    nullify_wish: str | None = None

    @property
    def footing(self) -> State:
        """The state whose forces act this step: the one a take-off leaves, else ``state``."""
        return self.state if self.take_off_from is None else self.take_off_from


@dataclass(frozen=True, slots=True)
class Transition:
    """A change of the controller's state in one step: at world ``time`` (s), from ``before``
    to ``after`` (the view, recordings and gameplay events read it).

    >>> Transition(1.5, State.GROUNDED, State.AIRBORNE).after.value
    'airborne'
    """

    time: float
    before: State
    after: State
