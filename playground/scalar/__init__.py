"""The scalar path: the tracked bodies' readings and perceived gravity in plain floats.

:mod:`~playground.scalar.path` (:class:`ScalarPath`, the per-step arithmetic and the crossover
:data:`SCALAR_MAX_BODIES`), :mod:`~playground.scalar.row` (one body's state),
:mod:`~playground.scalar.handoff` (the state's moves to and from the vectorised path),
:mod:`~playground.scalar.contacts` (the contact split's sums) and
:mod:`~playground.scalar.field` (a field that varies in space, evaluated body by body).
"""

from playground.scalar.path import SCALAR_MAX_BODIES, ScalarPath

__all__ = ["SCALAR_MAX_BODIES", "ScalarPath"]
