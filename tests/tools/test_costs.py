"""The small costs (:mod:`tools.costs`): the package's comments keep the reasons and no timing,
each choice they justify is timed and on docs/performance.md, and the rows read back."""

from __future__ import annotations

import json
import re
from pathlib import Path

from tools import costs

ROOT = Path(__file__).resolve().parents[2]
TIMING = re.compile(r"\d\s?(µs|ns)\b")
"""A figure in micro- or nanoseconds: it belongs on docs/performance.md, not in the code."""


def test_the_package_source_quotes_no_timing() -> None:
    """Law: no comment or docstring of playground/ quotes a µs or ns figure (they go stale)."""
    found = [
        f"{path.relative_to(ROOT)}:{n}: {line.strip()}"
        for path in sorted((ROOT / "playground").rglob("*.py"))
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if TIMING.search(line)
    ]
    assert not found, "\n".join(found)


def test_each_timed_choice_is_named_where_the_code_makes_it() -> None:
    """Law: every module a row names gives that row's key (so a reader finds the figure), and
    every key is in the committed docs/costs.json and on docs/performance.md."""
    data = json.loads((ROOT / "docs" / "costs.json").read_text(encoding="utf-8"))
    committed = {r.key for r in costs.from_dict(data, source="docs/costs.json")}
    page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
    for cost in costs.COSTS:
        for module in cost.where.split(", "):
            text = (ROOT / "playground" / module).read_text(encoding="utf-8")
            assert cost.key in text, f"playground/{module} does not name {cost.key}"
        assert cost.key in committed, f"docs/costs.json lacks {cost.key}: python -m tools costs"
        assert f"| {cost.what} |" in page, cost.key


def test_the_rows_read_back_and_a_bad_file_names_the_key() -> None:
    """Law: measured rows survive the JSON; a document without them names the key."""
    data = json.loads(json.dumps(costs.measure(repeats=1)))
    rows = costs.from_dict(data)
    assert [r.key for r in rows] == [c.key for c in costs.COSTS]
    assert all(r.us > 0.0 for r in rows)
    try:
        costs.from_dict({}, source="bad.json")
    except ValueError as exc:
        assert "bad.json" in str(exc) and "'costs'" in str(exc)
    else:
        raise AssertionError("an empty document was accepted")
