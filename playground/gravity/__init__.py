"""Gravity: the fields (:mod:`~playground.gravity.field`), each body's rule
(:mod:`~playground.gravity.rule`), a field body by body in plain floats for few bodies
(:mod:`~playground.gravity.plain`) and what a body perceives
(:mod:`~playground.gravity.perception`).

Values and formulas only, in m/s²: the world's gravity stage (``playground.world.gravity_stage``)
applies them to the bodies of a space.
"""

from playground.gravity.field import (
    STANDARD_GRAVITY,
    GravityField,
    Points,
    Radial,
    RotatingRoom,
    Turn,
    Uniform,
    Zone,
    Zones,
)
from playground.gravity.perception import PerceivedGravity, Perception
from playground.gravity.rule import GravityRule, apply_rules

__all__ = [
    "STANDARD_GRAVITY",
    "GravityField",
    "GravityRule",
    "PerceivedGravity",
    "Perception",
    "Points",
    "Radial",
    "RotatingRoom",
    "Turn",
    "Uniform",
    "Zone",
    "Zones",
    "apply_rules",
]
