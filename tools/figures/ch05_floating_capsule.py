"""Chapter 5, the floating capsule (docs/chapters/05-floating-capsule.md): the hover spring
against theory, its stability limit in pymunk, the drive, a shove that knocks the player over,
and the chapter's figure."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path
from typing import Literal

import numpy as np
import pymunk

from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.controller.spring import hover_limit, hover_spring
from playground.controller.states import State
from playground.intents import Intent, Script
from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, Array, record


@number
def ch5_k() -> float:
    """Hover stiffness of the default player, k = m·(2πf)², N/m."""
    c = ControllerConfig()
    return c.mass * (2.0 * math.pi * c.hover_frequency) ** 2


@number
def ch5_c() -> float:
    """Hover damping of the default player, c = 2ζ·m·2πf, N·s/m."""
    c = ControllerConfig()
    return 2.0 * c.hover_damping * c.mass * 2.0 * math.pi * c.hover_frequency


HOVER_DROP = 0.005
"""m: how far below ride height chapter 5's player starts: small, so the overshoot stays under
g/ω² ≈ 1 cm, where the spring would have to pull (a floor cannot pull: the hover clips at zero)."""


@cache
def hover_run(zeta: float, dt: float = DT) -> Array:
    """A player (5 Hz hover at damping ratio ``zeta``) released HOVER_DROP below its ride height,
    stepped at ``dt`` (s). Columns: t (s), height above the ride height (m) measured by the
    probe."""
    world = World(WorldConfig(dt=dt))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    cfg = ControllerConfig(hover_damping=zeta, lock_rotation=True)
    floor_top = 0.05  # the floor segment's radius: its surface, where the probe hits
    start = (0.0, floor_top + cfg.ride_height - HOVER_DROP)
    player = Controller(world, "player", start, config=cfg)
    return record(world, 0.6, lambda w: [player.body.position.y - floor_top - cfg.ride_height])


def hover_theory(zeta: float, t: Array) -> Array:
    """The damped oscillator x'' + 2ζω x' + ω² x = 0 from x = −HOVER_DROP at rest, m."""
    w = 2.0 * math.pi * ControllerConfig().hover_frequency
    x0 = -HOVER_DROP
    if zeta < 1.0:
        wd = w * math.sqrt(1.0 - zeta**2)
        out: Array = x0 * np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta * w / wd * np.sin(wd * t))
        return out
    return x0 * np.exp(-w * t) * (1.0 + w * t)


@number
def ch5_overshoot_sim() -> float:
    """Overshoot above ride height at ζ = 0.5, as a fraction of the drop (simulated)."""
    return float(np.max(hover_run(0.5)[:, 1]) / HOVER_DROP)


@number
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
    r = record(world, seconds, lambda wd: [abs(body.position.x)])
    if not np.all(r[:, 1] < SWING_CUTOFF):
        return math.inf  # blew past the cut-off, where the spring stops: unbounded growth
    window = 0.25
    mid = r[(r[:, 0] > seconds / 2 - window) & (r[:, 0] <= seconds / 2), 1].max()
    late = r[r[:, 0] > seconds - window, 1].max()
    return float(late / mid) if mid > 0.0 else 0.0


@number
def ch5_ratio_below() -> float:
    """Late/mid swing of an undamped spring at 2πf·dt = 1.9 (stable: it keeps its size)."""
    return spring_growth(1.9, 0.0)


@number
def ch5_ratio_above_log10() -> float:
    """log10 of late/mid swing of an undamped spring at 2πf·dt = 2.1 (unstable)."""
    return math.log10(spring_growth(2.1, 0.0))


@number
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


@number
def ch5_max_frequency() -> float:
    """The highest stable hover frequency at ζ = 1 and dt = 1/120 s, Hz."""
    return max_hover_frequency(1.0)


@number
def ch5_max_frequency_zeta05() -> float:
    """The same at ζ = 0.5, Hz."""
    return max_hover_frequency(0.5)


@number
def ch5_limit_zeta1() -> float:
    """The simulated stability limit on 2πf·dt of the hover's spring at ζ = 1."""
    return stability_limit(1.0)


@number
def ch5_limit_zeta05() -> float:
    """The same at ζ = 0.5."""
    return stability_limit(0.5)


@number
def ch5_explicit_limit_zeta1() -> float:
    """Stability limit on 2πf·dt of the naive spring (explicit Euler) at ζ = 1 (theory: 2ζ)."""
    return stability_limit(1.0, "explicit")


@number
def ch5_explicit_undamped_per_step() -> float:
    """Swing growth per step of an undamped naive spring (explicit Euler) at 5 Hz and
    dt = 1/120 s, simulated (measured over two seconds)."""
    wh = 2.0 * math.pi * ControllerConfig().hover_frequency * DT
    per_second = spring_growth(wh, 0.0, seconds=4.0, scheme="explicit") ** 0.5
    return float(per_second ** (1.0 / round(1.0 / DT)))


@number
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
    return record(world, 2.0, lambda w: [player.body.velocity.x, player.last_forces.drive[0]])


@number
def ch5_drive_peak() -> float:
    """Largest drive force while speeding up, N."""
    return float(np.max(walk_run()[:, 2]))


@number
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
    r = record(
        world, seconds, lambda w: [math.degrees(player.tilt), float(codes.get(player.state, 3))]
    )
    return bool(np.any(r[:, 2] == 1.0)), r


@number
def ch5_knockover() -> float:
    """The smallest head-height shove that knocks the player over, N·s (bisection, ±1 N·s)."""
    lo, hi = 0.0, 400.0
    while hi - lo > 1.0:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if shove(mid)[0] else (mid, hi)
    return hi


@figure("05-floating-capsule.png")
def fig_ch5(path: Path) -> Path:
    """Hover step response against theory; the stability limit; a shove that knocks it over."""
    fig, (a, b, c) = axes(3, height=2.6)
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
    return save(fig, path)
