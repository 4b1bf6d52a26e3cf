"""A world's step in instructions, for callgrind: build a crowd, a level or the pile, step it K
times.

The world is a crowd of :mod:`playground.bench.crowd` (``--actors N`` patrolling enemies,
settled), a shipped level's scene (``--level NAME``, as ``playground run`` builds it) or the
benchmarks' pile (``--pile N`` boxes, every one tracked and perceived, settled; ``--split``: with
the contact split, as ``benchmarks/split_pile.py`` times it; ``--bare``: its space's step only).
Run it under callgrind twice, with ``--steps 0`` and with ``--steps K``: the difference of the two
totals over K is the instructions of one step, free of imports and of building the world (a
count, not a time, so it holds on a loaded machine; fix ``PYTHONHASHSEED`` so both runs hash
alike).

    export PYTHONHASHSEED=0
    valgrind --tool=callgrind python benchmarks/step_instructions.py --actors 200 --steps 0
    valgrind --tool=callgrind python benchmarks/step_instructions.py --actors 200 --steps 60
    valgrind --tool=callgrind python benchmarks/step_instructions.py --level rest --steps 1000
    valgrind --tool=callgrind python benchmarks/step_instructions.py --pile 10 --split --steps 500
"""

from __future__ import annotations

import argparse
import gc

from playground.bench.crowd import crowd_world
from playground.bench.pile import pile_names, pile_world
from playground.level import find, load
from playground.scene import build
from playground.world.config import WorldConfig
from playground.world.world import World


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--actors", type=int, default=200, help="a crowd of N (the default)")
    which.add_argument("--level", help="a shipped level's scene instead")
    which.add_argument("--pile", type=int, help="the pile of N boxes instead")
    parser.add_argument("--split", action="store_true", help="the pile with the contact split")
    parser.add_argument("--bare", action="store_true", help="step the pile's space only")
    parser.add_argument("--steps", type=int, default=60)
    args = parser.parse_args()
    world: World
    if args.pile is not None:
        world = pile_world(args.pile, WorldConfig(contact_split=args.split))
        world.track(*pile_names(args.pile))
        for _ in range(30):
            world.step()
    elif args.level:
        world = build(load(find(args.level))).world
    else:
        world = crowd_world(args.actors)
    # No cycle collection while stepping: one falling inside one run and not the other (their
    # counts of allocations differ) would count as the steps'.
    gc.collect()
    gc.disable()
    space, dt = world.space, world.config.dt
    for _ in range(args.steps):
        if args.bare:
            space.step(dt)
        else:
            world.step()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
