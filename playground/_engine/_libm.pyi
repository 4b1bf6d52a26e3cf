"""The compiled helper of :mod:`playground._engine.libm` (``_libm.c``): ``math.atan2`` over
arrays in one C call."""

import numpy as np
from numpy.typing import NDArray

def atan2(y: NDArray[np.float64], x: NDArray[np.float64], out: NDArray[np.float64]) -> None:
    """``out[i] = math.atan2(y[i], x[i])`` for every i (rad): three C-contiguous float64 arrays
    of one length."""
