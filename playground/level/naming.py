"""The names of a level's checks: an expectation's own ``name``, or one made from what it reads
(``player.support.y at 2 s``), unique within the level.

>>> from playground.level import find, load
>>> check_names(load(find("incline")))[:2]
['normal force = m·g·cosθ', 'friction force = m·g·sinθ']
"""

from __future__ import annotations

from playground.level.document import Level
from playground.level.expect import Expectation, Reading

__all__ = ["check_names", "name_of", "reading_name"]


def name_of(exp: Expectation) -> str:
    """A readable default name: ``player.support.y at 2 s``."""
    if exp.name is not None:
        return exp.name
    what = f"{exp.body}.{exp.quantity}"
    if exp.filtered:
        what += "_filtered"
    if exp.relative_to is not None:
        what += f"-{exp.relative_to}.{exp.quantity}"
    if exp.minus is not None:
        what += f"-{reading_name(exp.minus)}"
    if exp.angle_to is not None:
        ref = exp.angle_to
        to = reading_name(ref) if isinstance(ref, Reading) else f"[{ref[0]:g}, {ref[1]:g}]"
        what = f"angle of {what} to {to}"
    if exp.change:
        what = f"change of {what}"
    if exp.component is not None:
        what += f".{exp.component}"
    if exp.check == "at":
        # An `at` check without its time is a problem of the level, named while it is reported.
        return f"{what} at {exp.t:g} s" if exp.t is not None else f"{what} at"
    if exp.window is None:
        return f"{what} {exp.check}"
    return f"{what} {exp.check} in [{exp.window[0]:g}, {exp.window[1]:g}] s"


def reading_name(r: Reading) -> str:
    """``-1·player.position``: another body's reading as a check's name shows it."""
    scale = "" if r.scale == 1.0 else f"{r.scale:g}·"
    return f"{scale}{r.body}.{r.quantity}"


def check_names(level: Level) -> list[str]:
    """The names of a level's checks, made unique (a repeated name gets `` #2``, …)."""
    seen: dict[str, int] = {}
    out = []
    for exp in level.expect:
        name = name_of(exp)
        n = seen.get(name, 0)
        seen[name] = n + 1
        out.append(f"{name} #{n + 1}" if n else name)
    return out
