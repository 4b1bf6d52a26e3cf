"""The accuracy sweep summarised one knob at a time as Markdown tables: error against dt, solver
iterations and substeps, the force estimators, the filters (reverse integration and no filter
unless a table says otherwise).
"""

from __future__ import annotations

import statistics
from collections.abc import Sequence

from playground.bench.accuracy import DTS, FILTERS, ITERATIONS, SUBSTEPS, Result
from playground.bench.markdown import dt_label, pct, table
from playground.bench.scenes import SCENES, Knobs
from playground.bench.sweep_rows import BASE, bookkeeping, pick

__all__ = ["accuracy_markdown"]


def _knob_table(rows: Sequence[Result], columns: Sequence[tuple[str, Knobs]]) -> str | None:
    picks = [(label, pick(rows, k)) for label, k in columns]
    picks = [(label, p) for label, p in picks if p]
    if len(picks) < 2:
        return None
    body = []
    books = set(bookkeeping(rows))
    for scene in SCENES:
        label = f"{scene} (bookkeeping)" if scene in books else scene
        body.append([label, *(pct(p[scene].error) if scene in p else "–" for _, p in picks)])
    body.append(
        [
            "cost, µs/step",
            *(f"{statistics.median(r.cost_us for r in p.values()):.0f}" for _, p in picks),
        ]
    )
    body.append(
        [
            "× bare pymunk",
            *(f"{statistics.median(r.ratio for r in p.values()):.0f}" for _, p in picks),
        ]
    )
    return table(["scene", *(label for label, _ in picks)], body)


def _estimator_table(rows: Sequence[Result]) -> str | None:
    by = {e: pick(rows, BASE, e) for e in ("reverse", "contact", "finite-difference")}
    by = {e: p for e, p in by.items() if p}
    if len(by) < 2:
        return None
    body = [[s, *(pct(p[s].error) if s in p else "–" for p in by.values())] for s in SCENES]
    body.append(
        [
            "cost, µs/step",
            *(f"{statistics.median(r.cost_us for r in p.values()):.0f}" for p in by.values()),
        ]
    )
    return table(["scene", *by], body)


def _filter_table(rows: Sequence[Result]) -> str | None:
    body = []
    for name in FILTERS:
        p = pick(rows, BASE, "reverse", name)
        if not p:
            continue
        errors = [r.error for r in p.values()]
        any_row = next(iter(p.values()))
        filter_us = any_row.cost_us - pick(rows, BASE)[any_row.scene].cost_us
        body.append(
            [
                name,
                pct(statistics.median(errors)),
                pct(p["hover"].error) if "hover" in p else "–",
                pct(p["stack"].jitter) if "stack" in p else "–",
                pct(p["ring"].jitter) if "ring" in p else "–",
                f"{1000 * any_row.lag:.0f}",
                f"{filter_us:.0f}",
            ]
        )
    if not body:
        return None
    header = [
        "filter",
        "median error",
        "hover error",
        "stack jitter",
        "ring jitter",
        "ramp lag, ms",
        "filter µs/step",
    ]
    return table(header, body)


def accuracy_markdown(rows: Sequence[Result]) -> str:
    """The sweep summarised one knob at a time (reverse integration, no filter, unless noted)."""
    parts = []
    sections = [
        (
            "Error against dt (1 substep, 10 iterations)",
            _knob_table(rows, [(dt_label(dt), Knobs(dt=dt)) for dt in DTS]),
        ),
        (
            "Error against solver iterations (dt = 1/120 s)",
            _knob_table(rows, [(str(i), Knobs(iterations=i)) for i in ITERATIONS]),
        ),
        (
            "Substeps at dt = 1/30 s, against dt = 1/120 s",
            _knob_table(
                rows,
                [
                    ("1/30 × 1", Knobs(dt=1 / 30)),
                    *((f"1/30 × {n}", Knobs(dt=1 / 30, substeps=n)) for n in SUBSTEPS),
                    ("1/120 × 1", BASE),
                ],
            ),
        ),
        ("Force estimators (dt = 1/120 s, 10 iterations, no filter)", _estimator_table(rows)),
        ("Filters (dt = 1/120 s, 10 iterations, reverse integration)", _filter_table(rows)),
    ]
    for title, text in sections:
        if text is not None:
            parts.append(f"### {title}\n\n{text}\n")
    return "\n".join(parts)
