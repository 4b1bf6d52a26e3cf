"""Chapter 4, filtering a spiky force (docs/chapters/04-filtering.md): jitter and lag of
the filters, the 1€ filter's tuning ladder and its lag on a ramp, a one-step spike, and the
chapter's figure."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache, partial
from pathlib import Path

import numpy as np

from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter
from playground.filters.row_filter import Filter
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, Array, G, level_scene, record

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
    scene = level_scene("bounce")
    raw = record(
        scene.world, scene.level.settings.seconds, lambda w: [w.forces("ball1").specific[1]]
    )
    cols = [_filtered(make, raw[:, 1], DT) for make in CH4_FILTERS.values()]
    return np.column_stack([raw[:, 0], *cols])


NOISE = 0.5
"""Standard deviation of the synthetic reading's noise at rest, m/s²."""


SEED = 7
"""The noise draw behind the figure's single-draw curves and the numbers quoted "on one draw"."""

SEEDS = 100
"""Noise draws (seeds 0 … SEEDS − 1) over which chapter 4 quotes a jitter's median and range and
runs the tuning's first step: one draw's jitter moves by tens of percent from seed to seed."""


@cache
def _noisy_rest(seed: int = SEED) -> Array:
    """Two seconds of a resting reading g plus seeded Gaussian noise, m/s²."""
    rng = np.random.default_rng(seed)
    return G + NOISE * rng.standard_normal(round(2.0 / DT))


def jitter(make: Callable[[], Filter] | None, seed: int = SEED) -> float:
    """Spread (standard deviation) of the filtered noisy rest signal after 1 s, m/s²."""
    out = _filtered(make, _noisy_rest(seed), DT)
    return float(np.std(out[round(1.0 / DT) :]))


@dataclass(frozen=True, slots=True)
class Spread:
    """A measure over the :data:`SEEDS` noise draws: its median, lowest and highest value."""

    median: float
    low: float
    high: float


def jitter_spread(make: Callable[[], Filter] | None) -> Spread:
    """The jitter of ``make``'s filter over :data:`SEEDS` noise draws, m/s²."""
    values = [jitter(make, seed) for seed in range(SEEDS)]
    return Spread(float(np.median(values)), min(values), max(values))


@cache
def filter_spread(label: str) -> Spread:
    """:func:`jitter_spread` of the filter of :data:`CH4_FILTERS` named ``label``."""
    return jitter_spread(CH4_FILTERS[label])


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


def first_step(seed: int = SEED) -> float:
    """The tuning's first step on one noise draw: the first ``min_cutoff`` of the ladder (β = 0)
    whose jitter is below :data:`JITTER_TARGET` (the last rung if none is), Hz."""
    for fc in TUNE_CUTOFFS:
        if jitter(partial(OneEuroFilter, min_cutoff=fc), seed) < JITTER_TARGET:
            return fc
    return TUNE_CUTOFFS[-1]


@cache
def first_step_picks() -> dict[float, int]:
    """How many of the :data:`SEEDS` noise draws the first step ends on each rung of the ladder."""
    picks = dict.fromkeys(TUNE_CUTOFFS, 0)
    for seed in range(SEEDS):
        picks[first_step(seed)] += 1
    return picks


@cache
def ladder_spread() -> list[tuple[float, Spread]]:
    """The first step's ladder over every noise draw: (min_cutoff, jitter spread at β = 0)."""
    return [(fc, jitter_spread(partial(OneEuroFilter, min_cutoff=fc))) for fc in TUNE_CUTOFFS]


@cache
def tuning() -> tuple[list[tuple[float, float]], float, list[tuple[float, float]], float]:
    """The tuning procedure on one noise draw (:data:`SEED`).

    Returns ([(min_cutoff, jitter)], chosen min_cutoff, [(β, lag)], chosen β).
    """
    steps = [(fc, jitter(partial(OneEuroFilter, min_cutoff=fc))) for fc in TUNE_CUTOFFS]
    chosen = first_step()
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


@number
def ch4_jitter_raw() -> float:
    """Jitter at rest of the raw reading, m/s²."""
    return jitter(None)


@number
def ch4_jitter_ema() -> float:
    """Jitter at rest through the 5 Hz moving average, m/s²."""
    return jitter(CH4_FILTERS["moving average 5 Hz"])


@number
def ch4_jitter_euro() -> float:
    """Jitter at rest through perception's 1€ filter (2 Hz, β 0.05), m/s²."""
    return jitter(CH4_FILTERS["1€ 2 Hz, β 0.05"])


@number
def ch4_jitter_euro_median() -> float:
    """Median jitter of perception's 1€ filter over the noise draws, m/s²."""
    return filter_spread("1€ 2 Hz, β 0.05").median


@number
def ch4_jitter_euro_low() -> float:
    """Lowest jitter of perception's 1€ filter over the noise draws, m/s²."""
    return filter_spread("1€ 2 Hz, β 0.05").low


@number
def ch4_jitter_euro_high() -> float:
    """Highest jitter of perception's 1€ filter over the noise draws, m/s²."""
    return filter_spread("1€ 2 Hz, β 0.05").high


@number
def ch4_jitter_euro_over_target() -> float:
    """On how many noise draws perception's 1€ filter jitters more than the target."""
    make = CH4_FILTERS["1€ 2 Hz, β 0.05"]
    return float(sum(jitter(make, seed) > JITTER_TARGET for seed in range(SEEDS)))


