"""Chapter 7, what accuracy costs (docs/chapters/07-what-accuracy-costs.md): the ring's
reading error against dt read at the end and at the middle of the step, its cost, and the
chapter's figure."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np

from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import Array

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
        fd_own: finite differences against their own centre, the time of their middle sample
            x₁ (the start of the step): the mean of the mid-step answers on either side, as the
            bench compares them.
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
    mid_all = np.array([_rotate(v, -0.5 * RING_RATE * dt) for v in ends])  # row i: step i + 1
    mid = mid_all[n_settle:]
    x = np.array(positions)
    fd_all = m * (x[2:] - 2.0 * x[1:-1] + x[:-2]) / (dt * dt)  # row j: read after step j + 1
    fd = fd_all[n_settle - 1 :]
    # Their centre, the start of the step: the mean of the mid-step answers on either side, as
    # the bench compares them (playground.bench.accuracy).
    own = 0.5 * (mid_all[n_settle:] + mid_all[n_settle - 1 : -1])
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


CH7_REPEATS = 45
"""Interleaved timing rounds of chapter 7's cost panel (the median and the 10th–90th percentiles
are drawn). Many short rounds rather than a few long ones: on a shared machine a busy spell lasts
longer than a round, and short rounds spread it over every dt alike (with 9 rounds of 120 steps
the medians came out of order under load; with 45 of 24 they repeat to a few percent)."""

CH7_BLOCK = 24
"""Steps per timed block of chapter 7's cost panel."""


@cache
def ring_costs(rounds: int = CH7_REPEATS) -> dict[float, tuple[float, float, float]]:
    """ms of computing per simulated second of the ring scene (reverse integration) at each dt:
    (median, 10th and 90th percentiles) over ``rounds`` rounds, every dt timed once per round
    so that a busy spell of the machine hits them all alike, in alternating order."""
    import time

    from playground.bench.scenes import Knobs, build

    worlds = {dt: build("ring", Knobs(dt=dt)).world for dt in CH7_DTS}
    for w in worlds.values():
        w.run(0.2)  # past the first steps' one-off costs
    samples: dict[float, list[float]] = {dt: [] for dt in CH7_DTS}
    for r in range(rounds):
        # Every other round in the reverse order, so that whatever the first or last world of a
        # round pays (a cold cache, a scheduler's tick) falls on every dt alike.
        order = CH7_DTS if r % 2 == 0 else CH7_DTS[::-1]
        for dt in order:
            w = worlds[dt]
            t0 = time.perf_counter()
            for _ in range(CH7_BLOCK):
                w.step()
                w.forces("player")
            per_step = (time.perf_counter() - t0) / CH7_BLOCK
            samples[dt].append(1e3 * per_step / dt)
    out = {}
    for dt, v in samples.items():
        p10, p50, p90 = np.percentile(v, [10, 50, 90])
        out[dt] = (float(p50), float(p10), float(p90))
    return out


@number
def ch7_substeps_30() -> float:
    """Ring error (mid-step) of reverse integration at dt = 1/30 s with 4 substeps, %."""
    from playground.bench.accuracy import Point, measure
    from playground.bench.scenes import Knobs

    (r,) = measure(Point("ring", Knobs(dt=1 / 30, substeps=4), "reverse"), ("none",), repeats=1)
    return r.error * 100.0


@number
def ch7_end_30() -> float:
    """Ring error against the end of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).end * 100.0


@number
def ch7_end_60() -> float:
    """The same at dt = 1/60 s, %."""
    return ring_errors(1 / 60).end * 100.0


@number
def ch7_end_120() -> float:
    """The same at dt = 1/120 s, %."""
    return ring_errors(1 / 120).end * 100.0


@number
def ch7_end_240() -> float:
    """The same at dt = 1/240 s, %."""
    return ring_errors(1 / 240).end * 100.0


@number
def ch7_tangential_30() -> float:
    """Tangential part of the reading against the end of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).tangential * 100.0


@number
def ch7_tangential_60() -> float:
    """The same at dt = 1/60 s, %."""
    return ring_errors(1 / 60).tangential * 100.0


@number
def ch7_tangential_120() -> float:
    """The same at dt = 1/120 s, %."""
    return ring_errors(1 / 120).tangential * 100.0


