"""The overhead profile: what each stage and each effect costs as bodies grow.

A pile of boxes resting on a floor is built twice — in a :class:`~playground.world.World` with one
effect switched on, and in a bare ``pymunk.Space`` with the same bodies in the same order — and
both are stepped in interleaved blocks in the same process, so the ratio holds on a busy machine.
A world that uses no effect (uniform gravity is ``space.gravity``) must cost no more than
:data:`NO_EFFECT_BUDGET` × bare pymunk; every effect's marginal cost is listed against it.

>>> rows = profile(sizes=(10,), effects=("none",), repeats=1)
>>> rows[0].effect, rows[0].bodies
('none', 10)
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import pymunk

from playground.bench.blocks import interleave
from playground.bench.markdown import table
from playground.bench.pile import floor_length, pile_space, pile_world
from playground.bench.plots import log_axes, pyplot, save
from playground.controller.controller import Controller
from playground.gravity import GravityRule, Radial, RotatingRoom, Turn
from playground.limits import MAX_TIME
from playground.movers import Sine
from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "EFFECTS",
    "NO_EFFECT_BUDGET",
    "SIZES",
    "OverheadRow",
    "fixed_cost",
    "overhead_figure",
    "overhead_markdown",
    "profile",
]

NO_EFFECT_BUDGET = 1.05
"""A scene that uses no effect may cost at most this many times bare pymunk."""

SIZES = (10, 30, 100, 300, 1000, 3000)
"""Body counts profiled by default."""

QUICK_SIZES = (10, 100)
"""Body counts profiled with ``quick``."""

MOVERS = 10
"""Kinematic platforms in the "movers" effect."""


# Each effect keeps the pile's motion the same as the bare space's, so that the difference is
# the effect's machinery, not a pile that topples (a turning room tips it over within seconds and
# bodies that fall off the floor stop costing contacts).


def _rotating_room(world: World, n: int) -> None:
    # A room that turns (a scheduled turn far in the future): the gravity stage runs every step.
    world.gravity = RotatingRoom(turns=(Turn(MAX_TIME, math.pi),))


def _radial(world: World, n: int) -> None:
    # A planet so large that its surface is flat under the pile (tilt < 0.2° at its ends).
    middle = floor_length(n) / 2.0
    world.gravity = Radial(center=(middle, -1e5), radius=1e5, softening=0.0)


def _rules(world: World, n: int) -> None:
    for i in range(0, n, 10):
        world.set_gravity_rule(f"box{i}", GravityRule(scale=1.0 + 1e-3))


def _movers(world: World, n: int) -> None:
    for i in range(MOVERS):
        body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        shape = pymunk.Poly.create_box(body, (1.0, 0.1))
        world.add(f"mover{i}", body, shape)
        world.add_mover(f"mover{i}", Sine(center=(2.0 * i, 20.0), amplitude=(1.0, 0.0)))


def _track_one(world: World, n: int) -> None:
    world.track("box0", perceive=False)


def _track_all(world: World, n: int) -> None:
    world.track(*(f"box{i}" for i in range(n)), perceive=False)


def _perceive_one(world: World, n: int) -> None:
    world.track("box0", perceive=True)


def _controller(world: World, n: int) -> None:
    Controller(world, "player", position=(-1.0, 1.0))


def _no_guard(world: World, n: int) -> None:
    # The runtime guard off: "none" minus this row is what the guard costs a scene with no effect.
    world.config = replace(world.config, guard=False)


EFFECTS: dict[str, Callable[[World, int], None] | None] = {
    "none": None,
    "rotating room": _rotating_room,
    "radial field": _radial,
    "per-body rule (every 10th body)": _rules,
    f"movers ({MOVERS})": _movers,
    "tracked solver (1 body)": _track_one,
    "tracked solver (every body)": _track_all,
    "contact split (1 body)": _track_one,
    "contact split (every body)": _track_all,
    "perceived-gravity filter (1 body)": _perceive_one,
    "controller (1)": _controller,
    "runtime guard off": _no_guard,
}
"""Each effect and how it is switched on (``None``: uniform gravity only)."""


@dataclass(frozen=True, slots=True)
class OverheadRow:
    """One effect at one body count.

    Attributes:
        bodies: boxes in the pile.  effect: a key of :data:`EFFECTS`.
        us_per_step: the world, µs per step.  bare_us: bare pymunk, µs per step.
        ratio: world / bare, the median over adjacent pairs of timed blocks (robust to load).
        us_per_step: ratio × bare_us, µs (consistent with the ratio).
        bare_us: median over every effect's bare blocks at this size, µs per step.
        best_ratio: fastest world block / fastest bare block.
        marginal_us: (ratio − the "none" ratio) × bare_us: what the effect adds, µs per step.
        events_us … filter_us: mean µs per step of each stage (0 when it did not run).
    """

    bodies: int
    effect: str
    us_per_step: float
    bare_us: float
    ratio: float
    best_ratio: float
    marginal_us: float
    events_us: float
    gravity_us: float
    movers_us: float
    control_us: float
    physics_us: float
    forces_us: float
    filter_us: float


_STAGES = (Stage.EVENTS, Stage.GRAVITY, Stage.MOVERS, Stage.CONTROL, Stage.PHYSICS, Stage.FORCES,
           Stage.FILTER)  # fmt: skip


def _time_blocks(
    world: World, bare: pymunk.Space, repeats: int
) -> tuple[float, float, float, float]:
    """(world, bare) µs per step, medians over interleaved blocks; the median of the ratios of
    adjacent blocks (robust to load drifting during the run); and the ratio of the fastest
    blocks (``timeit``'s best-of: robust to bursts of load on a shared machine)."""
    dt = world.config.dt
    t = interleave(world.step, lambda: bare.step(dt), repeats=repeats)
    return 1e6 * t.a_median, 1e6 * t.b_median, t.ratio, t.best


def _stage_means(world: World, steps: int) -> dict[Stage, float]:
    """Mean µs per step of each stage over ``steps`` timed steps (timing switched on)."""
    world.config = replace(world.config, timing=True)
    for s in Stage:
        world.timings[s].total = 0.0
        world.timings[s].calls = 0
    for _ in range(steps):
        world.step()
    world.config = replace(world.config, timing=False)
    return {s: 1e6 * world.timings[s].total / steps for s in _STAGES}


def profile(
    sizes: Sequence[int] | None = None,
    effects: Sequence[str] | None = None,
    *,
    quick: bool = False,
    repeats: int = 21,
    settle_steps: int = 30,
    progress: bool = False,
) -> list[OverheadRow]:
    """Time every effect at every size against bare pymunk; rows by size, then effect.

    ``progress`` shows a bar on stderr when it is a terminal (tqdm).
    """
    sizes = tuple(sizes) if sizes is not None else (QUICK_SIZES if quick else SIZES)
    effects = tuple(effects) if effects is not None else tuple(EFFECTS)
    for e in effects:
        if e not in EFFECTS:
            raise ValueError(f"effects: expected names from {list(EFFECTS)}, got {e!r}")
    if quick:
        repeats = min(repeats, 2)
    rows: list[OverheadRow] = []
    bar = _bar(len(sizes) * len(effects)) if progress else None
    for n in sizes:
        at_n: list[OverheadRow] = []
        for effect in effects:
            if bar is not None:
                bar.update(1)
            config = WorldConfig(contact_split=effect.startswith("contact split"))
            world = pile_world(n, config)
            setup = EFFECTS[effect]
            if setup is not None:
                setup(world, n)
            bare = pile_space(n, config)
            for _ in range(settle_steps):
                world.step()
                bare.step(config.dt)
            us, bare_us, ratio, best = _time_blocks(world, bare, repeats)
            stages = _stage_means(world, max(3, min(50, round(0.02 / (us * 1e-6)))))
            at_n.append(
                OverheadRow(
                    bodies=n,
                    effect=effect,
                    us_per_step=us,
                    bare_us=bare_us,
                    ratio=ratio,
                    best_ratio=best,
                    marginal_us=math.nan,
                    events_us=stages[Stage.EVENTS],
                    gravity_us=stages[Stage.GRAVITY],
                    movers_us=stages[Stage.MOVERS],
                    control_us=stages[Stage.CONTROL],
                    physics_us=stages[Stage.PHYSICS],
                    forces_us=stages[Stage.FORCES],
                    filter_us=stages[Stage.FILTER],
                )
            )
        bare_ref = statistics.median(r.bare_us for r in at_n)
        none = next((r.ratio for r in at_n if r.effect == "none"), math.nan)
        rows += [
            replace(
                r,
                bare_us=bare_ref,
                us_per_step=r.ratio * bare_ref,
                marginal_us=(r.ratio - none) * bare_ref,
            )
            for r in at_n
        ]
    if bar is not None:
        bar.close()
    return rows


def _bar(total: int) -> Any:
    """A tqdm bar on stderr, shown only when stderr is a terminal (``disable=None``)."""
    from tqdm import tqdm

    return tqdm(total=total, unit="point", desc="overhead", leave=False, disable=None)


def fixed_cost(repeats: int = 9, steps: int = 2000) -> tuple[float, float]:
    """(world, bare pymunk) µs per step for a scene with nothing but a static floor: the fixed
    Python cost of the world's step, medians over interleaved blocks."""
    config = WorldConfig()
    world = pile_world(0, config)
    bare = pile_space(0, config)
    t = interleave(world.step, lambda: bare.step(config.dt), repeats=repeats, steps=steps)
    return 1e6 * t.a_median, 1e6 * t.b_median


def overhead_markdown(rows: Sequence[OverheadRow]) -> str:
    """Three tables: µs per step (× bare), marginal µs per effect, stages at the largest size."""
    sizes = sorted({r.bodies for r in rows})
    effects = list(dict.fromkeys(r.effect for r in rows))
    at = {(r.bodies, r.effect): r for r in rows}
    bare = [
        "bare pymunk",
        *(f"{statistics.median(r.bare_us for r in rows if r.bodies == n):.0f}" for n in sizes),
    ]
    total = [
        [
            e,
            *(
                f"{at[n, e].us_per_step:.0f} (×{at[n, e].ratio:.2f}, "
                f"best ×{at[n, e].best_ratio:.2f})"
                for n in sizes
            ),
        ]
        for e in effects
    ]
    marginal = [
        [e, *(f"{at[n, e].marginal_us:+.0f}" for n in sizes)] for e in effects if e != "none"
    ]
    big = sizes[-1]
    stage_names = ("events", "gravity", "movers", "control", "physics", "forces", "filter")
    stages = [[e, *(f"{getattr(at[big, e], s + '_us'):.0f}" for s in stage_names)] for e in effects]
    header = ["effect", *(f"{n} bodies" for n in sizes)]
    return (
        "### µs per step (× bare pymunk: median of paired blocks, and fastest / fastest)\n\n"
        + table(header, [bare, *total])
        + "\n\n### Marginal µs per step of each effect (against no effect)\n\n"
        + table(header, marginal)
        + f"\n\n### Mean µs per step of each stage at {big} bodies\n\n"
        + table(["effect", *stage_names], stages)
        + "\n"
    )


def overhead_figure(rows: Sequence[OverheadRow], path: Path) -> None:
    """Marginal cost of each effect (and the no-effect ratio) against bodies, into ``path``.

    Needs matplotlib (``pip install 'pymunk-playground[bench]'``).
    """
    plt = pyplot()
    sizes = sorted({r.bodies for r in rows})
    effects = list(dict.fromkeys(r.effect for r in rows))
    at = {(r.bodies, r.effect): r for r in rows}
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 5))
    for e in effects:
        if e == "none":
            continue
        ys = [max(at[n, e].marginal_us, 0.1) for n in sizes]
        a.plot(sizes, ys, "-o", ms=3, label=e)
    log_axes(a, "bodies", "marginal µs per step", "Cost of each effect")
    a.legend(fontsize=7)
    b.plot(sizes, [at[n, "none"].ratio for n in sizes], "-o", label="no effect / bare pymunk")
    b.axhline(NO_EFFECT_BUDGET, color="red", ls="--", lw=0.8, label=f"{NO_EFFECT_BUDGET}× budget")
    b.set(xscale="log", xlabel="bodies", ylabel="× bare pymunk", title="World with no effect")
    b.legend(fontsize=8)
    save(fig, path)
