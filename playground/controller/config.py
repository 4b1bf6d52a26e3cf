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
    MAX_ACCELERATION,
    MAX_ANGULAR_SPEED,
    MAX_FORCE,
    MAX_FREQUENCY,
    MAX_LENGTH,
    MAX_MASS,
    MAX_SPEED,
    MIN_MASS,
)
from playground.params import check, param

__all__ = ["G0", "TUNED_HEIGHT", "TUNED_WEIGHT", "ControllerConfig"]

G0 = 9.81
"""m/s²: the standard gravity a body's weight is taken in for its budgets (the world's default
field), so that a budget stays where the field vanishes (a spinning ring, a nullified body)."""
TUNED_WEIGHT = 70.0 * G0
"""N: the weight of the 70 kg person the default budgets were tuned on (686.7 N)."""
TUNED_HEIGHT = 1.8
"""m: that person's height."""
MAX_WEIGHTS = 1.0e4
"""The largest budget in the body's weights."""


@dataclass(frozen=True, slots=True)
class ControllerConfig:
    """Body, sensing and force budgets; defaults fit a 70 kg, 1.8 m person, and the budgets
    follow the body: each is a multiple of its weight m·g₀ (a torque, of weight × height) unless
    given in newtons (``hover_force`` and the like), so one config serves a 35 kg and a 140 kg
    body. The defaults are the budgets tuned for 70 kg (``hover_force`` 5000 N, ``ground_force``
    350 N, ``air_force`` 70 N, ``balance_torque`` 600 N·m, ``grip_force`` 2000 N,
    ``push_force`` 1000 N, ``crush_force`` 1500 N) over its weight.

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
    hover_force: float | None = param(
        None,
        doc="The legs' budget: the most the hover pushes with (None: hover_weights).",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    hover_weights: float = param(
        5000.0 / TUNED_WEIGHT,
        doc="The legs' budget in the body's weights (unless hover_force is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
    )
    max_slope: float = param(
        math.radians(50.0),
        doc="Steepest walkable ground, between its normal and up (below π/2). 50° as Jolt's "
        "character: a 45° ramp, a common one in games, is floor with room to spare.",
        unit="rad",
        gt=0.0,
    )
    max_lean: float = param(
        math.radians(5.0),
        doc="How far the controller's up leans from the field's up while supported, beyond the "
        "lean its own drive explains while nothing touches it (a push from a wall or a bump is "
        "not support).",
        unit="rad",
        ge=0.0,
        le=math.pi / 2.0,
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
    traction: float = param(
        1.5,
        doc="Foot friction coefficient: the drive is at most traction × the hover's force. "
        "Standing on a slope θ takes tan θ; 1.5 (a rubber sole on dry rock) holds the "
        "steepest walkable slope (tan 50° = 1.19) with 0.2 of a weight left to walk up it.",
        ge=0.0,
    )
    ground_force: float | None = param(
        None,
        doc="Drive force budget on the ground (None: ground_weights).",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    ground_weights: float = param(
        350.0 / TUNED_WEIGHT,
        doc="Drive force budget in the body's weights (unless ground_force is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
    )
    air_force: float | None = param(
        None,
        doc="Steering force budget in the air, never used to brake (None: air_weights).",
        unit="N",
        ge=0.0,
        le=MAX_FORCE,
    )
    air_weights: float = param(
        70.0 / TUNED_WEIGHT,
        doc="Steering force budget in the body's weights (unless air_force is set).",
        ge=0.0,
        le=MAX_WEIGHTS,
    )
    balance_frequency: float = param(
        2.5, doc="Natural frequency of the upright PD.", unit="Hz", gt=0.0, le=MAX_FREQUENCY
    )
    balance_damping: float = param(1.5, doc="Damping ratio of the upright PD.", gt=0.0)
    balance_torque: float | None = param(
        None,
        doc="Balance torque budget (None: balance_weight_heights).",
        unit="N·m",
        gt=0.0,
        le=MAX_FORCE,
    )
    balance_weight_heights: float = param(
        600.0 / (TUNED_WEIGHT * TUNED_HEIGHT),
        doc="Balance torque budget in the body's weight × its height (unless balance_torque "
        "is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
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
    footing_time: float = param(
        0.02,
        doc="A worse footing (GROUNDED to SLIDING or AIRBORNE, SLIDING to AIRBORNE) is taken "
        "once it has lasted this long; a better one at once.",
        unit="s",
        ge=0.0,
    )
    jump_buffer: float = param(
        0.15, doc="A jump press is remembered this long before landing.", unit="s", ge=0.0
    )
    grab_reach: float = param(
        0.3, doc="How far beyond the head the hands reach.", unit="m", gt=0.0, le=MAX_LENGTH
    )
    grip_force: float | None = param(
        None,
        doc="Grip budget, the joint's max force (None: grip_weights).",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    grip_weights: float = param(
        2000.0 / TUNED_WEIGHT,
        doc="Grip budget in the body's weights (unless grip_force is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
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
    ledge_grab: float = param(
        0.4,
        doc="How far above the top of the head the hands find a ledge's top edge (from the "
        "head's cap centre up); its face must lie within radius + ledge_grab of the head.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    ledge_climb_acceleration: float = param(
        4.0,
        doc="The most the climb onto a ledge accelerates the body relative to the ledge, on "
        "top of holding its weight (within the grip budget).",
        unit="m/s²",
        gt=0.0,
        le=MAX_ACCELERATION,
    )
    push_reach: float = param(
        0.5,
        doc="How far beyond the body the arms reach to push.",
        unit="m",
        gt=0.0,
        le=MAX_LENGTH,
    )
    push_force: float | None = param(
        None,
        doc="Push budget (None: push_weights).",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    push_weights: float = param(
        1000.0 / TUNED_WEIGHT,
        doc="Push budget in the body's weights (unless push_force is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
    )
    crush_force: float | None = param(
        None,
        doc="Crushed when the load from above exceeds this (None: crush_weights).",
        unit="N",
        gt=0.0,
        le=MAX_FORCE,
    )
    crush_weights: float = param(
        1500.0 / TUNED_WEIGHT,
        doc="Crushed when the load from above exceeds this many of the body's weights "
        "(unless crush_force is set).",
        gt=0.0,
        le=MAX_WEIGHTS,
    )
    crush_release: float = param(
        0.8,
        doc="Crushed stays crushed while the load from above stays above this share of "
        "crush_force (hysteresis: a load swinging around crush_force crushes once).",
        gt=0.0,
        le=1.0,
    )
    crush_release_time: float = param(
        0.15,
        doc="Crushed stays crushed until the load from above has stayed at most crush_release "
        "× crush_force (or off) this long.",
        unit="s",
        ge=0.0,
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

    def hover_budget(self, mass: float) -> float:
        """The legs' budget for a body of ``mass`` kg, N."""
        f = self.hover_force
        return f if f is not None else self.hover_weights * mass * G0

    def ground_budget(self, mass: float) -> float:
        """The drive's budget on the ground for a body of ``mass`` kg, N."""
        f = self.ground_force
        return f if f is not None else self.ground_weights * mass * G0

    def air_budget(self, mass: float) -> float:
        """The air steering's budget for a body of ``mass`` kg, N."""
        f = self.air_force
        return f if f is not None else self.air_weights * mass * G0

    def balance_budget(self, mass: float) -> float:
        """The balance torque's budget for a body of ``mass`` kg and this height, N·m."""
        t = self.balance_torque
        return t if t is not None else self.balance_weight_heights * mass * G0 * self.height

    def grip_budget(self, mass: float) -> float:
        """The grip's budget for a body of ``mass`` kg, N."""
        f = self.grip_force
        return f if f is not None else self.grip_weights * mass * G0

    def push_budget(self, mass: float) -> float:
        """The push's budget for a body of ``mass`` kg, N."""
        f = self.push_force
        return f if f is not None else self.push_weights * mass * G0

    def crush_threshold(self, mass: float) -> float:
        """The load from above that crushes a body of ``mass`` kg, N."""
        f = self.crush_force
        return f if f is not None else self.crush_weights * mass * G0

    @property
    def half_length(self) -> float:
        """Half the distance between the capsule's two end-cap centres, m."""
        return self.height / 2.0 - self.radius
