"""The teaching chapters' figures and numbers (docs/chapters), made by the code itself.

Every number a chapter quotes is a function in :data:`NUMBERS` (name → value, in the unit the text
states) and every figure a function in :data:`FIGURES` (name → draws a PNG). The simulations behind
them run once per process (cached) and headless; matplotlib is imported only when a figure is
drawn (it is in the ``bench`` extra). ``playground figures`` regenerates every figure.

>>> round(NUMBERS["ch5_k"](), 1)
69087.2
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache, partial
from pathlib import Path
from typing import Any, Literal

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground.controller import Controller, ControllerConfig, State, hover_limit, hover_spring
from playground.filters import (
    ExponentialMovingAverage,
    Filter,
    FilterChain,
    Median3,
    OneEuroFilter,
)
from playground.intents import Intent, Script
from playground.level import Box as BoxShape
from playground.level import Level, RotatingGravity, Turn
from playground.level import Ring as RingShape
from playground.level import Spin as SpinPath
from playground.level import Waypoints as WaypointsPath
from playground.scene import Scene
from playground.world import Stage, World, WorldConfig

__all__ = ["FIGURES", "NUMBERS", "make_all"]

Array = NDArray[np.float64]
G = 9.81
"""Standard gravity of the levels, m/s²."""

DT = 1.0 / 120.0
"""The levels' step, s."""


def _scene(name: str, **settings: Any) -> Scene:
    """Build a shipped level, optionally with some of its settings changed."""
    from playground.level import find, load
    from playground.scene import build

    level = load(find(name))
    if settings:
        level = level.model_copy(update={"settings": level.settings.model_copy(update=settings)})
    return build(level)


def _record(world: World, seconds: float, probe: Callable[[World], list[float]]) -> Array:
    """Step ``world`` for ``seconds`` and stack ``[t, *probe(world)]`` after every step."""
    rows: list[list[float]] = []
    for _ in range(round(seconds / world.config.dt)):
        world.step()
        rows.append([world.time, *probe(world)])
    return np.array(rows, dtype=np.float64)


# -- chapter 1: kinematic and force-driven -------------------------------------------------------


@cache
def platform_run(acceleration: float = 1.0, feed_forward: bool = True) -> Array:
    """The moving_platform level (its platform accelerating at ``acceleration``, m/s², for 1 s),
    plus a kinematic character placed beside the player; ``feed_forward`` False runs it under
    the ``ground_acceleration_ignored`` break (the drive no longer feeds the platform's
    acceleration forward).

    Columns: t (s), platform x, player x, kinematic character x (m), drive force x (N).
    The kinematic character's velocity is its input (zero): nothing the world does can move it.
    """
    if not feed_forward:
        from playground.faults import apply

        with apply("ground_acceleration_ignored"):
            return _platform_run(acceleration)
    return _platform_run(acceleration)


def _platform_run(acceleration: float) -> Array:
    from playground.level import find, load
    from playground.scene import build

    level = load(find("moving_platform"))
    mover = level.movers[0]
    path = mover.path.model_copy(update={"acceleration": acceleration})
    level = level.model_copy(update={"movers": [mover.model_copy(update={"path": path})]})
    scene = build(level)
    world = scene.world
    kin = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    kin.position = (0.0, 0.95)
    world.add("kinematic", kin)
    player = scene.controllers["player"]

    def probe(w: World) -> list[float]:
        kin.velocity = (0.0, 0.0)  # input says "stand still": a kinematic body obeys exactly
        return [
            w.body("platform").position.x,
            w.body("player").position.x,
            kin.position.x,
            player.last_forces.drive[0],
        ]

    return _record(world, scene.level.settings.seconds, probe)


def ch1_platform_travel() -> float:
    """How far the platform travels during the level, m."""
    r = platform_run()
    return float(r[-1, 1] - r[0, 1])


def ch1_player_drift_cm(acceleration: float = 1.0, feed_forward: bool = True) -> float:
    """Largest drift of the force-driven player relative to the platform, cm."""
    r = platform_run(acceleration, feed_forward)
    rel = (r[:, 2] - r[:, 1]) - (r[0, 2] - r[0, 1])
    return float(np.max(np.abs(rel)) * 100.0)


def ch1_predicted_drift_cm() -> float:
    """Drift with the ground's acceleration fed forward: the acceleration is read one step late
    where it starts, a velocity gap a·dt closed with time constant τ: a·dt·τ (1 m/s², 1/120 s,
    0.05 s), cm."""
    return 1.0 * DT * ControllerConfig().drive_time * 100.0


def ch1_lag_drift_cm() -> float:
    """Drift of a drive without the feed-forward, a first-order lag: a·τ·T (1 m/s², 0.05 s,
    1 s), cm."""
    return 1.0 * ControllerConfig().drive_time * 1.0 * 100.0


def ch1_lag_simulated_cm() -> float:
    """The level's drift under the ``ground_acceleration_ignored`` break, cm."""
    return ch1_player_drift_cm(1.0, feed_forward=False)


def ch1_drift_2_cm() -> float:
    """The exercise: the same drift with the platform accelerating at 2 m/s², cm."""
    return ch1_player_drift_cm(2.0)


def ch1_budget_accel() -> float:
    """The largest acceleration the drive budget can follow: ground_force / mass, m/s²."""
    c = ControllerConfig()
    return c.ground_force / c.mass


def ch1_kinematic_drift() -> float:
    """Drift of the kinematic character relative to the platform at the end, m."""
    r = platform_run()
    rel = (r[:, 3] - r[:, 1]) - (r[0, 3] - r[0, 1])
    return float(abs(rel[-1]))


def ch1_drive_accel() -> float:
    """Mean drive force while the platform accelerates (t in [0.75, 1.5] s), N."""
    r = platform_run()
    window = (r[:, 0] >= 0.75) & (r[:, 0] <= 1.5)
    return float(np.mean(r[window, 4]))


# -- chapter 2: reverse force integration --------------------------------------------------------

SLIDE_DAMPING = 0.5
"""Chapter 2's world keeps half its velocity per second: damping large enough to see."""


@cache
def slide_run() -> Array:
    """A 10 kg box thrown sideways at 3 m/s onto a floor, in a world with damping 0.5.

    Columns: t (s), engine force x, y (reverse integration), contact sum x, y, and the naive
    estimate x, y that forgets damping, m·(v₁ − v₀)/dt − m·g (N).
    """
    world = World(WorldConfig(damping=SLIDE_DAMPING, contact_split=True))
    world.add_static_segment((-5.0, 0.0), (20.0, 0.0))
    box = world.add_box("box", mass=10.0, size=(0.5, 0.5), position=(0.0, 0.5), friction=0.3)
    box.velocity = (3.0, 0.0)
    world.track("box")
    last = [box.velocity.x, box.velocity.y]

    def probe(w: World) -> list[float]:
        f = w.forces("box")
        v = box.velocity
        m, dt = box.mass, w.config.dt
        naive = [m * (v.x - last[0]) / dt, m * (v.y - last[1]) / dt + m * G]
        last[:] = [v.x, v.y]
        return [*f.engine, *f.contact, *naive]

    return _record(world, 1.5, probe)


def ch2_ghost_exercise() -> float:
    """The exercise's ghost force: 10 kg at 6 m/s, damping 0.9, dt = 1/120 s, N."""
    return 10.0 * (1.0 - float(0.9**DT)) * 6.0 / DT


def ch2_max_disagreement() -> float:
    """Largest |engine − contact sum| over the run, as a fraction of the box's weight."""
    r = slide_run()
    return float(np.max(np.hypot(r[:, 1] - r[:, 3], r[:, 2] - r[:, 4])) / (10.0 * G))


def ch2_ghost_force() -> float:
    """The naive estimate's x force on the first step (nothing touches the box yet), N."""
    return float(slide_run()[0, 5])


@cache
def seesaw_run() -> Array:
    """The seesaw level with the contact split on. Columns: t (s), the plank's engine force y,
    contact y and constraint (joint) y (N), and the hover's reaction on the plank y (N)."""
    scene = _scene("seesaw", contact_split=True)
    player = scene.controllers["player"]

    def probe(w: World) -> list[float]:
        f = w.forces("plank")
        return [f.engine[1], f.contact[1], f.constraint[1], -player.last_forces.hover[1]]

    return _record(scene.world, scene.level.settings.seconds, probe)


def _last_second(r: Array, col: int) -> float:
    return float(np.mean(r[r[:, 0] > r[-1, 0] - 1.0, col]))


def ch2_plank_joint() -> float:
    """Mean joint force on the plank over the last second (the residual engine − contact), N."""
    return _last_second(seesaw_run(), 3)


def ch2_plank_contact() -> float:
    """Mean contact force on the plank over the last second, N."""
    return _last_second(seesaw_run(), 2)


def ch2_total_weight() -> float:
    """Weight of the plank (20 kg) and the player (70 kg), N."""
    return (20.0 + ControllerConfig().mass) * G


# -- chapter 3: perceived gravity ----------------------------------------------------------------


@cache
def room_run() -> Array:
    """The rotating_room level. Columns: t (s), the field's angle and the perceived gravity's
    angle (degrees, from +x), the player's tilt against its up (degrees)."""
    scene = _scene("rotating_room")

    def probe(w: World) -> list[float]:
        g = w.gravity_at("player")
        p = w.perceived_gravity("player")
        return [
            math.degrees(math.atan2(g[1], g[0])),
            math.degrees(math.atan2(p[1], p[0])),
            math.degrees(scene.tilt("player")),
        ]

    return _record(scene.world, scene.level.settings.seconds, probe)


def ch3_room_max_lag() -> float:
    """Largest angle between the field and the perceived gravity during the turn, degrees."""
    r = room_run()
    return float(np.max(np.abs(r[:, 2] - r[:, 1])[r[:, 0] > 0.5]))


def ch3_room_final_error() -> float:
    """Angle between the field and the perceived gravity at the end, degrees."""
    r = room_run()
    return float(abs(r[-1, 2] - r[-1, 1]))


@cache
def _level(name: str) -> Level:
    """A shipped level, loaded and validated once per process."""
    from playground.level import find, load

    return load(find(name))


def _room_turn() -> Turn:
    """rotating_room's (first) scheduled turn of its field."""
    gravity = _level("rotating_room").gravity
    if not isinstance(gravity, RotatingGravity) or not gravity.turns:
        raise TypeError("rotating_room: expected a rotating field with a scheduled turn")
    return gravity.turns[0]


def ch3_room_turn() -> float:
    """How far rotating_room's field turns, rad."""
    return _room_turn().angle


def ch3_room_turn_deg() -> float:
    """The same turn in degrees."""
    return math.degrees(ch3_room_turn())


def ch3_room_turn_time() -> float:
    """How long rotating_room's field takes to turn, s."""
    return _room_turn().duration


