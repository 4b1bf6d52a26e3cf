"""Interleaved timed blocks: the one timer every benchmark of the package uses.

Two callables are timed in alternating blocks in the same process, so a burst of load from other
processes on a shared machine slows both alike; the cost is read as the median of the ratios of
adjacent blocks, and the spread of those ratios says how much the load moved them. Blocks are
timed in CPU time of this thread (``time.thread_time``): time the scheduler gives to other
processes is not counted, contention for caches and memory still is.

>>> t = interleave(lambda: None, lambda: None, repeats=3, steps=10)
>>> len(t.a), len(t.b), t.ratio > 0
(3, 3, True)
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["BLOCK_SECONDS", "Blocks", "block_steps", "interleave", "per_call"]

BLOCK_SECONDS = 0.005
"""Wall time aimed at per timed block, s: long enough to dwarf ``perf_counter``'s cost, short
enough that a burst of load spoils few blocks."""

MAX_BLOCK_STEPS = 200
"""Most calls in one block (a cheap call would otherwise need thousands)."""


@dataclass(frozen=True, slots=True)
class Blocks:
    """Seconds per call of ``a`` and of ``b`` in each block, in the order they ran.

    Attributes:
        a, b: seconds per call, one entry per block.
    """

    a: tuple[float, ...]
    b: tuple[float, ...]

    @property
    def a_median(self) -> float:
        """Median seconds per call of ``a``."""
        return statistics.median(self.a)

    @property
    def b_median(self) -> float:
        """Median seconds per call of ``b``."""
        return statistics.median(self.b)

    @property
    def ratios(self) -> tuple[float, ...]:
        """a / b of each pair of adjacent blocks."""
        return tuple(x / y for x, y in zip(self.a, self.b, strict=True))

    @property
    def ratio(self) -> float:
        """Median of the pair ratios a / b: robust to load drifting during the run."""
        return statistics.median(self.ratios)

    @property
    def best(self) -> float:
        """Fastest ``a`` block over fastest ``b`` block (``timeit``'s best-of)."""
        return min(self.a) / min(self.b)

    @property
    def spread(self) -> tuple[float, float]:
        """Lowest and highest pair ratio."""
        return min(self.ratios), max(self.ratios)


def per_call(fn: Callable[[], object], steps: int) -> float:
    """CPU seconds (this thread's) per call of ``fn`` over a block of ``steps`` calls."""
    t0 = time.thread_time()
    for _ in range(steps):
        fn()
    return (time.thread_time() - t0) / steps


def block_steps(a: Callable[[], object], b: Callable[[], object]) -> int:
    """Calls per block so that a block of ``a`` and one of ``b`` take about
    2 × :data:`BLOCK_SECONDS` (one call of each is made to estimate it)."""
    t0 = time.thread_time()
    a()
    b()
    per = max(time.thread_time() - t0, 1e-6)
    return max(3, min(MAX_BLOCK_STEPS, round(2.0 * BLOCK_SECONDS / per)))


def interleave(
    a: Callable[[], object],
    b: Callable[[], object],
    *,
    repeats: int,
    steps: int | None = None,
    prepare_b: Callable[[], object] | None = None,
) -> Blocks:
    """Time ``repeats`` blocks of ``a`` and of ``b``, alternating which goes first so neither
    always inherits the other's cache or a burst of load; ``steps`` calls per block (default:
    :func:`block_steps`). ``prepare_b`` runs, untimed, before each block of ``b``."""
    if repeats < 1:
        raise ValueError(f"repeats: expected an integer >= 1, got {repeats!r}")
    if steps is None and prepare_b is not None:
        prepare_b()  # block_steps calls b once
    n = steps if steps is not None else block_steps(a, b)
    ta: list[float] = []
    tb: list[float] = []

    def time_b() -> None:
        if prepare_b is not None:
            prepare_b()
        tb.append(per_call(b, n))

    for k in range(repeats):
        if k % 2 == 0:
            ta.append(per_call(a, n))
            time_b()
        else:
            time_b()
            ta.append(per_call(a, n))
    return Blocks(tuple(ta), tuple(tb))
