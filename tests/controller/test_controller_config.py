"""Laws of the controller's configuration: a bad value is refused with its field named."""

from __future__ import annotations

import math

import pytest

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