def _ring(rate: float | None = None) -> Level:
    """The spinning_ring level, with its ring spinning at ``rate`` (rad/s) if given; the player
    starts carried by the floor at that rate (velocity ω·r, spin ω), as the level itself does."""
    level = _level("spinning_ring")
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

    return _record(scene.world, scene.level.settings.seconds, probe)


def ring_reading(rate: float) -> tuple[float, float]:
    """(|perceived gravity|, ω²·r at the player's centre) in the ring spinning at ``rate``
    (rad/s), each averaged over the settled part of the level, m/s²."""
    r = ring_run(rate)
    settled = r[:, 0] >= RING_SETTLED
    return float(np.mean(r[settled, 1])), float(np.mean(r[settled, 2]))


def ch3_ring_rim() -> float:
    """Inner radius of spinning_ring's ring, m."""
    (mover,) = _ring().movers
    shape = mover.shapes[0]
    if not isinstance(shape, RingShape):
        raise TypeError(f"spinning_ring: expected a ring shape, got {shape.kind!r}")
    return shape.radius


def ch3_ring_segments() -> float:
    """How many flat segments make spinning_ring's floor."""
    (mover,) = _ring().movers
    shape = mover.shapes[0]
    if not isinstance(shape, RingShape):
        raise TypeError(f"spinning_ring: expected a ring shape, got {shape.kind!r}")
    return float(shape.segments)


def ch3_ring_rate() -> float:
    """spinning_ring's spin ω, rad/s."""
    (mover,) = _ring().movers
    if not isinstance(mover.path, SpinPath):
        raise TypeError(f"spinning_ring: expected a spin path, got {mover.path.kind!r}")
    return mover.path.rate


def ch3_ring_centre() -> float:
    """Radius r of the player's centre at the start of spinning_ring, m."""
    return math.hypot(*_ring().actors[0].position)


def ch3_ring_centre_run() -> float:
    """Mean radius of the player's centre in spinning_ring once settled, m."""
    rate = ch3_ring_rate()
    r = ring_run(rate)
    return float(np.mean(r[r[:, 0] >= RING_SETTLED, 2])) / rate**2


def ch3_ring_expected() -> float:
    """ω²·r with the level's ω and r, m/s²."""
    return ch3_ring_rate() ** 2 * ch3_ring_centre()


def ch3_ring_perceived() -> float:
    """|Perceived gravity| in spinning_ring, averaged once settled, m/s²."""
    return ring_reading(ch3_ring_rate())[0]


def ch3_ring_mass() -> float:
    """The player's mass in spinning_ring, kg."""
    from playground.scene import build

    return build(_ring()).world.body("player").mass


def ch3_ring_support_expected() -> float:
    """N = m·ω²·r with the level's m, ω and r, N."""
    return ch3_ring_mass() * ch3_ring_expected()


def ch3_ring_support() -> float:
    """|Support| the solver reads in spinning_ring, averaged once settled, N."""
    r = ring_run(ch3_ring_rate())
    return float(np.mean(r[r[:, 0] >= RING_SETTLED, 3]))


def ch3_ring_ratio() -> float:
    """Perceived gravity at twice the level's spin over that at its spin."""
    rate = ch3_ring_rate()
    return ring_reading(2.0 * rate)[0] / ring_reading(rate)[0]


# -- chapter 4: filtering a spiky force ----------------------------------------------------------

CH4_FILTERS: dict[str, Callable[[], Filter] | None] = {
    "raw": None,
    "moving average 5 Hz": lambda: ExponentialMovingAverage(cutoff=5.0),
    "1€ 2 Hz, β 0.05": lambda: OneEuroFilter(min_cutoff=2.0, beta=0.05),
    "median-of-3 + 1€": lambda: FilterChain(Median3(), OneEuroFilter(min_cutoff=2.0, beta=0.05)),
}
"""Chapter 4's filters, by label (the last is what perception uses by default)."""


def _filtered(make: Callable[[], Filter] | None, x: Array, dt: float) -> Array:
    if make is None:
        return x
    f = make()
    return np.array([f.filter(float(v), dt) for v in x], dtype=np.float64)


@cache
def bounce_run() -> Array:
    """The bounce level: ball1's felt vertical specific force (m/s²) over time. Columns: t (s),
    then one column per filter of :data:`CH4_FILTERS`."""
    scene = _scene("bounce")
    raw = _record(
        scene.world, scene.level.settings.seconds, lambda w: [w.forces("ball1").specific[1]]
    )
    cols = [_filtered(make, raw[:, 1], DT) for make in CH4_FILTERS.values()]
    return np.column_stack([raw[:, 0], *cols])


NOISE = 0.5
"""Standard deviation of the synthetic reading's noise at rest, m/s²."""


@cache
def _noisy_rest() -> Array:
    """Two seconds of a resting reading g plus seeded Gaussian noise, m/s²."""
    rng = np.random.default_rng(7)
    return G + NOISE * rng.standard_normal(round(2.0 / DT))


def jitter(make: Callable[[], Filter] | None) -> float:
    """Spread (standard deviation) of the filtered noisy rest signal after 1 s, m/s²."""
    out = _filtered(make, _noisy_rest(), DT)
    return float(np.std(out[round(1.0 / DT) :]))


def lag(make: Callable[[], Filter] | None) -> float:
    """Delay following a ramp of g per second, s (see bench.accuracy.filter_lag)."""
    from playground.bench.accuracy import filter_lag

    return filter_lag(make, DT)


TUNE_CUTOFFS = (8.0, 4.0, 2.0, 1.0, 0.5)
"""Hz: the min_cutoff ladder of the tuning procedure (β = 0)."""

TUNE_BETAS = (0.0, 0.01, 0.05, 0.2, 1.0)
"""The β ladder of the tuning procedure."""

JITTER_TARGET = 0.1
"""m/s²: "stops jittering" — a 1 % wobble of g, below what a player sees in the camera's up."""

LAG_TARGET = 0.05
"""s: "stops lagging" — three steps at 60 fps."""


@cache
def tuning() -> tuple[list[tuple[float, float]], float, list[tuple[float, float]], float]:
    """The tuning procedure on the synthetic signal.

    Returns ([(min_cutoff, jitter)], chosen min_cutoff, [(β, lag)], chosen β).
    """
    steps = [(fc, jitter(partial(OneEuroFilter, min_cutoff=fc))) for fc in TUNE_CUTOFFS]
    chosen = next((fc for fc, j in steps if j < JITTER_TARGET), TUNE_CUTOFFS[-1])
    betas = [(b, lag(partial(OneEuroFilter, min_cutoff=chosen, beta=b))) for b in TUNE_BETAS]
    beta = next((b for b, d in betas if d < LAG_TARGET), TUNE_BETAS[-1])
    return steps, chosen, betas, beta


SPIKE = 300.0
"""Height of chapter 4's one-step spike over g, m/s² (a bounce of a 1 kg ball is of this order)."""


def spike_peak(make: Callable[[], Filter]) -> float:
    """Largest excess over g at the output when one step of a resting signal jumps by SPIKE."""
    x = np.full(240, G)
    x[120] += SPIKE
    return float(np.max(_filtered(make, x, DT)) - G)


def ch4_jitter_raw() -> float:
    return jitter(None)


def ch4_jitter_ema() -> float:
    return jitter(CH4_FILTERS["moving average 5 Hz"])


def ch4_jitter_euro() -> float:
    return jitter(CH4_FILTERS["1€ 2 Hz, β 0.05"])


def ch4_lag_ema() -> float:
    return lag(CH4_FILTERS["moving average 5 Hz"])


def ch4_lag_euro() -> float:
    return lag(CH4_FILTERS["1€ 2 Hz, β 0.05"])


def ch4_tuned_cutoff() -> float:
    return tuning()[1]


def ch4_tuned_beta() -> float:
    return tuning()[3]


def ch4_tuned_lag_beta0() -> float:
    """Lag of the chosen min_cutoff with β = 0, s."""
    return tuning()[2][0][1]


def ch4_tuned_lag() -> float:
    """Lag of the chosen min_cutoff and β, s."""
    _, _, betas, beta = tuning()
    return dict(betas)[beta]


def euro_ramp_lag(min_cutoff: float, beta: float, slope: float, dt: float) -> float:
    """The 1€ filter's lag on a ramp, s: the fixed point of

        L = 1/(2π·(min_cutoff + β·s·(1 + L/Te)))

    On a ramp of slope s (unit/s) the filter's output trails by L, and the derivative is taken
    against the previous *filtered* value, so the speed it sees is (X_i − X̂_{i−1})/Te =
    s·(Te + L)/Te; its cutoff is min_cutoff + β·s·(1 + L/Te), and an exponential average of
    cutoff fc trails a ramp by exactly τ = 1/(2π·fc), also in discrete time. The right side falls
    as L grows, so there is one fixed point, found by bisection between 0 and τ(min_cutoff).

    >>> round(euro_ramp_lag(1.0, 0.0, 9.81, 1 / 120), 4)   # β = 0: τ of 1 Hz
    0.1592
    """
    lo, hi = 0.0, 1.0 / (2.0 * math.pi * min_cutoff)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        rhs = 1.0 / (2.0 * math.pi * (min_cutoff + beta * slope * (1.0 + mid / dt)))
        lo, hi = (mid, hi) if rhs > mid else (lo, mid)
    return 0.5 * (lo + hi)


def ch4_lag_euro_fixed() -> float:
    """The fixed-point lag of perception's 1€ filter (2 Hz, β 0.05) on a ramp of g per second,
    s."""
    return euro_ramp_lag(2.0, 0.05, G, DT)


def ch4_tuned_lag_fixed() -> float:
    """The fixed-point lag of the tuned 1€ filter (chosen min_cutoff and β), s."""
    _, cutoff, _, beta = tuning()
    return euro_ramp_lag(cutoff, beta, G, DT)


def ch4_euro_seen_speed() -> float:
    """The speed perception's 1€ filter sees on the ramp of g per second: s·(1 + L/Te),
    m/s³."""
    return G * (1.0 + ch4_lag_euro_fixed() / DT)


def ch4_euro_cutoff_on_ramp() -> float:
    """The cutoff perception's 1€ filter opens to on that ramp: 2 Hz + β·s·(1 + L/Te), Hz."""
    return 2.0 + 0.05 * ch4_euro_seen_speed()


def ch4_spike_euro() -> float:
    return spike_peak(CH4_FILTERS["1€ 2 Hz, β 0.05"])  # type: ignore[arg-type]


def ch4_spike_median() -> float:
    return spike_peak(CH4_FILTERS["median-of-3 + 1€"])  # type: ignore[arg-type]


# -- chapter 5: the floating capsule -------------------------------------------------------------


def ch5_k() -> float:
    """Hover stiffness of the default player, k = m·(2πf)², N/m."""
    c = ControllerConfig()
    return c.mass * (2.0 * math.pi * c.hover_frequency) ** 2


