"""Laws of the world's settings: a bad value is refused, naming the field."""

from __future__ import annotations

import math

import pytest

from playground.world.config import WorldConfig


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("dt", 0.0),
        ("dt", -0.01),
        ("dt", math.nan),
        ("substeps", 0),
        ("substeps", 1.5),
        ("iterations", 0),
        ("damping", 0.0),
        ("damping", 1.5),
        ("damping", math.nan),
        ("collision_slop", -0.1),
        ("sleep_time", 0.0),
    ],
)
def test_config_rejects_bad_values(field: str, value: float) -> None:
    """Law: a bad setting raises ValueError naming the field."""
    with pytest.raises(ValueError, match=field):
        WorldConfig(**{field: value})  # type: ignore[arg-type]
