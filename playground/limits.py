"""Plausible ranges: the magnitudes a game-scale scene may use, each with the reason for its bound.

The level format, the world's public methods and the runtime guard refuse numbers outside these
ranges with an error naming the argument, instead of handing them to pymunk (which aborts the
process on some, and carries NaN or ∞ through every later step on others). SI units throughout.

>>> MAX_COORDINATE * MAX_ZOOM < 2**31
True
"""

from __future__ import annotations

__all__ = [
    "MAX_ACCELERATION",
    "MAX_ANGLE",
    "MAX_ANGULAR_SPEED",
    "MAX_COORDINATE",
    "MAX_DT",
    "MAX_FORCE",
    "MAX_FREQUENCY",
    "MAX_GRAVITY",
    "MAX_GRAVITY_SCALE",
    "MAX_IMPULSE",
    "MAX_ITERATIONS",
    "MAX_LENGTH",
    "MAX_MASS",
    "MAX_MASS_RATIO",
    "MAX_MOMENT",
    "MAX_OVERLAP",
    "MAX_SECONDS",
    "MAX_SPEED",
    "MAX_STIFFNESS",
    "MAX_SUBSTEPS",
    "MAX_TIME",
    "MAX_ZOOM",
    "MIN_DT",
    "MIN_MASS",
    "MIN_MOMENT",
    "RUNAWAY_FORCE",
    "RUNAWAY_POSITION",
    "RUNAWAY_SPEED",
    "SPRING_LIMIT",
]

MAX_ZOOM = 1.0e4
"""Largest view zoom, px/m (a 1 cm detail 100 px wide)."""

MAX_COORDINATE = 1.0e5
"""Largest |x| or |y| of a position, anchor or point, m (100 km). At the largest zoom a point
stays within 32-bit pixel coordinates (1e5 m · 1e4 px/m < 2³¹), and no game-scale level is wider."""

MAX_LENGTH = 1.0e4
"""Largest size, radius or distance of a shape or path, m (10 km): a shape must fit well inside the
coordinate range, and m·L² keeps its moment of inertia within :data:`MAX_MOMENT`."""

MIN_MASS = 1.0e-3
"""Smallest mass of a dynamic body, kg (a gram). Lighter bodies meet a 70 kg player at mass ratios
(> 1e4) that no iteration count holds, and 1/m overflows long before the mass reaches zero."""

MAX_MASS = 1.0e6
"""Largest mass of a dynamic body, kg (a thousand tonnes): the same mass-ratio argument against
the lightest body a player handles."""

MIN_MOMENT = 1.0e-9
"""Smallest moment of inertia, kg·m² (a gram at a millimetre): 1/I must stay finite."""

MAX_MOMENT = 1.0e15
"""Largest finite moment of inertia, kg·m² (:data:`MAX_MASS` at :data:`MAX_LENGTH`, times ten).
An infinite moment is accepted where a body's rotation is locked on purpose."""

MAX_SPEED = 1.0e3
"""Largest initial or driven speed, m/s. At 1/120 s a body at 1 km/s moves 8 m per step, further
than any shape is thick: it passes through walls without touching them."""

MAX_ANGULAR_SPEED = 1.0e3
"""Largest initial or driven turning rate, rad/s (160 turns a second): the same tunnelling
argument for the rim of a metre-sized body."""

MAX_ACCELERATION = 1.0e3
"""Largest driven acceleration (an elevator's), m/s² (100 g)."""

MAX_GRAVITY = 1.0e3
"""Largest gravity, m/s² (100 g): a body falls at most g·dt² ≈ 7 cm more per 1/120 s step, and the
hover spring and contacts still hold it; a gravity of 1e308 overflows m·g at once."""

MAX_GRAVITY_SCALE = 100.0
"""Largest |scale| of a body's own gravity (a multiple of the field): with :data:`MAX_GRAVITY` it
keeps a body's gravity within the forces the solver handles."""

MAX_FORCE = 1.0e8
"""Largest applied force or force budget, N: it accelerates :data:`MIN_MASS` by 1e11 m/s², already
far past anything a step integrates meaningfully, yet keeps F·dt and every sum of forces finite."""

MAX_IMPULSE = 1.0e6
"""Largest applied impulse, N·s (:data:`MAX_FORCE` over a 0.01 s step)."""

MAX_STIFFNESS = 1.0e9
"""Largest spring stiffness, N/m or N·m/rad. Whether a spring is stable at the level's dt is
checked when the level is built (2πf·dt < 2); this bound only keeps k·x finite."""

MAX_FREQUENCY = 1.0e3
"""Largest frequency, Hz (a mover's oscillation, a filter's cutoff): above half the step rate a
motion is not sampled at all (1/120 s steps resolve at most 60 Hz)."""

MAX_ANGLE = 1.0e3
"""Largest |angle|, rad (160 turns): differences of two angles stay exact to ~1e-13 rad, far from
overflow."""

MAX_TIME = 86_400.0
"""Latest time of an event, input, window or path phase, s (a day): later than any run."""

MAX_SECONDS = 3600.0
"""Longest run a level asks for, s (an hour: 432 000 steps at 1/120 s, minutes of wall time). The
CLI runs longer only with an explicit flag."""

MIN_DT = 1.0e-4
"""Smallest step, s (10 kHz): a second of simulation is then 10 000 steps; smaller steps turn a
short level into hours of wall time without making a game-scale scene more accurate."""

MAX_DT = 0.1
"""Largest step, s (10 Hz): a slower step is a slideshow, and a spring is only stable while
2πf·dt < 2 (below 3.2 Hz at 0.1 s; the controller's hover spring is 5 Hz)."""

MAX_SUBSTEPS = 64
"""Most ``space.step`` calls per step: 64 substeps of the largest dt are 1.6 ms each, finer than any
spring a level may hold needs; more only multiply the cost of every step."""

MAX_ITERATIONS = 1000
"""Most solver iterations per substep: enough for the largest mass ratio a level allows
(:data:`MAX_MASS_RATIO`); more cost time without holding anything more."""

RUNAWAY_POSITION = 1.0e10
"""The runtime guard's bound on |x|, |y| of a body, m. Nothing in an accepted level gets there in a
run: :data:`MAX_GRAVITY` for :data:`MAX_SECONDS` carries a body ½·g·t² ≈ 6.5e9 m. Beyond it the
solver has blown up (and NaN is a step or two away)."""

RUNAWAY_SPEED = 1.0e8
"""The runtime guard's bound on a body's speed components, m/s and rad/s: :data:`MAX_GRAVITY` for
:data:`MAX_SECONDS` gives 3.6e6 m/s; thirty times that is a blow-up, not a motion."""

RUNAWAY_FORCE = 1.0e13
"""The runtime guard's bound on a tracked body's force readings, N: :data:`MAX_FORCE` on the
heaviest body, times a hundred thousand; beyond it a contact or joint is fighting a blow-up."""

MAX_MASS_RATIO = 1.0e3
"""Largest mass ratio between two bodies joined by a joint or resting on each other at the start.
pymunk's sequential impulses need of the order of the ratio in iterations to hold such a pair, and
a level allows at most 1000 iterations: beyond it the light body is crushed or the joint stretches
whatever the settings."""

MAX_OVERLAP = 0.05
"""Deepest overlap of two bodies' shapes at the start, m. Deeper, a body was spawned inside another
and the solver pushes them apart at once (ten times the default collision slop of 5 mm)."""

SPRING_LIMIT = 2.0
"""A spring integrated by pymunk (force from the position before the step, then the velocity) is
stable while ω·h < 2, ω = √(k/m) its angular frequency and h the substep."""
