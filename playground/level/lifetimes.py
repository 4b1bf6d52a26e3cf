"""Lifetimes: when each body of a level exists, found by walking its timeline in run order.

A body exists from the start (props, movers, actors) or from its spawn, until its removal.
Events run in the order the world runs them (by time, then file order; see
:mod:`playground.world.schedule`), so an event or a scripted ``nullify`` that names a body not
there at its time — removed already, removed twice, not yet spawned — and a check that reads a
body during a window it is not there for are refused here, before any run, each at its key.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

from playground.level.document import Level
from playground.level.errors import Problem
from playground.level.timeline import Remove, Spawn

__all__ = ["Lifetime", "lifetime_problems", "lifetimes"]


@dataclass(frozen=True, slots=True)
class Lifetime:
    """A body exists from ``born`` (s; 0 for a body of the setup) until ``gone`` (s; inf when
    never removed), its spawn and removal included."""

    born: float
    gone: float = math.inf

    def covers(self, start: float, stop: float) -> bool:
        """Whether the body exists over all of ``[start, stop]`` (s)."""
        return self.born <= start and stop < self.gone


def lifetimes(level: Level) -> tuple[dict[str, Lifetime], list[Problem]]:
    """Every body's lifetime, and the events that name a body absent at their time."""
    setup = [*(p.name for p in level.props), *(m.name for m in level.movers)]
    alive = {name: Lifetime(0.0) for name in (*setup, *(a.name for a in level.actors))}
    # Bodies spawned later, as they will be: naming one before its spawn is an error too.
    spawns = {e.prop.name: Lifetime(e.t) for e in level.events if isinstance(e, Spawn)}
    problems: list[Problem] = []
    order = sorted(range(len(level.events)), key=lambda i: (level.events[i].t, i))
    for i in order:
        event = level.events[i]
        if isinstance(event, Spawn):
            alive[event.prop.name] = Lifetime(event.t)
            continue
        body = getattr(event, "body", None)
        if body is None:
            continue
        life = alive.get(body)
        if life is None:
            later = spawns.get(body)
            if later is not None:  # spawned later in the run (at this time: later in the file)
                problems.append(Problem(f"events.{i}.body", _unborn(body, event.t, later)))
            continue  # else an unknown name: reported by the cross-references
        if event.t >= life.gone:
            problems.append(Problem(f"events.{i}.body", _absent(body, event.t, life)))
        elif isinstance(event, Remove):
            alive[body] = Lifetime(life.born, event.t)
    return alive, problems


def _unborn(body: str, t: float, life: Lifetime) -> str:
    after = "after this event" if life.born > t else "by an event after this one"
    return f"{body!r} is spawned at t = {life.born:g} s, {after} (t = {t:g} s)"


def _absent(body: str, t: float, life: Lifetime) -> str:
    if t < life.born:
        return _unborn(body, t, life)
    return f"{body!r} was removed at t = {life.gone:g} s, before this event (t = {t:g} s)"


def lifetime_problems(level: Level) -> Iterator[Problem]:
    """Events, scripted ``nullify`` inputs and checks naming a body absent at their time."""
    alive, problems = lifetimes(level)
    yield from problems
    dt = level.settings.dt
    for i, inp in enumerate(level.inputs):
        if inp.nullify is None or inp.nullify not in alive:
            continue
        life = alive[inp.nullify]
        # The controller reads the input in the step at its time and nullifies in the next one.
        if not life.covers(inp.t, inp.t + 2.0 * dt):
            yield Problem(f"inputs.{i}.nullify", _absent(inp.nullify, inp.t, life))
    seconds = level.settings.seconds
    for i, exp in enumerate(level.expect):
        if exp.check == "at":
            if exp.t is None:
                continue
            start = stop = exp.t
        else:
            start, stop = exp.window or (0.0, seconds)
        named = [("body", exp.body), ("relative_to", exp.relative_to)]
        for key, reading in (("minus", exp.minus), ("angle_to", exp.angle_to)):
            body = getattr(reading, "body", None)
            if body is not None:
                named.append((f"{key}.body", body))
        for key, body in named:
            if body is None or body not in alive:
                continue
            life = alive[body]
            if not life.covers(start, min(stop, seconds)):
                yield Problem(
                    f"expect.{i}.{key}",
                    f"{body!r} exists from t = {life.born:g} s to {life.gone:g} s, not over all "
                    f"of the check's [{start:g}, {stop:g}] s; check it where it exists",
                )
