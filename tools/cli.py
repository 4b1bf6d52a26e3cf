"""The repository tools' command line: ``performance``, ``costs``, ``docs``, ``guide``,
``figures``.

Each regenerates something this repository publishes from the installed package's measurements
(:mod:`playground.bench`): docs/performance.md, docs/accuracy.md and its files, the settings
guide, the chapters' figures. Run from the checkout's root: ``python -m tools performance``.

>>> args = parser().parse_args(["performance", "--from", "perf.json"])
>>> args.tool, str(args.source)
('performance', 'perf.json')
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from playground.bench import overhead, performance
from playground.cli import bench as bench_cli
from playground.cli.exits import guarded
from playground.cli.preflight import UsageError, needs, writable
from tools import costs, guide
from tools.accuracy_page import write_docs
from tools.guide_report import guide_markdown
from tools.performance_page import performance_doc

__all__ = ["COSTS_JSON", "TOOLS", "main", "parser"]

COSTS_JSON = Path("docs/costs.json")
"""Where ``costs`` writes and ``performance`` reads the small costs (from the checkout's root)."""


def parser() -> argparse.ArgumentParser:
    """The parser: one subcommand per generated thing."""
    top = argparse.ArgumentParser(
        prog="python -m tools", description="regenerate the repository's pages and figures"
    )
    sub = top.add_subparsers(
        dest="tool", required=True, metavar="{performance,costs,docs,guide,figures}"
    )
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
        help="the output of `playground bench overhead --json` (default: measure now)",
    )
    perf.add_argument("--quick", action="store_true", help="one level, small piles (to try it)")
    perf.add_argument(
        "--costs",
        type=Path,
        default=COSTS_JSON,
        metavar="JSON",
        help="the output of `python -m tools costs`, the page's last section (default: "
        "%(default)s; left out if missing)",
    )
    cst = sub.add_parser("costs", help="time the small costs the code is shaped by (JSON)")
    cst.add_argument("--out", type=Path, default=COSTS_JSON, help="default: %(default)s")
    docs = sub.add_parser("docs", help="regenerate docs/accuracy.md, its tables and figures")
    docs.add_argument("dir", type=Path, nargs="?", default=Path("docs"), help="default: docs")
    docs.add_argument("--quick", action="store_true", help="small sizes (to try the command)")
    docs.add_argument("--workers", type=int, default=None, help="processes for the sweep")
    gd = sub.add_parser("guide", help="the settings guide: knobs against game-felt measures")
    gd.add_argument("--json", action="store_true", help="print every run as JSON on stdout")
    fig = sub.add_parser("figures", help="regenerate the teaching chapters' figures (headless)")
    fig.add_argument(
        "--out", type=Path, default=Path("docs/img/chapters"), help="default: %(default)s"
    )
    for p in (perf, cst, docs, gd, fig):
        p.add_argument("--no-progress", action="store_true", help="no progress bar")
    return top


def _json(option: str, path: Path) -> dict[str, Any]:
    try:
        data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise UsageError(f"{option}: {exc}") from None
    return data


def _performance(args: argparse.Namespace, progress: bool) -> int:
    # Overwriting is the point: the page is generated, and git holds the one it replaces.
    writable("--out", args.out, force=True)
    small = None
    if args.costs.exists():
        data = _json("--costs", args.costs)
        try:
            small = (costs.from_dict(data, source=str(args.costs)), data)
        except ValueError as exc:
            raise UsageError(f"--costs: {exc}") from None
    if args.source is not None:
        try:
            m = performance.from_dict(_json("--from", args.source), source=str(args.source))
        except ValueError as exc:
            raise UsageError(f"--from: {exc}") from None
    else:
        m = bench_cli.measure_run(args.quick, progress, "python -m tools performance")
    args.out.write_text(performance_doc(m, small), encoding="utf-8")
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def _costs(args: argparse.Namespace, progress: bool) -> int:
    writable("--out", args.out, force=True)  # generated, as the page
    args.out.write_text(json.dumps(costs.measure(), indent=1) + "\n", encoding="utf-8")
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def _docs(args: argparse.Namespace, progress: bool) -> int:
    needs("matplotlib", "python -m tools docs")
    t0 = time.perf_counter()
    rows = bench_cli.accuracy_rows(args.quick, args.workers, progress)
    t1 = time.perf_counter()
    over = overhead.profile(quick=args.quick, progress=progress)
    t2 = time.perf_counter()
    fixed = overhead.fixed_cost()
    runs = guide.guide(progress=progress)
    hover = guide.hover_table()
    t3 = time.perf_counter()
    for path in write_docs(
        rows, over, args.dir, seconds=(t1 - t0, t2 - t1), fixed=fixed, guide=(runs, hover, t3 - t2)
    ):
        print(f"wrote {path}", file=sys.stderr)
    return 0


def _guide(args: argparse.Namespace, progress: bool) -> int:
    from playground.bench.export import to_json

    t0 = time.perf_counter()
    runs = guide.guide(progress=progress)
    hover = guide.hover_table()
    print(to_json(runs) if args.json else guide_markdown(runs, hover, time.perf_counter() - t0))
    return 0


def _figures(args: argparse.Namespace, progress: bool) -> int:
    needs("matplotlib", "python -m tools figures")
    from tools.figures import make_all

    for path in make_all(args.out, progress=progress):
        print(f"wrote {path}")
    return 0


TOOLS = {
    "performance": _performance,
    "costs": _costs,
    "docs": _docs,
    "guide": _guide,
    "figures": _figures,
}
"""Each subcommand's function: the parsed arguments and whether to show progress → exit code."""


def main(argv: Sequence[str] | None = None) -> int:
    """Parse ``argv`` and run the tool; a usage error is one line on stderr, exit 2."""
    args = parser().parse_args(argv)
    tool = TOOLS[args.tool]
    return guarded(f"python -m tools {args.tool}", lambda: tool(args, not args.no_progress))
