"""The hover spring's maths: its force for one step, read where pymunk's integrator will use it,
and the largest stable frequency that follows.

>>> round(hover_limit(1.0), 4)
4.8284
"""

from __future__ import annotations

import math

from playground.controller.config import ControllerConfig

__all__ = ["TWO_PI", "hover_limit", "hover_spring", "stable_hover"]

TWO_PI = 2.0 * math.pi


def hover_spring(
    stiffness: float,
    damping: float,
    mass: float,
    error: float,
    speed: float,
    dt: float,
    substeps: int = 1,
) -> float:
    """The hover's spring-and-damper force along the ground normal for one step, N.

    ``stiffness`` k (N/m), ``damping`` c (N·s/m), ``mass`` m (kg), ``error`` = ride height −
    height (m), ``speed`` = the body's velocity along the normal relative to the ground point
    (m/s), ``dt`` the step (s) split into ``substeps`` equal ``space.step`` calls.

    Why not simply ``k·error − c·speed``: pymunk integrates positions *before* velocities, so a
    force read from the state before the step is explicit Euler, which gains energy (an undamped
    spring grows at any dt; a damped one is stable only while 2πf·dt < 2ζ). The force is instead
    evaluated where the integrator will use it. Over a step of n substeps of h = dt/n with the
    force held constant (the world re-applies the same force every substep), pymunk gives

        v' = v + dt·a          x' = x + dt·v + dt²·a·(n − 1)/(2n)

    Let the spring read the gap predicted a fraction s of the step ahead, x + s·dt·v (relative to
    the ground point, which moves with the ground's velocity), and let the damper act on the
    velocity at the end of the step (implicit, so damping can never feed energy in): with
    ω² = k/m, b = c·dt/m, w = ω·dt,

        a = −ω²·(x + s·dt·v) − (c/m)·v'   ⇒   a = (−ω²·(x + s·dt·v) − (c/m)·v) / (1 + b)

    (the weight feed-forward cancels gravity along the normal, so v' = v + dt·a here).

    The step's matrix on (x, dt·v) has determinant (1 + w²(1 − s − (n − 1)/(2n))) / (1 + b):
    with s = (n + 1)/(2n) it is 1/(1 + b), and an undamped spring (b = 0) keeps its area
    (symplectic: semi-implicit Euler for n = 1, s = 1; the midpoint s → 1/2 for many substeps).
    Its trace is then 1 + (1 − w²)/(1 + b), and the roots stay inside the unit circle while
    w² < 4 + 2b, i.e. ``2πf·dt < 2ζ + 2√(ζ² + 1)`` (:func:`hover_limit`): exactly 2 for an
    undamped spring and more with damping, for every number of substeps. Substeps do not raise
    it: the force is computed once per step, so the step that counts is dt, not h. At rest
    (error = speed = 0) the force is exactly 0, so the weight feed-forward alone holds the body.

    >>> hover_spring(100.0, 0.0, 1.0, 0.01, 0.0, 0.01)
    1.0
    >>> hover_spring(100.0, 20.0, 1.0, 0.0, 0.0, 0.01, substeps=4)
    0.0
    """
    ahead = (substeps + 1) / (2.0 * substeps) * dt
    return (stiffness * (error - ahead * speed) - damping * speed) / (1.0 + damping * dt / mass)


def hover_limit(damping_ratio: float) -> float:
    """The largest stable 2πf·dt of the hover spring at damping ratio ζ: 2ζ + 2√(ζ² + 1).

    Derived in :func:`hover_spring`; independent of the substeps.

    >>> hover_limit(0.0)
    2.0
    >>> round(hover_limit(1.0), 4)
    4.8284
    """
    return 2.0 * damping_ratio + 2.0 * math.sqrt(damping_ratio * damping_ratio + 1.0)


def stable_hover(config: ControllerConfig, dt: float) -> float:
    """The hover's 2π·f (rad/s), or ValueError if the spring would be unstable at ``dt`` (s)."""
    omega = TWO_PI * config.hover_frequency
    limit = hover_limit(config.hover_damping)
    if omega * dt >= limit:
        raise ValueError(
            f"hover_frequency: 2π·f·dt must stay below 2ζ + 2√(ζ² + 1) = {limit:.4g} "
            f"(ζ = hover_damping = {config.hover_damping!r}) for a stable spring; with dt = "
            f"{dt} s expected f < {limit / (TWO_PI * dt):.4g} Hz, "
            f"got {config.hover_frequency!r}"
        )
    return omega
