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
from dataclasses import dataclass, fields

from playground._validate import finite, positive

__all__ = ["ControllerConfig"]


@dataclass(frozen=True, slots=True)
class ControllerConfig:
    """Body, sensing and force budgets; defaults fit a 70 kg, 1.8 m person.

    Attributes:
        mass: kg, the body's mass when it is built (``World.set_mass`` may change it later: the
            controller follows the body's mass, see :attr:`Controller.mass`).
        height: capsule length, end to end, m.
        radius: capsule radius, m (less than half the height).
        lock_rotation: infinite moment of inertia: the capsule never tips (no balance needed).
        ride_height: distance held from the probe hit to the capsule's centre, m. Above half the
            height, so the feet hover a few centimetres over the ground and the capsule never
            scrapes it while walking.
        probe_length: how far the ground probe reaches from the centre along −up, m.
        probe_radius: radius of the probe's swept circle, m.
        hover_frequency: natural frequency of the hover spring, Hz (k = m·(2πf)²).
        hover_damping: damping ratio of the hover spring (c = 2ζ·m·2πf); 1 is critical, 0 is
            undamped. The spring is stable while 2πf·dt < :func:`hover_limit` (ζ), which is at
            least 2.
        hover_force: the legs' budget: the most the hover pushes with, N. Beyond it the capsule
            bottoms out and the contact takes the rest (a hard landing, a crushing load).
        max_slope: steepest walkable ground, rad between its normal and up.
        max_speed: walking speed at full move input, m/s.
        drive_time: time constant with which the drive closes the gap to its goal velocity, s.
        traction: foot friction coefficient: the drive is also bounded by traction × the hover
            force (no normal force, no traction).
        ground_force: drive force budget on the ground, N.
        air_force: steering force budget in the air, N (never used to brake).
        balance_frequency: natural frequency of the upright PD, Hz.
        balance_damping: damping ratio of the upright PD.
        balance_torque: balance torque budget, N·m.
        balance_loss_time: needing more than the budget this long while supported loses
            balance, s.
        settle_speed: below this speed relative to the ground a fallen body counts as still, m/s.
        settle_spin: below this angular speed a fallen body counts as still, rad/s.
        settle_time: how long a fallen body must stay still before getting up, s.
        getup_time: how long getting up takes, s.
        jump_speed: take-off speed along up relative to the ground, m/s.
        coyote_time: a jump still works this long after leaving the ground, s.
        jump_buffer: a jump press is remembered this long before landing, s.
        grab_reach: how far beyond the head the hands reach, m.
        grip_force: grip budget (the joint's max force), N.
        grip_slip: the grip lets go when its anchors drift this far apart, m.
        climb_speed: speed of the grip along the held body at full climb input, m/s.
        push_reach: how far beyond the body the arms reach to push, m.
        push_force: push budget, N.
        crush_force: crushed when the load from above exceeds this, N.
    """

    mass: float = 70.0
    height: float = 1.8
    radius: float = 0.25
    lock_rotation: bool = False
    ride_height: float = 0.95
    probe_length: float = 1.4
    probe_radius: float = 0.1
    hover_frequency: float = 5.0
    hover_damping: float = 1.0
    hover_force: float = 5000.0
    max_slope: float = 0.7
    max_speed: float = 4.0
    drive_time: float = 0.05
    traction: float = 1.0
    ground_force: float = 350.0
    air_force: float = 70.0
    balance_frequency: float = 2.5
    balance_damping: float = 1.5
    balance_torque: float = 600.0
    balance_loss_time: float = 0.3
    settle_speed: float = 0.3
    settle_spin: float = 0.5
    settle_time: float = 0.5
    getup_time: float = 1.0
    jump_speed: float = 4.0
    coyote_time: float = 0.1
    jump_buffer: float = 0.15
    grab_reach: float = 0.3
    grip_force: float = 2000.0
    grip_slip: float = 0.1
    climb_speed: float = 0.5
    push_reach: float = 0.5
    push_force: float = 1000.0
    crush_force: float = 1500.0

    def __post_init__(self) -> None:
        if not isinstance(self.lock_rotation, bool):
            raise ValueError(f"lock_rotation: expected a bool, got {self.lock_rotation!r}")
        non_negative = {
            "hover_damping",
            "traction",
            "air_force",
            "coyote_time",
            "jump_buffer",
            "climb_speed",
        }
        for f in fields(self):
            if f.name == "lock_rotation":
                continue
            value = getattr(self, f.name)
            if f.name in non_negative:
                finite(f.name, value)
                if value < 0.0:
                    raise ValueError(f"{f.name}: expected a number >= 0, got {value!r}")
            else:
                positive(f.name, value)
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
