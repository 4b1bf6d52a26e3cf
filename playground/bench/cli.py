"""The ``bench`` command line: ``accuracy``, ``overhead`` and ``docs`` subcommands.

``configure`` fills an argparse parser (the ``playground bench`` subcommand uses it too) and
``run`` executes the parsed arguments.

>>> parser = argparse.ArgumentParser(prog="bench")
>>> configure(parser)
>>> parser.parse_args(["accuracy", "--quick"]).quick
True
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from playground._preflight import needs, writable
from playground.bench import overhead, report
from playground.bench.accuracy import Result, plan, sweep

__all__ = ["configure", "main", "run"]

DEFAULT_REPEATS = 5
"""Timed blocks per point (the cost is their median)."""

QUICK_REPEATS = 2
"""Timed blocks per point with ``--quick``: enough to check the output, not to quote."""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the ``accuracy``, ``overhead`` and ``docs`` subcommands to ``parser``."""
    sub = parser.add_subparsers(dest="bench", required=True, metavar="{accuracy,overhead,docs}")
    acc = sub.add_parser("accuracy", help="sweep dt, iterations, estimators and filters")
    over = sub.add_parser("overhead", help="cost of each stage and effect as bodies grow")
    for p in (acc, over):
        p.add_argument("--quick", action="store_true", help="a small size for CI (seconds)")
        p.add_argument("--json", action="store_true", help="print every row as JSON on stdout")
        p.add_argument("--csv", type=Path, default=None, metavar="FILE", help="write the rows")
        p.add_argument("--figure", type=Path, default=None, metavar="PNG", help="draw the figure")
    acc.add_argument(
        "--workers", type=int, default=None, help="processes (default: CPU count; 0: in-process)"
    )
    for p in (acc, over):
        p.add_argument("--no-progress", action="store_true", help="no progress bar")
    docs = sub.add_parser("docs", help="regenerate docs/accuracy.md, its tables and figures")
    docs.add_argument("dir", type=Path, nargs="?", default=Path("docs"), help="default: docs")
    docs.add_argument("--quick", action="store_true", help="small sizes (to try the command)")
    docs.add_argument("--workers", type=int, default=None, help="processes for the sweep")


def _accuracy(args: argparse.Namespace) -> list[Result]:
    quick = bool(args.quick)
    return sweep(
        plan("quick" if quick else "default"),
        workers=args.workers,
        progress=not getattr(args, "no_progress", False),
        repeats=QUICK_REPEATS if quick else DEFAULT_REPEATS,
    )


def _preflight(args: argparse.Namespace) -> None:
    """Output folders and matplotlib checked before a sweep of minutes, not after it."""
    if args.bench == "docs":
        needs("matplotlib", "bench docs")
        return
    if args.csv is not None:
        writable("--csv", args.csv)
    if args.figure is not None:
        writable("--figure", args.figure)
        needs("matplotlib", "--figure")


def run(args: argparse.Namespace) -> int:
    """Run the parsed ``bench`` arguments; returns the exit status."""
    _preflight(args)
    progress = not getattr(args, "no_progress", False)
    if args.bench == "docs":
        t0 = time.perf_counter()
        rows = _accuracy(args)
        t1 = time.perf_counter()
        over = overhead.profile(quick=args.quick, progress=progress)
        t2 = time.perf_counter()
        fixed = overhead.fixed_cost()
        for path in report.write_docs(
            rows, over, args.dir, seconds=(t1 - t0, t2 - t1), fixed=fixed
        ):
            print(f"wrote {path}", file=sys.stderr)
        return 0
    if args.bench == "accuracy":
        rows = _accuracy(args)
        if args.csv is not None:
            args.csv.write_text(report.to_csv(rows), encoding="utf-8")
        if args.figure is not None:
            report.accuracy_figure(rows, args.figure)
        print(report.to_json(rows) if args.json else report.accuracy_markdown(rows))
        return 0
    rows_o = overhead.profile(quick=args.quick, progress=progress)
    if args.csv is not None:
        args.csv.write_text(report.to_csv(rows_o), encoding="utf-8")
    if args.figure is not None:
        overhead.overhead_figure(rows_o, args.figure)
    print(report.to_json(rows_o) if args.json else overhead.overhead_markdown(rows_o))
    return 0


def main(argv: list[str] | None = None) -> int:
    """``python -m playground.bench``: parse ``argv`` and run."""
    parser = argparse.ArgumentParser(
        prog="python -m playground.bench", description="accuracy and overhead benchmarks"
    )
    configure(parser)
    return run(parser.parse_args(argv))
