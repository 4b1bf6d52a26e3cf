"""Argument checks of single values, for what a declaration cannot say (a world's mutators, a
mover's arguments, a rule's direction): each error names the parameter and its unit."""

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


def bounded(name: str, value: float, limit: float, unit: str) -> None:
    """Raise ``ValueError`` unless ``value`` is finite and ``|value| <= limit``.

    >>> bounded("speed", 2e3, 1e3, "m/s")
    Traceback (most recent call last):
    ...
    ValueError: speed: expected a finite number within ±1000 m/s, got 2000.0
    """
    if _out_of_bounds(value, limit):
        raise ValueError(
            f"{name}: expected a finite number within ±{limit:g} {unit}, got {value!r}"
        )


def _out_of_bounds(value: float, limit: float) -> bool:
    """What :func:`bounded` refuses: not a real number, not finite, or beyond ±``limit``."""
    return (
        isinstance(value, bool)
        or not isinstance(value, int | float)
        or not math.isfinite(value)
        or abs(value) > limit
    )


def in_range(name: str, value: float, low: float, high: float, unit: str) -> None:
    """Raise ``ValueError`` unless ``low <= value <= high`` (finite).

    >>> in_range("mass", 0.0, 1e-3, 1e6, "kg")
    Traceback (most recent call last):
    ...
    ValueError: mass: expected a number in [0.001, 1e+06] kg, got 0.0
    """
    finite(name, value)
    if not low <= value <= high:
        raise ValueError(f"{name}: expected a number in [{low:g}, {high:g}] {unit}, got {value!r}")


def bounded_vec(name: str, value: Sequence[float], limit: float, unit: str) -> None:
    """Raise ``ValueError`` unless ``value`` is a pair of finite numbers within ±``limit``."""
    try:
        n = len(value)
    except TypeError:
        n = -1
    if n != 2:
        raise ValueError(f"{name}: expected a 2-vector (x, y) in {unit}, got {value!r}")
    for i, v in enumerate(value):
        # The element's name is formatted only for the error: this check runs on every force.
        if _out_of_bounds(v, limit):
            bounded(f"{name}[{i}]", v, limit, unit)


def unit(name: str, value: Sequence[float]) -> tuple[float, float]:
    """The direction of a finite non-zero 2-vector as a unit vector (any length, no overflow).

    >>> unit("direction", (0.0, 1e308))
    (0.0, 1.0)
    """
    finite_vec(name, value)
    x, y = float(value[0]), float(value[1])
    big = max(abs(x), abs(y))
    if big == 0.0:
        raise ValueError(f"{name}: expected a non-zero direction, got (0, 0)")
    x, y = x / big, y / big  # scaled first: hypot of two values near 1e308 would overflow
    n = math.hypot(x, y)
    return (x / n, y / n)
