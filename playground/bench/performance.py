"""What a step costs against the engine: every shipped level, the pile, and the goals they meet.

Every figure is a ratio of interleaved blocks in one process (:mod:`playground.bench.blocks`), so
it holds on a loaded machine where absolute microseconds move by 2×:

- **levels**: a shipped level's ``World.step`` against ``space.step`` of the same scene (a copy of
  its space taken before each bare block, so both run the same bodies and contacts), the real-time
  factor at the level's dt, and the mean µs of each stage (``World.timings``);
- **piles**: every box of a settled pile tracked and perceived (solver + 1€) against bare
  ``space.step`` of the same space; a per-body gravity field against uniform gravity; a world
  with no effect against a bare space holding the same pile.

:func:`measure` runs them all and judges :data:`GOALS`; :func:`performance_doc` writes the page.

>>> m = measure(levels=("rest",), sizes=(10,), field_bodies=10, crossover=(1,), repeats=1)
>>> [g.key for g in m.goals][:2]
['one_player_us', 'one_player_rt']
"""

from __future__ import annotations

import math
import os
import platform
import statistics
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, replace
from datetime import UTC, datetime
from typing import Any

import numpy as np
import pymunk

from playground.bench.blocks import Blocks, interleave
from playground.bench.pile import floor_length, pile_names, pile_space, pile_world
from playground.gravity import Radial
from playground.perception import Perception
from playground.scalar.path import SCALAR_MAX_BODIES
from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "GOALS",
    "Goal",
    "GoalResult",
    "LevelRow",
    "Measurement",
    "PileRow",
    "from_dict",
    "level_row",
    "measure",
    "performance_doc",
    "summary_markdown",
]

PILE_SIZES = (10, 100, 1000, 3000)
"""Pile sizes measured by default (the goals quote 10, 1000 and 3000)."""

CROSSOVER_SIZES = (1, 2, 4, 8, 12, 16, 20, 24, 32, 48)
"""Tracked bodies at which the scalar path is timed against the vectorised one."""

FIELD_BODIES = 1000
"""Boxes in the pile on which a per-body gravity field is timed against uniform gravity."""

REPEATS = 21
"""Interleaved blocks per measurement (the figure is their median pair ratio)."""

SETTLE_STEPS = 30
"""Steps a pile or a level runs before it is timed (first readings, filter state, buffers)."""

STAGE_STEPS = 200
"""Steps timed stage by stage after the blocks (``World.timings``; timing costs ~0.2 µs a
stage)."""

_STAGES = (Stage.INPUTS, Stage.EVENTS, Stage.GRAVITY, Stage.MOVERS, Stage.CONTROL, Stage.PHYSICS,
           Stage.FORCES, Stage.FILTER, Stage.OBSERVE)  # fmt: skip


@dataclass(frozen=True, slots=True)
class LevelRow:
    """One shipped level.

    Attributes:
        level: its name.  dt: its step, s.  players: controllers it runs.
        level_us: ``World.step``, µs (ratio × engine_us).  engine_us: its space's bare steps, µs.
        ratio: level / engine, median of paired blocks.  ratio_lo, ratio_hi: their spread.
        realtime: dt / level step: simulated seconds per wall second.
        stages: median µs of each stage over the steps it ran in, by lower-case stage name.
        scalar: its tracked bodies are served by the scalar path (plain floats), not numpy.
    """

    level: str
    dt: float
    players: int
    level_us: float
    engine_us: float
    ratio: float
    ratio_lo: float
    ratio_hi: float
    realtime: float
    stages: dict[str, float]
    scalar: bool


@dataclass(frozen=True, slots=True)
class PileRow:
    """One measurement on the pile.

    Attributes:
        kind: ``solver+1€`` (every box tracked and perceived against bare steps of the same
            space), ``field`` (a per-body radial field against uniform gravity), ``no effect``
            (a world against a bare space holding the same pile) or ``scalar/vector`` (the
            scalar path against the vectorised one, every box tracked and perceived).
        bodies: boxes.  us: the measured side, µs per step.  base_us: what it is compared with.
        ratio: us / base_us, median of paired blocks.  ratio_lo, ratio_hi: their spread.
        overhead: ratio − 1.
    """

    kind: str
    bodies: int
    us: float
    base_us: float
    ratio: float
    ratio_lo: float
    ratio_hi: float
    overhead: float