def ch5_c() -> float:
    """Hover damping of the default player, c = 2ζ·m·2πf, N·s/m."""
    c = ControllerConfig()
    return 2.0 * c.hover_damping * c.mass * 2.0 * math.pi * c.hover_frequency


HOVER_DROP = 0.005
"""m: how far below ride height chapter 5's player starts: small, so the overshoot stays under
g/ω² ≈ 1 cm, where the spring would have to pull (a floor cannot pull: the hover clips at zero)."""


@cache
def hover_run(zeta: float) -> Array:
    """A player released HOVER_DROP below its ride height. Columns: t (s), height above the
    ride height (m) measured by the probe."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    cfg = ControllerConfig(hover_damping=zeta, lock_rotation=True)
    floor_top = 0.05  # the floor segment's radius: its surface, where the probe hits
    start = (0.0, floor_top + cfg.ride_height - HOVER_DROP)
    player = Controller(world, "player", start, config=cfg)
    return _record(world, 0.6, lambda w: [player.body.position.y - floor_top - cfg.ride_height])


def hover_theory(zeta: float, t: Array) -> Array:
    """The damped oscillator x'' + 2ζω x' + ω² x = 0 from x = −HOVER_DROP at rest, m."""
    w = 2.0 * math.pi * ControllerConfig().hover_frequency
    x0 = -HOVER_DROP
    if zeta < 1.0:
        wd = w * math.sqrt(1.0 - zeta**2)
        out: Array = x0 * np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta * w / wd * np.sin(wd * t))
        return out
    return x0 * np.exp(-w * t) * (1.0 + w * t)


def ch5_overshoot_sim() -> float:
    """Overshoot above ride height at ζ = 0.5, as a fraction of the drop (simulated)."""
    return float(np.max(hover_run(0.5)[:, 1]) / HOVER_DROP)


def ch5_overshoot_theory() -> float:
    """Overshoot of a damped oscillator at ζ = 0.5: exp(−ζπ/√(1 − ζ²))."""
    z = 0.5
    return math.exp(-z * math.pi / math.sqrt(1.0 - z * z))


SWING_CUTOFF = 1e100
"""m: beyond this swing the chapter-5 spring stops pushing (it has long since blown up)."""


def spring_growth(
    omega_dt: float,
    zeta: float,
    seconds: float = 2.0,
    scheme: Literal["controller", "explicit"] = "controller",
) -> float:
    """How much a spring's swing grows over the second half of a run (late peak / mid peak).

    A 1 kg body in pymunk on a spring force (k = ω², c = 2ζω, ω = omega_dt / dt), put on it
    every step before ``space.step`` as the hover does: ``controller`` is the hover's own force
    (:func:`playground.controller.hover_spring`, spring on the height about to be used, damper on
    the velocity after the step), ``explicit`` the naive −k·x − c·v from the state before the
    step (explicit Euler). Above 1: it gains energy, unstable.
    """
    # The guard would stop the blow-up this measures: it is off here, on purpose.
    world = World(WorldConfig(guard=False), gravity=(0.0, 0.0))
    body = pymunk.Body(1.0, math.inf)
    world.add("bob", body)
    body.position = (0.01, 0.0)
    w = omega_dt / world.config.dt
    k, c = w * w, 2.0 * zeta * w

    def spring(wd: World) -> None:
        x, v = body.position.x, body.velocity.x
        if math.isfinite(x) and abs(x) < SWING_CUTOFF:
            if scheme == "explicit":
                force = -k * x - c * v
            else:
                force = hover_spring(k, c, 1.0, -x, v, wd.config.dt)
            wd.apply_force(body, (force, 0.0))

    world.on(Stage.CONTROL, spring)
    r = _record(world, seconds, lambda wd: [abs(body.position.x)])
    if not np.all(r[:, 1] < SWING_CUTOFF):
        return math.inf  # blew past the cut-off, where the spring stops: unbounded growth
    window = 0.25
    mid = r[(r[:, 0] > seconds / 2 - window) & (r[:, 0] <= seconds / 2), 1].max()
    late = r[r[:, 0] > seconds - window, 1].max()
    return float(late / mid) if mid > 0.0 else 0.0


def ch5_ratio_below() -> float:
    """Late/mid swing of an undamped spring at 2πf·dt = 1.9 (stable: it keeps its size)."""
    return spring_growth(1.9, 0.0)


def ch5_ratio_above_log10() -> float:
    """log10 of late/mid swing of an undamped spring at 2πf·dt = 2.1 (unstable)."""
    return math.log10(spring_growth(2.1, 0.0))


def ch5_undamped_per_second() -> float:
    """Growth of an undamped spring's swing per second at the default 5 Hz and dt = 1/120 s
    (1: it neither gains nor loses energy)."""
    wh = 2.0 * math.pi * ControllerConfig().hover_frequency * DT
    return float(spring_growth(wh, 0.0, seconds=4.0) ** 0.5)


def stability_limit(zeta: float, scheme: Literal["controller", "explicit"] = "controller") -> float:
    """The largest 2πf·dt at which the simulated spring at damping ratio ``zeta`` does not grow,
    by bisection to 1e-3 (``scheme`` as in :func:`spring_growth`)."""
    lo, hi = 0.01, 6.0
    while hi - lo > 1e-3:
        mid = 0.5 * (lo + hi)
        if spring_growth(mid, zeta, seconds=20.0, scheme=scheme) <= 1.0:
            lo = mid
        else:
            hi = mid
    return lo


def max_hover_frequency(zeta: float) -> float:
    """The highest stable hover frequency at dt = 1/120 s: 2πf·dt < 2ζ + 2√(ζ² + 1), Hz."""
    return hover_limit(zeta) / (2.0 * math.pi * DT)


def ch5_max_frequency() -> float:
    return max_hover_frequency(1.0)


def ch5_max_frequency_zeta05() -> float:
    return max_hover_frequency(0.5)


def ch5_limit_zeta1() -> float:
    return stability_limit(1.0)


def ch5_limit_zeta05() -> float:
    return stability_limit(0.5)


def ch5_explicit_limit_zeta1() -> float:
    """Stability limit on 2πf·dt of the naive spring (explicit Euler) at ζ = 1 (theory: 2ζ)."""
    return stability_limit(1.0, "explicit")


def ch5_explicit_undamped_per_step() -> float:
    """Swing growth per step of an undamped naive spring (explicit Euler) at 5 Hz and
    dt = 1/120 s, simulated (measured over two seconds)."""
    wh = 2.0 * math.pi * ControllerConfig().hover_frequency * DT
    per_second = spring_growth(wh, 0.0, seconds=4.0, scheme="explicit") ** 0.5
    return float(per_second ** (1.0 / round(1.0 / DT)))


def ch5_explicit_undamped_theory() -> float:
    """√(1 + (2πf·dt)²): the naive undamped spring's growth per step at 5 Hz, 1/120 s (the
    determinant of its step matrix is 1 + (2πf·dt)²)."""
    wh = 2.0 * math.pi * ControllerConfig().hover_frequency * DT
    return math.sqrt(1.0 + wh * wh)


@cache
def walk_run() -> Array:
    """A player starts walking right at full input at t = 0.5 s. Columns: t (s), speed (m/s),
    drive force x (N)."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (20.0, 0.0))
    script = Script(((0.0, Intent()), (0.5, Intent(move=1.0))))
    player = Controller(world, "player", (0.0, 0.95), source=script)
    return _record(world, 2.0, lambda w: [player.body.velocity.x, player.last_forces.drive[0]])


def ch5_drive_peak() -> float:
    """Largest drive force while speeding up, N."""
    return float(np.max(walk_run()[:, 2]))


def ch5_time_to_90() -> float:
    """Time from the first input to 90 % of max_speed, s."""
    r = walk_run()
    fast = r[r[:, 1] >= 0.9 * ControllerConfig().max_speed, 0]
    return float(fast[0] - 0.5)


def shove(impulse: float, seconds: float = 2.0) -> tuple[bool, Array]:
    """A sideways impulse (N·s) at head height on a standing player after 1 s.

    Returns (lost balance?, rows of t (s), tilt (degrees), state code (0 grounded, 1 off balance,
    2 getting up, 3 other)) over ``seconds`` of simulation.
    """
    world = World()
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0))
    player = Controller(world, "player", (0.0, 0.95))
    world.at(1.0, lambda w: w.apply_impulse("player", (impulse, 0.0), point=(0.0, 1.7)))
    codes = {State.GROUNDED: 0, State.OFF_BALANCE: 1, State.GETTING_UP: 2}
    r = _record(
        world, seconds, lambda w: [math.degrees(player.tilt), float(codes.get(player.state, 3))]
    )
    return bool(np.any(r[:, 2] == 1.0)), r


def ch5_knockover() -> float:
    """The smallest head-height shove that knocks the player over, N·s (bisection, ±1 N·s)."""
    lo, hi = 0.0, 400.0
    while hi - lo > 1.0:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if shove(mid)[0] else (mid, hi)
    return hi


# -- chapter 6: playing with gravity -------------------------------------------------------------


@cache
def flip_run() -> Array:
    """The gravity_flip level. Columns: t (s), height y (m), tilt against up (degrees),
    perceived gravity y (m/s²), grounded (1/0), the capsule touching something (1/0)."""
    scene = _scene("gravity_flip")
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

    return _record(scene.world, scene.level.settings.seconds, probe)


FLIP_TIME = 1.0
"""s: when gravity_flip turns gravity over."""


def _in_flight(r: Array) -> Array:
    """Rows from the first step after the flip at which the player is off the floor."""
    return r[np.nonzero((r[:, 0] > FLIP_TIME) & (r[:, 4] == 0.0))[0][0] :]


def ch6_leave_time() -> float:
    """Time after the flip at which the floor lets go of the player, s."""
    return float(_in_flight(flip_run())[0, 0] - FLIP_TIME)


def ch6_upright_time() -> float:
    """Time after the flip at which the tilt first drops below 15° in the air, s (once its up
    has turned to the field: from the most tilted step on)."""
    r = _in_flight(flip_run())
    r = r[int(np.argmax(r[:, 2])) :]
    return float(r[r[:, 2] < 15.0][0, 0] - FLIP_TIME)


def ch6_probe_tilt() -> float:
    """Tilt against up when the probe first finds the ceiling (the hover catches it), degrees."""
    r = _in_flight(flip_run())
    return float(r[r[:, 4] == 1.0][0, 2])


def ch6_contact_tilt() -> float:
    """Tilt against up when the capsule's body first touches the ceiling, degrees."""
    r = _in_flight(flip_run())
    return float(r[r[:, 5] == 1.0][0, 2])


def ch6_final_perceived() -> float:
    """Perceived gravity y at the end, m/s² (positive: "down" is now up)."""
    return float(flip_run()[-1, 3])


