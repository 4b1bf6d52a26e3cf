"""Forces on bodies: the ones we apply, and the ones the engine applied, recovered.

:mod:`~playground.forces.ledger` records the forces we put on bodies, by :class:`Category`;
:mod:`~playground.forces.solver` recovers the engine's force on each tracked body by reverse
integration; :mod:`~playground.forces.contact_split` tells its contact part from its joint part;
:mod:`~playground.forces.readings` holds one body's readings as plain values.
"""

from playground.forces.ledger import Category, ForceLedger
from playground.forces.readings import BodyForces
from playground.forces.solver import ForceSolver

__all__ = ["BodyForces", "Category", "ForceLedger", "ForceSolver"]