@dataclass(frozen=True, slots=True)
class Goal:
    """A goal of the performance issue: ``measured(levels, piles) <op> target``.

    Attributes:
        key: short identifier.  measure: what is measured.  text: the goal as written.
        target: the bound.  at_most: the measured value must be ≤ target (else ≥).
        unit: of the value.  why: why it is missed when it is (what the time is spent on).
    """

    key: str
    measure: str
    text: str
    target: float
    at_most: bool
    unit: str
    why: str


@dataclass(frozen=True, slots=True)
class GoalResult:
    """A goal against its measurement: ``value`` the worst case over what the goal covers,
    ``detail`` the measured range in words, ``off_by`` value / target (≥ 1 means as far off)."""

    key: str
    measure: str
    goal: str
    value: float
    detail: str
    met: bool
    off_by: float
    why: str


@dataclass(frozen=True, slots=True)
class Measurement:
    """One run of :func:`measure`: the machine, the rows and the goals judged on them."""

    machine: dict[str, str]
    command: str
    repeats: int
    levels: tuple[LevelRow, ...]
    piles: tuple[PileRow, ...]
    goals: tuple[GoalResult, ...]

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON-ready values (NaN as None)."""
        out: dict[str, Any] = _clean(asdict(self))
        return out


def from_dict(data: dict[str, Any], source: str = "<data>") -> Measurement:
    """A :class:`Measurement` back from :meth:`Measurement.to_dict` (the JSON of ``bench overhead
    --json``; other keys are ignored). ``ValueError`` names ``source`` and the missing key."""

    def num(v: Any) -> float:
        return math.nan if v is None else float(v)

    try:
        levels = tuple(
            LevelRow(
                level=str(r["level"]),
                dt=num(r["dt"]),
                players=int(r["players"]),
                level_us=num(r["level_us"]),
                engine_us=num(r["engine_us"]),
                ratio=num(r["ratio"]),
                ratio_lo=num(r["ratio_lo"]),
                ratio_hi=num(r["ratio_hi"]),
                realtime=num(r["realtime"]),
                stages={str(k): num(v) for k, v in r["stages"].items()},
                scalar=bool(r["scalar"]),
            )
            for r in data["levels"]
        )
        piles = tuple(PileRow(**r) for r in data["piles"])
        return Measurement(
            machine=dict(data["machine"]),
            command=str(data["command"]),
            repeats=int(data["repeats"]),
            levels=levels,
            piles=piles,
            goals=judge(levels, piles),
        )
    except KeyError as exc:
        raise ValueError(
            f"{source}: expected the key {exc} (the output of bench overhead --json)"
        ) from None
    except (TypeError, AttributeError, ValueError) as exc:
        raise ValueError(f"{source}: not the output of bench overhead --json ({exc})") from None


def _clean(v: Any) -> Any:
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, dict):
        return {k: _clean(x) for k, x in v.items()}
    if isinstance(v, list | tuple):
        return [_clean(x) for x in v]
    return v


# -- levels ----------------------------------------------------------------------------------


def _stage_medians(world: World, steps: int) -> dict[str, float]:
    """Median µs of each stage over the ``steps`` steps (timing on) in which it ran.

    Medians of single steps, not means: on a loaded machine a step the scheduler interrupts
    counts once, not in proportion to how long another process held the core.
    """
    world.config = replace(world.config, timing=True)
    samples: dict[Stage, list[float]] = {s: [] for s in _STAGES}
    for _ in range(steps):
        calls = [world.timings[s].calls for s in _STAGES]
        world.step()
        for s, before in zip(_STAGES, calls, strict=True):
            if world.timings[s].calls != before:
                samples[s].append(world.timings[s].last)
    world.config = replace(world.config, timing=False)
    return {s.name.lower(): 1e6 * statistics.median(v) for s, v in samples.items() if v}


def level_row(name: str, repeats: int = REPEATS) -> LevelRow:
    """Time the shipped level ``name`` against its engine (see the module docstring)."""
    from playground.level.files import find
    from playground.level.loading import load
    from playground.scene import build

    scene = build(load(find(name)))
    world = scene.world
    for _ in range(SETTLE_STEPS):
        world.step()
    copy: list[pymunk.Space] = [world.space.copy()]
    engine = _engine_step_of(copy, world.config)

    def fresh_copy() -> None:
        # The bare side steps a copy of the level's space as it is now: the same bodies, shapes,
        # joints and contacts, without the controllers that would keep it where the level is.
        copy[0] = world.space.copy()

    t = interleave(world.step, engine, repeats=repeats, prepare_b=fresh_copy)
    stages = _stage_medians(world, STAGE_STEPS)
    engine_us = 1e6 * t.b_median
    level_us = t.ratio * engine_us
    lo, hi = t.spread
    return LevelRow(
        level=name,
        dt=world.config.dt,
        players=len(scene.controllers),
        level_us=level_us,
        engine_us=engine_us,
        ratio=t.ratio,
        ratio_lo=lo,
        ratio_hi=hi,
        realtime=world.config.dt / (level_us * 1e-6),
        stages=stages,
        scalar=world.on_scalar_path,
    )


def _engine_step_of(holder: list[pymunk.Space], config: WorldConfig) -> Callable[[], None]:
    h = config.dt / config.substeps
    n = config.substeps

    def step() -> None:
        space = holder[0]
        for _ in range(n):
            space.step(h)

    return step


# -- piles -----------------------------------------------------------------------------------


def _settle(*steps: Callable[[], object]) -> None:
    for _ in range(SETTLE_STEPS):
        for step in steps:
            step()


def _pile_row(kind: str, n: int, t: Blocks) -> PileRow:
    lo, hi = t.spread
    base = 1e6 * t.b_median
    return PileRow(kind, n, t.ratio * base, base, t.ratio, lo, hi, t.ratio - 1.0)


def solver_row(n: int, repeats: int = REPEATS) -> PileRow:
    """Every box tracked and perceived (1€ alone, the goals' configuration) against bare steps
    of the same space."""
    world = pile_world(n, WorldConfig(perception=Perception(spike_filter=False)))
    world.track(*pile_names(n))
    space, dt = world.space, world.config.dt
    _settle(world.step)
    return _pile_row(
        "solver+1€", n, interleave(world.step, lambda: space.step(dt), repeats=repeats)
    )


def crossover_row(n: int, repeats: int = REPEATS) -> PileRow:
    """The scalar path against the vectorised one, every box tracked and perceived (the default
    perception): where the ratio passes 1 is where the world should switch."""
    worlds = []
    for most in (n, 0):
        world = pile_world(n, WorldConfig())
        world.scalar_max_bodies = most
        world.track(*pile_names(n))
        worlds.append(world)
    _settle(worlds[0].step, worlds[1].step)
    return _pile_row(
        "scalar/vector", n, interleave(worlds[0].step, worlds[1].step, repeats=repeats)
    )


def field_row(n: int, repeats: int = REPEATS) -> PileRow:
    """A per-body radial field against uniform ``space.gravity``, on two untracked piles. The
    planet is so large that its surface is flat under the pile (tilt < 0.2° at its ends): the
    same physics."""
    middle = floor_length(n) / 2.0
    far = 1e5
    radial = Radial(center=(middle, -far), surface_gravity=9.81, radius=far, softening=0.0)
    field = pile_world(n, WorldConfig(), gravity=radial)
    uniform = pile_world(n, WorldConfig())
    _settle(field.step, uniform.step)
    return _pile_row("field", n, interleave(field.step, uniform.step, repeats=repeats))


def no_effect_row(n: int, repeats: int = REPEATS) -> PileRow:
    """A world that uses no effect against a bare space holding the same pile."""
    config = WorldConfig()
    world = pile_world(n, config)
    bare = pile_space(n, config)
    _settle(world.step, lambda: bare.step(config.dt))
    return _pile_row(
        "no effect", n, interleave(world.step, lambda: bare.step(config.dt), repeats=repeats)
    )


# -- goals -----------------------------------------------------------------------------------

GOALS = (
    Goal(
        "one_player_us",
        "one-player level step",
        "≤ 25 µs",
        25.0,
        True,
        "µs",
        "Python cost per step, not physics: {stages}. The controller is most of it (its step in "
        "plain floats is not done yet). {vector} keep the vectorised solver (the scalar path "
        "splits no contacts and writes no per-body field), whose physics, forces and filter "
        "stages are a few dozen numpy calls (about 1 µs each) and batch calls (about 5 µs).",
    ),
    Goal(
        "one_player_rt",
        "one-player level, real-time factor",
        "≥ 300× at dt = 1/120 s",
        300.0,
        False,
        "×",
        "The same fixed cost per step as the row above.",
    ),
    Goal(
        "every_level_rt",
        "every shipped level, real-time factor",
        "≥ 200×",
        200.0,
        False,
        "×",
        "The same fixed cost per step: the engine's own step is {engine} of the level's (see "
        "the levels table).",
    ),
    Goal(
        "controller_us",
        "controller, per actor per step",
        "≤ 10 µs",
        10.0,
        True,
        "µs",
        "The controller senses with shape queries, reads its body's state attribute by "
        "attribute through cffi (about 0.3–1 µs each) and writes its forces and their reactions "
        "through the ledger; `playground run LEVEL --profile` lists its functions.",
    ),
    Goal(
        "pile_10",
        "pile, solver + 1€ on every body, N = 10 (overhead / bare)",
        "≤ 3×",
        3.0,
        True,
        "×",
        "Ten tracked bodies are on the scalar path: {per_body} µs of Python per body per step "
        "(attribute reads through cffi before and after the step, reverse integration, "
        "median-of-3 and 1€ in floats), against {bare_per_body} µs per box for the bare step.",
    ),
    Goal(
        "pile_large",
        "same, N = 1000 and 3000 (overhead / bare)",
        "≤ 0.10×",
        0.10,
        True,
        "×",
        "The two batch reads per step iterate every body in Chipmunk, and the 1€ filter and the "
        "perceived-gravity magnitude and direction are a dozen numpy passes over the rows.",
    ),
    Goal(
        "field_1000",
        "per-body gravity field, N = 1000 (× uniform)",
        "≤ 1.05×",
        1.05,
        True,
        "×",
        "A per-body field reads every position (one batch read), evaluates the field and writes "
        "every force (one batch write): two passes over all bodies that uniform gravity does in "
        "Chipmunk's own loop.",
    ),
    Goal(
        "no_effect",
        "scene with no effect (× bare)",
        "≤ 1.05×",
        1.05,
        True,
        "×",
        "`World.step`'s own Python around the bare `space.step` (the plan check, the step count "
        "and time, the guard's countdown) is about 1 µs: a seventh of a bare step of ten boxes, "
        "lost in the noise at 1000.",
    ),
)
"""The goals of the performance issue, in the order of its table."""


def _range(values: Sequence[float], fmt: str) -> str:
    lo, hi = min(values), max(values)
    return (
        fmt.format(lo)
        if math.isclose(lo, hi, rel_tol=0.005)
        else f"{fmt.format(lo)}–{fmt.format(hi)}"
    )


def _where(levels: Sequence[LevelRow]) -> str:
    """The median µs of each stage over ``levels``, largest first, with the engine's."""
    names = sorted({s for r in levels for s in r.stages})
    med = {s: statistics.median(r.stages.get(s, 0.0) for r in levels) for s in names}
    parts = [f"{s} {v:.0f} µs" for s, v in sorted(med.items(), key=lambda kv: -kv[1]) if v >= 1]
    engine = statistics.median(r.engine_us for r in levels) if levels else math.nan
    return "median stages " + ", ".join(parts) + f"; the engine's step {engine:.1f} µs"


def _facts(
    one: Sequence[LevelRow], levels: Sequence[LevelRow], solver: dict[int, PileRow]
) -> dict[str, str]:
    """The measured facts the goals' explanations quote."""
    vector = [r.level for r in levels if not r.scalar and r.players]
    small = solver.get(10)
    return {
        "stages": _where(one),
        "engine": _engine_share(levels),
        "vector": ("Levels " + ", ".join(vector)) if vector else "No level",
        "per_body": f"{(small.us - small.base_us) / 10:.1f}" if small else "?",
        "bare_per_body": f"{small.base_us / 10:.1f}" if small else "?",
    }


def _engine_share(levels: Sequence[LevelRow]) -> str:
    """The range of engine / level step over ``levels``, as percentages."""
    shares = [100.0 / r.ratio for r in levels]
    return f"{_range(shares, '{:.0f}')} %" if shares else "n/a"


def judge(levels: Sequence[LevelRow], piles: Sequence[PileRow]) -> tuple[GoalResult, ...]:
    """Each of :data:`GOALS` against the rows (a goal whose rows were not measured is left out)."""
    one = [r for r in levels if r.players == 1]
    actors = [r for r in levels if r.players >= 1 and "control" in r.stages]
    solver = {r.bodies: r for r in piles if r.kind == "solver+1€"}
    fields = [r for r in piles if r.kind == "field"]
    none = [r for r in piles if r.kind == "no effect"]
    found: dict[str, tuple[float, str]] = {}
    if one:
        us = [r.level_us for r in one]
        rt = [r.realtime for r in one]
        found["one_player_us"] = (max(us), f"{_range(us, '{:.0f}')} µs over {len(one)} levels")
        found["one_player_rt"] = (min(rt), f"{_range(rt, '{:.0f}')}×")
    if levels:
        rt = [r.realtime for r in levels]
        found["every_level_rt"] = (min(rt), f"{_range(rt, '{:.0f}')}× over {len(levels)} levels")
    if actors:
        per = [r.stages["control"] / r.players for r in actors]
        found["controller_us"] = (max(per), f"{_range(per, '{:.1f}')} µs")
    if 10 in solver:
        r = solver[10]
        found["pile_10"] = (
            r.overhead,
            f"{r.overhead:.1f}× (blocks {r.ratio_lo - 1:.1f}–{r.ratio_hi - 1:.1f}×)",
        )
    big = [solver[n] for n in sorted(solver) if n >= 1000]
    if big:
        found["pile_large"] = (
            max(r.overhead for r in big),
            ", ".join(f"{r.overhead:.2f}× (N = {r.bodies})" for r in big),
        )
    if fields:
        r = max(fields, key=lambda x: x.bodies)
        found["field_1000"] = (
            r.ratio,
            f"{r.ratio:.2f}× (N = {r.bodies}, blocks {r.ratio_lo:.2f}–{r.ratio_hi:.2f})",
        )
    if none:
        rs = [r.ratio for r in none]
        found["no_effect"] = (
            max(rs),
            ", ".join(f"{r.ratio:.2f}× (N = {r.bodies})" for r in none),
        )
    out = []
    for g in GOALS:
        if g.key not in found:
            continue
        value, detail = found[g.key]
        met = value <= g.target if g.at_most else value >= g.target
        off = value / g.target if g.at_most else g.target / value
        why = "" if met else g.why.format(**_facts(one, levels, solver))
        out.append(GoalResult(g.key, g.measure, g.text, value, detail, met, off, why))
    return tuple(out)


def machine() -> dict[str, str]:
    """What the numbers were measured on: CPU, cores, load, versions."""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = os.getloadavg() if hasattr(os, "getloadavg") else (math.nan,) * 3
    return {
        "cpu": model,
        "cores": str(os.cpu_count()),
        "load": " ".join(f"{x:.1f}" for x in load),
        "python": platform.python_version(),
        "pymunk": pymunk.version,
        "numpy": np.__version__,
        "date": datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC"),
    }


def measure(
    levels: Sequence[str] | None = None,
    sizes: Sequence[int] = PILE_SIZES,
    *,
    field_bodies: int = FIELD_BODIES,
    crossover: Sequence[int] = CROSSOVER_SIZES,
    repeats: int = REPEATS,
    progress: bool = False,
    command: str = "playground bench overhead --json",
) -> Measurement:
    """Time every shipped level (or ``levels``) and the piles of ``sizes``; judge the goals.

    ``progress`` shows a bar on stderr when it is a terminal (tqdm).
    """
    from playground.level.files import shipped

    names = sorted(shipped()) if levels is None else list(levels)
    jobs: list[Callable[[], LevelRow | PileRow]] = [
        *(lambda n=n: level_row(n, repeats) for n in names),
        *(lambda n=n: solver_row(n, repeats) for n in sizes),
        lambda: field_row(field_bodies, repeats),
        *(lambda n=n: no_effect_row(n, repeats) for n in sorted({min(sizes), field_bodies})),
        *(lambda n=n: crossover_row(n, repeats) for n in crossover),
    ]
    bar = _bar(len(jobs)) if progress else None
    rows = []
    for job in jobs:
        rows.append(job())
        if bar is not None:
            bar.update(1)
    if bar is not None:
        bar.close()
    level_rows = tuple(r for r in rows if isinstance(r, LevelRow))
    pile_rows = tuple(r for r in rows if isinstance(r, PileRow))
    return Measurement(
        machine=machine(),
        command=command,
        repeats=repeats,
        levels=level_rows,
        piles=pile_rows,
        goals=judge(level_rows, pile_rows),
    )


def _bar(total: int) -> Any:
    """A tqdm bar on stderr, shown only when stderr is a terminal (``disable=None``)."""
    from tqdm import tqdm

    return tqdm(total=total, unit="row", desc="performance", leave=False, disable=None)


# -- the page --------------------------------------------------------------------------------


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def goals_markdown(goals: Sequence[GoalResult]) -> str:
    """The goals table: measure, goal, measured, met, and by how much and why when missed."""
    rows = []
    for g in goals:
        verdict = "met" if g.met else f"missed by {g.off_by:.1f}×"
        rows.append([g.measure, g.goal, g.detail, verdict, g.why])
    return _table(["measure", "goal", "measured", "met?", "why it is missed"], rows)


def levels_markdown(levels: Sequence[LevelRow]) -> str:
    """One row per level: step, engine, ratio, real-time factor and the stages."""
    names = [s.name.lower() for s in _STAGES]
    used = [s for s in names if any(s in r.stages for r in levels)]
    rows = [
        [
            r.level,
            str(r.players),
            "scalar" if r.scalar else "vector",
            f"{r.level_us:.0f}",
            f"{r.engine_us:.1f}",
            f"{r.ratio:.0f}× ({r.ratio_lo:.0f}–{r.ratio_hi:.0f})",
            f"{r.realtime:.0f}×",
            *(f"{r.stages[s]:.1f}" if s in r.stages else "" for s in used),
        ]
        for r in levels
    ]
    header = ["level", "players", "path", "step µs", "engine µs", "× engine (blocks)",
              "× real time", *(f"{s} µs" for s in used)]  # fmt: skip
    return _table(header, rows)


def piles_markdown(piles: Sequence[PileRow]) -> str:
    """One row per pile measurement."""
    rows = [
        [
            r.kind,
            str(r.bodies),
            f"{r.us:.0f}",
            f"{r.base_us:.0f}",
            f"{r.ratio:.3f}× ({r.ratio_lo:.3f}–{r.ratio_hi:.3f})",
            f"{r.overhead:.3f}×",
        ]
        for r in piles
    ]
    return _table(["measure", "N", "µs", "compared with, µs", "ratio (blocks)", "overhead"], rows)


def crossover_markdown(piles: Sequence[PileRow]) -> str:
    """Where the scalar path stops paying: the measured ratios and the crossover they give."""
    rows = sorted((r for r in piles if r.kind == "scalar/vector"), key=lambda r: r.bodies)
    if not rows:
        return ""
    below = [r.bodies for r in rows if r.ratio < 1.0]
    above = [r.bodies for r in rows if r.ratio >= 1.0]
    cross = (
        f"the scalar path is cheaper up to {max(below)} tracked bodies"
        + (f" and dearer from {min(above)}" if above else "")
        if below
        else "the scalar path is never cheaper"
    )
    return (
        "## Two paths: where the scalar one stops paying\n\n"
        "With few tracked bodies the solver and the filter run in plain floats, reading each "
        "body's attributes (`playground/scalar.py`); with many, on numpy arrays filled by "
        "`pymunk.batch`. "
        "Both give the same readings (tests/test_solver_oracle.py compares them step by step on "
        "random scenes). Measured here on the pile with every box tracked and perceived, scalar "
        f"step / vectorised step: {cross}. The world switches at "
        f"`SCALAR_MAX_BODIES` = {SCALAR_MAX_BODIES} tracked bodies.\n\n"
        + _table(
            ["tracked bodies", "scalar µs", "vectorised µs", "scalar / vectorised (blocks)"],
            [
                [
                    str(r.bodies),
                    f"{r.us:.0f}",
                    f"{r.base_us:.0f}",
                    f"{r.ratio:.2f}× ({r.ratio_lo:.2f}–{r.ratio_hi:.2f})",
                ]
                for r in rows
            ],
        )
        + "\n"
    )


def summary_markdown(m: Measurement) -> str:
    """The goals, levels, pile and crossover tables under headings."""
    piles = [r for r in m.piles if r.kind != "scalar/vector"]
    cross = crossover_markdown(m.piles)
    return (
        f"## The goals\n\n{goals_markdown(m.goals)}\n\n"
        f"## Every shipped level\n\n{levels_markdown(m.levels)}\n\n"
        f"## The pile\n\n{piles_markdown(piles)}\n" + (f"\n{cross}" if cross else "")
    )


def performance_doc(m: Measurement) -> str:
    """docs/performance.md, generated from one measurement."""
    mc = m.machine
    return f"""# What a step costs

<!-- Generated by `playground bench performance` from one run of `{m.command}`; do not edit. -->

This page is generated: every number below comes from one run of

    {m.command} > perf.json
    playground bench performance --from perf.json     # writes this page

(or `playground bench performance` alone, which measures and writes in one go).

## How it is measured, and how far to trust it

Measured on {mc["cpu"]}, {mc["cores"]} cores, load average {mc["load"]} when the run ended;
Python {mc["python"]}, pymunk {mc["pymunk"]}, numpy {mc["numpy"]}; {mc["date"]}.

The machine is shared by several engineers running test suites (load around 7 on 2 cores is
usual), so absolute microseconds move by up to 2× between runs and even between blocks. **The
ratios are the measure**: each one compares two things timed in alternating blocks in the same
process ({m.repeats} blocks of each, about 5 ms a block), so a burst of load slows both sides
alike; blocks are timed in CPU time of the benchmark's thread (`time.thread_time`), so the time
the scheduler gives other processes is not counted, while their contention for caches and memory
is. The figure is the median of the ratios of adjacent blocks, and the range in brackets is the
lowest and highest of those ratios. Microseconds are quoted as ratio × the engine's median, for
orientation only.

- **Levels**: the level's `World.step` against `space.step` of the same scene: before each bare
  block the level's space is copied as it is at that moment, so both sides step the same bodies,
  contacts and joints. "× real time" is dt divided by the level's step. The stage columns are the
  median µs of each stage from `World.timings` over {STAGE_STEPS} steps with timing on (wall
  time of single steps: the median leaves out the steps another process interrupted).
- **Piles**: columns of 0.5 m boxes resting on a floor. "solver+1€": every box tracked and
  perceived (reverse integration and the 1€ filter without the median-of-3 stage) against bare
  steps of the same space. "field": a per-body radial field whose centre is 10⁵ m below (flat
  under the pile to 0.2°, so the same physics) against uniform `space.gravity`. "no effect": a world
  using no effect against a bare space holding the same pile.

{summary_markdown(m)}"""
