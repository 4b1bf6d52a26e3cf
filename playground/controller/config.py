"""The controller's configuration: the capsule's body, its sensing and its force budgets.

One frozen value per controller, checked when it is built; the controller's state lives in
:class:`~playground.controller.controller.Controller`.

>>> ControllerConfig().half_length
0.65
>>> ControllerConfig(radius=1.0)
Traceback (most recent call last):
...
ValueError: radius: expected less than half the height (0.9 m), got 1.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from playground.limits import (
    MAX_ANGULAR_SPEED,
    MAX_FORCE,
    MAX_FREQUENCY,
    MAX_LENGTH,
    MAX_MASS,
    MAX_SPEED,
    MIN_MASS,
)
from playground.params import check, param

__all__ = ["ControllerConfig"]


@dataclass(frozen=True, slots=True)
class ControllerConfig:
    """Body, sensing and force budgets; defaults fit a 70 kg, 1.8 m person.

    ``mass`` is the body's mass when it is built (``World.set_mass`` may change it later: the
    controller follows the body's mass, see :attr:`Controller.mass`). ``ride_height`` lies above
    half the height, so the feet hover a few centimetres over the ground and the capsule never
    scrapes it while walking. The hover spring is k = m·(2πf)², c = 2ζ·m·2πf, stable while
    2πf·dt < :func:`hover_limit` (ζ), which is at least 2. Beyond ``hover_force`` the capsule
    bottoms out and the contact takes the rest (a hard landing, a crushing load). The drive is
    also bounded by ``traction`` × the hover force (no normal force, no traction).

    Change what a game needs and keep the rest; every key is checked, naming the key:

    >>> hopper = ControllerConfig(jump_speed=6.0, max_speed=5.0)      # m/s, m/s
    >>> round(hopper.jump_speed**2 / (2 * 9.81), 2)                    # m: its jump's height
    1.83
    >>> ControllerConfig(mass=-1.0)
    Traceback (most recent call last):
    ...
    ValueError: mass: expected a number in [0.001, 1e+06] kg, got -1.0
    """

    mass: float = param(70.0, doc="Mass when built.", unit="kg", ge=MIN_MASS, le=MAX_MASS)
    height: float = param(1.8, doc="Capsule length, end to end.", unit="m", gt=0.0, le=MAX_LENGTH)
    radius: float = param(
        0.25, doc="Capsule radius (less than half the height).", unit="m", gt=0.0, le=MAX_LENGTH
    )
    lock_rotation: bool = param(
        False, doc="Infinite moment of inertia: the capsule never tips (no balance needed)."
    )
    ride_height: float = param(
        0.95,
        doc="Distance held from the probe hit to the capsule's centre.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    probe_length: float = param(
        1.4,
        doc="How far the ground probe reaches from the centre along −up.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    probe_radius: float = param(
        0.1, doc="Radius of the probe's swept circle.", unit="m", gt=0.0, le=MAX_LENGTH
    )
    hover_frequency: float = param(
        5.0, doc="Natural frequency of the hover spring.", unit="Hz", gt=0.0, le=MAX_FREQUENCY
    )
    hover_damping: float = param(
        1.0, doc="Damping ratio of the hover spring (1: critical, 0: undamped).", ge=0.0
    )
    hover_force: float = param(
        5000.0,
        doc="The legs' budget: the most the hover pushes with.",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    max_slope: float = param(
        0.7,
        doc="Steepest walkable ground, between its normal and up (below π/2).",
        unit="rad",
        gt=0.0,
    )
    max_speed: float = param(
        4.0, doc="Walking speed at full move input.", unit="m/s", gt=0.0, le=MAX_SPEED
    )
    drive_time: float = param(
        0.05,
        doc="Time constant of the drive closing the gap to its goal velocity.",
        unit="s",
        gt=0.0,
    )
    traction: float = param(1.0, doc="Foot friction coefficient.", ge=0.0)
    ground_force: float = param(
        350.0, doc="Drive force budget on the ground.", unit="N", gt=0.0, le=MAX_FORCE
    )
    air_force: float = param(
        70.0,
        doc="Steering force budget in the air (never used to brake).",
        unit="N",
        ge=0.0,
        le=MAX_FORCE,
    )
    balance_frequency: float = param(
        2.5, doc="Natural frequency of the upright PD.", unit="Hz", gt=0.0, le=MAX_FREQUENCY
    )
    balance_damping: float = param(1.5, doc="Damping ratio of the upright PD.", gt=0.0)
    balance_torque: float = param(
        600.0, doc="Balance torque budget.", unit="N·m", gt=0.0, le=MAX_FORCE
    )
    balance_loss_time: float = param(
        0.3,
        doc="Needing more than the budget this long while supported loses balance.",
        unit="s",
        gt=0.0,
    )
    settle_speed: float = param(
        0.3,
        doc="Below this speed relative to the ground a fallen body counts as still.",
        unit="m/s",
        gt=0.0,
        le=MAX_SPEED,
    )
    settle_spin: float = param(
        0.5,
        doc="Below this angular speed a fallen body counts as still.",
        unit="rad/s",
        gt=0.0,
        le=MAX_ANGULAR_SPEED,
    )
    settle_time: float = param(
        0.5, doc="How long a fallen body stays still before getting up.", unit="s", gt=0.0
    )
    getup_time: float = param(1.0, doc="How long getting up takes.", unit="s", gt=0.0)
    jump_speed: float = param(
        4.0,
        doc="Take-off speed along up relative to the ground.",
        unit="m/s",
        gt=0.0,
        le=MAX_SPEED,
    )
    coyote_time: float = param(
        0.1, doc="A jump still works this long after leaving the ground.", unit="s", ge=0.0
    )
    jump_buffer: float = param(
        0.15, doc="A jump press is remembered this long before landing.", unit="s", ge=0.0
    )
    grab_reach: float = param(
        0.3, doc="How far beyond the head the hands reach.", unit="m", gt=0.0, le=MAX_LENGTH
    )
    grip_force: float = param(
        2000.0, doc="Grip budget (the joint's max force).", unit="N", gt=0.0, le=MAX_FORCE
    )
    grip_slip: float = param(
        0.1,
        doc="The grip lets go when its anchors drift this far apart.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    climb_speed: float = param(
        0.5,
        doc="Speed of the grip along the held body at full climb input.",
        unit="m/s",
        ge=0.0,
        le=MAX_SPEED,
    )
    push_reach: float = param(
        0.5,
        doc="How far beyond the body the arms reach to push.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    push_force: float = param(1000.0, doc="Push budget.", unit="N", gt=0.0, le=MAX_FORCE)
    crush_force: float = param(
        1500.0,
        doc="Crushed when the load from above exceeds this.",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )

    def __post_init__(self) -> None:
        if not isinstance(self.lock_rotation, bool):
            raise ValueError(f"lock_rotation: expected a bool, got {self.lock_rotation!r}")
        check(self)
        if self.radius >= self.height / 2.0:
            raise ValueError(
                f"radius: expected less than half the height ({self.height / 2.0} m), "
                f"got {self.radius!r}"
            )
        if self.ride_height >= self.probe_length:
            raise ValueError(
                f"ride_height: expected less than probe_length ({self.probe_length} m), "
                f"got {self.ride_height!r}"
            )
        if self.max_slope >= math.pi / 2.0:
            raise ValueError(f"max_slope: expected less than π/2 rad, got {self.max_slope!r}")

    @property
    def half_length(self) -> float:
        """Half the distance between the capsule's two end-cap centres, m."""
        return self.height / 2.0 - self.radius
