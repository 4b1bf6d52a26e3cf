"""A/B timing of every shipped level's step between two source trees (e.g. main and a branch).

Each round runs, for each level, one process per tree in alternating order; a process builds the
level, steps it through ``--warmup`` steps, then times ``--blocks`` blocks of ``--steps`` steps
and reports the median µs per step. The answer per level is the median over the rounds of the
ratio B/A of the two processes of a round (robust to load drifting during the run).

    python benchmarks/step_ab.py --a ../main --b . --rounds 7

Only the library and the levels of each tree are used: ``PYTHONPATH``, ``PLAYGROUND_LEVELS``
and the tree as the child's working directory (``python -c`` puts the working directory first on
``sys.path``: a child started in another checkout would import that one), so both run the same
script.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

_CHILD = """
import json, sys, time, statistics
from playground.level import find, load
from playground.scene import build
name, warmup, blocks, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
scene = build(load(find(name)))
step = scene.world.step
for _ in range(warmup):
    step()
times = []
for _ in range(blocks):
    t0 = time.perf_counter()
    for _ in range(steps):
        step()
    times.append((time.perf_counter() - t0) / steps * 1e6)
print(json.dumps(statistics.median(times)))
"""


def _env(tree: Path) -> dict[str, str]:
    """The environment of a child of ``tree``: its library first on the path and its own levels
    first (``$PLAYGROUND_LEVELS``; else an editable install's levels would be found)."""
    return {**os.environ, "PYTHONPATH": str(tree), "PLAYGROUND_LEVELS": str(tree / "levels")}


def levels(tree: Path) -> list[str]:
    """The shipped levels of ``tree`` (``playground list``)."""
    out = subprocess.run(
        [sys.executable, "-m", "playground", "list"],
        check=True,
        capture_output=True,
        text=True,
        env=_env(tree),
        cwd=tree,
    ).stdout
    return [line.split()[0] for line in out.splitlines() if line.strip()]


def time_level(tree: Path, level: str, warmup: int, blocks: int, steps: int) -> float:
    """Median µs per step of ``level`` run from ``tree``."""
    out = subprocess.run(
        [sys.executable, "-c", _CHILD, level, str(warmup), str(blocks), str(steps)],
        check=True,
        capture_output=True,
        text=True,
        env=_env(tree),
        cwd=tree,
    ).stdout
    return float(json.loads(out))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--a", type=Path, required=True, help="the reference tree")
    parser.add_argument("--b", type=Path, required=True, help="the tree compared with it")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=60)
    parser.add_argument("--blocks", type=int, default=9)
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--levels", nargs="*", help="default: every shipped level")
    parser.add_argument("--json", action="store_true", help="print the table as JSON")
    args = parser.parse_args()
    names = args.levels or levels(args.a.resolve())
    a, b = args.a.resolve(), args.b.resolve()
    rows = []
    for level in names:
        pairs = []
        for r in range(args.rounds):
            order = (a, b) if r % 2 == 0 else (b, a)
            t = {
                tree: time_level(tree, level, args.warmup, args.blocks, args.steps)
                for tree in order
            }
            pairs.append((t[a], t[b]))
        rows.append(
            {
                "level": level,
                "a_us": statistics.median(p[0] for p in pairs),
                "b_us": statistics.median(p[1] for p in pairs),
                "ratio": statistics.median(p[1] / p[0] for p in pairs),
            }
        )
        if not args.json:
            row = rows[-1]
            print(
                f"{level:16s} {row['a_us']:7.1f} {row['b_us']:7.1f}  {row['ratio']:.3f}x",
                flush=True,
            )
    if args.json:
        print(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