@number
def ch4_jitter_ema_median() -> float:
    """Median jitter of the 5 Hz moving average over the noise draws, m/s²."""
    return filter_spread("moving average 5 Hz").median


@number
def ch4_jitter_ema_low() -> float:
    """Lowest jitter of the 5 Hz moving average over the noise draws, m/s²."""
    return filter_spread("moving average 5 Hz").low


@number
def ch4_jitter_ema_high() -> float:
    """Highest jitter of the 5 Hz moving average over the noise draws, m/s²."""
    return filter_spread("moving average 5 Hz").high


@number
def ch4_seeds() -> float:
    """How many noise draws chapter 4's medians and ranges are taken over."""
    return float(SEEDS)


@number
def ch4_picks_2() -> float:
    """Noise draws on which the tuning's first step picks 2 Hz."""
    return float(first_step_picks()[2.0])


@number
def ch4_picks_1() -> float:
    """Noise draws on which the tuning's first step picks 1 Hz."""
    return float(first_step_picks()[1.0])


@number
def ch4_picks_other() -> float:
    """Noise draws on which the tuning's first step picks neither 2 Hz nor 1 Hz."""
    picks = first_step_picks()
    return float(SEEDS - picks[2.0] - picks[1.0])


@number
def ch4_jitter_1hz_median() -> float:
    """Median jitter of the 1€ filter at 1 Hz, β 0.05 (the steadier rung) over the draws, m/s²."""
    return jitter_spread(partial(OneEuroFilter, min_cutoff=1.0, beta=0.05)).median


@number
def ch4_jitter_2hz_beta0_median() -> float:
    """Median jitter of the 1€ filter at 2 Hz, β = 0 over the noise draws, m/s²."""
    return jitter_spread(partial(OneEuroFilter, min_cutoff=2.0, beta=0.0)).median


@number
def ch4_lag_ema() -> float:
    """Lag of the 5 Hz moving average on a ramp of g per second, s."""
    return lag(CH4_FILTERS["moving average 5 Hz"])


@number
def ch4_lag_euro() -> float:
    """Lag of perception's 1€ filter on the same ramp, s."""
    return lag(CH4_FILTERS["1€ 2 Hz, β 0.05"])


@number
def ch4_tuned_cutoff() -> float:
    """The tuning procedure's min_cutoff, Hz."""
    return tuning()[1]


@number
def ch4_tuned_beta() -> float:
    """The tuning procedure's β (s²/m for a signal in m/s²)."""
    return tuning()[3]


@number
def ch4_tuned_lag_beta0() -> float:
    """Lag of the chosen min_cutoff with β = 0, s."""
    return tuning()[2][0][1]


@number
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


@number
def ch4_lag_euro_fixed() -> float:
    """The fixed-point lag of perception's 1€ filter (2 Hz, β 0.05) on a ramp of g per second,
    s."""
    return euro_ramp_lag(2.0, 0.05, G, DT)


@number
def ch4_tuned_lag_fixed() -> float:
    """The fixed-point lag of the tuned 1€ filter (chosen min_cutoff and β), s."""
    _, cutoff, _, beta = tuning()
    return euro_ramp_lag(cutoff, beta, G, DT)


@number
def ch4_euro_seen_speed() -> float:
    """The speed perception's 1€ filter sees on the ramp of g per second: s·(1 + L/Te),
    m/s³."""
    return G * (1.0 + ch4_lag_euro_fixed() / DT)


@number
def ch4_euro_cutoff_on_ramp() -> float:
    """The cutoff perception's 1€ filter opens to on that ramp: 2 Hz + β·s·(1 + L/Te), Hz."""
    return 2.0 + 0.05 * ch4_euro_seen_speed()


@number
def ch4_spike_euro() -> float:
    """The one-step spike's peak through the 1€ filter alone, m/s² over g."""
    return spike_peak(CH4_FILTERS["1€ 2 Hz, β 0.05"])  # type: ignore[arg-type]


@number
def ch4_spike_median() -> float:
    """The same through median-of-3 then the 1€ filter, m/s² over g."""
    return spike_peak(CH4_FILTERS["median-of-3 + 1€"])  # type: ignore[arg-type]


@figure("04-filtering.png")
def fig_ch4(path: Path) -> Path:
    """A bouncing ball's felt force through each filter; jitter and lag of the tuning ladder."""
    r = bounce_run()
    steps, _, betas, _ = tuning()
    fig, (a, b, c) = axes(3, height=2.6)
    for i, label in enumerate(CH4_FILTERS, start=1):
        a.plot(r[:, 0], r[:, i], lw=1 if i == 1 else 2, label=label)
    a.set_ylim(-20, 150)
    a.set_xlabel("time (s)")
    a.set_ylabel("felt force / mass (m/s²)")
    a.set_title("bounce: ball1 (raw spikes reach thousands of m/s²; clipped)")
    a.legend(fontsize=8, ncol=2)
    spread = ladder_spread()
    b.fill_between(
        [fc for fc, _ in spread],
        [sp.low for _, sp in spread],
        [sp.high for _, sp in spread],
        color="C0",
        alpha=0.15,
        label=f"range over {SEEDS} noise draws",
    )
    b.plot([fc for fc, _ in spread], [sp.median for _, sp in spread], "C0--", label="median")
    b.plot([fc for fc, _ in steps], [j for _, j in steps], "o-", label=f"one draw (seed {SEED})")
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
    return save(fig, path)
