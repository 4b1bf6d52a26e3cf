"""The force solver and the perceived-gravity filter on a plain pymunk space, for a game that keeps
its own space and its own loop (no :class:`~playground.world.World`).

:class:`ForceSensor` tracks bodies of any ``pymunk.Space``: it reads them around each
``space.step`` and recovers, by reverse integration, the force the engine put on each (contacts
and joints), and from it the 1€-filtered perceived gravity, the same numbers a world gives. It
serves few bodies in plain floats and many with ``pymunk.batch``, as the world does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pymunk

from playground._engine import raw
from playground.forces.ledger import ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.tracked import SCALAR_MAX_BODIES, TrackedSet
from playground.gravity import Perception
from playground.vec import Vec

__all__ = ["ForceSensor"]


@dataclass(frozen=True, slots=True)
class _Settings:
    """A sensor's settings as the tracked bodies read them (see
    :class:`~playground.forces.tracked.Settings`)."""

    contact_split: bool
    sleep_time: float
    """s: the space's ``sleep_time_threshold`` (∞: bodies never sleep)."""
    perception: Perception


class ForceSensor:
    """Engine forces and perceived gravity of chosen bodies of a plain pymunk space.

    Call :meth:`step` instead of ``space.step`` (it steps the space), or keep calling
    ``space.step`` yourself between :meth:`before_step` and :meth:`after_substep` (once after
    each ``space.step`` of the frame), then :meth:`finish`. Read :meth:`readings`,
    :meth:`perceived_gravity` and :meth:`perceived_up` after that. Forces you set on a body
    (``body.force``) count as applied, not as the engine's: the support a body reads is what its
    contacts and joints did. ``perception`` tunes the filter; ``contact_split`` also tells the
    contacts' part from the joints' (see :class:`~playground.forces.readings.BodyForces`).
    Gravity is the space's (``space.gravity``, m/s²), damping the space's.

    A 10 kg crate resting on the floor reads its weight, and feels g:

    >>> space = pymunk.Space()
    >>> space.gravity = (0.0, -9.81)                                             # m/s²
    >>> floor = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.05)  # m
    >>> crate = pymunk.Body(10.0, pymunk.moment_for_box(10.0, (1.0, 1.0)))        # kg, kg·m²
    >>> crate.position = (0.0, 0.55)                                             # m
    >>> space.add(floor, crate, pymunk.Poly.create_box(crate, (1.0, 1.0)))        # m
    >>> sensor = ForceSensor(space)
    >>> sensor.track(crate)
    >>> for _ in range(120):
    ...     sensor.step(1 / 60)                                                  # s
    >>> round(sensor.readings(crate).support[1], 1)  # N: m·g
    98.1
    >>> tuple(round(g, 2) for g in sensor.perceived_gravity(crate))  # m/s²
    (0.0, -9.81)

    With your own ``space.step`` calls (two substeps here):

    >>> sensor.before_step(2)
    >>> for _ in range(2):
    ...     space.step(1 / 120)                                                  # s
    ...     sensor.after_substep()
    >>> sensor.finish(1 / 60)                                                    # s
    >>> round(sensor.readings(crate).support[1], 1)  # N
    98.1
    """

    def __init__(
        self,
        space: pymunk.Space,
        *,
        perception: Perception | None = None,
        contact_split: bool = False,
    ) -> None:
        self.space = space
        self._space_h = raw.space_handle(space)
        self._settings = _Settings(
            contact_split=contact_split,
            sleep_time=space.sleep_time_threshold,
            perception=perception if perception is not None else Perception(),
        )
        self._tracked = TrackedSet(space, self._settings, self._replan)
        self._ledger = ForceLedger()
        self._dirty = True
        self._substeps = 1  # space.step calls the frame makes (before_step's argument)
        self._done = -1  # after_substep calls since before_step (-1: no frame begun)
        self._steps = 0  # space.step calls seen, for the contact split's stamps
        self._last_h = math.nan  # the length of the last space.step seen, s
        self._idle = True  # no body tracked this frame: nothing to read

    def _replan(self) -> None:
        self._dirty = True

    def track(self, body: pymunk.Body, *, perceive: bool = True) -> None:
        """Track a dynamic body of the space from the next step on; ``perceive`` also filters
        its perceived gravity.

        >>> space = pymunk.Space()
        >>> space.gravity = (0.0, -9.81)                               # m/s²
        >>> ball = pymunk.Body(1.0, 1.0)                               # kg, kg·m²
        >>> space.add(ball, pymunk.Circle(ball, 0.1))                  # m
        >>> sensor = ForceSensor(space)
        >>> sensor.track(ball)
        >>> sensor.step(1 / 60)                                        # s
        >>> sensor.readings(ball).valid, sensor.readings(ball).passive  # N: its weight
        (True, (0.0, -9.81))
        """
        if not isinstance(body, pymunk.Body) or body.space is not self.space:
            raise ValueError(f"body: expected a body of the sensor's space, got {body!r}")
        self._tracked.track(body, perceive)

    def untrack(self, body: pymunk.Body) -> None:
        """Stop tracking ``body`` (one not tracked is left alone). A tracked body taken out of
        the space with ``space.remove`` needs no call: the next :meth:`before_step` untracks
        it, and reading it then raises a ``KeyError`` that says it left."""
        if self._tracked.row_of(body) is not None:
            self._tracked.untrack(body)

    @property
    def bodies(self) -> list[pymunk.Body]:
        """The tracked bodies, in the order they were tracked (a copy)."""
        return list(self._tracked.bodies)

    # -- the step --------------------------------------------------------------------------------

    def step(self, dt: float, substeps: int = 1) -> None:
        """Step the space by ``dt`` seconds in ``substeps`` equal ``space.step`` calls, reading
        the tracked bodies around them.

        >>> space = pymunk.Space()
        >>> space.gravity = (0.0, -9.81)                         # m/s²
        >>> ball = pymunk.Body(1.0, 1.0)                         # kg, kg·m²
        >>> space.add(ball, pymunk.Circle(ball, 0.1))            # m
        >>> sensor = ForceSensor(space)
        >>> sensor.track(ball)
        >>> sensor.step(1 / 60, substeps=2)                      # s: two space.step of 1/120 s
        >>> round(ball.velocity.y, 6)                            # m/s: −g·dt
        -0.1635
        >>> tuple(round(f, 9) for f in sensor.readings(ball).support)  # N: nothing holds it
        (0.0, 0.0)
        """
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt: expected a finite number of seconds > 0, got {dt!r}")
        if not (isinstance(substeps, int) and substeps >= 1):
            raise ValueError(f"substeps: expected a whole number >= 1, got {substeps!r}")
        self.before_step(substeps)
        h = dt / substeps
        for _ in range(substeps):
            self.space.step(h)
            self.after_substep()
        self.finish(dt)

    def before_step(self, substeps: int = 1) -> None:
        """Read the tracked bodies before the frame's first ``space.step``; ``substeps``: how
        many ``space.step`` calls the frame makes (with more than one, the forces set on bodies
        before this call are written again before each later one, since pymunk clears them)."""
        if not (isinstance(substeps, int) and substeps >= 1):
            raise ValueError(f"substeps: expected a whole number >= 1, got {substeps!r}")
        tracked = self._tracked
        in_space = self.space.bodies  # a live view: membership is a dict look-up
        for body in [b for b in tracked.bodies if b not in in_space]:
            tracked.untrack(body)  # the game took it out of the space
        if self._dirty:
            tracked.plan(SCALAR_MAX_BODIES, True, substeps)
            self._dirty = False
        self._substeps = substeps
        self._done = 0
        self._last_h = raw.current_time_step(self._space_h)
        self._idle = not tracked.bodies
        if not self._idle:
            tracked.active.before_step(None, substeps)

    def after_substep(self) -> None:
        """Read the tracked bodies after one ``space.step`` of the frame."""
        if self._done < 0:
            raise RuntimeError("after_substep: call before_step before the frame's space.step")
        done = self._done + 1
        if done > self._substeps:
            raise RuntimeError(
                f"after_substep: called {done} times since before_step({self._substeps})"
            )
        self._done = done
        last = done == self._substeps
        h = raw.current_time_step(self._space_h)
        # Chipmunk rescales warm starts when a step's length differs from the one before.
        rescaled = self._settings.contact_split and h != self._last_h
        self._last_h = h
        self._steps += 1
        if self._idle:
            return
        active = self._tracked.active
        active.after_substep(last=last, stamp=self._steps, rescaled=rescaled)
        if not last:
            active.before_substep()  # for the next space.step: pymunk cleared the forces

    def finish(self, dt: float) -> None:
        """The frame's readings and perceived gravity, after its last ``space.step`` (``dt``:
        the frame's length, s, the sum of its steps)."""
        if self._done != self._substeps:
            raise RuntimeError(
                f"finish: {self._done} after_substep calls since before_step({self._substeps})"
            )
        self._done = -1  # a finished frame: after_substep and finish wait for before_step
        if self._idle:
            return
        tracked = self._tracked
        active = tracked.active
        active.finish(
            dt=dt,
            substeps=self._substeps,
            damping=self.space.damping,
            space_gravity=raw.gravity(self._space_h),
            ledger=self._ledger,
        )
        if tracked.perceivers:
            active.filter(dt, self._up_at)

    def _up_at(self, body: pymunk.Body) -> Vec:
        """A body's up until it has felt a reading: against the space's gravity."""
        gx, gy = raw.gravity(self._space_h)
        n = math.hypot(gx, gy)
        return (-gx / n, -gy / n) if n > 0.0 else (0.0, 1.0)

    # -- readings --------------------------------------------------------------------------------

    def _row(self, body: pymunk.Body) -> int:
        row = self._tracked.row_of(body)
        if row is None:
            if isinstance(body, pymunk.Body) and body.space is not self.space:
                raise KeyError(
                    f"{body!r}: not tracked, it is not in the sensor's space (a tracked body "
                    "taken out with space.remove is untracked at the next step)"
                )
            raise KeyError(f"{body!r}: not tracked (call sensor.track(body) first)")
        return row

    def readings(self, body: pymunk.Body) -> BodyForces:
        """The last readings of a tracked body: forces in N, what an accelerometer on it reads
        in m/s² (see :class:`~playground.forces.readings.BodyForces`). A force the game sets on
        the body counts as applied, not as support.

        >>> space = pymunk.Space()
        >>> ball = pymunk.Body(2.0, 1.0)                         # kg, kg·m²
        >>> space.add(ball, pymunk.Circle(ball, 0.1))            # m
        >>> sensor = ForceSensor(space)
        >>> sensor.track(ball)
        >>> ball.force = (4.0, 0.0)                              # N: the game's own push
        >>> sensor.step(1 / 60)                                  # s
        >>> readings = sensor.readings(ball)
        >>> readings.applied, readings.support, readings.specific  # N, N, m/s²
        ((4.0, 0.0), (0.0, 0.0), (0.0, 0.0))
        """
        return self._tracked.active.reading(self._row(body))

    def perceived_gravity(self, body: pymunk.Body) -> Vec:
        """The filtered perceived gravity of a tracked body, m/s²."""
        return self._tracked.active.perceived_gravity(self._row(body))

    def perceived_up(self, body: pymunk.Body) -> Vec:
        """Unit vector opposite the perceived gravity, held through weak readings."""
        return self._tracked.active.perceived_up(self._row(body))

    def table(self) -> TrackedReadings:
        """Every tracked body's last readings and perceived gravity as arrays (copies)."""
        return self._tracked.active.table()