@cache
def null_run() -> Array:
    """The null_enemy level. Columns: t (s), the enemy's speed (m/s), its |perceived gravity|
    (m/s²), its gravity y (m/s²)."""
    scene = _scene("null_enemy")
    enemy = scene.controllers["enemy"]

    def probe(w: World) -> list[float]:
        return [
            float(np.hypot(*enemy.body.velocity)),
            float(np.hypot(*w.perceived_gravity("enemy"))),
            w.gravity_at("enemy")[1],
        ]

    return _record(scene.world, scene.level.settings.seconds, probe)


def ch6_null_perceived() -> float:
    """The nullified enemy's |perceived gravity| at the end, m/s²."""
    return float(null_run()[-1, 2])


def ch6_null_before() -> float:
    """The enemy's |perceived gravity| while it patrols (t in [0.2, 0.45] s), m/s²."""
    r = null_run()
    window = (r[:, 0] >= 0.2) & (r[:, 0] <= 0.45)
    return float(np.mean(r[window, 2]))


def ch6_null_budget_accel() -> float:
    """The patrol's acceleration at the drive budget: ground_force / mass, m/s²."""
    c = ControllerConfig()
    return c.ground_force / c.mass


def ch6_null_before_expected() -> float:
    """√(g² + (ground_force/m)²): what a body feels while its drive pushes at budget, m/s²."""
    return math.hypot(G, ch6_null_budget_accel())


def ch6_null_speed_change() -> float:
    """Largest change of the enemy's speed after t = 1.5 s, m/s."""
    r = null_run()
    after = r[r[:, 0] >= 1.5, 1]
    return float(np.max(np.abs(after - after[0])))


def ch6_air_budget_bound() -> float:
    """What the air budget allows over 1.5 s: air_force / m · 1.5 s, m/s."""
    c = ControllerConfig()
    return c.air_force / c.mass * 1.5


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

    level = _level("gravity_leap")
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

    return _record(scene.world, scene.level.settings.seconds, probe)


def _landing(r: Array) -> Array:
    """The first row at which the player stands on the creature."""
    row: Array = r[np.nonzero(r[:, 1] == 1.0)[0][0]]
    return row


def ch6_leap_land_time() -> float:
    """Time from the leap to standing on the creature, s."""
    return float(_landing(leap_run())[0] - LEAP_TIME)


def ch6_leap_land_x() -> float:
    """Where the player lands: its x relative to the creature's centre, m."""
    return float(_landing(leap_run())[2])


def ch6_leap_end_x() -> float:
    """The player's x relative to the creature's centre at the end, m."""
    return float(leap_run()[-1, 2])


def ch6_leap_ride_y() -> float:
    """The player's y relative to the creature's centre at the end, m (below it: negative)."""
    return float(leap_run()[-1, 3])


def ch6_leap_relative_speed() -> float:
    """The player's speed relative to the creature at the end, m/s."""
    return float(leap_run()[-1, 4])


def ch6_leap_speed() -> float:
    """How fast gravity_leap's creature flies, m/s."""
    (mover,) = _level("gravity_leap").movers
    if not isinstance(mover.path, WaypointsPath):
        raise TypeError(f"gravity_leap: expected a waypoints path, got {mover.path.kind!r}")
    return mover.path.speed


def leap_half_width() -> float:
    """Half the width of gravity_leap's creature, m: the player stands on it while its x relative
    to the creature's centre is within ± this."""
    (mover,) = _level("gravity_leap").movers
    shape = mover.shapes[0]
    if not isinstance(shape, BoxShape):
        raise TypeError(f"gravity_leap: expected a box creature, got {shape.kind!r}")
    return 0.5 * shape.size[0]


def ch6_leap_perceived() -> float:
    """|Perceived gravity| at the end, m/s²."""
    return float(np.hypot(*leap_run()[-1, 6:8]))


def ch6_leap_slope() -> float:
    """Angle between the perceived gravity at the end and the creature's underside's normal
    (+y), degrees: how steep a slope that flat underside is to the player."""
    gx, gy = leap_run()[-1, 6:8]
    return math.degrees(math.atan2(abs(gx), gy))


LEAP_FAST = 2.0
"""m/s: the exercise's creature, twice as fast as the level's."""


def ch6_leap_fast_land_time() -> float:
    """The exercise: time from the leap to standing on a creature flying at LEAP_FAST, s."""
    return float(_landing(leap_run(LEAP_FAST))[0] - LEAP_TIME)


def ch6_leap_fast_land_x() -> float:
    """The exercise: where the player lands on a creature flying at LEAP_FAST, m."""
    return float(_landing(leap_run(LEAP_FAST))[2])


def ch6_leap_fast_end_x() -> float:
    """The exercise: the player's x relative to the fast creature's centre at the end, m."""
    return float(leap_run(LEAP_FAST)[-1, 2])


# -- chapter 7: what accuracy costs --------------------------------------------------------------

CH7_DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240)
"""Steps of chapter 7's sweep, s."""


@dataclass(frozen=True, slots=True)
class RingErrors:
    """The bench's ring scene at one dt, reverse integration, unfiltered, read three ways.

    All errors are relative to the scene's force scale m·ω²·r (1 = 100 %). Attributes:
        dt: the step, s.
        end: RMS error against the exact force at the *end* of each step.
        tangential: mean tangential part of the reading's direction against the end-of-step
            exact force (the sine of the angle between them).
        half_turn: ω·dt/2, rad — how far the ring turns in half a step.
        mid: RMS error against the exact force at the *middle* of each step.
        fd_end: finite differences m·(x₂ − 2x₁ + x₀)/dt² against the end of the step.
        fd_own: finite differences against their own mid-point: the time of their middle sample
            x₁, the start of the step.
    """

    dt: float
    end: float
    tangential: float
    half_turn: float
    mid: float
    fd_end: float
    fd_own: float


def _rotate(v: Array, angle: float) -> Array:
    c, s = math.cos(angle), math.sin(angle)
    out: Array = np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])
    return out


@cache
def ring_errors(dt: float) -> RingErrors:
    """Run the bench's ring scene at ``dt`` and read its error with each convention."""
    from playground.bench.scenes import RING_RATE, Knobs, build

    scene = build("ring", Knobs(dt=dt))
    world = scene.world
    body = world.body("player")
    m = body.mass
    n_settle = round(scene.settle / dt)
    n_total = n_settle + round(scene.measure / dt)
    reads, ends, positions = [], [], [np.array(body.position)]
    for _ in range(n_total):
        world.step()
        reads.append(np.array(world.forces("player").support))
        ends.append(-m * RING_RATE**2 * np.array(body.position))
        positions.append(np.array(body.position))
    f, e = np.array(reads)[n_settle:], np.array(ends)[n_settle:]
    mid = np.array([_rotate(v, -0.5 * RING_RATE * dt) for v in e])
    x = np.array(positions)
    fd_all = m * (x[2:] - 2.0 * x[1:-1] + x[:-2]) / (dt * dt)  # row j: read after step j + 1
    fd = fd_all[n_settle - 1 :]
    own = np.array([_rotate(v, -RING_RATE * dt) for v in e])  # the start of the step
    scale = scene.scale

    def rms(residual: Array) -> float:
        return float(np.sqrt(np.mean(np.sum(residual**2, axis=1)))) / scale

    unit_t = np.column_stack([-e[:, 1], e[:, 0]]) / np.hypot(e[:, 0], e[:, 1])[:, None]
    tangential = np.sum(f * unit_t, axis=1) / np.hypot(f[:, 0], f[:, 1])
    return RingErrors(
        dt=dt,
        end=rms(f - e),
        tangential=float(-np.mean(tangential)),
        half_turn=0.5 * RING_RATE * dt,
        mid=rms(f - mid),
        fd_end=rms(fd - e),
        fd_own=rms(fd - own),
    )


CH7_REPEATS = 9
"""Interleaved timing rounds of chapter 7's cost panel (median and range are drawn)."""

CH7_BLOCK = 120
"""Steps per timed block of chapter 7's cost panel."""


@cache
def ring_costs() -> dict[float, tuple[float, float, float]]:
    """ms of computing per simulated second of the ring scene (reverse integration) at each dt:
    (median, lowest, highest) over :data:`CH7_REPEATS` rounds, every dt timed once per round so
    that a busy spell of the machine hits them all alike."""
    import time

    from playground.bench.scenes import Knobs, build

    worlds = {dt: build("ring", Knobs(dt=dt)).world for dt in CH7_DTS}
    for w in worlds.values():
        w.run(0.2)  # past the first steps' one-off costs
    samples: dict[float, list[float]] = {dt: [] for dt in CH7_DTS}
    for _ in range(CH7_REPEATS):
        for dt, w in worlds.items():
            t0 = time.perf_counter()
            for _ in range(CH7_BLOCK):
                w.step()
                w.forces("player")
            per_step = (time.perf_counter() - t0) / CH7_BLOCK
            samples[dt].append(1e3 * per_step / dt)
    return {dt: (float(np.median(v)), min(v), max(v)) for dt, v in samples.items()}


def ch7_substeps_30() -> float:
    """Ring error (mid-step) of reverse integration at dt = 1/30 s with 4 substeps, %."""
    from playground.bench.accuracy import Point, measure
    from playground.bench.scenes import Knobs

    (r,) = measure(Point("ring", Knobs(dt=1 / 30, substeps=4), "reverse"), ("none",), repeats=1)
    return r.error * 100.0


def ch7_end_30() -> float:
    """Ring error against the end of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).end * 100.0


def ch7_end_60() -> float:
    return ring_errors(1 / 60).end * 100.0


def ch7_end_120() -> float:
    return ring_errors(1 / 120).end * 100.0


def ch7_end_240() -> float:
    return ring_errors(1 / 240).end * 100.0


def ch7_tangential_30() -> float:
    """Tangential part of the reading against the end of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).tangential * 100.0


def ch7_tangential_60() -> float:
    return ring_errors(1 / 60).tangential * 100.0


def ch7_tangential_120() -> float:
    return ring_errors(1 / 120).tangential * 100.0


def ch7_tangential_240() -> float:
    return ring_errors(1 / 240).tangential * 100.0


def ch7_half_30() -> float:
    """ω·dt/2 at dt = 1/30 s, % (of a radian)."""
    return ring_errors(1 / 30).half_turn * 100.0


def ch7_half_60() -> float:
    return ring_errors(1 / 60).half_turn * 100.0


def ch7_half_120() -> float:
    return ring_errors(1 / 120).half_turn * 100.0


def ch7_half_240() -> float:
    return ring_errors(1 / 240).half_turn * 100.0