@number
def ch7_tangential_240() -> float:
    """The same at dt = 1/240 s, %."""
    return ring_errors(1 / 240).tangential * 100.0


@number
def ch7_half_30() -> float:
    """ω·dt/2 at dt = 1/30 s, % (of a radian)."""
    return ring_errors(1 / 30).half_turn * 100.0


@number
def ch7_half_60() -> float:
    """The same at dt = 1/60 s, %."""
    return ring_errors(1 / 60).half_turn * 100.0


@number
def ch7_half_120() -> float:
    """The same at dt = 1/120 s, %."""
    return ring_errors(1 / 120).half_turn * 100.0


@number
def ch7_half_240() -> float:
    """The same at dt = 1/240 s, %."""
    return ring_errors(1 / 240).half_turn * 100.0


@number
def ch7_mid_30() -> float:
    """Ring error against the middle of the step at dt = 1/30 s, %."""
    return ring_errors(1 / 30).mid * 100.0


@number
def ch7_mid_60() -> float:
    """The same at dt = 1/60 s, %."""
    return ring_errors(1 / 60).mid * 100.0


@number
def ch7_mid_120() -> float:
    """The same at dt = 1/120 s, %."""
    return ring_errors(1 / 120).mid * 100.0


@number
def ch7_mid_240() -> float:
    """The same at dt = 1/240 s, %."""
    return ring_errors(1 / 240).mid * 100.0


@number
def ch7_tangential_short_30() -> float:
    """How far the tangential part at dt = 1/30 s falls short of ω·dt/2, % of ω·dt/2."""
    e = ring_errors(1 / 30)
    return (1.0 - e.tangential / math.sin(e.half_turn)) * 100.0


@number
def ch7_bumps_per_second() -> float:
    """How many segment joints of the bench's ring pass under the box per second."""
    from playground.bench.scenes import RING_RATE

    return 64 * RING_RATE / (2.0 * math.pi)


@number
def ch7_fd_end_120() -> float:
    """Finite differences against the end of the step at dt = 1/120 s, %."""
    return ring_errors(1 / 120).fd_end * 100.0


@number
def ch7_fd_own_120() -> float:
    """Finite differences against their own mid-point at dt = 1/120 s, %."""
    return ring_errors(1 / 120).fd_own * 100.0


@figure("07-accuracy-costs.png")
def fig_ch7(path: Path) -> Path:
    """The ring's error against dt with each convention, and the cost with its spread."""
    errs = [ring_errors(dt) for dt in CH7_DTS]
    dts = [e.dt for e in errs]
    fig, (a, b) = axes(2, height=3.2)
    a.loglog(dts, [100 * e.end for e in errs], "o-", label="against the end of the step")
    a.loglog(dts, [100 * e.tangential for e in errs], "s:", label="  its tangential part")
    a.loglog(dts, [100 * e.half_turn for e in errs], "k--", lw=1, label="ω·dt/2")
    a.loglog(dts, [100 * e.mid for e in errs], "o-", label="against the middle of the step")
    a.loglog(
        dts, [100 * e.fd_own for e in errs], "x", ms=10, color="C3",
        label="finite differences, against their own centre",
    )  # fmt: skip
    a.set_ylabel("error (% of m·ω²·r)")
    a.set_title("ring scene, reverse integration, unfiltered: the same readings, two clocks")
    a.legend(fontsize=8)
    costs = ring_costs()
    med = np.array([costs[dt][0] for dt in dts])
    lo = np.array([costs[dt][1] for dt in dts])
    hi = np.array([costs[dt][2] for dt in dts])
    b.errorbar(
        dts,
        med,
        yerr=[med - lo, hi - med],
        fmt="o-",
        capsize=4,
        label="median, 10th–90th percentile",
    )
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("dt (s)")
    b.set_ylabel("ms per simulated second")
    b.set_title(f"cost on the machine that drew this ({CH7_REPEATS} interleaved rounds)")
    b.legend(fontsize=8)
    for ax in (a, b):
        ax.set_xticks(dts, [f"1/{round(1 / dt)}" for dt in dts])
        ax.minorticks_off()
    return save(fig, path)
