"""The ``bench`` command line: the ``accuracy`` and ``overhead`` subcommands.

``configure`` fills an argparse parser (the ``playground bench`` subcommand uses it too) and
``run`` executes the parsed arguments.

>>> parser = argparse.ArgumentParser(prog="bench")
>>> configure(parser)
>>> parser.parse_args(["accuracy", "--quick"]).quick
True
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from playground.bench import overhead, performance
from playground.bench.accuracy import Result, plan, sweep
from playground.bench.accuracy_figure import accuracy_figure
from playground.bench.accuracy_tables import accuracy_markdown
from playground.bench.export import to_csv, to_json
from playground.bench.measurement import Measurement
from playground.bench.performance_tables import summary_markdown
from playground.cli.preflight import needs, writable

__all__ = ["accuracy_rows", "configure", "main", "measure_run", "run"]

DEFAULT_REPEATS = 5
"""Timed blocks per point (the cost is their median)."""

QUICK_REPEATS = 2
"""Timed blocks per point with ``--quick``: enough to check the output, not to quote."""

QUICK_LEVELS = ("rest",)
"""Levels timed with ``--quick``."""

QUICK_SIZES = (10, 1000)
"""Piles timed with ``--quick``: the smallest and the smallest large size the goals quote."""

QUICK_CROWDS = (1, 10)
"""Crowds (actors) timed with ``--quick``."""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the ``accuracy`` and ``overhead`` subcommands."""
    sub = parser.add_subparsers(dest="bench", required=True, metavar="{accuracy,overhead}")
    acc = sub.add_parser("accuracy", help="sweep dt, iterations, estimators and filters")
    over = sub.add_parser(
        "overhead", help="every level and the pile against the engine, each effect"
    )
    for p in (acc, over):
        p.add_argument("--quick", action="store_true", help="a small size for CI (seconds)")
        p.add_argument("--json", action="store_true", help="print every row as JSON on stdout")
        p.add_argument("--csv", type=Path, default=None, metavar="FILE", help="write the rows")
        p.add_argument("--figure", type=Path, default=None, metavar="PNG", help="draw the figure")
        p.add_argument("--force", action="store_true", help="overwrite existing --csv, --figure")
    acc.add_argument(
        "--workers", type=int, default=None, help="processes (default: CPU count; 0: in-process)"
    )
    for p in (acc, over):
        p.add_argument("--no-progress", action="store_true", help="no progress bar")


def accuracy_rows(quick: bool, workers: int | None, progress: bool) -> list[Result]:
    """The accuracy sweep: its default plan, or with ``quick`` the small one in fewer blocks."""
    return sweep(
        plan("quick" if quick else "default"),
        workers=workers,
        progress=progress,
        repeats=QUICK_REPEATS if quick else DEFAULT_REPEATS,
    )


def _preflight(args: argparse.Namespace) -> None:
    """Output files and matplotlib checked before a sweep of minutes, not after it."""
    if args.csv is not None:
        writable("--csv", args.csv, force=args.force)
    if args.figure is not None:
        writable("--figure", args.figure, force=args.force)
        needs("matplotlib", "--figure")


def run(args: argparse.Namespace) -> int:
    """Run the parsed ``bench`` arguments; returns the exit status."""
    _preflight(args)
    progress = not args.no_progress
    if args.bench == "accuracy":
        rows = accuracy_rows(args.quick, args.workers, progress)
        if args.csv is not None:
            args.csv.write_text(to_csv(rows), encoding="utf-8")
        if args.figure is not None:
            accuracy_figure(rows, args.figure)
        print(to_json(rows) if args.json else accuracy_markdown(rows))
        return 0
    command = "playground bench overhead" + (" --quick" if args.quick else "") + " --json"
    m = measure_run(args.quick, progress, command)
    rows_o = overhead.profile(quick=args.quick, progress=progress)
    if args.csv is not None:
        args.csv.write_text(to_csv(rows_o), encoding="utf-8")
    if args.figure is not None:
        overhead.overhead_figure(rows_o, args.figure)
    if args.json:
        data = {**m.to_dict(), "effects": json.loads(to_json(rows_o))}
        print(json.dumps(data, indent=1, ensure_ascii=False))
    else:
        print(summary_markdown(m) + "\n" + overhead.overhead_markdown(rows_o))
    return 0


def measure_run(quick: bool, progress: bool, command: str) -> Measurement:
    """The levels, the piles and the crowds (``quick``: one level, two piles, two crowds, 2
    blocks)."""
    if quick:
        return performance.measure(
            levels=QUICK_LEVELS,
            sizes=QUICK_SIZES,
            field_bodies=QUICK_SIZES[-1],
            crossover=(1, 32),
            split_sizes=QUICK_SIZES,
            crowds=QUICK_CROWDS,
            repeats=QUICK_REPEATS,
            progress=progress,
            command=command,
        )
    return performance.measure(progress=progress, command=command)


def main(argv: list[str] | None = None) -> int:
    """``python -m playground.bench``: parse ``argv`` and run."""
    parser = argparse.ArgumentParser(
        prog="python -m playground.bench", description="accuracy and overhead benchmarks"
    )
    configure(parser)
    return run(parser.parse_args(argv))