def ch7_mid_30() -> float:
    """Ring error against the middle of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).mid * 100.0


def ch7_mid_60() -> float:
    return ring_errors(1 / 60).mid * 100.0


def ch7_mid_120() -> float:
    return ring_errors(1 / 120).mid * 100.0


def ch7_mid_240() -> float:
    return ring_errors(1 / 240).mid * 100.0


def ch7_tangential_short_30() -> float:
    """How far the tangential part at dt = 1/30 s falls short of ω·dt/2, % of ω·dt/2."""
    e = ring_errors(1 / 30)
    return (1.0 - e.tangential / math.sin(e.half_turn)) * 100.0


def ch7_bumps_per_second() -> float:
    """How many segment joints of the bench's ring pass under the box per second."""
    from playground.bench.scenes import RING_RATE

    return 64 * RING_RATE / (2.0 * math.pi)


def ch7_fd_end_120() -> float:
    """Finite differences against the end of the step at dt = 1/120 s, %."""
    return ring_errors(1 / 120).fd_end * 100.0


def ch7_fd_own_120() -> float:
    """Finite differences against their own mid-point at dt = 1/120 s, %."""
    return ring_errors(1 / 120).fd_own * 100.0


# -- chapter 8: the fixed step -------------------------------------------------------------------

CH8_DISPLAYS = (60.0, 144.0)
"""Display rates of chapter 8's frame timelines, Hz."""

CH8_FRAMES = 24
"""Frames drawn in each timeline."""

CH8_HITCH = 0.1
"""s: one slow frame (a hitch) in chapter 8's 60 Hz timeline."""


