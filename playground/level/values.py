"""The bounded value types every table of a level uses, and the strict base of every table.

Every number is bounded (see :mod:`playground.limits` for each bound's reason) and finite.

>>> from pydantic import TypeAdapter
>>> TypeAdapter(Whole).validate_python(2.0)
2
"""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, Strict

from playground import limits

# Every number is bounded (see playground.limits for each bound's reason). A plain number — a
# length, position, time, angle, rate, tolerance — lies within ±MAX_COORDINATE (1e5): larger is
# beyond any game-scale level, and sums and products of such numbers stay far from overflow.
# Quantities with a tighter plausible range (masses, speeds, gravities, forces, stiffnesses,
# frequencies, dt) say so where they are declared.
PLAIN = limits.MAX_COORDINATE
Finite = Annotated[float, Field(ge=-PLAIN, le=PLAIN, allow_inf_nan=False)]
Positive = Annotated[float, Field(gt=0.0, le=PLAIN, allow_inf_nan=False)]
NonNegative = Annotated[float, Field(ge=0.0, le=PLAIN, allow_inf_nan=False)]
Unit = Annotated[float, Field(ge=-1.0, le=1.0, allow_inf_nan=False)]
# Tables are strict (no true -> 1.0, no "10" -> 10, as the JSON Schema says); a TOML array is a
# list, so fixed-length arrays are the one place a conversion (list -> tuple) is allowed.
Vec = Annotated[tuple[Finite, Finite], Strict(False)]


def _whole(value: object) -> object:
    """A float with no fraction is an integer (as in JSON Schema): 2.0 -> 2."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


Whole = Annotated[int, BeforeValidator(_whole)]
Mass = Annotated[float, Field(ge=limits.MIN_MASS, le=limits.MAX_MASS, allow_inf_nan=False)]
"""kg: see ``MIN_MASS`` and ``MAX_MASS`` (mass ratios with a 70 kg player)."""
Moment = Annotated[float, Field(ge=limits.MIN_MOMENT, le=limits.MAX_MOMENT, allow_inf_nan=False)]
"""kg·m²: 1/I must stay finite, m·L² of the largest body must fit."""
Speed = Annotated[float, Field(ge=-limits.MAX_SPEED, le=limits.MAX_SPEED, allow_inf_nan=False)]
"""m/s: faster bodies cross more than their own size per step and tunnel."""
TurnRate = Annotated[
    float, Field(ge=-limits.MAX_ANGULAR_SPEED, le=limits.MAX_ANGULAR_SPEED, allow_inf_nan=False)
]
"""rad/s: the same tunnelling argument at a metre-sized body's rim."""
Gravity_ = Annotated[
    float, Field(ge=-limits.MAX_GRAVITY, le=limits.MAX_GRAVITY, allow_inf_nan=False)
]
"""m/s²: at most 100 g, which the contacts and the hover spring still hold at 1/120 s."""
Force = Annotated[float, Field(gt=0.0, le=limits.MAX_FORCE, allow_inf_nan=False)]
"""N: keeps F·dt and every sum of forces finite."""
Stiffness = Annotated[float, Field(gt=0.0, le=limits.MAX_STIFFNESS, allow_inf_nan=False)]
"""N/m or N·m/rad; stability at the level's dt is checked when the level is built."""
Damping = Annotated[float, Field(ge=0.0, le=limits.MAX_STIFFNESS, allow_inf_nan=False)]
"""N·s/m or N·m·s/rad: bounded like a stiffness."""
Frequency = Annotated[float, Field(gt=0.0, le=limits.MAX_FREQUENCY, allow_inf_nan=False)]
"""Hz: above half the step rate a motion is not sampled at all."""
Name = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[A-Za-z_][A-Za-z0-9_\-]*$")]


class Table(BaseModel):
    """Every table of a level: unknown keys are errors, values are frozen."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)
