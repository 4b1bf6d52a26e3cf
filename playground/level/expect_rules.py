"""Whether an expectation is a check that can be made: its bodies, times, comparison and readings.

:func:`check_expectation` runs a table of small rules, each about one key or one pair of keys,
and reports every problem they find, in the order of the table. A state (a name such as
``"grounded"``) and a number or vector are checked by different rules.

>>> from playground.level.errors import LevelError
>>> from playground.level.loading import loads
>>> try:
...     loads('title = "x"\\ndescription = "y"\\n[[props]]\\nname = "c"\\nposition = [0, 1]\\n'
...           'mass = 1\\nshapes = [{kind = "box", size = [1, 1]}]\\n'
...           '[[expect]]\\nbody = "c"\\nquantity = "position"\\nt = 1\\nabove = 0\\n')
... except LevelError as exc:
...     print(*exc.problems, sep="\\n")
expect.0.component: bounds need a component: x, y or norm
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterator, Sequence

from playground.level.document import Level
from playground.level.errors import Problem, suggest
from playground.level.expect import (
    CONTROLLER_QUANTITIES,
    FORCE_QUANTITIES,
    SCALAR_QUANTITIES,
    VECTOR_QUANTITIES,
    Expectation,
    Reading,
)
from playground.quantities import CHECKED, QUANTITIES

__all__ = ["Context", "check_expectation"]

RELATIVE_QUANTITIES = tuple(q.name for q in CHECKED if q.source == "body")
"""Quantities that may be read relative to another body's same quantity."""

SPLIT_QUANTITIES = tuple(q.name for q in CHECKED if q.split)
"""Force readings that exist only when the engine's forces are split (``contact_split``)."""


@dataclasses.dataclass(frozen=True, slots=True)
class Context:
    """What the rules know of the level: its bodies, its actors and its tracked bodies."""

    level: Level
    names: Sequence[str]
    actors: Sequence[str]
    tracked: Sequence[str]


Rule = Callable[[str, Expectation, Context], Iterator[Problem]]
"""A rule: the expectation's key path, the expectation, the level -> its problems."""


