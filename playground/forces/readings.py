"""The tracked bodies' force readings after a step: one body's as plain values
(:class:`BodyForces`), every body's as arrays (:class:`TrackedReadings`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground.vec import Vec

__all__ = ["BodyForces", "TrackedReadings"]


@dataclass(frozen=True, slots=True)
class BodyForces:
    """One tracked body's readings after a step (plain values, SI).

    A 10 kg crate at rest on a floor: the floor holds it up with its weight, gravity pulls it
    down with as much, and an accelerometer on it reads g, upward:

    >>> from playground import World
    >>> world = World()
    >>> floor = world.add_static_segment((-5.0, 0.0), (5.0, 0.0))                  # m
    >>> _ = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.55))  # kg, m
    >>> world.track("crate")
    >>> world.run(1.0)                                                              # s
    >>> r = world.forces("crate")
    >>> r.valid, round(r.support[1], 6), round(r.passive[1], 6)                    # N, N
    (True, 98.1, -98.1)
    >>> round(r.specific[1], 6)                                                     # m/s²
    9.81

    Attributes:
        valid: False when the body was not integrated through the whole step (asleep after one of
            its substeps, or absent from the space); the other fields then hold the last valid
            reading.
        engine: force the engine applied (contacts + joints), N.
        engine_torque: torque the engine applied, N·m.
        support: engine + our SUPPORT forces (hover, drive, grip), N.
        specific: support / m — what an accelerometer on the body reads, m/s².
        passive: gravity and fields on the body, N.
        applied: our APPLIED forces (self-propulsion, scripts), N.
        contact: sum of the body's arbiter impulses / dt, N (NaN unless ``split_valid``).
        contact_normal / contact_friction: the contact force's normal and tangential parts, N.
        constraint: engine − contact: what joints did, N (NaN unless ``split_valid``).
        split_valid: the contact split is on and known this step. It is unknown (the four
            fields above NaN) on a step where one of the body's arbiters reports an impulse the
            engine did not apply (see
            :class:`~playground.forces.contact_split.ContactSplit`).
    """

    valid: bool
    engine: Vec
    engine_torque: float
    support: Vec
    specific: Vec
    passive: Vec
    applied: Vec
    contact: Vec
    contact_normal: Vec
    contact_friction: Vec
    constraint: Vec
    split_valid: bool


@dataclass(frozen=True, slots=True)
class TrackedReadings:
    """Every tracked body's readings after a step, one row each in :attr:`bodies` order (copies:
    the next step does not change them). Each array means what the :class:`BodyForces` field
    of the same name means; ``perceived_gravity`` (m/s²) and ``perceived_up`` (unit vectors)
    are the filter's, as of its last step.
    """

    bodies: tuple[pymunk.Body, ...]
    valid: NDArray[np.bool_]
    engine: NDArray[np.float64]
    engine_torque: NDArray[np.float64]
    support: NDArray[np.float64]
    specific: NDArray[np.float64]
    passive: NDArray[np.float64]
    applied: NDArray[np.float64]
    contact: NDArray[np.float64]
    contact_normal: NDArray[np.float64]
    constraint: NDArray[np.float64]
    split_valid: NDArray[np.bool_]
    perceived_gravity: NDArray[np.float64]
    perceived_up: NDArray[np.float64]
