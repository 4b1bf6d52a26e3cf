"""Intents: what a player or an enemy wants to do this step, as plain values.

A controller never reads the keyboard. Something that implements :class:`IntentSource` (a scripted
:class:`Script`, a :class:`Patrol` enemy, :class:`Idle`, or the view's keyboard) says what it wants
at time ``t``; the controller turns that into forces within its budgets.

>>> script = Script(((0.0, Intent()), (1.0, Intent(move=1.0)), (2.0, Intent(jump=True))))
>>> script.intent(1.5).move, script.intent(2.5).jump
(1.0, True)
"""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from playground._validate import finite, positive, unit

__all__ = ["Idle", "Intent", "IntentSource", "Patrol", "Script"]


def _unit_range(name: str, value: float) -> None:
    finite(name, value)
    if not -1.0 <= value <= 1.0:
        raise ValueError(f"{name}: expected a number in [-1, 1], got {value!r}")


@dataclass(frozen=True, slots=True)
class Intent:
    """One step's wishes. Held values (``grab``, ``push``) act while True.

    Attributes:
        move: −1 … 1 along the ground tangent; +1 is "right" when facing with up = up (the
            tangent is up rotated by −90°).
        jump: wants to jump (a press is remembered for the controller's jump buffer).
        grab: held: grab and hang on what the hands touch; released: let go.
        push: held: push the body in contact, within the push budget.
        climb: −1 … 1: move the grip along the held body.
        gravity: switch one's own gravity to this direction (unit-ised); None: no change.
        restore_gravity: back to the field.
        nullify: name of a body whose gravity to nullify (scale 0); None: nobody.

    >>> Intent(gravity=(0.0, 2.0)).gravity
    (0.0, 1.0)
    >>> Intent(move=2.0)
    Traceback (most recent call last):
    ...
    ValueError: move: expected a number in [-1, 1], got 2.0
    """

    move: float = 0.0
    jump: bool = False
    grab: bool = False
    push: bool = False
    climb: float = 0.0
    gravity: tuple[float, float] | None = None
    restore_gravity: bool = False
    nullify: str | None = None

    def __post_init__(self) -> None:
        _unit_range("move", self.move)
        _unit_range("climb", self.climb)
        if self.gravity is not None:
            object.__setattr__(self, "gravity", unit("gravity", self.gravity))
        if self.nullify is not None and not isinstance(self.nullify, str):
            raise ValueError(f"nullify: expected a body name or None, got {self.nullify!r}")


IDLE = Intent()
"""The intent to do nothing."""


@runtime_checkable
class IntentSource(Protocol):
    """Anything that says what it wants at time ``t`` (s)."""

    def intent(self, t: float) -> Intent: ...


@dataclass(frozen=True, slots=True)
class Idle:
    """Wants nothing, ever.

    >>> Idle().intent(3.0) == Intent()
    True
    """

    def intent(self, t: float) -> Intent:
        return IDLE


@dataclass(frozen=True, slots=True)
class Script:
    """A scripted input timeline: ``(t seconds, Intent)`` keys, sorted by time.

    The intent in force at ``t`` is the one of the last key with key time <= t; before the first
    key it is the idle intent.

    >>> Script(((1.0, Intent(push=True)),)).intent(0.5).push
    False
    """

    timeline: tuple[tuple[float, Intent], ...]
    _times: tuple[float, ...] = field(default=(), repr=False, compare=False)

    def __init__(self, timeline: tuple[tuple[float, Intent], ...]) -> None:
        timeline = tuple((float(t), i) for t, i in timeline)
        for k, (t, i) in enumerate(timeline):
            finite(f"timeline[{k}] time", t)
            if not isinstance(i, Intent):
                raise ValueError(f"timeline[{k}]: expected an Intent, got {i!r}")
            if k and t < timeline[k - 1][0]:
                raise ValueError(
                    f"timeline[{k}]: expected times sorted ascending, got {t} after "
                    f"{timeline[k - 1][0]}"
                )
        object.__setattr__(self, "timeline", timeline)
        object.__setattr__(self, "_times", tuple(t for t, _ in timeline))

    def intent(self, t: float) -> Intent:
        k = bisect_right(self._times, t)
        return self.timeline[k - 1][1] if k else IDLE


@dataclass(frozen=True, slots=True)
class Patrol:
    """A simple enemy: walks one way for ``period / 2`` seconds, then the other, forever.

    Attributes:
        speed: magnitude of the move axis, 0 … 1 (a fraction of the controller's max speed).
        period: time for one walk there and back, s.

    >>> p = Patrol(speed=0.5, period=4.0)
    >>> p.intent(1.0).move, p.intent(3.0).move
    (0.5, -0.5)
    """

    speed: float = 0.5
    period: float = 4.0

    def __post_init__(self) -> None:
        finite("speed", self.speed)
        if not 0.0 <= self.speed <= 1.0:
            raise ValueError(f"speed: expected a number in [0, 1], got {self.speed!r}")
        positive("period", self.period)

    def intent(self, t: float) -> Intent:
        phase = (t % self.period) / self.period
        return Intent(move=self.speed if phase < 0.5 else -self.speed)
