"""Laws of the controller's state between steps: a new controller is airborne with nothing
pressed or held; a take-off step's forces follow the state it leaves; every change of state in
a step is observable as one :class:`Transition` value."""

from __future__ import annotations

import math

from playground import Controller, Intent, Script, State, World
from playground.controller import ControllerState, Transition


def test_a_new_state_is_airborne_with_nothing_pressed_or_held() -> None:
    state = ControllerState()
    assert state.state is State.AIRBORNE
    assert state.jump_pressed_at == -math.inf and state.grounded_at == -math.inf
    assert state.grip is None and state.take_off_from is None
    assert state.footing is State.AIRBORNE


def test_the_footing_is_the_state_a_take_off_leaves() -> None:
    """On the take-off step the state is airborne, while its forces follow the grounded state
    (the take-off step still carries the weight)."""
    state = ControllerState(state=State.AIRBORNE, take_off_from=State.GROUNDED)
    assert state.footing is State.GROUNDED


def test_landing_and_jumping_are_one_transition_each() -> None:
    """A player dropped onto a floor lands (airborne → grounded) once, at the step it lands,
    and a jump later takes off (grounded → airborne) once: the controller reports each change
    of state as a Transition of that step, and None on the steps between."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    player = Controller(
        world, "p", (0.0, 1.5), source=Script(((0.0, Intent()), (1.5, Intent(jump=True))))
    )
    seen: list[Transition] = []
    for _ in range(round(2.0 / world.config.dt)):
        world.step()
        if player.transition is not None:
            seen.append(player.transition)
            assert player.transition.after is player.state
    pairs = [(t.before, t.after) for t in seen]
    assert pairs[0] == (State.AIRBORNE, State.GROUNDED)
    assert (State.GROUNDED, State.AIRBORNE) in pairs
    take_off = next(t for t in seen if t.before is State.GROUNDED)
    assert 1.5 <= take_off.time < 1.5 + 2.0 * world.config.dt
