"""The compiled helper of :mod:`playground._engine.inertia` (``_inertia.c``): many bodies' mass
and moment of inertia in one C call."""

import numpy as np
from numpy.typing import NDArray

def mass_moment(
    get_mass: int, get_moment: int, bodies: NDArray[np.uintp], out: NDArray[np.float64]
) -> None:
    """``out[0, k]``, ``out[1, k]`` = the mass (kg) and moment (kg·m²) of the body at address
    ``bodies[k]``, read through the getters at the addresses ``get_mass`` and ``get_moment``
    (``cpBodyGetMass``, ``cpBodyGetMoment``); ``out`` is C-contiguous float64, 2 × n."""
