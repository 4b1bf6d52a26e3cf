"""What happens during a run: scripted inputs of the actors and timed events."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field, Strict

from playground import limits
from playground.intents import Intent
from playground.level.bodies import Prop
from playground.level.derive import Derived, to_core
from playground.level.values import Finite, Gravity_, Name, NonNegative, Table, Vec


class IntentTable(Derived):
    """One intent, as a level's ``[[inputs]]`` table and a replay's change both write it: the
    fields of :class:`playground.intents.Intent` (a replay leaves out those at their default).

    >>> from playground.intents import Intent
    >>> IntentTable.of(Intent(move=-1.0, gravity=(0.0, 1.0))).table()
    {'move': -1.0, 'gravity': [0.0, 1.0]}
    >>> IntentTable.model_validate({"jump": True}).intent() == Intent(jump=True)
    True
    """

    __core__ = Intent

    @classmethod
    def of(cls, intent: Intent) -> IntentTable:
        """The table of a core intent (validated: what a level could not hold is refused)."""
        return cls.model_validate({name: getattr(intent, name) for name in _INTENT_KEYS})

    def intent(self) -> Intent:
        """The core intent these keys describe."""
        intent: Intent = to_core(self)
        return intent

    def table(self) -> dict[str, Any]:
        """The keys that differ from the defaults, as JSON and TOML write them (lists, not
        tuples)."""
        return self.model_dump(mode="json", include=set(_INTENT_KEYS), exclude_defaults=True)


_INTENT_KEYS = tuple(IntentTable.model_fields)
"""The intent's keys, in order (an input adds its time and actor to them)."""


class Input(IntentTable):
    """From time ``t`` on, ``actor`` holds this intent (until its next input)."""

    t: NonNegative = Field(description="When.", json_schema_extra={"unit": "s"})
    actor: Name = Field(default="player", description="Whose intent.")


Impulse_ = Annotated[
    float, Field(ge=-limits.MAX_IMPULSE, le=limits.MAX_IMPULSE, allow_inf_nan=False)
]
"""N·s: spread over one step of the smallest dt it stays within MAX_FORCE."""


class _Event(Table):
    t: NonNegative = Field(description="When, s.")


class SetGravity(_Event):
    """Replace the field with uniform gravity ``g`` (m/s²)."""

    kind: Literal["set_gravity"]
    g: Annotated[tuple[Gravity_, Gravity_], Strict(False)]


class FlipGravity(_Event):
    """Turn a uniform field by ``angle`` rad (π: a flip), instantly."""

    kind: Literal["flip_gravity"]
    angle: Finite = math.pi


class Nullify(_Event):
    """Zero one body's gravity."""

    kind: Literal["nullify"]
    body: Name


class RestoreGravity(_Event):
    """Give a body the field's gravity back."""

    kind: Literal["restore_gravity"]
    body: Name


class BodyGravity(_Event):
    """Give a body its own gravity: ``scale`` × the field, along ``direction`` if given."""

    kind: Literal["body_gravity"]
    body: Name
    scale: Annotated[
        float,
        Field(ge=-limits.MAX_GRAVITY_SCALE, le=limits.MAX_GRAVITY_SCALE, allow_inf_nan=False),
    ] = 1.0
    direction: Vec | None = None


class Impulse(_Event):
    """A one-step impulse (N·s) on a body, at a world point (m) or its centre."""

    kind: Literal["impulse"]
    body: Name
    impulse: Annotated[tuple[Impulse_, Impulse_], Strict(False)]
    point: Vec | None = None


class Spawn(_Event):
    """Add a prop."""

    kind: Literal["spawn"]
    prop: Prop


class Remove(_Event):
    """Remove a body."""

    kind: Literal["remove"]
    body: Name


Event = Annotated[
    SetGravity | FlipGravity | Nullify | RestoreGravity | BodyGravity | Impulse | Spawn | Remove,
    Field(discriminator="kind"),
]
