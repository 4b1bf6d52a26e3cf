"""Intents: what a player or an enemy wants to do this step, as plain values.

A controller never reads the keyboard. Something that implements :class:`IntentSource` (a scripted
:class:`Script`, a :class:`Patrol` enemy, :class:`Idle`, or the view's keyboard) says what it wants
at time ``t``; the controller turns that into forces within its budgets.

>>> script = Script(((0.0, Intent()), (1.0, Intent(move=1.0)), (2.0, Intent(jump=True))))
>>> script.intent(1.5).move, script.intent(2.5).jump
(1.0, True)
"""

from __future__ import annotations

import functools
from bisect import bisect_right
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from playground.params import check, finite, param, unit

__all__ = ["Idle", "Intent", "IntentSource", "Patrol", "Script"]


@dataclass(frozen=True, slots=True)
class Intent:
    """One step's wishes. Held values (``grab``, ``push``) act while True.

    ``move`` (−1 … 1, a fraction of the controller's ``max_speed``, no unit) +1 is "right" when
    facing with up = up (the tangent is up rotated by −90°); ``climb`` (−1 … 1 of
    ``climb_speed``) moves the grip along the held body; a ``jump`` press is remembered for the
    controller's jump buffer (``jump_buffer``, s); a ``gravity`` direction (no unit) is
    unit-ised.

    >>> wish = Intent(move=-0.5, jump=True)   # walk left at half the top speed, and jump
    >>> wish.move, wish.jump, wish.grab
    (-0.5, True, False)

    >>> Intent(gravity=(0.0, 2.0)).gravity
    (0.0, 1.0)
    >>> Intent(move=2.0)
    Traceback (most recent call last):
    ...
    ValueError: move: expected a number in [-1, 1], got 2.0
    """

    move: float = param(0.0, doc="Move along the ground tangent, −1 … 1.", ge=-1.0, le=1.0)
    jump: bool = param(False, doc="Wants to jump.")
    grab: bool = param(False, doc="Held: grab and hang on what the hands touch; released: let go.")
    push: bool = param(False, doc="Held: push the body in contact, within the push budget.")
    climb: float = param(0.0, doc="Move the grip along the held body, −1 … 1.", ge=-1.0, le=1.0)
    gravity: tuple[float, float] | None = param(
        None,
        doc="Own gravity direction (any length); none: no change.",
        nonzero=True,
    )
    restore_gravity: bool = param(False, doc="Own gravity back to the field's.")
    nullify: str | None = param(None, doc="Body whose gravity to nullify; none: nobody.")

    def __post_init__(self) -> None:
        check(self)
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

    The ``speed`` is a fraction of the controller's max speed.

    >>> p = Patrol(speed=0.5, period=4.0)
    >>> p.intent(1.0).move, p.intent(3.0).move
    (0.5, -0.5)
    """

    speed: float = param(0.5, doc="Move input, 0 … 1.", ge=0.0, le=1.0)
    period: float = param(4.0, doc="One walk there and back.", unit="s", gt=0.0)
    # Its two intents, made once (intents are frozen): a step only picks one. Not parameters.
    _there: Intent = field(default=IDLE, init=False, repr=False, compare=False)
    _back: Intent = field(default=IDLE, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        check(self)
        object.__setattr__(self, "_there", _moving(self.speed))
        object.__setattr__(self, "_back", _moving(-self.speed))

    def intent(self, t: float) -> Intent:
        phase = (t % self.period) / self.period
        return self._there if phase < 0.5 else self._back


@functools.lru_cache(maxsize=64)
def _moving(move: float) -> Intent:
    """The intent to move at ``move`` (intents are frozen: one serves every step)."""
    return Intent(move=move)
