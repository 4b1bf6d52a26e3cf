"""The replay file's document: its head (format, version, level, dt, length, actor) as a model.

A replay is read like a level: a JSON object validated by pydantic, every number bounded, unknown
keys refused. Its ``changes`` and ``grabs`` lists are checked entry by entry by
:mod:`playground.scene.replay`, which names each entry (each change is an
:class:`~playground.level.timeline.IntentTable`, as a level's ``[[inputs]]`` table is).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field

from playground import limits
from playground.level.values import Name, Table

__all__ = ["MAX_REPLAY_STEPS", "ReplayDocument"]

MAX_REPLAY_STEPS = round(limits.MAX_TIME / limits.MIN_DT)
"""Steps: the longest run ``playground run --long`` allows (a day) at the smallest dt. A larger
count is no replay anyone recorded, and steps·dt stays an ordinary float."""

Step = Annotated[int, Field(ge=0, le=MAX_REPLAY_STEPS)]
"""A step index of a replay (0 is the level's first step)."""


class ReplayDocument(Table):
    """A replay file: what it replays, at which dt, for how many steps, and the entries."""

    format: Literal["playground-replay"]
    version: Literal[1]
    level: str = Field(min_length=1, max_length=255, description="The level's name (file stem).")
    dt: Annotated[float, Field(ge=limits.MIN_DT, le=limits.MAX_DT, allow_inf_nan=False)] = Field(
        description="The level's step, s (it must equal the level's).",
    )
    steps: Step = Field(description="Steps recorded.")
    actor: Name = Field(default="player", description="The actor the replay drives.")
    changes: list[Any] = Field(description="[step, intent] from which each intent held.")
    grabs: list[Any] = Field(
        default_factory=list, description="[step, grab or null] from which the mouse held it."
    )
