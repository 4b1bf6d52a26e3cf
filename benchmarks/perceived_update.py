"""A crowd's FILTER stage alone, for instruction counts: ``PerceivedGravity.update`` on N rows.

The default perception (median of 3, then the 1€ filter) fed ``--calls`` steps of N rows of
specific force near 1 g, every row valid, as a world's batch path feeds it. Run it twice under
callgrind with two call counts: the difference of the two totals over the difference of the
calls is the instructions of one update, free of start-up and imports.

    valgrind --tool=callgrind python benchmarks/perceived_update.py --rows 200 --calls 100
    valgrind --tool=callgrind python benchmarks/perceived_update.py --rows 200 --calls 1100

It prints a checksum of the last perceived gravity (the same before and after a change that
must not alter results).
"""

from __future__ import annotations

import argparse

import numpy as np

from playground.gravity.perception import PerceivedGravity, Perception

DT = 1.0 / 120.0
"""s: the step."""


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=200)
    parser.add_argument("--calls", type=int, default=1000)
    args = parser.parse_args()
    perceived = PerceivedGravity(Perception())
    perceived.resize(np.full(args.rows, -1, dtype=np.intp))
    rng = np.random.default_rng(1)
    samples = rng.normal(size=(args.calls + 1, args.rows, 2)) + np.array([0.0, 9.81])  # m/s²
    valid = np.ones(args.rows, dtype=bool)
    for sample in samples:  # the first starts every row
        perceived.update(sample, valid, DT, all_valid=True)
    print(repr(float(perceived.gravity.sum())))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
