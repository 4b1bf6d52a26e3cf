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
    from playground.controller.ledge import Ledge
    from playground.controller.sensing import GroundHit

__all__ = [
    "AIRBORNE",
    "CLIMBING",
    "CRUSHED",
    "GETTING_UP",
    "GROUNDED",
    "HANGING",
    "OFF_BALANCE",
    "SLIDING",
    "SLOPE_BAND",
    "ControllerState",
    "State",
    "Transition",
]


class State(Enum):
    """What the controller is doing; the world, the view and tests read it, and a game picks
    its animation by it:

    - GROUNDED: on walkable ground, hover and drive acting: idle, or the walk/run cycle at the
      speed relative to the ground (``Controller.ground_velocity``). On stairs it stays
      GROUNDED up a flight (lifted onto the tread ahead) and down one, while it drops onto a
      tread within its step's reach (:mod:`~playground.controller.stairs`): the walk cycle
      over each step, not the fall.
    - SLIDING: on ground too steep to stand on (its normal beyond ``max_slope`` of up): the
      feet have no grip, so the hover holds it off the slope and it slides down, with no
      traction up it and no jump: the slide, crouched, facing down the slope.
    - AIRBORNE: no ground under it within the probe's reach (jumping, falling, or a step off
      an edge within ``coyote_time``, when a jump still works): the jump, or the fall.
    - HANGING: holding on with its hands (a body anywhere, or a ledge's edge) through the grip
      joint: the hang, a climb along the held body.
    - CLIMBING: pulling itself up onto a ledge and over its edge, its hands on the edge: the
      climb-up; it stands (GROUNDED) once its feet are over the top.
    - OFF_BALANCE: knocked over, lying or tumbling, no force of its own: the ragdoll.
    - GETTING_UP: rising back to its feet over ``getup_time``: the get-up.
    - CRUSHED: pinned under a load heavier than its ``crush_force``: the crouch under it.

    >>> State("grounded") is State.GROUNDED, State.CRUSHED.value
    (True, 'crushed')

    Between GROUNDED, SLIDING and AIRBORNE a better footing is taken at once (landing, or
    reaching walkable ground) and a worse one only once it has lasted ``footing_time`` (the
    probe losing the ground at the edge of its reach, a crest crossed at speed); ground a
    little steeper than ``max_slope`` (:data:`SLOPE_BAND`) still holds a GROUNDED controller:
    a signal near a threshold never makes the state flicker.
    """

    GROUNDED = "grounded"
    AIRBORNE = "airborne"
    HANGING = "hanging"
    OFF_BALANCE = "off_balance"
    GETTING_UP = "getting_up"
    CRUSHED = "crushed"
    CLIMBING = "climbing"
    SLIDING = "sliding"


# The members as module names, for the step: reading ``State.X`` goes through the enum's
# metaclass, a module name does not, and a step reads a dozen of them.
GROUNDED = State.GROUNDED
AIRBORNE = State.AIRBORNE
HANGING = State.HANGING
OFF_BALANCE = State.OFF_BALANCE
GETTING_UP = State.GETTING_UP
CRUSHED = State.CRUSHED
CLIMBING = State.CLIMBING
SLIDING = State.SLIDING

SLOPE_BAND = 0.035
"""rad (2°): how much steeper than ``max_slope`` the ground under a GROUNDED controller may
read before it slides: the probe's circle reads a surface's normal a hair either side of
``max_slope`` on a slope at it (and where two facets meet)."""


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
        rising: taking off, until it stops rising relative to the ground (to the world out of
            its reach: a jump up through a one-way platform does not stand on it rising).
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
        ledge: the ledge held by its edge or being climbed (None: none).
        footing_lost: how long the footing sensed has been worse than ``state`` (GROUNDED
            over none or too steep a ground, SLIDING over none), s: it changes at
            ``footing_time``.
        touched_at: when its body last touched anything (−∞: never).
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
    ledge: Ledge | None = None
    footing_lost: float = 0.0
    touched_at: float = -math.inf

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
