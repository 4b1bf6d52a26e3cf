"""The compiled helper of :class:`playground._engine.sweep.Sweeps` (``_nearest.c``): many
probes' nearest-hit segment queries through Chipmunk in one C call."""

import numpy as np
from numpy.typing import NDArray

def segment_queries(
    query: int,
    is_sensor: int,
    spaces: NDArray[np.uintp],
    filters: NDArray[np.uintp],
    rows: NDArray[np.intp],
    x0: NDArray[np.float64],
    y0: NDArray[np.float64],
    x1: NDArray[np.float64],
    y1: NDArray[np.float64],
    radius: NDArray[np.float64],
    which: NDArray[np.intp],
    shapes: NDArray[np.uintp],
    hits: NDArray[np.float64],
) -> int:
    """For each k, the nearest non-sensor hit of a circle of ``radius[k]`` (m) swept from
    (x0[k], y0[k]) to (x1[k], y1[k]) (m) through ``spaces[rows[k]]`` among the shapes
    ``filters[rows[k]]`` lets through; written into ``which`` (index into ``shapes``, -1: none),
    ``shapes`` (the distinct ``cpShape*`` hit) and ``hits`` (4 × len(rows): x, y, nx, ny);
    returns the number of distinct shapes."""
