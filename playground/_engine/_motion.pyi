"""The compiled helper of :mod:`playground._engine.motion` (``_motion.c``): many bodies'
velocity, angular velocity, force and torque in one C call."""

from typing import Any

def motion(
    get_velocity: int,
    get_angular_velocity: int,
    get_force: int,
    get_torque: int,
    bodies: Any,
    forces: bool,
) -> list[Any]:
    """One tuple a body at the addresses ``bodies`` (a buffer of ``cpBody*``), in order: (vx, vy,
    w) (m/s, rad/s), and with ``forces`` (vx, vy, w, fx, fy, t) (N, N·m), read through the
    getters at the given addresses (``cpBodyGetVelocity``, ``cpBodyGetAngularVelocity``,
    ``cpBodyGetForce``, ``cpBodyGetTorque``)."""
