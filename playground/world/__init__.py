"""The world: a pymunk space in SI units and the fixed step that runs every stage top-down.

The package's parts: :mod:`~playground.world.world` (the world, its step and its facade over the
parts it holds), :mod:`~playground.world.registry` (named bodies),
:mod:`~playground.world.gravity_stage`, :mod:`~playground.world.force_input` (forces put on
bodies, checked, into the ledger), :mod:`~playground.world.physics` (substeps, forces, filter),
:mod:`~playground.world.schedule` (stages, hooks, timed events), :mod:`~playground.world.guard`,
:mod:`~playground.world.config`, :mod:`~playground.world.bodies` (checks, sleeping groups) and
:mod:`~playground.world.errors` (the world's own error for a call at the wrong moment).
"""

from playground.world.config import WorldConfig
from playground.world.errors import WorldUsageError
from playground.world.schedule import Stage, StageTiming
from playground.world.world import World

__all__ = ["Stage", "StageTiming", "World", "WorldConfig", "WorldUsageError"]
