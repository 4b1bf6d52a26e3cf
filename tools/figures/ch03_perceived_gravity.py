"""Chapter 3, perceived gravity (docs/chapters/03-perceived-gravity.md): the rotating room's
turning field and the spinning ring's v²/r, and the chapter's figure."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np

from playground.level.document import Level
from playground.level.gravity import RotatingGravity, Turn
from playground.level.paths import Spin as SpinPath
from playground.level.shapes import Ring as RingShape
from playground.world.world import World
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import Array, level_scene, record, shipped_level


@cache
def room_run() -> Array:
    """The rotating_room level. Columns: t (s), the field's angle and the perceived gravity's
    angle (degrees, from +x), the player's tilt against its up (degrees)."""
    scene = level_scene("rotating_room")

    def probe(w: World) -> list[float]:
        g = w.gravity_at("player")
        p = w.perceived_gravity("player")
        return [
            math.degrees(math.atan2(g[1], g[0])),
            math.degrees(math.atan2(p[1], p[0])),
            math.degrees(scene.tilt("player")),
        ]

    return record(scene.world, scene.level.settings.seconds, probe)


@number
def ch3_room_max_lag() -> float:
    """Largest angle between the field and the perceived gravity during the turn, degrees."""
    r = room_run()
    return float(np.max(np.abs(r[:, 2] - r[:, 1])[r[:, 0] > 0.5]))


@number
def ch3_room_final_error() -> float:
    """Angle between the field and the perceived gravity at the end, degrees."""
    r = room_run()
    return float(abs(r[-1, 2] - r[-1, 1]))


def _room_turn() -> Turn:
    """rotating_room's (first) scheduled turn of its field."""
    gravity = shipped_level("rotating_room").gravity
    if not isinstance(gravity, RotatingGravity) or not gravity.turns:
        raise TypeError("rotating_room: expected a rotating field with a scheduled turn")
    turn: Turn = gravity.turns[0]
    return turn


@number
def ch3_room_turn() -> float:
    """How far rotating_room's field turns, rad."""
    angle: float = _room_turn().angle
    return angle


@number
def ch3_room_turn_deg() -> float:
    """The same turn in degrees."""
    return math.degrees(ch3_room_turn())


@number
def ch3_room_turn_time() -> float:
    """How long rotating_room's field takes to turn, s."""
    duration: float = _room_turn().duration
    return duration


def _ring(rate: float | None = None) -> Level:
    """The spinning_ring level, with its ring spinning at ``rate`` (rad/s) if given; the player
    starts carried by the floor at that rate (velocity ω·r, spin ω), as the level itself does."""
    level = shipped_level("spinning_ring")
    if rate is None:
        return level
    (mover,) = level.movers
    (actor,) = level.actors
    r0 = math.hypot(*actor.position)
    path = mover.path.model_copy(update={"rate": rate})
    actor = actor.model_copy(update={"velocity": (rate * r0, 0.0), "angular_velocity": rate})
    return level.model_copy(
        update={"movers": [mover.model_copy(update={"path": path})], "actors": [actor]}
    )


RING_SETTLED = 2.0
"""s: readings in the ring are averaged from here to the level's end (the 1€ filter has settled;
the level's own perceived-gravity check uses the same window)."""


@cache
def ring_run(rate: float) -> Array:
    """The spinning_ring level with its ring spinning at ``rate`` (rad/s), no gravity.

    Columns: t (s), |perceived gravity| (m/s²), ω²·r at the player's centre (m/s²), |support| (N).
    """
    from playground.scene import build

    scene = build(_ring(rate))

    def probe(w: World) -> list[float]:
        r = float(np.hypot(*w.body("player").position))
        return [
            float(np.hypot(*w.perceived_gravity("player"))),
            rate**2 * r,
            float(np.hypot(*w.forces("player").support)),
        ]

    return record(scene.world, scene.level.settings.seconds, probe)


