"""The contact split's cost on the pile, off and on, against the engine's step (issue 27).

Every box of a settled pile tracked and perceived (the default perception), the contact split
off, then on; each world's ``World.step`` against ``space.step`` of its own space in interleaved
blocks in one process (:func:`playground.bench.performance.split_row`, the rows ``playground
bench overhead`` prints): the overhead is the median of the ratios of adjacent blocks, minus 1.

    python benchmarks/split_pile.py                      # N = 10, 100, 1000
    python benchmarks/split_pile.py --sizes 10 --repeats 31
    python benchmarks/split_pile.py --on-off             # split on against split off
    python benchmarks/split_pile.py --crossover          # the scalar sums: one read or walks

``--on-off`` times the world with the split on against the same world with it off (and that one
against the bare step) in interleaved blocks: what the split itself adds, in bare steps, is
(on / off − 1) × off / bare, less noisy than the difference of two overheads.

``--crossover`` times the scalar implementation's two ways of summing the tracked bodies' arbiter
impulses (:class:`~playground.forces.scalar.contacts.ContactSums`), one read of every arbiter
against a walk over each tracked body's, on piles of N boxes with R of them tracked (N:R), in
interleaved blocks: where the ratio passes 1 sets ``ONE_READ_MIN_ROWS`` (every box tracked) and
``ONE_READ_BODIES_PER_ROW`` (untracked boxes too).
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from contextlib import contextmanager

from playground.bench.blocks import interleave
from playground.bench.performance import SPLIT_SIZES, split_row
from playground.bench.pile import pile_names, pile_world
from playground.forces.scalar import contacts
from playground.forces.scalar.row import Row
from playground.world.config import WorldConfig

CROSSOVER = ("1:1", "2:2", "3:3", "4:4", "10:10", "28:28", "10:1", "20:2", "40:4", "80:8",
             "40:2", "80:4", "200:10")  # fmt: skip
"""Piles N:R timed by ``--crossover``."""


@contextmanager
def _crossover(min_rows: int, bodies_per_row: int) -> Iterator[None]:
    saved = contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW
    contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW = min_rows, bodies_per_row
    try:
        yield
    finally:
        contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW = saved


def on_off_row(n: int, repeats: int) -> tuple[float, float, float]:
    """(on / off, off / bare, what the split adds in bare steps) on a settled pile of ``n``."""
    worlds = []
    for split in (True, False):
        world = pile_world(n, WorldConfig(contact_split=split))
        world.track(*pile_names(n))
        for _ in range(30):
            world.step()
        worlds.append(world)
    on, off = worlds
    space, dt = off.space, off.config.dt
    ratio = interleave(on.step, off.step, repeats=repeats).ratio
    base = interleave(off.step, lambda: space.step(dt), repeats=repeats).ratio
    return ratio, base, (ratio - 1.0) * base


def crossover_row(n: int, tracked: int, repeats: int) -> tuple[float, float, float, float]:
    """One read / walks on a settled pile of ``n`` boxes, ``tracked`` of them: (median ratio,
    lowest, highest, walks µs)."""
    world = pile_world(n, WorldConfig(contact_split=True))
    for _ in range(30):
        world.step()
    space = world.space
    rows = [Row(world.body(name)) for name in pile_names(n)[:tracked]]
    walk, one = contacts.ContactSums(), contacts.ContactSums()

    def walks() -> None:
        with _crossover(10**9, 0):
            walk.accumulate(rows, space, 5, False, fresh=True)

    def one_read() -> None:
        with _crossover(1, 10**9):
            one.accumulate(rows, space, 5, False, fresh=True)

    t = interleave(one_read, walks, repeats=repeats)
    lo, hi = t.spread
    return t.ratio, lo, hi, 1e6 * t.b_median


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="*", default=list(SPLIT_SIZES))
    parser.add_argument("--repeats", type=int, default=21)
    parser.add_argument("--crossover", action="store_true", help="one read against walks")
    parser.add_argument("--on-off", action="store_true", help="split on against split off")
    args = parser.parse_args()
    if args.on_off:
        print("| N | on / off | off / bare | the split adds, × bare |")
        print("|---|---|---|---|")
        for n in args.sizes:
            ratio, base, adds = on_off_row(n, args.repeats)
            print(f"| {n} | {ratio:.3f} | {base:.2f} | {adds:.2f} |", flush=True)
        return 0
    if args.crossover:
        print(f"ONE_READ_MIN_ROWS = {contacts.ONE_READ_MIN_ROWS}, "
              f"ONE_READ_BODIES_PER_ROW = {contacts.ONE_READ_BODIES_PER_ROW}\n")  # fmt: skip
        print("| N boxes | tracked | one read / walks (blocks) | walks µs |")
        print("|---|---|---|---|")
        for spec in CROSSOVER:
            n, tracked = map(int, spec.split(":"))
            ratio, lo, hi, us = crossover_row(n, tracked, args.repeats)
            print(f"| {n} | {tracked} | {ratio:.2f} ({lo:.2f}–{hi:.2f}) | {us:.1f} |", flush=True)
        return 0
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
