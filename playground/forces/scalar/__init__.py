"""The scalar implementation of the tracked bodies: their readings and perceived gravity in plain
floats, for few bodies.

:mod:`~playground.forces.scalar.bodies` (:class:`ScalarBodies`, the per-step arithmetic and the
crossover :data:`SCALAR_MAX_BODIES`), :mod:`~playground.forces.scalar.row` (one body's state),
:mod:`~playground.forces.scalar.handoff` (the state's moves to and from the batch
implementation) and :mod:`~playground.forces.scalar.contacts` (the contact split's sums).
"""

from playground.forces.scalar.bodies import SCALAR_MAX_BODIES, ScalarBodies

__all__ = ["SCALAR_MAX_BODIES", "ScalarBodies"]
