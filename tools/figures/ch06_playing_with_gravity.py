"""Chapter 6, playing with gravity (docs/chapters/06-playing-with-gravity.md): the gravity
flip, the nullified enemy, the leap onto a flying creature, and the chapter's figure."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np
import pymunk

from playground.controller.config import ControllerConfig
from playground.controller.states import State
from playground.level.paths import Waypoints as WaypointsPath
from playground.level.shapes import Box as BoxShape
from playground.world.world import World
from tools.figures.ch01_kinematic_vs_force_driven import ch1_budget_accel
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import Array, G, level_scene, record, shipped_level


@cache
def flip_run() -> Array:
    """The gravity_flip level. Columns: t (s), height y (m), tilt against up (degrees),
    perceived gravity y (m/s²), grounded (1/0), the capsule touching something (1/0)."""
    scene = level_scene("gravity_flip")
    player = scene.controllers["player"]

    def touching() -> float:
        found: list[pymunk.Arbiter] = []
        player.body.each_arbiter(found.append)
        return 1.0 if found else 0.0

    def probe(w: World) -> list[float]:
        return [
            player.body.position.y,
            math.degrees(scene.tilt("player")),
            w.perceived_gravity("player")[1],
            1.0 if player.state is State.GROUNDED else 0.0,
            touching(),
        ]

    return record(scene.world, scene.level.settings.seconds, probe)


FLIP_TIME = 1.0
"""s: when gravity_flip turns gravity over."""


def _in_flight(r: Array) -> Array:
    """Rows from the first step after the flip at which the player is off the floor."""
    return r[np.nonzero((r[:, 0] > FLIP_TIME) & (r[:, 4] == 0.0))[0][0] :]


@number
def ch6_leave_time() -> float:
    """Time after the flip at which the floor lets go of the player, s."""
    return float(_in_flight(flip_run())[0, 0] - FLIP_TIME)


@number
def ch6_upright_time() -> float:
    """Time after the flip at which the tilt first drops below 15° in the air, s (once its up
    has turned to the field: from the most tilted step on)."""
    r = _in_flight(flip_run())
    r = r[int(np.argmax(r[:, 2])) :]
    return float(r[r[:, 2] < 15.0][0, 0] - FLIP_TIME)


@number
def ch6_probe_tilt() -> float:
    """Tilt against up when the probe first finds the ceiling (the hover catches it), degrees."""
    r = _in_flight(flip_run())
    return float(r[r[:, 4] == 1.0][0, 2])


@number
def ch6_contact_tilt() -> float:
    """Tilt against up when the capsule's body first touches the ceiling, degrees."""
    r = _in_flight(flip_run())
    return float(r[r[:, 5] == 1.0][0, 2])


@number
def ch6_final_perceived() -> float:
    """Perceived gravity y at the end, m/s² (positive: "down" is now up)."""
    return float(flip_run()[-1, 3])


@cache
def null_run() -> Array:
    """The null_enemy level. Columns: t (s), the enemy's speed (m/s), its |perceived gravity|
    (m/s²), its gravity y (m/s²)."""
    scene = level_scene("null_enemy")
    enemy = scene.controllers["enemy"]

    def probe(w: World) -> list[float]:
        return [
            float(np.hypot(*enemy.body.velocity)),
            float(np.hypot(*w.perceived_gravity("enemy"))),
            w.gravity_at("enemy")[1],
        ]

    return record(scene.world, scene.level.settings.seconds, probe)


@number
def ch6_null_perceived() -> float:
    """The nullified enemy's |perceived gravity| at the end, m/s²."""
    return float(null_run()[-1, 2])


@number
def ch6_null_before() -> float:
    """The enemy's |perceived gravity| while it patrols (t in [0.2, 0.45] s), m/s²."""
    r = null_run()
    window = (r[:, 0] >= 0.2) & (r[:, 0] <= 0.45)
    return float(np.mean(r[window, 2]))


@number
def ch6_null_budget_accel() -> float:
    """The patrol's acceleration at the drive budget: ground_force / mass (chapter 1's budget),
    m/s²."""
    return ch1_budget_accel()


@number
def ch6_null_before_expected() -> float:
    """√(g² + (ground_force/m)²): what a body feels while its drive pushes at budget, m/s²."""
    return math.hypot(G, ch6_null_budget_accel())


@number
def ch6_null_speed_change() -> float:
    """Largest change of the enemy's speed after t = 1.5 s, m/s."""
    r = null_run()
    after = r[r[:, 0] >= 1.5, 1]
    return float(np.max(np.abs(after - after[0])))


@number
def ch6_air_budget_bound() -> float:
    """What the air budget allows over 1.5 s: air_force / m · 1.5 s, m/s."""
    c = ControllerConfig()
    return c.air_budget(c.mass) / c.mass * 1.5


LEAP_TIME = 1.0
"""s: when gravity_leap's player switches its gravity and jumps."""


@cache
def leap_run(speed: float | None = None) -> Array:
    """The gravity_leap level, its creature flying at ``speed`` (m/s) if given.

    Columns: t (s), standing on the creature (1/0: grounded, its probe on the creature), the
    player's centre relative to the creature's x, y (m), its speed relative to the creature (m/s),
    tilt against its up (degrees), perceived gravity x, y (m/s²).
    """
    from playground.scene import build

    level = shipped_level("gravity_leap")
    if speed is not None:
        (mover,) = level.movers
        path = mover.path.model_copy(update={"speed": speed})
        level = level.model_copy(update={"movers": [mover.model_copy(update={"path": path})]})
    scene = build(level)
    player = scene.controllers["player"]
    beast = scene.world.body("beast")

    def probe(w: World) -> list[float]:
        hit = player.probe
        on = player.state is State.GROUNDED and hit is not None and hit.body is beast
        rel = player.body.position - beast.position
        return [
            1.0 if on else 0.0,
            rel.x,
            rel.y,
            (player.body.velocity - beast.velocity).length,
            math.degrees(scene.tilt("player")),
            *w.perceived_gravity("player"),
        ]

    return record(scene.world, scene.level.settings.seconds, probe)


