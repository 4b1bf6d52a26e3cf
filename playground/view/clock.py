"""The view's clock: wall time into whole physics steps of the level's dt (a fixed-step
accumulator), and the speeds the view runs at.

Physics and rendering are independent: each frame adds its wall time (× the speed factor) to an
accumulator and runs as many whole physics steps as fit; drawing only reads the world.

>>> acc = Accumulator(dt=0.01)
>>> acc.advance(0.025), acc.advance(0.006), acc.advance(0.0, speed=2.0)
(2, 1, 0)
"""

from __future__ import annotations

import math

__all__ = ["HEADLESS_FRAME", "MAX_STEPS_PER_FRAME", "SPEEDS", "Accumulator"]

MAX_STEPS_PER_FRAME = 32  # physics steps run at most per frame; beyond that the view falls behind
SPEEDS = (0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0)  # slow motion … fast forward, × real time
HEADLESS_FRAME = 1.0 / 60.0  # s of wall time a headless frame stands for


class Accumulator:
    """Turns wall time into whole physics steps of ``dt`` seconds (a fixed-step accumulator)."""

    def __init__(self, dt: float, max_steps: int = MAX_STEPS_PER_FRAME) -> None:
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt: expected a number of seconds > 0, got {dt!r}")
        self.dt = dt
        self.max_steps = max_steps
        self._acc = 0.0

    def advance(self, elapsed: float, speed: float = 1.0) -> int:
        """Add ``elapsed`` s of wall time at ``speed`` × and return the steps to run now."""
        self._acc += max(elapsed, 0.0) * speed
        # A small tolerance so 0.025 s at dt 0.01 gives 2 steps, not 1 because of rounding.
        n = int((self._acc + 1e-9 * self.dt) // self.dt)
        if n > self.max_steps:
            n = self.max_steps
            self._acc = 0.0
        else:
            self._acc -= n * self.dt
        return n

    def reset(self) -> None:
        self._acc = 0.0
