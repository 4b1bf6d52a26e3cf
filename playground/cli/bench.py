"""The ``bench`` command line: ``accuracy``, ``overhead``, ``performance`` and ``docs`` subcommands.

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
import sys
import time
from pathlib import Path

from playground.bench import guide, overhead, performance, report
from playground.bench.accuracy import Result, plan, sweep
from playground.bench.accuracy_figure import accuracy_figure
from playground.bench.accuracy_tables import accuracy_markdown
from playground.bench.export import to_csv, to_json
from playground.bench.guide_report import guide_markdown
from playground.bench.measurement import Measurement
from playground.bench.performance_page import performance_doc, summary_markdown
from playground.cli.preflight import UsageError, needs, writable

__all__ = ["configure", "main", "run"]

DEFAULT_REPEATS = 5
"""Timed blocks per point (the cost is their median)."""

QUICK_REPEATS = 2
"""Timed blocks per point with ``--quick``: enough to check the output, not to quote."""

QUICK_LEVELS = ("rest",)
"""Levels timed with ``--quick``."""

QUICK_SIZES = (10, 1000)
"""Piles timed with ``--quick``: the smallest and the smallest large size of the goals."""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the ``accuracy``, ``overhead``, ``performance``, ``guide`` and ``docs`` subcommands."""
    sub = parser.add_subparsers(
        dest="bench", required=True, metavar="{accuracy,overhead,performance,guide,docs}"
    )
    acc = sub.add_parser("accuracy", help="sweep dt, iterations, estimators and filters")
    over = sub.add_parser(
        "overhead", help="every level and the pile against the engine, the goals, each effect"
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
    perf = sub.add_parser("performance", help="write docs/performance.md (measures, or --from)")
    perf.add_argument(
        "--out", type=Path, default=Path("docs/performance.md"), help="default: %(default)s"
    )
    perf.add_argument(
        "--from",
        dest="source",
        type=Path,
        default=None,
        metavar="JSON",
        help="the output of `bench overhead --json` (default: measure now)",
    )
    perf.add_argument("--quick", action="store_true", help="one level, small piles (to try it)")
    perf.add_argument("--no-progress", action="store_true", help="no progress bar")
    gd = sub.add_parser("guide", help="the settings guide: knobs against game-felt measures")
    gd.add_argument("--json", action="store_true", help="print every run as JSON on stdout")
    gd.add_argument("--no-progress", action="store_true", help="no progress bar")
    docs = sub.add_parser("docs", help="regenerate docs/accuracy.md, its tables and figures")
    docs.add_argument("dir", type=Path, nargs="?", default=Path("docs"), help="default: docs")
    docs.add_argument("--quick", action="store_true", help="small sizes (to try the command)")
    docs.add_argument("--workers", type=int, default=None, help="processes for the sweep")
    docs.add_argument("--no-progress", action="store_true", help="no progress bar")


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
    if args.bench == "guide":
        return  # prints to stdout: nothing to check beforehand
    if args.bench == "performance":
        writable("--out", args.out)
        return
    if args.csv is not None:
        writable("--csv", args.csv, force=args.force)
    if args.figure is not None:
        writable("--figure", args.figure, force=args.force)
        needs("matplotlib", "--figure")


def run(args: argparse.Namespace) -> int:
    """Run the parsed ``bench`` arguments; returns the exit status."""
    _preflight(args)
    progress = not getattr(args, "no_progress", False)
    if args.bench == "guide":
        t0 = time.perf_counter()
        runs = guide.guide(progress=progress)
        hover = guide.hover_table()
        if args.json:
            print(to_json(runs))
        else:
            print(guide_markdown(runs, hover, time.perf_counter() - t0))
        return 0
    if args.bench == "docs":
        t0 = time.perf_counter()
        rows = _accuracy(args)
        t1 = time.perf_counter()
        over = overhead.profile(quick=args.quick, progress=progress)
        t2 = time.perf_counter()
        fixed = overhead.fixed_cost()
        runs = guide.guide(progress=progress)
        hover = guide.hover_table()
        t3 = time.perf_counter()
        for path in report.write_docs(
            rows,
            over,
            args.dir,
            seconds=(t1 - t0, t2 - t1),
            fixed=fixed,
            guide=(runs, hover, t3 - t2),
        ):
            print(f"wrote {path}", file=sys.stderr)
        return 0
    if args.bench == "accuracy":
        rows = _accuracy(args)
        if args.csv is not None:
            args.csv.write_text(to_csv(rows), encoding="utf-8")
        if args.figure is not None:
            accuracy_figure(rows, args.figure)
        print(to_json(rows) if args.json else accuracy_markdown(rows))
        return 0
    if args.bench == "performance":
        if args.source is not None:
            try:
                data = json.loads(args.source.read_text(encoding="utf-8"))
                m = performance.from_dict(data, source=str(args.source))
            except (json.JSONDecodeError, ValueError) as exc:
                raise UsageError(f"--from: {exc}") from None
        else:
            m = _measure(args.quick, progress, "playground bench performance")
        args.out.write_text(performance_doc(m), encoding="utf-8")
        print(f"wrote {args.out}", file=sys.stderr)
        return 0
    command = "playground bench overhead" + (" --quick" if args.quick else "") + " --json"
    m = _measure(args.quick, progress, command)
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


def _measure(quick: bool, progress: bool, command: str) -> Measurement:
    """The levels, the piles and the goals (``quick``: one level, two piles, 2 blocks)."""
    if quick:
        return performance.measure(
            levels=QUICK_LEVELS,
            sizes=QUICK_SIZES,
            field_bodies=QUICK_SIZES[-1],
            crossover=(1, 32),
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
