"""What a performance run records (:mod:`playground.bench.measurement`): its JSON writes NaN as
null, and reading it back gives the same rows."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

from playground.bench.performance import from_dict

ROOT = Path(__file__).resolve().parents[2]


def test_to_dict_round_trips_through_json_with_nan_as_null() -> None:
    data = json.loads((ROOT / "docs" / "performance.json").read_text(encoding="utf-8"))
    m = from_dict(data, source="docs/performance.json")
    assert from_dict(json.loads(json.dumps(m.to_dict()))).to_dict() == m.to_dict()
    first = m.levels[0]
    row = dataclasses.replace(first, stages={**first.stages, "observe": math.nan})
    out = dataclasses.replace(m, levels=(row,)).to_dict()
    assert out["levels"][0]["stages"]["observe"] is None
    assert math.isnan(from_dict(json.loads(json.dumps(out))).levels[0].stages["observe"])
