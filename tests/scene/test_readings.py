"""Laws of the readings (:mod:`playground.scene.readings`): every quantity has one reader, it
returns the quantity's kind, and the level's checks, the recording and the ``run --json`` report
all read the same value through it."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from playground.cli import main
from playground.level import find, load
from playground.quantities import QUANTITIES, REPORTED, Quantity, Value
from playground.scene import Scene, build
from playground.scene.checks import read as check_read
from playground.scene.readings import READERS, read, sample
from playground.scene.recording import read as read_recording
from playground.scene.recording import recording


def sandbox(seconds: float = 1.0) -> Scene:
    scene = build(load(find("sandbox")))
    scene.run(seconds)
    return scene


def test_every_quantity_has_exactly_one_reader() -> None:
    assert list(READERS) == list(QUANTITIES)


@pytest.fixture(scope="module")
def running() -> Scene:
    """The sandbox a second in: its player stands, its forces and perception have readings."""
    return sandbox()


@pytest.mark.parametrize("q", list(QUANTITIES.values()), ids=list(QUANTITIES))
def test_each_reading_has_its_kind(q: Quantity, running: Scene) -> None:
    """Every reader works on an actor of a running level and returns its declared kind."""
    value = read(q, running, "player")
    if q.kind == "vector":
        assert isinstance(value, tuple) and len(value) == 2
        assert all(isinstance(v, float) for v in value)
    elif q.kind == "scalar":
        assert isinstance(value, float)
    else:
        assert isinstance(value, str)


def as_json(value: Value) -> object:
    """What strict JSON holds for a reading: null for a non-finite number or an all-NaN vector."""
    if isinstance(value, tuple):
        out = [v if math.isfinite(v) else None for v in value]
        return None if all(v is None for v in out) else out
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    return value


def test_recording_report_and_checks_read_the_same_value(tmp_path: Path) -> None:
    """Law: at the last step of a run, the recording's row, the ``run --json`` report and the
    checks' reading of each tracked body agree exactly (one reader each)."""
    from playground.cli.running import _body_report

    scene = build(load(find("sandbox")))
    path = tmp_path / "sandbox.csv"
    with recording(scene, path):
        scene.run(0.5)
    columns = read_recording(path)
    bodies = list(scene.tracked)
    last = len(columns["time"]) - len(bodies)
    for row, name in enumerate(bodies, start=last):
        assert columns["body"][row] == name
        report = _body_report(scene, name)
        for q in QUANTITIES.values():
            if q.source == "controller" and name not in scene.controllers:
                continue  # a prop has no controller's readings (a level may not ask for them)
            value = sample(q, scene, name)
            cells = value if isinstance(value, tuple) else (value,)
            for column, cell in zip(q.columns, cells if q.columns else (), strict=True):
                if isinstance(cell, float):
                    assert columns[column][row] == cell or math.isnan(cell)
                else:
                    assert str(columns[column][row]) == (cell or "")
            if q.report is not None:
                group = report[q.report] if q.report else report
                assert group[q.name] == as_json(value), (name, q.name)
            if q.checked:
                # NaN (a contact split unknown this step) compares by its place, not its value.
                assert as_json(check_read(scene, name, q.name)) == as_json(
                    "" if value is None else value
                )


def test_run_json_reports_every_reported_quantity(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "rest", "--json", "--seconds", "0.1", "--no-progress"]) in (0, 1)
    body = json.loads(capsys.readouterr().out)["bodies"]["player"]
    top = [q.name for q in REPORTED if not q.report]
    groups = {q.report for q in REPORTED if q.report}
    assert set(body) == {*top, *groups}
    for group in groups:
        assert set(body[group]) == {q.name for q in REPORTED if q.report == group}
