"""A/B of the one gravity-rule formula against the two copies it replaced (issue 21).

Prints the best of 7 repeats per variant, in one process: ``apply_rules`` for 10 and
1000 bodies (the vectorised stage), and one body's rule with its own direction (the
controller's read). Also asserts the rows agree bit for bit. Run:
``python benchmarks/gravity_rule_ab.py``.
"""

from __future__ import annotations

import math
import timeit

import numpy as np
from numpy.typing import NDArray

from playground.gravity import GravityRule, apply_rules

Rows = NDArray[np.float64]


def rows_before(field_g: Rows, scale: Rows, direction: Rows) -> Rows:
    """``apply_rules`` as it was written before the formula had one home."""
    g = field_g * scale[:, None]
    own = ~np.isnan(direction[:, 0])
    if own.any():
        mag = np.hypot(field_g[own, 0], field_g[own, 1]) * scale[own]
        g[own] = direction[own] * mag[:, None]
    return g


def controller_before(rule: GravityRule, gx: float, gy: float) -> tuple[float, float]:
    """The controller's copy of the formula before (``math.hypot``)."""
    if rule.direction is None:
        return (rule.scale * gx, rule.scale * gy)
    mag = rule.scale * math.hypot(gx, gy)
    return (mag * rule.direction[0], mag * rule.direction[1])


def best(fn: object, number: int) -> float:
    """Seconds per call: the best of 7 repeats of ``number`` calls."""
    return min(timeit.repeat(fn, number=number, repeat=7)) / number  # type: ignore[arg-type]


def main() -> None:
    rng = np.random.default_rng(1)
    for n in (10, 1000):
        f = rng.normal(size=(n, 2))
        s = rng.uniform(size=n)
        d = np.where(rng.random((n, 1)) < 0.5, np.nan, rng.normal(size=(n, 2)))
        assert (rows_before(f, s, d) == apply_rules(f, s, d)).all()
        before = best(lambda f=f, s=s, d=d: rows_before(f, s, d), 2000)
        after = best(lambda f=f, s=s, d=d: apply_rules(f, s, d), 2000)
        print(f"apply_rules, {n} bodies: {before * 1e6:.2f} -> {after * 1e6:.2f} us")
    rule = GravityRule(0.5, (0.0, 1.0))
    before = best(lambda: controller_before(rule, 3.0, -4.0), 200_000)
    after = best(lambda: rule.apply(3.0, -4.0), 200_000)
    print(f"one body, own direction: {before * 1e9:.0f} -> {after * 1e9:.0f} ns")


if __name__ == "__main__":
    main()
