"""Laws of declared fields: the one bounds check refuses what a field's spec refuses, naming the
field and what was expected, and admits the rest."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import pytest

from playground.params import check, param, spec


@dataclass(frozen=True)
class Sample:
    """Every shape of field the core declares."""

    rate: float = param(1.0, doc="A rate.", unit="Hz", gt=0.0, le=10.0)
    count: int = param(1, doc="A count.", ge=1, le=4)
    where: tuple[float, float] = param((0.0, 0.0), doc="A place.", unit="m", ge=-5.0, le=5.0)
    axis: tuple[float, float] | None = param(
        None, doc="A direction.", nonzero=True, ge=-5.0, le=5.0
    )
    path: tuple[tuple[float, float], ...] = param(
        ((0.0, 0.0), (1.0, 0.0)), doc="Points.", unit="m", min_items=2, ge=-5.0, le=5.0
    )
    mode: Literal["a", "b"] = param("a", doc="A choice.")
    forever: float = param(math.inf, doc="A time.", unit="s", gt=0.0, le=10.0, inf=True)
    flag: bool = param(False, doc="A switch.")

    def __post_init__(self) -> None:
        check(self)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"rate": 0.0}, r"rate: expected a number in \(0, 10\] Hz, got 0.0"),
        ({"rate": math.nan}, "rate: expected a number"),
        ({"rate": True}, "rate: expected a number"),
        ({"count": 2.0}, r"count: expected an integer in \[1, 4\], got 2.0"),
        ({"count": 5}, "count: expected an integer"),
        ({"where": (0.0, 6.0)}, r"where\[1\]: expected a number in \[-5, 5\] m"),
        ({"where": (0.0,)}, r"where: expected a 2-vector"),
        ({"axis": (0.0, 0.0)}, "axis: expected a non-zero vector"),
        ({"path": ((0.0, 0.0),)}, "path: expected at least 2 points, got 1"),
        ({"path": ((0.0, 0.0), (9.0, 0.0))}, r"path\[1\]\[0\]: expected a number"),
        ({"mode": "c"}, "mode: expected one of 'a', 'b', got 'c'"),
        ({"forever": -math.inf}, "forever: expected a number"),
    ],
)
def test_a_value_outside_its_spec_is_refused_with_the_field_named(
    kwargs: dict[str, object], message: str
) -> None:
    """Law: each kind of field refuses what its spec refuses, and the message names it."""
    with pytest.raises(ValueError, match=message):
        Sample(**kwargs)  # type: ignore[arg-type]


def test_values_within_their_spec_are_admitted() -> None:
    """Law: bounds are inclusive where declared so, ∞ passes where declared, None where allowed."""
    s = Sample(rate=10.0, count=4, where=(-5.0, 5.0), axis=(0.0, 1.0), forever=10.0)
    assert (s.rate, s.count, s.axis) == (10.0, 4, (0.0, 1.0))
    assert Sample().forever == math.inf


def test_a_spec_is_read_back_by_name() -> None:
    """The doc and unit of a field are what it declared."""
    assert (spec(Sample, "rate").doc, spec(Sample, "rate").unit) == ("A rate.", "Hz")
    with pytest.raises(KeyError):
        spec(Sample, "nothing")