def ring_reading(rate: float) -> tuple[float, float]:
    """(|perceived gravity|, ω²·r at the player's centre) in the ring spinning at ``rate``
    (rad/s), each averaged over the settled part of the level, m/s²."""
    r = ring_run(rate)
    settled = r[:, 0] >= RING_SETTLED
    return float(np.mean(r[settled, 1])), float(np.mean(r[settled, 2]))


def _ring_shape() -> RingShape:
    """spinning_ring's ring, as the level declares it."""
    (mover,) = _ring().movers
    shape = mover.shapes[0]
    if not isinstance(shape, RingShape):
        raise TypeError(f"spinning_ring: expected a ring shape, got {shape.kind!r}")
    return shape


@number
def ch3_ring_rim() -> float:
    """Inner radius of spinning_ring's ring, m."""
    return _ring_shape().radius


@number
def ch3_ring_segments() -> float:
    """How many flat segments make spinning_ring's floor."""
    return float(_ring_shape().segments)


@number
def ch3_ring_rate() -> float:
    """spinning_ring's spin ω, rad/s."""
    (mover,) = _ring().movers
    if not isinstance(mover.path, SpinPath):
        raise TypeError(f"spinning_ring: expected a spin path, got {mover.path.kind!r}")
    rate: float = mover.path.rate
    return rate


@number
def ch3_ring_centre() -> float:
    """Radius r of the player's centre at the start of spinning_ring, m."""
    return math.hypot(*_ring().actors[0].position)


@number
def ch3_ring_centre_run() -> float:
    """Mean radius of the player's centre in spinning_ring once settled, m."""
    rate = ch3_ring_rate()
    r = ring_run(rate)
    return float(np.mean(r[r[:, 0] >= RING_SETTLED, 2])) / rate**2


@number
def ch3_ring_expected() -> float:
    """ω²·r with the level's ω and r, m/s²."""
    return ch3_ring_rate() ** 2 * ch3_ring_centre()


@number
def ch3_ring_perceived() -> float:
    """|Perceived gravity| in spinning_ring, averaged once settled, m/s²."""
    return ring_reading(ch3_ring_rate())[0]


@number
def ch3_ring_mass() -> float:
    """The player's mass in spinning_ring, kg."""
    from playground.scene import build

    return build(_ring()).world.body("player").mass


@number
def ch3_ring_support_expected() -> float:
    """N = m·ω²·r with the level's m, ω and r, N."""
    return ch3_ring_mass() * ch3_ring_expected()


@number
def ch3_ring_support() -> float:
    """|Support| the solver reads in spinning_ring, averaged once settled, N."""
    r = ring_run(ch3_ring_rate())
    return float(np.mean(r[r[:, 0] >= RING_SETTLED, 3]))


@number
def ch3_ring_ratio() -> float:
    """Perceived gravity at twice the level's spin over that at its spin."""
    rate = ch3_ring_rate()
    return ring_reading(2.0 * rate)[0] / ring_reading(rate)[0]


@figure("03-perceived-gravity.png")
def fig_ch3(path: Path) -> Path:
    """The rotating room's field and perceived gravity; the ring's v²/r."""
    r = room_run()
    fig, (a, b) = axes(2)
    a.plot(r[:, 0], r[:, 1], lw=3, alpha=0.5, label="gravity field at the player")
    a.plot(r[:, 0], r[:, 2], "k--", label="perceived gravity (1€-filtered)")
    a.set_xlabel("time (s)")
    a.set_ylabel("direction (degrees from +x)")
    a.set_title("rotating_room")
    a.legend()
    rates = np.array([0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
    readings = np.array([ring_reading(float(w)) for w in rates])
    b.plot(rates, readings[:, 1], lw=3, alpha=0.5, label="ω²·r at the player's centre")
    b.plot(rates, readings[:, 0], "ko", label="|perceived gravity|")
    b.axvline(ch3_ring_rate(), color="k", ls="--", lw=1, label="the level's spin")
    b.set_xlabel("ring spin ω (rad/s)")
    b.set_ylabel("gravity felt (m/s²)")
    b.set_title(f"spinning_ring: the player on a {ch3_ring_rim():g} m ring, no gravity at all")
    b.legend()
    return save(fig, path)
