"""The ``faults`` command: levels run clean and under each break they declare to catch (see
:mod:`playground.faults`), as a matrix or one JSON object."""

from __future__ import annotations

import argparse
import importlib
import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from playground.cli.exits import EXIT_FAILED, EXIT_OK, EXIT_USAGE
from playground.cli.levelfiles import add_set_option, load_checked
from playground.level.errors import LevelError
from playground.level.files import find, shipped

__all__ = ["cmd_faults", "configure"]


def cmd_faults(args: argparse.Namespace) -> int:
    """Run levels clean and under each break they declare (see :mod:`playground.faults`); exit 1
    when a declared break goes uncaught, a clean run fails or a break cannot be applied."""
    from playground.faults.catalog import BREAKS, names
    from playground.faults.matrix import matrix

    known = names()
    if args.list:
        width = max(len(name) for name in known)
        for name in known:
            print(f"{name:<{width}}  {BREAKS[name].doc}")
        return EXIT_OK
    unknown = [b for b in args.breaks or [] if b not in known]
    if unknown:
        print(
            f"playground faults: no break named {', '.join(map(repr, unknown))} "
            f"(valid: {', '.join(known)})",
            file=sys.stderr,
        )
        return EXIT_USAGE
    try:
        items = args.levels or list(shipped())
        sets = tuple(args.sets)
        levels = [(_level_name(item), load_checked(find(item), sets)) for item in items]
    except LevelError as exc:
        print(f"playground faults: {exc}", file=sys.stderr)
        return EXIT_USAGE
    total = sum(1 + len(args.breaks or level.catches) for _, level in levels)
    bar = _progress(total, "faults") if sys.stderr.isatty() and not args.no_progress else None
    start = time.perf_counter()
    rows = matrix(
        levels, args.breaks, progress=None if bar is None else lambda label: bar.update(1)
    )
    if bar is not None:
        bar.close()
    wall = time.perf_counter() - start
    ok = all(row.ok for row in rows)
    if args.json:
        print(json.dumps(_faults_report(rows, ok, wall), indent=2))
    else:
        _print_matrix(rows, wall)
    return EXIT_OK if ok else EXIT_FAILED


def _level_name(item: str) -> str:
    return Path(item).stem if item.endswith(".toml") else item


def _progress(total: int, desc: str) -> Any:
    """A tqdm progress bar on stderr (None if tqdm, a dependency, cannot be imported)."""
    try:
        tqdm = importlib.import_module("tqdm").tqdm
    except ImportError:
        return None
    return tqdm(total=total, desc=desc, unit="run", leave=False)


def _outcome(o: Any) -> dict[str, Any]:
    return {
        "break": o.fault,
        "declared": o.declared,
        "ok": o.ok,
        "caught": bool(o.failed) and o.error is None,
        "caught_by": list(o.failed),
        "error": o.error,
        "wall_seconds": o.seconds,
    }


def _faults_report(rows: Sequence[Any], ok: bool, wall: float) -> dict[str, Any]:
    return {
        "ok": ok,
        "wall_seconds": wall,
        "levels": [
            {
                "level": row.level,
                "ok": row.ok,
                "checks": row.clean.checks,
                "clean": {
                    "passed": row.clean.ok,
                    "failed": list(row.clean.failed),
                    "error": row.clean.error,
                },
                "breaks": [_outcome(o) for o in row.breaks],
            }
            for row in rows
        ],
    }


def _print_matrix(rows: Sequence[Any], wall: float) -> None:
    """One line per level (its clean run) and one per break tried: which checks caught it."""
    width = max((len(o.fault or "") for row in rows for o in row.breaks), default=0)
    width = max(width, len("(clean)"))
    runs = 0
    for row in rows:
        clean = row.clean
        runs += 1 + len(row.breaks)
        if clean.error is not None:
            verdict = f"ERROR  {clean.error}"
        elif clean.failed:
            verdict = f"FAIL   {len(clean.failed)} check(s) fail: {'; '.join(clean.failed)}"
        else:
            verdict = f"ok     all {clean.checks} checks pass"
        print(f"{row.level}")
        print(f"  {'(clean)':<{width}}  {verdict}")
        for o in row.breaks:
            if o.error is not None:
                verdict = f"ERROR  {o.error}"
            elif o.failed:
                verdict = f"caught by {'; '.join(o.failed)}"
                verdict = f"{'ok' if o.declared else '(ok)':<6} {verdict}"
            elif o.declared:
                verdict = "MISSED no check failed"
            else:
                verdict = "-      not declared; no check failed"
            print(f"  {o.fault:<{width}}  {verdict}")
    bad = sum(1 for row in rows for o in (row.clean, *row.breaks) if not o.ok)
    summary = "all declared breaks caught" if bad == 0 else f"{bad} run(s) not ok"
    print(f"{len(rows)} level(s), {runs} runs in {wall:.1f} s: {summary}")


def configure(p: argparse.ArgumentParser) -> None:
    p.add_argument("levels", nargs="*", metavar="LEVEL", help="default: every shipped level")
    p.add_argument(
        "--break",
        dest="breaks",
        action="append",
        metavar="NAME",
        help="try this break on every level, declared or not (repeatable)",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--list", action="store_true", help="list the breaks and what each breaks")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    add_set_option(p)
    p.set_defaults(func=cmd_faults)
