"""Laws of the quantities vocabulary (:mod:`playground.quantities`): one table feeds the level's
quantity enum, the checks' units and the recording's columns."""

from __future__ import annotations

from playground.level import schema
from playground.quantities import CHECKED, RECORDED
from playground.scene.checks import UNITS
from playground.scene.recording import COLUMNS

RECORDING_COLUMNS = (
    "time",
    "body",
    "x",
    "y",
    "vx",
    "vy",
    "angle",
    "engine_x",
    "engine_y",
    "contact_x",
    "contact_y",
    "constraint_x",
    "constraint_y",
    "support_x",
    "support_y",
    "support_filtered_x",
    "support_filtered_y",
    "perceived_gravity_x",
    "perceived_gravity_y",
    "state",
)
"""The columns recordings have always had, in order: users' scripts read them by name."""


def test_the_level_checks_exactly_the_checked_quantities() -> None:
    """The schema's quantity enum is the registry's checked quantities, each with its unit."""
    enum = schema()["$defs"]["Expectation"]["properties"]["quantity"]["enum"]
    assert enum == [q.name for q in CHECKED]
    assert {q.name: q.unit for q in CHECKED} == UNITS


def test_recordings_keep_their_columns() -> None:
    assert COLUMNS == RECORDING_COLUMNS
    assert [c for q in RECORDED for c in q.columns] == list(RECORDING_COLUMNS[2:])
