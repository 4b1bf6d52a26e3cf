"""Small argument checks shared by the core's frozen configs: each error names the parameter."""

from __future__ import annotations

import math
from collections.abc import Sequence


def finite(name: str, value: float) -> None:
    """Raise ``ValueError`` unless ``value`` is a finite real number."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise ValueError(f"{name}: expected a finite number, got {value!r}")


def positive(name: str, value: float) -> None:
    """Raise ``ValueError`` unless ``value`` is finite and > 0."""
    finite(name, value)
    if value <= 0:
        raise ValueError(f"{name}: expected a number > 0, got {value!r}")


def finite_vec(name: str, value: Sequence[float]) -> None:
    """Raise ``ValueError`` unless ``value`` is a pair of finite numbers."""
    if len(value) != 2:
        raise ValueError(f"{name}: expected a 2-vector (x, y), got {value!r}")
    for i, v in enumerate(value):
        finite(f"{name}[{i}]", v)
