"""The schedule: the stages of a step, the hooks that run in them and the timed events.

Scripts, controllers and observers hook into four stages (INPUTS, EVENTS, CONTROL, OBSERVE);
events run once, in the EVENTS stage of the first step at or after their time. Each stage can be
timed (:class:`StageTiming`). The world steps through the stages in the order of :class:`Stage`.

>>> schedule = Schedule(replan=lambda: None)
>>> def count(world: object) -> None: ...
>>> schedule.on(Stage.OBSERVE, count)
>>> schedule.observers == [count]
True
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import Enum
from typing import TYPE_CHECKING

from playground.params import finite

if TYPE_CHECKING:
    from playground.world.world import World

__all__ = ["EVENT_EARLY", "Hook", "Schedule", "Stage", "StageTiming", "run_hooks"]

Hook = Callable[["World"], None]

EVENT_EARLY = 1e-12
"""s: an event is due when its time is at most this much after the step's start, so an event
scheduled at a time a sum of steps reaches with rounding error still runs in that step."""


class Stage(Enum):
    """The stages of one step, in the order they run."""

    INPUTS = 1
    EVENTS = 2
    GRAVITY = 3
    MOVERS = 4
    CONTROL = 5
    PHYSICS = 6
    FORCES = 7
    FILTER = 8
    OBSERVE = 9


@dataclass(slots=True)
class StageTiming:
    """Wall-clock cost of one stage: total seconds, calls, and the last call's seconds."""

    total: float = 0.0
    calls: int = 0
    last: float = 0.0

    @property
    def mean(self) -> float:
        """Mean seconds per call."""
        return self.total / self.calls if self.calls else 0.0


_HOOK_LISTS = {
    Stage.INPUTS: "inputs",
    Stage.EVENTS: "event_hooks",
    Stage.CONTROL: "controls",
    Stage.OBSERVE: "observers",
}
"""The Schedule attribute holding each stage's hooks."""


def run_hooks(hooks: list[Hook], world: World) -> None:
    """Run each hook on the world, in the order they were added."""
    for hook in hooks:
        hook(world)


class Schedule:
    """The hooks of each hook stage and the pending timed events (a heap: the next one first).

    ``replan`` is called whenever the schedule changes: a step that had nothing to run may now
    have something, and the other way round.
    """

    def __init__(self, replan: Callable[[], None]) -> None:
        self._replan = replan
        # One plain list per hook stage (not a dict keyed by Stage: an Enum's hash is Python code
        # and the step checks these every time).
        self.inputs: list[Hook] = []
        self.event_hooks: list[Hook] = []
        self.controls: list[Hook] = []
        self.observers: list[Hook] = []
        # A binary heap keyed by (time, scheduling order): the next event is events[0], and
        # scheduling or running one costs O(log n). The order is a counter that never goes back,
        # so events at the same time run in the order they were scheduled, whatever ran before.
        self.events: list[tuple[float, int, Hook]] = []
        self._order = itertools.count()

    @staticmethod
    def check(stage: Stage) -> None:
        """Refuse a stage hooks do not run in (the world's own stages)."""
        if stage not in _HOOK_LISTS:
            raise ValueError(f"stage: hooks run in INPUTS, EVENTS, CONTROL or OBSERVE, not {stage}")

    def on(self, stage: Stage, hook: Hook) -> None:
        """Run ``hook(world)`` every step in ``stage`` (INPUTS, EVENTS, CONTROL or OBSERVE)."""
        self.check(stage)
        self._hooks(stage).append(hook)
        self._replan()

    def off(self, stage: Stage, hook: Hook) -> None:
        """Stop running ``hook`` in ``stage``; the stage that is running finishes with the hooks
        it started with.

        >>> schedule = Schedule(replan=lambda: None)
        >>> def count(world: object) -> None: ...
        >>> schedule.on(Stage.OBSERVE, count)
        >>> schedule.off(Stage.OBSERVE, count)
        >>> schedule.off(Stage.OBSERVE, count)
        Traceback (most recent call last):
        ...
        ValueError: hook: count is not registered in OBSERVE
        """
        hooks = self._hooks(stage)
        if hook not in hooks:
            name = getattr(hook, "__name__", repr(hook))
            raise ValueError(f"hook: {name} is not registered in {stage.name}")
        kept = list(hooks)  # a new list: a step iterating the old one is not disturbed
        kept.remove(hook)
        setattr(self, _HOOK_LISTS[stage], kept)
        self._replan()

    def replace(self, stage: Stage, old: Sequence[Hook], new: Sequence[Hook]) -> bool:
        """Put ``new`` in the place of ``old``, hooks of ``stage`` that run one right after
        another in that order (whoever swaps them makes ``new`` run what ``old`` ran); False,
        and nothing changes, if they do not. The stage that is running finishes with the hooks
        it started with.

        >>> schedule = Schedule(replan=lambda: None)
        >>> def a(world: object) -> None: ...
        >>> def b(world: object) -> None: ...
        >>> def ab(world: object) -> None: ...
        >>> for hook in (a, b):
        ...     schedule.on(Stage.INPUTS, hook)
        >>> schedule.replace(Stage.INPUTS, [b, a], [ab])
        False
        >>> schedule.replace(Stage.INPUTS, [a, b], [ab]), schedule.inputs == [ab]
        (True, True)
        """
        hooks = self._hooks(stage)
        if not old or old[0] not in hooks:
            return False
        at = hooks.index(old[0])
        if hooks[at : at + len(old)] != list(old):
            return False
        setattr(self, _HOOK_LISTS[stage], [*hooks[:at], *new, *hooks[at + len(old) :]])
        self._replan()
        return True

    def _hooks(self, stage: Stage) -> list[Hook]:
        hooks: list[Hook] = getattr(self, _HOOK_LISTS[stage])
        return hooks

    def at(self, t: float, event: Hook) -> None:
        """Run ``event(world)`` once, in the EVENTS stage of the first step starting at or after
        ``t`` (s). Events at the same time run in the order they were scheduled."""
        finite("t", t)
        heapq.heappush(self.events, (t, next(self._order), event))
        self._replan()

    def run_events(self, world: World) -> None:
        """The EVENTS stage: the events due at the world's time, then the event hooks."""
        events = self.events
        while events and events[0][0] <= world.time + EVENT_EARLY:
            _, _, event = heapq.heappop(events)
            event(world)
            self._replan()
        for hook in self.event_hooks:
            hook(world)
