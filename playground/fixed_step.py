"""The fixed step for a game loop: a display frame's time into whole physics steps of the world's
dt, the fraction of a step left over for drawing between steps, and a cap on steps per frame.

Chapter 8 (docs/chapters/08-fixed-step.md) explains why the physics must not follow the display.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

__all__ = ["FixedStep", "FrameSteps"]

STEP_TOLERANCE = 1e-9
"""Fraction of a step that still counts as a whole one: frame times are sums of floats, and
0.025 s at dt = 0.01 s must run 2 steps, not 1 and a bank of 0.00999… s."""


class _Config(Protocol):
    @property
    def dt(self) -> float: ...


class Steppable(Protocol):
    """What :class:`FixedStep` drives: a :class:`~playground.World`, or anything with a ``step()``
    and a ``config.dt`` (s)."""

    @property
    def config(self) -> _Config: ...

    def step(self) -> None: ...


@dataclass(frozen=True, slots=True)
class FrameSteps:
    """What one frame's :meth:`FixedStep.advance` did."""

    steps: int
    """Physics steps taken this frame (0 when the frame was shorter than what the bank lacks)."""
    alpha: float
    """Fraction of a step the bank holds after them, 0 ≤ alpha < 1: draw each body at
    ``previous + alpha·(current − previous)`` for motion as smooth as the display."""
    dropped: float
    """Time dropped because the frame needed more than the cap's steps, s (0.0 normally)."""


class FixedStep:
    """Steps a world at its fixed dt from a game loop that runs at the display's rate.

    Each frame, :meth:`advance` adds the frame's time to a bank, takes as many whole steps of dt
    as it holds and keeps the rest for the next frame. At most ``max_steps_per_frame`` steps are
    taken in a frame, and the time beyond them is dropped, because of the *spiral of death*: when
    a step costs more wall time than dt (a slow machine, a big level), every frame banks more time
    than it can step, the next frame must take more steps and so lasts longer still, and the game
    freezes. With the cap the game slows down instead, and a hitch (a 2 s pause at a breakpoint)
    costs one capped frame, not two seconds of catching up.

    >>> from playground import World
    >>> world = World()                       # dt = 1/120 s
    >>> clock = FixedStep(world, max_steps_per_frame=8)
    >>> clock.advance(1 / 60)                 # a 60 Hz frame: two steps, nothing left over
    FrameSteps(steps=2, alpha=0.0, dropped=0.0)
    >>> [clock.advance(1 / 144).steps for _ in range(6)]   # a 144 Hz display: some frames none
    [0, 1, 1, 1, 1, 1]
    >>> frame = clock.advance(0.5)            # a hitch: 60 steps' worth, 8 taken
    >>> frame.steps, round(frame.dropped, 4)  # s dropped
    (8, 0.4333)
    """

    def __init__(self, world: Steppable, max_steps_per_frame: int = 8) -> None:
        dt = world.config.dt
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"world.config.dt: expected a number of seconds > 0, got {dt!r}")
        if isinstance(max_steps_per_frame, bool) or not isinstance(max_steps_per_frame, int):
            raise ValueError(
                f"max_steps_per_frame: expected a whole number ≥ 1, got {max_steps_per_frame!r}"
            )
        if max_steps_per_frame < 1:
            raise ValueError(
                f"max_steps_per_frame: expected a whole number ≥ 1, got {max_steps_per_frame!r}"
            )
        self.world = world
        self.dt = dt
        """The world's step, s (read once: a fixed step does not change under a running clock)."""
        self.max_steps_per_frame = max_steps_per_frame
        self._bank = 0.0

    @property
    def bank(self) -> float:
        """Time banked toward the next step, s (0 ≤ bank < dt between frames)."""
        return self._bank

    def advance(self, frame_seconds: float) -> FrameSteps:
        """Add one frame's time (s, ≥ 0) to the bank and step the world as many whole dt as it
        holds, at most ``max_steps_per_frame`` times; return what was done.

        >>> from playground import World
        >>> clock = FixedStep(World())
        >>> clock.advance(-0.1)
        Traceback (most recent call last):
        ...
        ValueError: frame_seconds: expected a finite number of seconds ≥ 0, got -0.1
        """
        if not (isinstance(frame_seconds, int | float) and math.isfinite(frame_seconds)) or (
            frame_seconds < 0.0
        ):
            raise ValueError(
                f"frame_seconds: expected a finite number of seconds ≥ 0, got {frame_seconds!r}"
            )
        dt = self.dt
        bank = self._bank + frame_seconds
        due = int((bank + STEP_TOLERANCE * dt) // dt)
        steps = min(due, self.max_steps_per_frame)
        bank = max(bank - due * dt, 0.0)
        dropped = (due - steps) * dt
        for _ in range(steps):
            self.world.step()
        self._bank = bank
        return FrameSteps(steps=steps, alpha=bank / dt, dropped=dropped)

    def reset(self) -> None:
        """Empty the bank (after a pause, a level restart): the next frame starts from zero."""
        self._bank = 0.0
