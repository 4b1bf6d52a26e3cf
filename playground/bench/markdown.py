"""Markdown for the generated benchmark pages: a table from a header and rows of cells, and the
way the pages write a relative error and a step.

>>> print(table(["a", "b"], [[pct(0.0123), dt_label(1 / 120)]]))
| a | b |
|---|---|
| 1.2 % | 1/120 |
"""

from __future__ import annotations

import math
from collections.abc import Sequence

__all__ = ["dt_label", "pct", "table"]


def table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """A Markdown table: ``header`` then one line per row of ``rows`` (cells already text)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def pct(v: float) -> str:
    """A relative error as the pages print it: 0, 1.2 %, 35 % (– when not finite)."""
    if not math.isfinite(v):
        return "–"
    p = 100.0 * v
    if p == 0.0:
        return "0"
    return f"{p:.2g} %" if p < 10 else f"{p:.0f} %"


def dt_label(dt: float) -> str:
    """A step as a fraction of a second: 1/120."""
    return f"1/{round(1.0 / dt)}"
