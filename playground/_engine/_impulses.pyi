"""The compiled helper of :mod:`playground._engine.impulses` (``_impulses.c``): each tracked
body's arbiter impulses summed in one C call."""

from array import array
from typing import Any

def sums(
    values: Any,
    starts: array[int],
    terms: array[int],
    previous: list[tuple[float, float, float, float]] | None,
) -> list[tuple[float, float, float, float]]:
    """Each row's (jx, jy, jnx, jny) sums, N·s: from +0.0 (``previous`` None) or added to
    ``previous``, row k's terms ``terms[starts[k]:starts[k + 1]]`` (i < m: arbiter i's J and
    normal part for its body A; m + i: their negation for its body B) in the order Python sorts
    their tuples; ``values``: jx, jy, nx, ny of each of the m arbiters, a buffer of doubles."""
