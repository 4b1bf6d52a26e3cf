"""Laws of the controller's configuration: a bad value is refused with its field named, and the
budgets follow the body's weight unless given in newtons."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from playground import ControllerConfig


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("mass", 0.0),
        ("height", -1.0),
        ("radius", 1.0),
        ("ride_height", 2.0),
        ("max_slope", 2.0),
        ("air_force", -1.0),
        ("hover_frequency", math.nan),
    ],
)
def test_bad_config_names_the_field(field: str, value: float) -> None:
    """Bad input gets a clear error naming the field."""
    with pytest.raises(ValueError, match=field):
        ControllerConfig(**{field: value})


BUDGETS = ("hover", "ground", "air", "balance", "grip", "push", "crush")
"""The budgets (and the crush threshold) a config gives for a body's mass."""
TUNED = {
    "hover": 5000.0,
    "ground": 350.0,
    "air": 70.0,
    "balance": 600.0,
    "grip": 2000.0,
    "push": 1000.0,
    "crush": 1500.0,
}
"""The newtons (N·m for the balance) the defaults were tuned with for a 70 kg, 1.8 m person."""
TOL_BUDGET_REL = 1e-12
"""A budget is a product of three or four floats: a few ulps."""


def budget(config: ControllerConfig, name: str, mass: float) -> float:
    method = "crush_threshold" if name == "crush" else f"{name}_budget"
    value: float = getattr(config, method)(mass)
    return value


@pytest.mark.parametrize("name", BUDGETS)
def test_default_budgets_are_the_tuned_newtons_at_70_kg(name: str) -> None:
    """Law: at the mass the defaults were tuned for, each budget is the tuned value exactly,
    so a 70 kg player runs as before."""
    assert budget(ControllerConfig(), name, 70.0) == TUNED[name]


@pytest.mark.parametrize("name", BUDGETS)
@given(mass=st.floats(min_value=1.0, max_value=1000.0))
def test_default_budgets_follow_the_bodys_weight(name: str, mass: float) -> None:
    """Law: a budget is a multiple of the body's weight (torques of weight × height): at any
    mass it is the tuned value scaled by mass / 70 kg."""
    expected = TUNED[name] * mass / 70.0
    assert budget(ControllerConfig(), name, mass) == pytest.approx(expected, rel=TOL_BUDGET_REL)


@pytest.mark.parametrize("name", BUDGETS)
def test_a_budget_in_newtons_wins_at_any_mass(name: str) -> None:
    """Law: a budget given in newtons is that, whatever the body's mass."""
    field = {"balance": "balance_torque", "crush": "crush_force"}.get(name, f"{name}_force")
    config = ControllerConfig(**{field: 123.0})
    assert budget(config, name, 35.0) == budget(config, name, 140.0) == 123.0


def test_the_balance_budget_grows_with_height() -> None:
    """Law: the balance torque's budget is in weight × height: twice as tall, twice the torque
    (the radius is kept below half the height)."""
    short, tall = ControllerConfig(height=1.0), ControllerConfig(height=2.0)
    assert tall.balance_budget(70.0) == pytest.approx(2.0 * short.balance_budget(70.0))
