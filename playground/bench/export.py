"""Rows of dataclasses (the sweep's results, the overhead profile, the guide's runs) as data files:
CSV with a header, and JSON with NaN written as null.

>>> from playground.bench.accuracy import Result
>>> r = Result("rest", 0.01, 1, 10, "reverse", "none", 0.0, 0.0, 0.0, 5.0, 4.0, 1.25)
>>> to_csv([r]).splitlines()[1]
'rest,0.01,1,10,reverse,none,0.0,0.0,0.0,5.0,4.0,1.25'
"""

from __future__ import annotations

import csv
import io
import json
import math
from collections.abc import Iterable
from dataclasses import asdict, fields

__all__ = ["to_csv", "to_json"]


def to_csv(rows: Iterable[object]) -> str:
    """Rows of dataclasses as CSV text, a header first."""
    rows = list(rows)
    if not rows:
        return ""
    out = io.StringIO()
    names = [f.name for f in fields(rows[0])]  # type: ignore[arg-type]
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(names)
    for r in rows:
        writer.writerow([getattr(r, n) for n in names])
    return out.getvalue()


def to_json(rows: Iterable[object]) -> str:
    """Rows of dataclasses as a JSON list of objects (NaN written as null)."""

    def clean(v: object) -> object:
        return None if isinstance(v, float) and not math.isfinite(v) else v

    data = [{k: clean(v) for k, v in asdict(r).items()} for r in rows]  # type: ignore[call-overload]
    return json.dumps(data, indent=1, ensure_ascii=False)
