"""Forces on bodies: the ones we apply, and the ones the engine applied, recovered.

:mod:`~playground.forces.ledger` records the forces we put on bodies, by :class:`Category`;
:mod:`~playground.forces.solver` recovers the engine's force on each tracked body by reverse
integration; :mod:`~playground.forces.contact_split` tells its contact part from its joint part;
:mod:`~playground.forces.readings` holds the readings as plain values. The tracked bodies sit
behind one interface (:mod:`~playground.forces.tracked`), served in plain floats for few bodies
(:mod:`~playground.forces.scalar`) or with numpy for many (:mod:`~playground.forces.batch`);
:class:`ForceSensor` (:mod:`~playground.forces.sensor`) runs them on a plain pymunk space.
"""

from playground.forces.ledger import Category, ForceLedger
from playground.forces.readings import BodyForces, TrackedReadings
from playground.forces.sensor import ForceSensor
from playground.forces.solver import ForceSolver

__all__ = ["BodyForces", "Category", "ForceLedger", "ForceSensor", "ForceSolver", "TrackedReadings"]
