"""A level with many timed events, and how long ``playground run`` takes on it.

The events are tiny impulses on one crate resting on the ground, spread evenly over the run,
several to a step, so the schedule holds tens of thousands of pending events at once (what a
quadratic schedule pays for) while the physics stays trivial.

    python benchmarks/many_events.py --events 100000            # write, run, print the seconds
    python benchmarks/many_events.py --events 100000 --out big.toml --no-run
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SECONDS = 10.0
"""Simulated seconds of the level (1200 steps at the default dt)."""


def level_text(events: int, seconds: float = SECONDS) -> str:
    """TOML of a one-crate level with ``events`` impulses at times spread over ``seconds``."""
    head = f'''title = "Many events"
description = "{events} tiny impulses on a crate resting on the ground."

[settings]
seconds = {seconds!r}

[[geometry]]
kind = "segment"
a = [-50.0, 0.0]
b = [50.0, 0.0]

[[props]]
name = "crate"
position = [0.0, 0.5]
mass = 10.0
shapes = [{{ kind = "box", size = [1.0, 1.0] }}]
'''
    # Times walked backwards, so scheduling in file order inserts every event before the others.
    rows = [
        f'[[events]]\nkind = "impulse"\nt = {seconds * (events - k) / (events + 1)!r}\n'
        f'body = "crate"\nimpulse = [0.0, 1e-6]\n'
        for k in range(events)
    ]
    return head + "\n" + "\n".join(rows)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--events", type=int, default=100_000)
    p.add_argument("--out", type=Path, help="write the level here (default: a temporary file)")
    p.add_argument("--no-run", action="store_true", help="only write the level")
    args = p.parse_args(argv)
    text = level_text(args.events)
    with tempfile.TemporaryDirectory() as tmp:
        path = args.out or Path(tmp) / "many_events.toml"
        path.write_text(text, encoding="utf-8")
        if args.no_run:
            print(path)
            return 0
        start = time.perf_counter()
        done = subprocess.run(
            [sys.executable, "-m", "playground", "run", str(path), "--no-progress"],
            capture_output=True,
            text=True,
        )
        wall = time.perf_counter() - start
        print(done.stdout.strip() or done.stderr.strip())
        print(f"{args.events} events: playground run took {wall:.2f} s (exit {done.returncode})")
        return done.returncode


if __name__ == "__main__":
    sys.exit(main())
