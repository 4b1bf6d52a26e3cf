"""The robustness matrix: every shipped level × the 27 variants of playground.scene.robustness
(player mass ×0.5, ×1, ×2 × dt 1/60, 1/120, 1/240 s × substeps 1, 2, 4), as a Markdown table.

    python benchmarks/matrix.py                      # every shipped level, 2 processes
    python benchmarks/matrix.py crusher planet -v    # two levels, each failing check's detail
    python benchmarks/matrix.py --workers 1 --json out.json

Each cell holds one mark per variant at that mass, ordered dt 1/60, 1/120, 1/240 (groups) ×
substeps 1, 2, 4: ``P`` passes, ``d`` fails and is declared unsupported by the level
(``[[variants.unsupported]]``), ``S`` is declared but passes (a stale declaration), ``F`` fails
undeclared, ``·`` does not exist (no player to scale). The last lines say how long it took: the
wall time, and the CPU time the runs took (what the slow tier adds to a serial ``pytest``).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from playground.level import shipped
from playground.scene.robustness import DTS, MASS_FACTORS, SUBSTEPS, VARIANTS, Outcome, run

MARKS = {"pass": "P", "declared": "d", "stale": "S", "fail": "F", "none": "·"}


def _one(job: tuple[str, str, int]) -> Outcome:
    name, path, index = job
    return run(Path(path), name, VARIANTS[index])


def table(outcomes: list[Outcome]) -> list[str]:
    """The Markdown table: a row per level, a column per mass, and the counts."""
    levels = sorted({o.level for o in outcomes})
    head = " / ".join(f"1/{round(1 / dt)}" for dt in DTS)
    lines = [
        f"| level | {' | '.join(f'm×{m:g}' for m in MASS_FACTORS)} | pass | declared | fail |",
        "|---|" + "---|" * (len(MASS_FACTORS) + 3),
    ]
    for level in levels:
        mine = {o.variant: o for o in outcomes if o.level == level}
        cells = []
        for m in MASS_FACTORS:
            groups = []
            for dt in DTS:
                marks = "".join(
                    MARKS[mine[v].verdict]
                    for v in VARIANTS
                    if v.mass == m and v.dt == dt and v in mine
                )
                groups.append(marks)
            cells.append(f"`{' '.join(groups)}`")
        verdicts = [o.verdict for o in mine.values()]
        fails = verdicts.count("fail") + verdicts.count("stale")
        lines.append(
            f"| {level} | {' | '.join(cells)} | {verdicts.count('pass')} | "
            f"{verdicts.count('declared')} | {fails} |"
        )
    lines.append("")
    lines.append(
        f"Each cell: dt {head} s (groups) × substeps {', '.join(map(str, SUBSTEPS))}; "
        "P pass, d declared unsupported, S declared but passes, F fails, · no player."
    )
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("levels", nargs="*", help="level names (default: every shipped level)")
    parser.add_argument("--workers", type=int, default=2, help="processes (default 2)")
    parser.add_argument("-v", "--verbose", action="store_true", help="each failure's detail")
    parser.add_argument("--json", type=Path, help="also write every outcome here")
    args = parser.parse_args(argv)
    levels = shipped()
    names = args.levels or sorted(levels)
    jobs = [(n, str(levels[n]), i) for n in names for i in range(len(VARIANTS))]
    start, cpu = time.perf_counter(), os.times()
    if args.workers > 1:
        with ProcessPoolExecutor(args.workers) as pool:
            outcomes = list(pool.map(_one, jobs, chunksize=1))
    else:
        outcomes = [_one(j) for j in jobs]
    wall = time.perf_counter() - start
    end = os.times()
    used = (end.user - cpu.user) + (end.children_user - cpu.children_user)
    used += (end.system - cpu.system) + (end.children_system - cpu.children_system)
    print("\n".join(table(outcomes)))
    ran = [o for o in outcomes if o.verdict != "none"]
    print(
        f"\n{len(ran)} runs in {wall:.1f} s wall, {sum(o.seconds for o in ran):.1f} s of runs, "
        f"{used:.1f} s CPU, {args.workers} process(es); load average {os.getloadavg()[0]:.1f}"
    )
    if args.verbose:
        for o in outcomes:
            if o.verdict in ("fail", "stale", "declared"):
                print(f"\n{o.level} {o.variant.label}: {o.verdict}")
                for d in o.declared:
                    print(f"  declared: {d}")
                if o.error:
                    print(f"  error: {o.error}")
                for f in o.details:
                    print(f"  - {f}")
    if args.json is not None:
        rows = [
            {
                "level": o.level,
                "variant": o.variant.label,
                "verdict": o.verdict,
                "failed": list(o.failed),
                "details": list(o.details),
                "error": o.error,
                "seconds": o.seconds,
            }
            for o in outcomes
        ]
        args.json.write_text(json.dumps(rows, indent=1) + "\n", encoding="utf-8")
    return 1 if any(o.verdict in ("fail", "stale") for o in outcomes) else 0


if __name__ == "__main__":
    sys.exit(main())
