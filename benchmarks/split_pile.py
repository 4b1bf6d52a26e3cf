"""The contact split's cost on the pile, off and on, against the engine's step (issue 27).

Every box of a settled pile tracked and perceived (the default perception), the contact split
off, then on; each world's ``World.step`` against ``space.step`` of its own space in interleaved
blocks in one process (:func:`playground.bench.performance.split_row`, the rows ``playground
bench overhead`` prints): the overhead is the median of the ratios of adjacent blocks, minus 1.

    python benchmarks/split_pile.py                      # N = 10, 100, 1000
    python benchmarks/split_pile.py --sizes 10 --repeats 31
"""

from __future__ import annotations

import argparse

from playground.bench.performance import SPLIT_SIZES, split_row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="*", default=list(SPLIT_SIZES))
    parser.add_argument("--repeats", type=int, default=21)
    args = parser.parse_args()
    print("| N | split | overhead / bare (blocks) | bare µs |")
    print("|---|---|---|---|")
    for n in args.sizes:
        for split in (False, True):
            r = split_row(n, split, args.repeats)
            print(
                f"| {n} | {'on' if split else 'off'} | {r.overhead:.2f}× "
                f"({r.ratio_lo - 1:.2f}–{r.ratio_hi - 1:.2f}) | {r.base_us:.0f} |",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
