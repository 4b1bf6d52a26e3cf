"""playground: a 2D game-physics playground for force-driven player bodies, built on pymunk.

The core imports pymunk and numpy only; the desktop view lives in ``playground.view``.
The distribution is ``pymunk-playground``; the package and the command are ``playground``.
"""

from playground.controller import Controller, ControllerConfig, ControllerForces, GroundHit, State
from playground.fixed_step import FixedStep, FrameSteps
from playground.forces.ledger import Category, ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.sensor import ForceSensor
from playground.forces.solver import ForceSolver
from playground.gameplay import (
    Crushed,
    Freed,
    Gameplay,
    GameplayEvent,
    GotUp,
    Grabbed,
    GravityChanged,
    Landed,
    LostBalance,
    Released,
)
from playground.gravity import (
    GravityField,
    GravityRule,
    PerceivedGravity,
    Perception,
    Radial,
    RotatingRoom,
    Turn,
    Uniform,
    Zone,
    Zones,
)
from playground.intents import Idle, Intent, IntentSource, Patrol, Script
from playground.movers import Circle, Elevator, Mover, Sine, Spin, Waypoints, ring_room
from playground.world.config import WorldConfig
from playground.world.schedule import Stage, StageTiming
from playground.world.world import World

__version__ = "0.1.0"
"""The release (also the distribution's version: pyproject.toml reads it from here)."""

__all__ = [
    "BodyForces",
    "Category",
    "Circle",
    "Controller",
    "ControllerConfig",
    "ControllerForces",
    "Crushed",
    "Elevator",
    "FixedStep",
    "ForceLedger",
    "ForceSensor",
    "ForceSolver",
    "FrameSteps",
    "Freed",
    "Gameplay",
    "GameplayEvent",
    "GotUp",
    "Grabbed",
    "GravityChanged",
    "GravityField",
    "GravityRule",
    "GroundHit",
    "Idle",
    "Intent",
    "IntentSource",
    "Landed",
    "LostBalance",
    "Mover",
    "Patrol",
    "PerceivedGravity",
    "Perception",
    "Radial",
    "Released",
    "RotatingRoom",
    "Script",
    "Sine",
    "Spin",
    "Stage",
    "StageTiming",
    "State",
    "TrackedReadings",
    "Turn",
    "Uniform",
    "Waypoints",
    "World",
    "WorldConfig",
    "Zone",
    "Zones",
    "ring_room",
]