def check_expectation(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    """Every problem of the expectation at ``path``; none past an unknown body."""
    if exp.body not in ctx.names:
        yield _unknown(f"{path}.body", exp.body, ctx.names)
        return
    rules = _STATE_RULES if exp.quantity == "state" else _VALUE_RULES
    for rule in (*_COMMON_RULES, *rules):
        yield from rule(path, exp, ctx)


def _unknown(path: str, name: str, names: Sequence[str]) -> Problem:
    return Problem(path, f"no body named {name!r}{suggest(name, list(names))}")


# -- rules for every quantity --------------------------------------------------------------------


def _relative_to(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    if exp.relative_to is None:
        return
    if exp.relative_to not in ctx.names:
        yield _unknown(f"{path}.relative_to", exp.relative_to, ctx.names)
    if exp.quantity not in RELATIVE_QUANTITIES:
        yield Problem(
            f"{path}.relative_to",
            "only position, velocity, angle and angular_velocity are relative to a body",
        )


def _change(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    if exp.change and (exp.check == "at" or exp.quantity == "state"):
        yield Problem(f"{path}.change", "change needs a window (always, eventually, mean, impulse)")


def _impulse(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    """An impulse integrates a force over a window of some length."""
    if exp.check != "impulse" or exp.quantity == "state":
        return
    if exp.quantity not in FORCE_QUANTITIES + CONTROLLER_QUANTITIES or exp.angle_to is not None:
        what = "an angle" if exp.angle_to is not None else exp.quantity
        yield Problem(f"{path}.check", f"an impulse integrates a force, not {what}")
    if exp.window is not None and exp.window[1] == exp.window[0]:
        yield Problem(f"{path}.window", "an impulse needs a window of some length")


def _timing(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    seconds = ctx.level.settings.seconds
    if exp.check == "at":
        if exp.t is None:
            yield Problem(f"{path}.t", "check = 'at' needs a time t, s")
        elif exp.t > seconds:
            yield Problem(f"{path}.t", f"t = {exp.t} s is after the run's end ({seconds} s)")
        if exp.window is not None:
            yield Problem(f"{path}.window", "check = 'at' takes t, not a window")
        return
    if exp.t is not None:
        yield Problem(f"{path}.t", f"check = {exp.check!r} takes a window, not t")
    if exp.window is not None and exp.window[1] > seconds:
        yield Problem(f"{path}.window", f"ends after the run's end ({seconds} s)")


# -- a state -------------------------------------------------------------------------------------


def _state(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    if exp.body not in ctx.actors:
        yield Problem(f"{path}.quantity", f"{exp.body!r} is not an actor: it has no state")
    if not isinstance(exp.equals, str) and exp.one_of is None:
        yield Problem(path, "a state check needs equals = 'state' or one_of = [...]")
    if exp.check in ("mean", "impulse"):
        yield Problem(f"{path}.check", f"a state has no {exp.check}")
    if exp.above is not None or exp.below is not None or exp.component is not None:
        yield Problem(path, "a state compares with equals or one_of only")


# -- a number or a vector ------------------------------------------------------------------------


def _comparison(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    bounded = exp.above is not None or exp.below is not None
    if isinstance(exp.equals, str) or exp.one_of is not None:
        yield Problem(f"{path}.equals", f"{exp.quantity} is a number or vector, not a state name")
    if exp.equals is None and not bounded:
        yield Problem(path, "nothing to compare: give equals, above or below")
    if exp.equals is not None and bounded:
        yield Problem(path, "give equals (± tolerance) or above/below bounds, not both")
    if exp.quantity in SCALAR_QUANTITIES and exp.component is not None:
        yield Problem(f"{path}.component", f"{exp.quantity} is a number; it has no component")


def _own_reading(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    yield from _readable(path, exp.body, exp.quantity, ctx, filtered=exp.filtered)
    if exp.filtered and exp.quantity not in FORCE_QUANTITIES:
        yield Problem(f"{path}.filtered", f"only force readings are filtered, not {exp.quantity}")


def _minus(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    if exp.minus is None:
        return
    yield from _other_reading(f"{path}.minus", exp.minus, ctx)
    if (exp.minus.quantity in VECTOR_QUANTITIES) != (exp.quantity in VECTOR_QUANTITIES):
        yield Problem(
            f"{path}.minus.quantity",
            f"{exp.minus.quantity} and {exp.quantity} are not both vectors or both numbers",
        )


def _angle_to(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    if exp.angle_to is None:
        return
    if isinstance(exp.angle_to, Reading):
        ref = exp.angle_to
        yield from _other_reading(f"{path}.angle_to", ref, ctx)
        if ref.quantity not in VECTOR_QUANTITIES:
            yield Problem(f"{path}.angle_to.quantity", f"{ref.quantity} is not a vector")
        if ref.scale == 0.0:
            yield Problem(f"{path}.angle_to.scale", "a zero vector has no direction")
    elif exp.angle_to == (0.0, 0.0):
        yield Problem(f"{path}.angle_to", "a zero vector has no direction")
    if exp.quantity not in VECTOR_QUANTITIES:
        yield Problem(f"{path}.angle_to", f"{exp.quantity} is a number: it has no direction")
    if exp.component is not None:
        yield Problem(f"{path}.component", "angle_to compares directions: no component")
    if exp.change:
        yield Problem(f"{path}.change", "angle_to compares directions, not changes")


def _kind_of_value(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    """A whole vector compares with a vector; a component, an angle or a number with a number."""
    angle = exp.angle_to is not None
    vector = exp.quantity in VECTOR_QUANTITIES and exp.component is None and not angle
    if vector and (exp.above is not None or exp.below is not None):
        yield Problem(f"{path}.component", "bounds need a component: x, y or norm")
    if vector and isinstance(exp.equals, float | int):
        yield Problem(f"{path}.equals", f"{exp.quantity} is a vector: give [x, y] or a component")
    if not vector and isinstance(exp.equals, tuple):
        yield Problem(f"{path}.equals", "expected a number for a component, angle or scalar")


def _own_terms(path: str, exp: Expectation, ctx: Context) -> Iterator[Problem]:
    """A check in a body's weights (or per its kilogram) names a body with a mass and reads a
    force; it is one or the other."""
    for key, body in (("weights_of", exp.weights_of), ("per_mass_of", exp.per_mass_of)):
        if body is None:
            continue
        at = f"{path}.{key}"
        if body not in ctx.names:
            yield _unknown(at, body, ctx.names)
        elif body in (m.name for m in ctx.level.movers):
            yield Problem(at, f"{body!r} is a mover (kinematic): it has no mass")
        if exp.quantity not in FORCE_QUANTITIES + CONTROLLER_QUANTITIES or exp.angle_to:
            what = "an angle" if exp.angle_to is not None else exp.quantity
            yield Problem(at, f"only a force is counted in a body's mass or weight, not {what}")
    if exp.weights_of is not None and exp.per_mass_of is not None:
        yield Problem(path, "give weights_of or per_mass_of, not both")


_COMMON_RULES: tuple[Rule, ...] = (_relative_to, _change, _impulse, _timing, _own_terms)
_STATE_RULES: tuple[Rule, ...] = (_state,)
_VALUE_RULES: tuple[Rule, ...] = (_comparison, _own_reading, _minus, _angle_to, _kind_of_value)


# -- readings ------------------------------------------------------------------------------------


def _other_reading(path: str, reading: Reading, ctx: Context) -> Iterator[Problem]:
    """Another reading an expectation refers to (``minus``, ``angle_to``)."""
    if reading.body not in ctx.names:
        yield _unknown(f"{path}.body", reading.body, ctx.names)
        return
    if reading.quantity == "state":
        yield Problem(f"{path}.quantity", "a state is not a number or vector")
        return
    yield from _readable(path, reading.body, reading.quantity, ctx)


def _readable(
    path: str, body: str, q: str, ctx: Context, *, filtered: bool = False
) -> Iterator[Problem]:
    """What a body needs for its quantity ``q`` to be read."""
    level = ctx.level
    if QUANTITIES[q].source in ("solver", "perception") and body not in ctx.tracked:
        yield Problem(f"{path}.body", f"{body!r} is not tracked; add it to tracking.bodies")
    if q in CONTROLLER_QUANTITIES and body not in ctx.actors:
        yield Problem(f"{path}.quantity", f"{body!r} is not an actor: it has no {q} reading")
    if q in SPLIT_QUANTITIES and not level.settings.contact_split:
        yield Problem(f"{path}.quantity", f"{q} needs settings.contact_split = true")
    perceived = q == "perceived_gravity" or (q == "support" and filtered)
    if perceived and body not in ctx.actors and not level.tracking.perceive:
        yield Problem(f"{path}.quantity", "needs tracking.perceive = true")
    if q == "tilt" and body not in ctx.tracked:
        yield Problem(f"{path}.body", f"tilt needs an up: {body!r} must be an actor or tracked")
