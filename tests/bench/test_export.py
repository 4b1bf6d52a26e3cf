"""The data files of the benchmarks (:mod:`playground.bench.export`): CSV and JSON hold every
row and field."""

from __future__ import annotations

import csv
import io
import json
from dataclasses import fields

from playground.bench.accuracy import Result
from playground.bench.export import to_csv, to_json


def test_csv_and_json_hold_every_row(rows: list[Result]) -> None:
    """Law: the CSV and JSON outputs round-trip every row and field."""
    names = [f.name for f in fields(Result)]
    table = list(csv.DictReader(io.StringIO(to_csv(rows))))
    assert len(table) == len(rows) and list(table[0]) == names
    data = json.loads(to_json(rows))
    assert len(data) == len(rows) and list(data[0]) == names