def steps_per_frame(frame_times: list[float], dt: float) -> list[int]:
    """Physics steps a fixed-step accumulator runs at each frame of the given wall durations (s):
    the whole steps of ``dt`` that fit in the time so far, less those already run. (This is the
    view's Accumulator without its cap on steps per frame.)

    >>> steps_per_frame([1 / 60] * 4, 1 / 120)
    [2, 2, 2, 2]
    """
    total, done, out = 0.0, 0, []
    for elapsed in frame_times:
        total += elapsed
        n = int((total + 1e-9 * dt) // dt) - done
        done += n
        out.append(n)
    return out


def ch8_idle_frames_144() -> float:
    """Share of a 144 Hz display's frames that run no physics step at dt = 1/120 s, %."""
    n = steps_per_frame([1.0 / 144.0] * 144, DT)
    return 100.0 * n.count(0) / len(n)


def ch8_hitch_steps() -> float:
    """Steps the accumulator runs on one 0.1 s frame at dt = 1/120 s."""
    return float(steps_per_frame([CH8_HITCH], DT)[0])


@cache
def jump_apex(dt: float) -> float:
    """How high the default player's jump lifts its centre, m, with physics stepped at ``dt``."""
    world = World(WorldConfig(dt=dt))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    script = Script(((0.0, Intent()), (1.0, Intent(jump=True)), (1.1, Intent())))
    player = Controller(world, "player", (0.0, 0.95), source=script)
    world.run(1.0)
    y0 = top = player.body.position.y
    for _ in range(round(1.5 / dt)):
        world.step()
        top = max(top, player.body.position.y)
    return top - y0


CH8_RATES = (20.0, 30.0, 60.0, 120.0, 144.0, 240.0)
"""Hz: the rates chapter 8 steps the jump at, as a game that steps at its display rate would."""


def ch8_apex_60() -> float:
    """Jump apex at dt = 1/60 s, cm."""
    return 100.0 * jump_apex(1.0 / 60.0)


def ch8_apex_144() -> float:
    """Jump apex at dt = 1/144 s, cm."""
    return 100.0 * jump_apex(1.0 / 144.0)


def ch8_apex_exact() -> float:
    """The continuous apex v²/(2g) of the 4 m/s take-off, cm."""
    v = ControllerConfig().jump_speed
    return 100.0 * v * v / (2.0 * G)


def ch8_apex_first_order_60() -> float:
    """v²/(2g) + v·dt/2 at dt = 1/60 s: the first-order estimate of the stepped apex, cm."""
    v = ControllerConfig().jump_speed
    return ch8_apex_exact() + 100.0 * v * (1.0 / 60.0) / 2.0


@cache
def hover_dt_run(dt: float) -> Array:
    """:func:`hover_run`'s release (ζ = 1, 5 Hz) stepped at ``dt``. Columns: t (s), height −
    ride height (m)."""
    world = World(WorldConfig(dt=dt))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    cfg = ControllerConfig(lock_rotation=True)
    floor_top = 0.05
    start = (0.0, floor_top + cfg.ride_height - HOVER_DROP)
    player = Controller(world, "player", start, config=cfg)
    return _record(world, 0.6, lambda w: [player.body.position.y - floor_top - cfg.ride_height])


def ch8_hover_limit_hitch() -> float:
    """The highest hover frequency (ζ = 1) still stable on a 0.1 s step, Hz."""
    return hover_limit(1.0) / (2.0 * math.pi * CH8_HITCH)


def ch8_hover_overshoot_20() -> float:
    """Overshoot of the critically damped 5 Hz hover stepped at 1/20 s, fraction of the drop."""
    return float(np.max(hover_dt_run(1.0 / 20.0)[:, 1]) / HOVER_DROP)


def ch8_hover_overshoot_120() -> float:
    """The same at the levels' 1/120 s (critical damping: no overshoot in theory)."""
    return float(np.max(hover_dt_run(DT)[:, 1]) / HOVER_DROP)


# -- chapter 9: contact impulses -----------------------------------------------------------------

DROP_ACCELERATION = 3.0
"""m/s²: chapter 9's platform accelerates downward at this rate (less than g: the box rides it)."""

DROP_START = 0.5
"""s: when chapter 9's platform starts to fall."""


@cache
def stale_run(acceleration: float = DROP_ACCELERATION) -> Array:
    """A 10 kg box on a kinematic platform that starts falling at ``acceleration`` (m/s²), in bare
    pymunk (no playground code between the reader and the engine).

    Columns: t (s), reverse integration's vertical force m·(v₁ − v₀)/h + m·g, the sum of the
    box's ``Arbiter.total_impulse`` / h (vertical; N), and 1 where the box touched the platform
    in the step before the previous one but not in the previous one (a contact re-made while its
    arbiter was still cached), else 0.
    """
    space = pymunk.Space()
    space.gravity = (0.0, -G)
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    floor = pymunk.Poly.create_box(platform, (4.0, 0.2))
    floor.friction = 1.0
    space.add(platform, floor)
    m = 10.0
    box = pymunk.Body(m, pymunk.moment_for_box(m, (0.5, 0.5)))
    box.position = (0.0, 0.35)
    shape = pymunk.Poly.create_box(box, (0.5, 0.5))
    shape.friction = 1.0
    space.add(box, shape)
    rows: list[list[float]] = []
    touching: list[bool] = []
    for k in range(round(1.0 / DT)):
        t = k * DT
        platform.velocity = (0.0, -acceleration * max(t - DROP_START, 0.0))
        v0 = box.velocity.y
        space.step(DT)
        arbiters: list[pymunk.Arbiter] = []
        box.each_arbiter(arbiters.append)
        impulse = sum(
            (a.total_impulse.y if a.shapes[0].body is box else -a.total_impulse.y) for a in arbiters
        )
        remade = len(touching) >= 2 and not touching[-1] and bool(arbiters)
        touching.append(bool(arbiters))
        rows.append([t + DT, m * (box.velocity.y - v0) / DT + m * G, impulse / DT, float(remade)])
    return np.array(rows, dtype=np.float64)


def _stale_excess(acceleration: float = DROP_ACCELERATION) -> Array:
    r = stale_run(acceleration)
    out: Array = (r[:, 2] - r[:, 1]) / (10.0 * G)
    return out


def ch9_max_excess() -> float:
    """Largest excess of the arbiter sum over the applied force, in units of m·g."""
    return float(np.max(np.abs(_stale_excess())))


def ch9_stale_steps() -> float:
    """Steps (in the falling second) on which the arbiter sum is off by more than 1e-9·m·g."""
    return float(np.count_nonzero(np.abs(_stale_excess()) > 1e-9))


def ch9_stale_steps_1() -> float:
    """The exercise: stale steps with the platform falling at 1 m/s²."""
    return float(np.count_nonzero(np.abs(_stale_excess(1.0)) > 1e-9))


def ch9_max_excess_1() -> float:
    """The exercise: the largest excess at 1 m/s², m·g."""
    return float(np.max(np.abs(_stale_excess(1.0))))


def ch9_contact_steps() -> float:
    """Steps on which the box touches the platform after it starts falling."""
    r = stale_run()
    return float(np.count_nonzero((r[:, 0] > DROP_START) & (r[:, 2] != 0.0)))


def ch9_fresh_error() -> float:
    """Largest |arbiter sum − reverse integration| on the steps that are not re-made contacts,
    in units of m·g."""
    r = stale_run()
    return float(np.max(np.abs(_stale_excess()[r[:, 3] == 0.0])))


def ch9_excess_vs_two_back() -> float:
    """Largest |excess − the arbiter sum two steps earlier| on re-made contacts, m·g."""
    r = stale_run()
    idx = np.nonzero(r[:, 3] == 1.0)[0]
    excess = _stale_excess()
    return float(np.max(np.abs(excess[idx] - r[idx - 2, 2] / (10.0 * G))))


@cache
def stale_world_run() -> tuple[int, float]:
    """Chapter 9's falling platform in a :class:`World` with the contact split on: (steps whose
    split is known, largest |contact sum − engine force| on them in m·g) over one second."""
    world = World(WorldConfig(contact_split=True))
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    floor = pymunk.Poly.create_box(platform, (4.0, 0.2))
    floor.friction = 1.0
    world.add("platform", platform, floor)
    world.add_box("box", mass=10.0, size=(0.5, 0.5), position=(0.0, 0.35), friction=1.0)
    world.track("box")

    def fall(w: World) -> None:
        platform.velocity = (0.0, -DROP_ACCELERATION * max(w.time - DROP_START, 0.0))

    world.on(Stage.CONTROL, fall)
    known, worst = 0, 0.0
    for _ in range(round(1.0 / DT)):
        world.step()
        f = world.forces("box")
        if f.split_valid:
            known += 1
            worst = max(worst, abs(f.contact[1] - f.engine[1]) / (10.0 * G))
    return known, worst


def ch9_world_known_steps() -> float:
    """Steps (of 120) on which the World's contact split is known on the falling platform."""
    return float(stale_world_run()[0])


def ch9_world_worst() -> float:
    """Largest |contact sum − engine force| on those steps, m·g."""
    return stale_world_run()[1]


def ch9_weight_share() -> float:
    """(g − a)/g: the share of its weight the falling platform carries on average."""
    return (G - DROP_ACCELERATION) / G


# -- chapter 10: staying stable ------------------------------------------------------------------

CH10_DTS = (1 / 60, 1 / 240)
"""s: the stability matrix's steps (as tests/test_stability.py)."""

CH10_ITERATIONS = (2, 10)
"""The matrix's solver iterations (as tests/test_stability.py)."""

CH10_SUBSTEPS = (1, 4)
"""The matrix's substeps (the chapter adds them to the tests' matrix)."""

CH10_RATES = (60.0, 30.0, 20.0, 15.0, 10.0)
"""Hz: the steps, ever coarser, at which each hard scene is run to find where it breaks (1/10 s
is the largest step a world accepts)."""


@dataclass(frozen=True, slots=True)
class HardOutcome:
    """One run of a hard scene: what broke first (``None``: nothing), at which step, and the
    deepest penetration seen before (m)."""

    broke: str | None
    step: int
    penetration: float


@cache
def hard_run(scene: str, dt: float, iterations: int = 10, substeps: int = 1) -> HardOutcome:
    """Run the hard scene ``scene`` with every invariant checked (see
    :mod:`playground.bench.stability`); the runtime guard's stop counts as a breach too."""
    from playground.bench.stability import SCENES as HARD
    from playground.bench.stability import InvariantError, run_checked
    from playground.guard import RunawayError

    hard = HARD[scene](WorldConfig(dt=dt, iterations=iterations, substeps=substeps))
    try:
        worst = run_checked(hard)
    except InvariantError as exc:
        return HardOutcome(exc.invariant, exc.step, math.nan)
    except RunawayError:
        return HardOutcome("runaway", hard.world.steps, math.nan)
    return HardOutcome(None, 0, worst["penetration"])


def hard_scenes() -> tuple[str, ...]:
    """The hard scenes' names, in the stability suite's order."""
    from playground.bench.stability import SCENES as HARD

    return tuple(HARD)


def breaking_rate(scene: str, iterations: int = 10) -> float:
    """The finest of :data:`CH10_RATES` (Hz) at which ``scene`` breaks an invariant, stepping
    ever coarser; 0 if it holds at all of them."""
    for rate in CH10_RATES:
        if hard_run(scene, 1.0 / rate, iterations).broke is not None:
            return rate
    return 0.0


def ch10_runs() -> float:
    """Runs in the chapter's matrix: scenes × dt × iterations × substeps."""
    return float(len(hard_scenes()) * len(CH10_DTS) * len(CH10_ITERATIONS) * len(CH10_SUBSTEPS))


def ch10_matrix_breaches() -> float:
    """Runs of the matrix that break an invariant."""
    return float(
        sum(
            hard_run(sc, dt, it, sub).broke is not None
            for sc in hard_scenes()
            for dt in CH10_DTS
            for it in CH10_ITERATIONS
            for sub in CH10_SUBSTEPS
        )
    )


def ch10_chaos_penetration_mm() -> float:
    """Deepest overlap in elastic chaos at 1/60 s, 2 iterations, 1 substep, mm."""
    return 1000.0 * hard_run("elastic chaos", 1 / 60, 2, 1).penetration


def ch10_chaos_penetration_sub_mm() -> float:
    """The same with 4 substeps, mm."""
    return 1000.0 * hard_run("elastic chaos", 1 / 60, 2, 4).penetration


def ch10_break_crusher() -> float:
    return breaking_rate("crusher")


def ch10_break_ring() -> float:
    return breaking_rate("spinning ring")


def ch10_break_tiny() -> float:
    return breaking_rate("tiny under heavy")


def ch10_holding_scenes() -> float:
    """Hard scenes that hold every invariant at every rate of :data:`CH10_RATES`."""
    return float(sum(breaking_rate(sc) == 0.0 for sc in hard_scenes()))


def ch10_ring_20_substeps_holds() -> float:
    """The exercise: 1 if the hard spinning ring holds at 1/20 s with 4 substeps, else 0."""
    return 1.0 if hard_run("spinning ring", 1 / 20, 10, 4).broke is None else 0.0


def ch10_ring_20_iterations_step() -> float:
    """The exercise: the step at which it breaks at 1/20 s with 40 iterations and 1 substep."""
    return float(hard_run("spinning ring", 1 / 20, 40, 1).step)


THIN_WALL = 0.1
"""m: ring_room's default half thickness of the wall (0.2 m thick), which the hard spinning ring
replaces by 0.3 m (0.6 m thick)."""

THIN_WALL_DT = 1 / 30
"""s: the step at which chapter 10 runs the hard spinning ring with the default wall."""


@cache
def thin_ring_outcome() -> HardOutcome:
    """The hard spinning ring at THIN_WALL_DT, 10 iterations, with ring_room's default wall."""
    from playground.bench import stability

    saved = stability.RING_WALL
    stability.RING_WALL = THIN_WALL
    try:
        return hard_run.__wrapped__("spinning ring", THIN_WALL_DT, 10, 1)
    finally:
        stability.RING_WALL = saved


def ch10_thin_wall_escape() -> float:
    """When a body leaves the ring through the default wall (THIN_WALL_DT, 10 iterations), s."""
    return thin_ring_outcome().step * THIN_WALL_DT


GUARD_OMEGA_DT = 2.1
"""The naive spring run without its guards: 2πf·dt just above the limit 2 of an undamped one."""


@cache
def runaway_run(guard: bool) -> tuple[Array, int, str]:
    """A 1 kg body on an undamped spring stepped beyond its stability limit (2πf·dt = 2.1) with
    the force read from the position the integrator is about to use (chapter 5's scheme, which is
    stable only below 2), tracked so its readings are checked.

    Returns (rows of step, |x| (m), |support| (N), |perceived gravity| (m/s²); the step at which
    the runtime guard stopped it, 0 if it did not; the guard's message).
    """
    from playground.guard import RunawayError

    world = World(WorldConfig(guard=guard), gravity=(0.0, 0.0))
    body = pymunk.Body(1.0, math.inf)
    world.add("bob", body)
    body.position = (0.01, 0.0)
    world.track("bob")
    w = GUARD_OMEGA_DT / world.config.dt

    def spring(wd: World) -> None:
        x, v = body.position.x, body.velocity.x
        if math.isfinite(x) and math.isfinite(v):
            wd.apply_force(body, (hover_spring(w * w, 0.0, 1.0, -x, v, wd.config.dt), 0.0))

    world.on(Stage.CONTROL, spring)
    rows: list[list[float]] = []
    # Unguarded, the numbers overflow on purpose: numpy's overflow warnings are the point, not news.
    for k in range(1, 1201):
        try:
            with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                world.step()
        except (RunawayError, ValueError) as exc:  # the runaway bounds: on state or on a force
            return np.array(rows, dtype=np.float64), k, str(exc)
        f = world.forces("bob")
        rows.append(
            [float(k), abs(body.position.x), float(np.hypot(*f.support)),
             float(np.hypot(*world.perceived_gravity("bob")))]
        )  # fmt: skip
    return np.array(rows, dtype=np.float64), 0, ""


def ch10_guard_step() -> float:
    """The step at which the runtime guard stops the runaway spring."""
    return float(runaway_run(True)[1])


def ch10_unguarded_last_step() -> float:
    """Without the guard: the last step the runaway spring completes before its own force
    overflows (a force that is not a finite number is refused even then)."""
    return float(runaway_run(False)[0][-1, 0])


def ch10_unguarded_log10_x() -> float:
    """Without the guard: log10 of |x| (m) at that last step."""
    return math.log10(runaway_run(False)[0][-1, 1])


def ch10_guard_log10_x() -> float:
    """With the guard: log10 of |x| (m) at the last step before it stopped the world."""
    return math.log10(runaway_run(True)[0][-1, 1])


NUMBERS: dict[str, Callable[[], float]] = {
    f.__name__: f
    for f in (
        ch1_platform_travel,
        ch1_player_drift_cm,
        ch1_predicted_drift_cm,
        ch1_lag_drift_cm,
        ch1_lag_simulated_cm,
        ch1_drift_2_cm,
        ch1_budget_accel,
        ch1_kinematic_drift,
        ch1_drive_accel,
        ch2_max_disagreement,
        ch2_ghost_exercise,
        ch2_ghost_force,
        ch2_plank_joint,
        ch2_plank_contact,
        ch2_total_weight,
        ch3_room_max_lag,
        ch3_room_final_error,
        ch3_room_turn,
        ch3_room_turn_deg,
        ch3_room_turn_time,
        ch3_ring_rim,
        ch3_ring_rate,
        ch3_ring_segments,
        ch3_ring_centre,
        ch3_ring_centre_run,
        ch3_ring_mass,
        ch3_ring_expected,
        ch3_ring_perceived,
        ch3_ring_support_expected,
        ch3_ring_support,
        ch3_ring_ratio,
        ch4_jitter_raw,
        ch4_jitter_ema,
        ch4_jitter_euro,
        ch4_lag_ema,
        ch4_lag_euro,
        ch4_tuned_cutoff,
        ch4_tuned_beta,
        ch4_tuned_lag_beta0,
        ch4_tuned_lag,
        ch4_lag_euro_fixed,
        ch4_tuned_lag_fixed,
        ch4_euro_seen_speed,
        ch4_euro_cutoff_on_ramp,
        ch4_spike_euro,
        ch4_spike_median,
        ch5_k,
        ch5_c,
        ch5_overshoot_sim,
        ch5_overshoot_theory,
        ch5_ratio_below,
        ch5_ratio_above_log10,
        ch5_undamped_per_second,
        ch5_max_frequency,
        ch5_max_frequency_zeta05,
        ch5_limit_zeta1,
        ch5_limit_zeta05,
        ch5_explicit_limit_zeta1,
        ch5_explicit_undamped_per_step,
        ch5_explicit_undamped_theory,
        ch5_drive_peak,
        ch5_time_to_90,
        ch5_knockover,
        ch6_leave_time,
        ch6_upright_time,
        ch6_probe_tilt,
        ch6_contact_tilt,
        ch6_final_perceived,
        ch6_null_perceived,
        ch6_null_speed_change,
        ch6_null_before,
        ch6_null_budget_accel,
        ch6_null_before_expected,
        ch6_air_budget_bound,
        ch6_leap_land_time,
        ch6_leap_land_x,
        ch6_leap_end_x,
        ch6_leap_ride_y,
        ch6_leap_relative_speed,
        ch6_leap_speed,
        ch6_leap_perceived,
        ch6_leap_slope,
        ch6_leap_fast_land_time,
        ch6_leap_fast_land_x,
        ch6_leap_fast_end_x,
        ch7_end_30,
        ch7_end_60,
        ch7_end_120,
        ch7_end_240,
        ch7_tangential_30,
        ch7_tangential_60,
        ch7_tangential_120,
        ch7_tangential_240,
        ch7_half_30,
        ch7_half_60,
        ch7_half_120,
        ch7_half_240,
        ch7_mid_30,
        ch7_mid_60,
        ch7_mid_120,
        ch7_mid_240,
        ch7_fd_end_120,
        ch7_tangential_short_30,
        ch7_bumps_per_second,
        ch7_fd_own_120,
        ch7_substeps_30,
        ch8_idle_frames_144,
        ch8_hitch_steps,
        ch8_apex_60,
        ch8_apex_144,
        ch8_apex_exact,
        ch8_apex_first_order_60,
        ch8_hover_limit_hitch,
        ch8_hover_overshoot_20,
        ch8_hover_overshoot_120,
        ch9_max_excess,
        ch9_stale_steps,
        ch9_stale_steps_1,
        ch9_max_excess_1,
        ch9_contact_steps,
        ch9_fresh_error,
        ch9_excess_vs_two_back,
        ch9_weight_share,
        ch9_world_known_steps,
        ch9_world_worst,
        ch10_runs,
        ch10_matrix_breaches,
        ch10_chaos_penetration_mm,
        ch10_chaos_penetration_sub_mm,
        ch10_break_crusher,
        ch10_break_ring,
        ch10_break_tiny,
        ch10_holding_scenes,
        ch10_thin_wall_escape,
        ch10_guard_step,
        ch10_unguarded_last_step,
        ch10_unguarded_log10_x,
        ch10_guard_log10_x,
        ch10_ring_20_substeps_holds,
        ch10_ring_20_iterations_step,
    )
}
"""Every number the chapters quote, by the name their markers use."""


# -- figures -------------------------------------------------------------------------------------


def _axes(rows: int, cols: int = 1, height: float = 3.0) -> tuple[Any, Any]:
    """A matplotlib figure (headless Agg backend) and its axes, as a flat list."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(rows, cols, figsize=(7.5 * cols, height * rows), squeeze=False)
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    return fig, list(axes.flat)


def _save(fig: Any, path: Path) -> Path:
    import matplotlib.pyplot as plt

    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def fig_ch1(path: Path) -> Path:
    """Drift relative to the platform (the kinematic character's, then the player's with and
    without the feed-forward, in mm), and the drive force that carries the player."""
    r = platform_run()
    lag = platform_run(feed_forward=False)

    def rel(run: Array, col: int) -> Array:
        out: Array = (run[:, col] - run[:, 1]) - (run[0, col] - run[0, 1])
        return out

    fig, (a, b, c) = _axes(3, height=2.6)
    a.plot(r[:, 0], 100 * rel(r, 2), label="force-driven player")
    a.plot(r[:, 0], 100 * rel(r, 3), label="kinematic character")
    a.set_ylabel("x relative to platform (cm)")
    a.set_title("moving_platform: who stays on the platform?")
    a.legend()
    b.plot(r[:, 0], 1000 * rel(r, 2), label="force-driven player")
    b.plot(lag[:, 0], 1000 * rel(lag, 2), ls=":", color="C3", label="acceleration not fed forward")
    b.set_ylabel("x relative to platform (mm)")
    b.set_title("the force-driven player, closer")
    b.legend()
    c.plot(r[:, 0], r[:, 4], color="C2", label="drive force on the player")
    c.axhline(70.0, color="k", ls="--", lw=1, label="m·a = 70 kg · 1 m/s²")
    c.set_xlabel("time (s)")
    c.set_ylabel("drive force x (N)")
    c.legend()
    return _save(fig, path)


def fig_ch2(path: Path) -> Path:
    """Reverse integration against the contact sum, the naive estimate, and a joint's share."""
    r = slide_run()
    s = seesaw_run()
    fig, (a, b, c) = _axes(3, height=2.6)
    a.plot(r[:, 0], r[:, 1], lw=3, alpha=0.5, label="reverse integration (damping included)")
    a.plot(r[:, 0], r[:, 3], "k--", lw=1, label="sum of contact impulses / dt")
    a.plot(r[:, 0], r[:, 5], color="C3", label="naive: m·Δv/dt − m·g (damping forgotten)")
    a.set_ylim(-40.0, 10.0)
    a.set_ylabel("force x (N)")
    a.set_title(
        f"a 10 kg box thrown at 3 m/s, damping 0.5: friction along x "
        f"(clipped: the landing reaches {np.min(r[:, 1]):.0f} N)",
        fontsize=10,
    )
    a.legend(fontsize=8, loc="lower right")
    b.plot(r[:, 0], r[:, 2], lw=3, alpha=0.5, label="reverse integration")
    b.plot(r[:, 0], r[:, 4], "k--", lw=1, label="contact sum")
    b.set_ylabel("force y (N)")
    b.set_xlabel("time (s)")
    b.legend(fontsize=8)
    c.plot(s[:, 0], s[:, 1], lw=3, alpha=0.5, label="plank: engine force (reverse integration)")
    c.plot(s[:, 0], s[:, 2], "k--", label="plank: contact sum")
    c.plot(s[:, 0], s[:, 3], color="C3", label="residual engine − contact = joints")
    c.set_ylim(-100, 1200)
    c.set_xlabel("time (s)")
    c.set_ylabel("force y (N)")
    c.set_title(
        f"seesaw: the pivot carries plank and player (clipped at 1200 N; the plank hitting "
        f"its limit: {np.max(s[:, 1]):.0f} N)",
        fontsize=10,
    )
    c.legend(fontsize=8)
    return _save(fig, path)


def fig_ch3(path: Path) -> Path:
    """The rotating room's field and perceived gravity; the ring's v²/r."""
    r = room_run()
    fig, (a, b) = _axes(2)
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
    return _save(fig, path)


def fig_ch4(path: Path) -> Path:
    """A bouncing ball's felt force through each filter; jitter and lag of the tuning ladder."""
    r = bounce_run()
    steps, _, betas, _ = tuning()
    fig, axes = _axes(3, height=2.6)
    a, b, c = axes
    for i, label in enumerate(CH4_FILTERS, start=1):
        a.plot(r[:, 0], r[:, i], lw=1 if i == 1 else 2, label=label)
    a.set_ylim(-20, 150)
    a.set_xlabel("time (s)")
    a.set_ylabel("felt force / mass (m/s²)")
    a.set_title("bounce: ball1 (raw spikes reach thousands of m/s²; clipped)")
    a.legend(fontsize=8, ncol=2)
    b.plot([fc for fc, _ in steps], [j for _, j in steps], "o-")
    b.axhline(JITTER_TARGET, color="k", ls="--", lw=1, label="jitter target")
    b.set_xscale("log")
    b.set_xticks(TUNE_CUTOFFS, [f"{v:g}" for v in TUNE_CUTOFFS])
    b.minorticks_off()  # the log axis's own minor labels would overprint the ladder's
    b.set_xlabel("min_cutoff (Hz), β = 0")
    b.set_ylabel("jitter at rest (m/s²)")
    b.set_title("step 1: lower min_cutoff until the jitter stops")
    b.legend()
    c.plot(
        [max(be, 1e-3) for be, _ in betas], [d for _, d in betas], "o-", color="C1",
        label="measured",
    )  # fmt: skip
    fine = np.geomspace(TUNE_BETAS[1], TUNE_BETAS[-1], 60)
    c.plot(
        [1e-3, *fine],
        [euro_ramp_lag(tuning()[1], float(be), G, DT) for be in (0.0, *fine)],
        "k:",
        label="fixed point L = 1/(2π(fc₀ + β·s·(1 + L/Te)))",
    )
    c.axhline(LAG_TARGET, color="k", ls="--", lw=1, label="lag target")
    c.set_xscale("log")
    c.set_xticks([1e-3, *TUNE_BETAS[1:]], ["0", *(f"{v:g}" for v in TUNE_BETAS[1:])])
    c.minorticks_off()
    c.set_xlabel("β (s²/m for a signal in m/s²; β = 0 drawn at the left)")
    c.set_ylabel("lag on a ramp (s)")
    c.set_title("step 2: raise β until the lag goes")
    c.legend()
    return _save(fig, path)


def fig_ch5(path: Path) -> Path:
    """Hover step response against theory; the stability limit; a shove that knocks it over."""
    fig, (a, b, c) = _axes(3, height=2.6)
    for zeta, color in ((0.5, "C0"), (1.0, "C1")):
        h = hover_run(zeta)
        a.plot(
            h[:, 0], 1000 * h[:, 1], color=color, lw=3, alpha=0.5, label=f"simulated, ζ = {zeta}"
        )
        a.plot(
            h[:, 0],
            1000 * hover_theory(zeta, h[:, 0]),
            "--",
            color=color,
            label=f"theory, ζ = {zeta}",
        )
    a.set_xlabel("time (s)")
    a.set_ylabel("height − ride height (mm)")
    a.set_title("hover spring, 5 Hz, released 5 mm low")
    a.legend(fontsize=8, ncol=2)
    wh = np.linspace(0.05, 5.2, 52)
    steps = round(1.0 / DT)  # the growth is measured over one second
    for zeta, color in ((0.0, "C2"), (0.5, "C0"), (1.0, "C1")):
        per_step = [spring_growth(float(x), zeta) ** (1.0 / steps) for x in wh]
        b.plot(wh, per_step, color=color, label=f"controller's spring, ζ = {zeta}")
    for zeta, color in ((0.0, "C2"), (1.0, "C1")):
        naive = [spring_growth(float(x), zeta, scheme="explicit") ** (1.0 / steps) for x in wh]
        b.plot(
            wh, naive, ":", color=color, lw=2, label=f"naive −kx − cv (explicit Euler), ζ = {zeta}"
        )
    b.axhline(1.0, color="k", ls="--", lw=1)
    b.set_ylim(0.0, 1.4)
    b.set_xlabel("2πf·dt")
    b.set_ylabel("swing growth per step")
    b.set_title("the spring in pymunk: above 1 the swing grows every step (unstable)")
    b.legend(fontsize=7, loc="lower right", framealpha=0.9)
    for impulse, color in ((120.0, "C0"), (200.0, "C3")):
        _, r = shove(impulse, seconds=5.0)
        c.plot(r[:, 0], r[:, 1], color=color, label=f"shove {impulse:.0f} N·s")
        off = r[r[:, 2] == 1.0, 0]
        if len(off):
            c.axvspan(off[0], off[-1], color=color, alpha=0.1)
    c.set_xlabel("time (s)")
    c.set_ylabel("tilt from up (degrees)")
    c.set_title("balance: a shove at head height (shaded: off balance)")
    c.legend()
    return _save(fig, path)


def fig_ch6(path: Path) -> Path:
    """The gravity flip: height and tilt; the null enemy's felt gravity; the leap, seen from the
    creature."""
    r = flip_run()
    n = null_run()
    leap = leap_run()
    fast = leap_run(LEAP_FAST)
    fig, (a, b, c, d) = _axes(4, height=2.6)
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
    return _save(fig, path)


def fig_ch7(path: Path) -> Path:
    """The ring's error against dt with each convention, and the cost with its spread."""
    errs = [ring_errors(dt) for dt in CH7_DTS]
    dts = [e.dt for e in errs]
    fig, (a, b) = _axes(2, height=3.2)
    a.loglog(dts, [100 * e.end for e in errs], "o-", label="against the end of the step")
    a.loglog(dts, [100 * e.tangential for e in errs], "s:", label="  its tangential part")
    a.loglog(dts, [100 * e.half_turn for e in errs], "k--", lw=1, label="ω·dt/2")
    a.loglog(dts, [100 * e.mid for e in errs], "o-", label="against the middle of the step")
    a.loglog(
        dts, [100 * e.fd_own for e in errs], "x", ms=10, color="C3",
        label="finite differences, against their own mid-point",
    )  # fmt: skip
    a.set_ylabel("error (% of m·ω²·r)")
    a.set_title("ring scene, reverse integration, unfiltered: the same readings, two clocks")
    a.legend(fontsize=8)
    costs = ring_costs()
    med = np.array([costs[dt][0] for dt in dts])
    lo = np.array([costs[dt][1] for dt in dts])
    hi = np.array([costs[dt][2] for dt in dts])
    b.errorbar(dts, med, yerr=[med - lo, hi - med], fmt="o-", capsize=4, label="median, range")
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("dt (s)")
    b.set_ylabel("ms per simulated second")
    b.set_title(f"cost on the machine that drew this ({CH7_REPEATS} interleaved rounds)")
    b.legend(fontsize=8)
    for ax in (a, b):
        ax.set_xticks(dts, [f"1/{round(1 / dt)}" for dt in dts])
        ax.minorticks_off()
    return _save(fig, path)


def fig_ch8(path: Path) -> Path:
    """Steps per frame of the accumulator; the jump stepped at display rates; the hover's dt."""
    fig, (a, b, c) = _axes(3, height=2.7)
    frames = np.arange(1, CH8_FRAMES + 1)
    for i, hz in enumerate(CH8_DISPLAYS):
        n = steps_per_frame([1.0 / hz] * CH8_FRAMES, DT)
        a.step(frames, np.array(n) + 0.06 * i, where="mid", label=f"{hz:g} Hz display")
    hitch = [1.0 / 60.0] * CH8_FRAMES
    hitch[CH8_FRAMES // 2] = CH8_HITCH
    a.step(
        frames, np.array(steps_per_frame(hitch, DT)) - 0.06, where="mid",
        ls="--", label=f"60 Hz display, one {1000 * CH8_HITCH:.0f} ms hitch",
    )  # fmt: skip
    a.set_xlabel("frame")
    a.set_ylabel("physics steps run")
    a.set_title("fixed step dt = 1/120 s: the accumulator runs whole steps, whatever the display")
    a.legend(fontsize=8)
    rates = np.array(CH8_RATES)
    b.plot(rates, [100 * jump_apex(1.0 / r) for r in rates], "o-", label="simulated apex")
    b.axhline(ch8_apex_exact(), color="k", ls="--", lw=1, label="v²/2g (continuous)")
    b.set_xscale("log")
    b.set_xticks(rates, [f"{r:g}" for r in rates])
    b.minorticks_off()
    b.set_xlabel("physics rate 1/dt (Hz) — what a game stepping at its display rate would get")
    b.set_ylabel("jump height (cm)")
    b.set_title("the same jump, stepped at different rates")
    b.legend(fontsize=8)
    for dt, color in ((1.0 / 20.0, "C3"), (1.0 / 60.0, "C1"), (DT, "C0")):
        h = hover_dt_run(dt)
        c.plot(h[:, 0], 1000 * h[:, 1], ".-", color=color, ms=4, label=f"dt = 1/{round(1 / dt)} s")
    c.plot(
        hover_run(1.0)[:, 0], 1000 * hover_theory(1.0, hover_run(1.0)[:, 0]), "k--", lw=1,
        label="continuous",
    )  # fmt: skip
    c.set_xlabel("time (s)")
    c.set_ylabel("height − ride height (mm)")
    c.set_title("the 5 Hz, ζ = 1 hover released 5 mm low, at three steps")
    c.legend(fontsize=8)
    return _save(fig, path)


def fig_ch9(path: Path) -> Path:
    """The arbiter sum against reverse integration on a falling platform; the stale excess."""
    r = stale_run()
    mg = 10.0 * G
    fig, (a, b) = _axes(2, height=3.0)
    a.plot(r[:, 0], r[:, 2] / mg, "k.-", lw=0.8, ms=5, label="Σ Arbiter.total_impulse / h")
    a.plot(r[:, 0], r[:, 1] / mg, "o", ms=6, mfc="none", color="C0", label="reverse integration")
    stale = r[:, 3] == 1.0
    a.plot(r[stale, 0], r[stale, 2] / mg, "v", color="C3", ms=8, label="contact re-made (stale)")
    a.axhline(ch9_weight_share(), color="C2", ls="--", lw=1, label="(g − a)/g, the mean")
    a.set_xlim(DROP_START - 0.1, r[-1, 0])
    a.set_xlabel("time (s)")
    a.set_ylabel("vertical contact force / m·g")
    a.set_title(
        f"a box on a platform falling at {DROP_ACCELERATION:g} m/s² from t = {DROP_START:g} s"
    )
    a.legend(fontsize=8, ncol=2, loc="upper left")
    excess = _stale_excess()
    idx = np.nonzero(stale)[0]
    two_back = r[idx - 2, 2] / mg
    b.plot(two_back, excess[idx], "v", color="C3", ms=8, label="re-made contacts")
    top = float(max(np.max(two_back), np.max(excess[idx]))) * 1.1
    b.plot([0.0, top], [0.0, top], "k--", lw=1, label="excess = the sum two steps earlier")
    b.set_xlabel("arbiter sum two steps earlier / m·g")
    b.set_ylabel("arbiter sum − applied / m·g")
    b.set_title("the excess is the old contact's impulse, reported again")
    b.legend(fontsize=8)
    return _save(fig, path)


def fig_ch10(path: Path) -> Path:
    """The stability matrix; where each scene breaks as dt grows; the runaway guard."""
    import matplotlib.pyplot as plt

    scenes = hard_scenes()
    cols = [(dt, it, sub) for dt in CH10_DTS for it in CH10_ITERATIONS for sub in CH10_SUBSTEPS]
    pen = np.array([[hard_run(sc, *c).penetration * 1000.0 for c in cols] for sc in scenes])
    fig = plt.figure(figsize=(9.0, 10.5))
    grid = fig.add_gridspec(3, 1, height_ratios=[1.3, 1.0, 1.0])
    a = fig.add_subplot(grid[0])
    shown = np.where(np.isfinite(pen), np.log10(np.maximum(pen, 0.1)), np.nan)
    image = a.imshow(shown, cmap="viridis", aspect="auto", vmin=-1, vmax=3)
    for i in range(len(scenes)):
        for j in range(len(cols)):
            v = pen[i, j]
            text = "broke" if not np.isfinite(v) else f"{v:.0f}" if v >= 1 else f"{v:.1f}"
            a.text(j, i, text, ha="center", va="center", fontsize=8,
                   color="w" if np.isfinite(v) and shown[i, j] < 1.5 else "k")  # fmt: skip
    a.set_yticks(range(len(scenes)), scenes)
    a.set_xticks(
        range(len(cols)), [f"1/{round(1 / dt)} s\n{it} it\n×{sub}" for dt, it, sub in cols],
        fontsize=8,
    )  # fmt: skip
    a.set_title(
        "every invariant held in every cell; the number: deepest overlap into static ground (mm)",
        fontsize=10,
    )
    fig.colorbar(image, ax=a, label="log10 overlap (mm)")
    b = fig.add_subplot(grid[1])
    for i, sc in enumerate(scenes):
        for rate in CH10_RATES:
            out = hard_run(sc, 1.0 / rate)
            b.plot(rate, i, "o" if out.broke is None else "X",
                   color="C2" if out.broke is None else "C3", ms=9)  # fmt: skip
            if out.broke is not None:
                b.annotate(out.broke, (rate, i), xytext=(6, 4), textcoords="offset points",
                           fontsize=7)  # fmt: skip
    b.set_yticks(range(len(scenes)), scenes)
    b.set_xscale("log")
    b.set_xticks(CH10_RATES, [f"1/{r:g}" for r in CH10_RATES])
    b.minorticks_off()
    b.invert_xaxis()
    b.invert_yaxis()  # the matrix's order, top to bottom
    b.set_xlabel("dt (s), 10 iterations — green: holds, red: the first invariant it breaks")
    b.set_title("where each scene breaks as the step grows")
    b.grid(True, alpha=0.3)
    c = fig.add_subplot(grid[2])
    free, _, _ = runaway_run(False)
    held, stop, _ = runaway_run(True)
    c.plot(free[:, 0], np.log10(free[:, 1]), color="C3", label="runtime guard off")
    c.plot(held[:, 0], np.log10(held[:, 1]), color="C0", lw=4, label="guard on: the world stops")
    c.axvline(stop, color="C0", ls="--", lw=1)
    c.set_xlabel("step")
    c.set_ylabel("log10 |x| (x in m)")
    c.set_title(f"a spring stepped beyond its limit (2πf·dt = {GUARD_OMEGA_DT:g})")
    c.legend(fontsize=8)
    c.grid(True, alpha=0.3)
    return _save(fig, path)


FIGURES: dict[str, Callable[[Path], Path]] = {
    "01-kinematic-vs-force-driven.png": fig_ch1,
    "02-reverse-integration.png": fig_ch2,
    "03-perceived-gravity.png": fig_ch3,
    "04-filtering.png": fig_ch4,
    "05-floating-capsule.png": fig_ch5,
    "06-playing-with-gravity.png": fig_ch6,
    "07-accuracy-costs.png": fig_ch7,
    "08-fixed-step.png": fig_ch8,
    "09-contact-impulses.png": fig_ch9,
    "10-stability.png": fig_ch10,
}
"""Every chapter figure, by file name."""


def make_all(out: Path, progress: bool = False) -> list[Path]:
    """Draw every figure into directory ``out`` (created if needed); the paths written.

    With ``progress`` a bar on stderr names the figure being drawn (the simulations behind some
    take tens of seconds); it needs tqdm, in the same ``bench`` extra as matplotlib.
    """
    out.mkdir(parents=True, exist_ok=True)
    items = list(FIGURES.items())
    if not progress:
        return [draw(out / name) for name, draw in items]
    import importlib

    tqdm = importlib.import_module("tqdm").tqdm  # untyped; the bench extra installs it
    written = []
    with tqdm(items, unit="figure", desc="figures") as bar:
        for name, draw in bar:
            bar.set_postfix_str(name)
            written.append(draw(out / name))
    return written
