"""The settings guide's four game-felt scenarios, each a shipped level run with the real controller
and observed after every step:

* **platform** (moving_platform): how far the player drifts relative to a platform that speeds up
  at 1 m/s², cm, and how much its perceived up shakes (the RMS rate at which it turns once the
  filter has settled, °/s: nothing turns there, so every degree is the filter's jitter);
* **ring** (spinning_ring): the angle between the perceived up and the exact one (away from the
  ring's floor, along the radius through the player's centre), RMS once settled, degrees;
* **room** (rotating_room): the largest angle between the perceived gravity and the field while
  the field turns, degrees;
* **landing** (rest, dropped from 1 m): the largest tilt after touchdown, degrees, and the deepest
  overlap of the capsule with the ground, mm.

:func:`build_with` builds a scenario's level with one knob (or a combination) moved from the
defaults.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import Any

from playground.level.document import Level
from tools.guide_settings import KNOBS, Combo, Knob

__all__ = ["DROP", "RUN_SPEED", "SCENARIOS", "build_with"]


def _level(name: str) -> Level:
    from playground.level.files import find
    from playground.level.loading import load

    return load(find(name))


def _with(level: Level, knob: Knob | None, value: float | bool) -> Level:
    """``level`` with ``knob`` set to ``value`` (None: unchanged)."""
    if knob is None or knob.where == "world":
        return level
    if knob.where == "settings":
        settings = level.settings.model_copy(update={knob.name: value})
        return level.model_copy(update={"settings": settings})
    if knob.where == "perception":
        perception = level.tracking.perception.model_copy(update={knob.name: value})
        tracking = level.tracking.model_copy(update={"perception": perception})
        return level.model_copy(update={"tracking": tracking})
    actors = [
        a.model_copy(update={"controller": a.controller.model_copy(update={knob.name: value})})
        for a in level.actors
    ]
    return level.model_copy(update={"actors": actors})


def _angle(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Angle between two vectors, degrees (0 when either has no length)."""
    na, nb = math.hypot(*a), math.hypot(*b)
    if na == 0.0 or nb == 0.0:
        return 0.0
    c = (a[0] * b[0] + a[1] * b[1]) / (na * nb)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def _penetration(body: Any) -> float:
    """Deepest overlap of ``body`` with static geometry now, m."""
    import pymunk

    deepest = 0.0

    def visit(arb: pymunk.Arbiter) -> None:
        nonlocal deepest
        if any(s.body is not None and s.body.body_type == pymunk.Body.STATIC for s in arb.shapes):
            for p in arb.contact_point_set.points:
                deepest = max(deepest, -p.distance)

    body.each_arbiter(visit)
    return deepest


# -- scenarios: build a level, then observe every step -----------------------------------------


def _platform_level() -> Level:
    return _level("moving_platform")


SHAKE_FROM = 1.0
"""s: the platform's shake is measured from here on (the filter has settled)."""


def _signed_angle(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Angle from ``b`` to ``a``, degrees, counter-clockwise positive."""
    return math.degrees(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))


def _platform_observe(scene: Any, s: dict[str, float]) -> None:
    w = scene.world
    rel = w.body("player").position.x - w.body("platform").position.x
    s.setdefault("start", rel)
    s["drift"] = max(s.get("drift", 0.0), 100.0 * abs(rel - s["start"]))
    # Shake: how fast the perceived up (the camera's roll) turns, RMS, where nothing turns.
    ux, uy = w.perceived_up("player")
    if w.time > SHAKE_FROM and "up x" in s:
        rate = _signed_angle((ux, uy), (s["up x"], s["up y"])) / w.config.dt
        s["shake sum"] = s.get("shake sum", 0.0) + rate * rate
        s["shake n"] = s.get("shake n", 0.0) + 1.0
        s["shake"] = math.sqrt(s["shake sum"] / s["shake n"])
    s["up x"], s["up y"] = ux, uy


RING_SECONDS = 4.0
"""s: the ring scenario's length (the level runs 10 s; the up settles within 2 s)."""

RING_SETTLED = 2.0
"""s: the ring's up error is measured from here on."""


def _ring_level() -> Level:
    level = _level("spinning_ring")
    settings = level.settings.model_copy(update={"seconds": RING_SECONDS})
    return level.model_copy(update={"settings": settings})


def _ring_observe(scene: Any, s: dict[str, float]) -> None:
    w = scene.world
    if w.time < RING_SETTLED:
        return
    p = w.body("player").position
    exact_up = (-p.x, -p.y)  # toward the axis: away from the floor the player stands on
    err = _angle(w.perceived_up("player"), exact_up)
    s["sum"] = s.get("sum", 0.0) + err * err
    s["n"] = s.get("n", 0.0) + 1.0
    s["ring up"] = math.sqrt(s["sum"] / s["n"])


def _room_level() -> Level:
    return _level("rotating_room")


def _room_observe(scene: Any, s: dict[str, float]) -> None:
    w = scene.world
    if w.time < 0.5:
        return
    g = w.gravity_at("player")
    s["room up"] = max(s.get("room up", 0.0), _angle(w.perceived_gravity("player"), g))


DROP = 2.0
"""m: how far above its ride height the landing scenario drops the player."""

RUN_SPEED = 3.0
"""m/s: the landing player's sideways speed (a running jump's landing, not a drop in place)."""


def _landing_level() -> Level:
    level = _level("rest")
    (actor,) = level.actors
    x, y = actor.position
    actor = actor.model_copy(update={"position": (x, y + DROP), "velocity": (RUN_SPEED, 0.0)})
    return level.model_copy(update={"actors": [actor]})


def _landing_observe(scene: Any, s: dict[str, float]) -> None:
    body = scene.world.body("player")
    pen = _penetration(body)
    s["penetration"] = max(s.get("penetration", 0.0), 1000.0 * pen)
    ctrl = scene.controllers["player"]
    if ctrl.probe is not None and body.velocity.y > -0.5:
        s["landed"] = 1.0
    if s.get("landed"):
        s["landing tilt"] = max(s.get("landing tilt", 0.0), math.degrees(abs(scene.tilt("player"))))
    else:
        s.setdefault("landing tilt", 0.0)


SCENARIOS: dict[
    str, tuple[Callable[[], Level], Callable[[Any, dict[str, float]], None], tuple[str, ...]]
] = {
    "platform": (_platform_level, _platform_observe, ("drift", "shake")),
    "ring": (_ring_level, _ring_observe, ("ring up",)),
    "room": (_room_level, _room_observe, ("room up",)),
    "landing": (_landing_level, _landing_observe, ("landing tilt", "penetration")),
}
"""Scenario name → (its level, what it observes after every step, the measures it reports)."""


def build_with(level: Level, knob: Knob | Combo | None, value: float | bool) -> Any:
    """Build ``level`` as a scene with ``knob`` set to ``value`` (None: the defaults; a
    :class:`Combo`: each of its knobs set, ``value`` unused)."""
    from playground.scene import build

    moves: list[tuple[Knob, float | bool]]
    if isinstance(knob, Combo):
        by_name = {k.name: k for k in KNOBS}
        moves = [(by_name[name], v) for name, v in knob.moves]
    else:
        moves = [] if knob is None else [(knob, value)]
    for k, v in moves:
        level = _with(level, k, v)
    scene = build(level)
    for k, v in moves:
        if k.where == "world":
            # The only world knob: sleeping, which the level format does not carry.
            scene.world.config = dataclasses.replace(scene.world.config, sleep_time=float(v))
    return scene