def _landing(r: Array) -> Array:
    """The first row at which the player stands on the creature."""
    row: Array = r[np.nonzero(r[:, 1] == 1.0)[0][0]]
    return row


@number
def ch6_leap_land_time() -> float:
    """Time from the leap to standing on the creature, s."""
    return float(_landing(leap_run())[0] - LEAP_TIME)


@number
def ch6_leap_land_x() -> float:
    """Where the player lands: its x relative to the creature's centre, m."""
    return float(_landing(leap_run())[2])


@number
def ch6_leap_end_x() -> float:
    """The player's x relative to the creature's centre at the end, m."""
    return float(leap_run()[-1, 2])


@number
def ch6_leap_ride_y() -> float:
    """The player's y relative to the creature's centre at the end, m (below it: negative)."""
    return float(leap_run()[-1, 3])


@number
def ch6_leap_relative_speed() -> float:
    """The player's speed relative to the creature at the end, m/s."""
    return float(leap_run()[-1, 4])


@number
def ch6_leap_speed() -> float:
    """How fast gravity_leap's creature flies, m/s."""
    (mover,) = shipped_level("gravity_leap").movers
    if not isinstance(mover.path, WaypointsPath):
        raise TypeError(f"gravity_leap: expected a waypoints path, got {mover.path.kind!r}")
    speed: float = mover.path.speed
    return speed


def leap_half_width() -> float:
    """Half the width of gravity_leap's creature, m: the player stands on it while its x relative
    to the creature's centre is within ± this."""
    (mover,) = shipped_level("gravity_leap").movers
    shape = mover.shapes[0]
    if not isinstance(shape, BoxShape):
        raise TypeError(f"gravity_leap: expected a box creature, got {shape.kind!r}")
    return 0.5 * shape.size[0]


@number
def ch6_leap_perceived() -> float:
    """|Perceived gravity| at the end, m/s²."""
    return float(np.hypot(*leap_run()[-1, 6:8]))


@number
def ch6_leap_slope() -> float:
    """Angle between the perceived gravity at the end and the creature's underside's normal
    (+y), degrees: how steep a slope that flat underside is to the player."""
    gx, gy = leap_run()[-1, 6:8]
    return math.degrees(math.atan2(abs(gx), gy))


LEAP_FAST = 2.0
"""m/s: the exercise's creature, twice as fast as the level's."""


@number
def ch6_leap_fast_land_time() -> float:
    """The exercise: time from the leap to standing on a creature flying at LEAP_FAST, s."""
    return float(_landing(leap_run(LEAP_FAST))[0] - LEAP_TIME)


@number
def ch6_leap_fast_land_x() -> float:
    """The exercise: where the player lands on a creature flying at LEAP_FAST, m."""
    return float(_landing(leap_run(LEAP_FAST))[2])


@number
def ch6_leap_fast_end_x() -> float:
    """The exercise: the player's x relative to the fast creature's centre at the end, m."""
    return float(leap_run(LEAP_FAST)[-1, 2])


@figure("06-playing-with-gravity.png")
def fig_ch6(path: Path) -> Path:
    """The gravity flip: height and tilt; the null enemy's felt gravity; the leap, seen from the
    creature."""
    r = flip_run()
    n = null_run()
    leap = leap_run()
    fast = leap_run(LEAP_FAST)
    fig, (a, b, c, d) = axes(4, height=2.6)
    a.plot(r[:, 0], r[:, 1])
    a.axhline(r[-1, 1], color="k", ls="--", lw=1, label="ride height under the ceiling")
    a.set_ylabel("height of the centre (m)")
    a.set_title(f"gravity_flip: gravity turns over at t = {FLIP_TIME:g} s")
    a.legend()
    b.plot(r[:, 0], r[:, 2], label="tilt from up")
    b.axhline(15.0, color="k", ls="--", lw=1, label="15°")
    b.set_xlabel("time (s)")
    b.set_ylabel("tilt (degrees)")
    b.legend()
    c.plot(n[:, 0], n[:, 3], lw=3, alpha=0.5, label="gravity y at the enemy")
    c.plot(n[:, 0], -n[:, 2], "k--", label="−|perceived gravity| of the enemy")
    c.set_xlabel("time (s)")
    c.set_ylabel("m/s²")
    c.set_title("null_enemy: gravity nullified at t = 1 s")
    c.legend()
    d.plot(leap[:, 0], leap[:, 2], color="C0", label="x relative to the creature")
    d.plot(leap[:, 0], leap[:, 3], color="C1", label="y relative to the creature")
    d.plot(fast[:, 0], fast[:, 2], ":", color="C0", label=f"x, creature at {LEAP_FAST:g} m/s")
    d.axvline(LEAP_TIME + ch6_leap_land_time(), color="k", ls="--", lw=1, label="lands")
    half = leap_half_width()
    d.axhspan(-half, half, color="C0", alpha=0.08, label="x on the creature's width")
    d.set_ylim(-7.0, 10.0)
    d.set_xlabel("time (s)")
    d.set_ylabel("m")
    d.set_title(f"gravity_leap: own gravity switched and a jump at t = {LEAP_TIME:g} s")
    d.legend(fontsize=8, ncol=3, loc="upper center")
    return save(fig, path)
