"""The goals of the performance issue and their verdicts: :data:`GOALS` in the order of its table,
and :func:`judge`, which takes each goal's worst case over the rows it covers and, where a goal is
missed, says by how much and why, quoting the measured facts (the stages the time goes to, the
engine's share, the levels served by the batch implementation, the per-body cost on the pile).
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass

from playground.bench.measurement import CrowdRow, LevelRow, PileRow

__all__ = ["GOALS", "Goal", "GoalResult", "judge"]


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


GOALS = (
    Goal(
        "one_player_us",
        "one-player level step",
        "≤ 25 µs",
        25.0,
        True,
        "µs",
        "Python cost per step, not physics: {stages}. {vector}. The controller is most of "
        "what is left (see its row); `playground run LEVEL --profile` lists its functions.",
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
        "Python calls, not pymunk: the controller reads its body and its ground through "
        "Chipmunk's C getters, probes through one C callback and writes its own forces and "
        "torque in one checked call (their reactions on a dynamic ground in one more), but a "
        "step still makes some 40 Python calls and 40 C calls "
        "(on `rest`, in the running loop: nearly half sensing, the probe about a quarter, "
        "nearly half the force laws and their writes); hover, drive, balance, push and the "
        "gravity switches "
        "stay methods of their own (the break catalogue patches them by name). "
        "`playground run LEVEL --profile` lists its functions.",
    ),
    Goal(
        "pile_10",
        "pile, solver + 1€ on every body, N = 10 (overhead / bare)",
        "≤ 3×",
        3.0,
        True,
        "×",
        "Ten tracked bodies are served in plain floats (the scalar implementation): "
        "{per_body} µs of Python per body per step "
        "(four Chipmunk getters through cffi before the step and two after it, about 0.1 µs "
        "each, then reverse integration and the 1€ filter in floats), against {bare_per_body} "
        "µs per box for the bare step.",
    ),
    Goal(
        "pile_large",
        "same, N = 1000 and 3000 (overhead / bare)",
        "≤ 0.10×",
        0.10,
        True,
        "×",
        "Chipmunk's two batch loops alone (every body's state read before the step, its "
        "velocities after it) cost 0.04–0.05 of the bare step at N = 1000 and 3000, timed where "
        "the world step runs them; the rest is about 35 numpy passes over the rows (gathers into "
        "tracked order, reverse integration, the 1€ filter's ten operations, the perceived "
        "gravity's magnitude and direction), on rows the engine's step has just pushed out of "
        "the cache (they cost 1.3–2× what they cost warm). Fewer passes would mean other float "
        "operations, and other readings.",
    ),
    Goal(
        "split_10",
        "pile, contact split on every body, N = 10 (overhead / bare)",
        "≤ 4×",
        4.0,
        True,
        "×",
        "Below 28 tracked bodies the split is the scalar implementation's: every arbiter of "
        "the space read in one batch walk, each tracked body's impulses summed in one C call "
        "(plain Python floats without the compiled helper), then its contact, normal and "
        "constraint forces in Python floats, body by body, on top of the solver's and the "
        "filter's; the bare step of ten boxes is a few microseconds, so each Python operation "
        "a body counts.",
    ),
    Goal(
        "split_1000",
        "same, N = 1000 (overhead / bare)",
        "≤ 0.5×",
        0.5,
        True,
        "×",
        "The split's batch read of every arbiter and its numpy sums come on top of the solver "
        "and filter rows above; a change of the arbiters' ids remakes the plan of which row "
        "each arbiter's impulse goes to.",
    ),
    Goal(
        "field_1000",
        "per-body gravity field, N = 1000 (× uniform)",
        "≤ 1.05×",
        1.05,
        True,
        "×",
        "A per-body field reads every position and force (one batch read) and writes every "
        "force (one batch write, through Chipmunk's setter, which also resets the idle clock of "
        "the body and of every body it touches, walking its contacts): those two loops alone "
        "cost 0.05–0.07 of the uniform step at N = 1000 and 3000, timed where the world step "
        "runs them, more than the goal allows. The engine's own step is the same on both piles "
        "(within 5 %); the field's evaluation is 10–15 µs at N = 1000.",
    ),
    Goal(
        "crowd_per_actor",
        "crowd of 100 and of 200 patrolling actors, per actor per step",
        "≤ 4 µs",
        4.0,
        True,
        "µs",
        "Numpy calls over the actors, each about as dear at 100 rows as at 10, so the cost per "
        "actor falls with the crowd's size (the 200 row meets it). At 100 actors a step is "
        "about 3.7 M instructions (`benchmarks/step_instructions.py --actors 100`); measured "
        "per function before the last 8 % came off: the laws of `controller/crowd/acting.py` "
        "(hover, drive, balance) about 0.8 M, the lean of the members leaning past max_lean "
        "(about 70 of the 100 each step while the patrols turn) 0.6–0.7 M, the tread-ahead "
        "test of `crowd/step_up.py` with its rays 0.44 M, the probes 0.25 M (nearly all "
        "Chipmunk's query, all actors in one call of `_engine/_nearest.c`); around the "
        "controller the solver's, the ledger's and the filter's rows about 0.8 M. Timed in "
        "the crowd's steady state, its patrols turning (`playground/bench/crowd.py`, SETTLE).",
    ),
    Goal(
        "crowd_engine",
        "crowd of 200 patrolling actors (× engine)",
        "≤ 15×",
        15.0,
        True,
        "×",
        "The same costs as the row above, against an engine step that only moves 200 "
        "floating capsules and their floor.",
    ),
    Goal(
        "crowd_rt",
        "crowd of 200 patrolling actors, real-time factor",
        "≥ 10× at dt = 1/120 s",
        10.0,
        False,
        "×",
        "The same costs as the rows above.",
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
        "vector": (
            "Levels " + ", ".join(vector) + " keep the vectorised solver (numpy and batch calls)"
            if vector
            else "Every one-player level is served by the scalar implementation "
            "(plain floats, no numpy)"
        ),
        "per_body": f"{(small.us - small.base_us) / 10:.1f}" if small else "?",
        "bare_per_body": f"{small.base_us / 10:.1f}" if small else "?",
    }


def _engine_share(levels: Sequence[LevelRow]) -> str:
    """The range of engine / level step over ``levels``, as percentages."""
    shares = [100.0 / r.ratio for r in levels]
    return f"{_range(shares, '{:.0f}')} %" if shares else "n/a"


def judge(
    levels: Sequence[LevelRow], piles: Sequence[PileRow], crowds: Sequence[CrowdRow] = ()
) -> tuple[GoalResult, ...]:
    """Each of :data:`GOALS` against the rows (a goal whose rows were not measured is left out:
    a quick run measures no crowd of 100 or 200 actors)."""
    one = [r for r in levels if r.players == 1]
    actors = [r for r in levels if r.players >= 1 and "control" in r.stages]
    solver = {r.bodies: r for r in piles if r.kind == "solver+1€"}
    split = {r.bodies: r for r in piles if r.kind == "split on"}
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
    for n, key in ((10, "split_10"), (1000, "split_1000")):
        if n in split:
            r = split[n]
            found[key] = (
                r.overhead,
                f"{r.overhead:.2f}× (blocks {r.ratio_lo - 1:.2f}–{r.ratio_hi - 1:.2f}×)",
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
    big_crowds = [r for r in crowds if r.actors in (100, 200)]
    if big_crowds:
        per = [c.per_actor_us for c in big_crowds]
        found["crowd_per_actor"] = (
            max(per),
            ", ".join(f"{c.per_actor_us:.1f} µs ({c.actors} actors)" for c in big_crowds),
        )
    for c in crowds:
        if c.actors == 200:
            found["crowd_engine"] = (
                c.ratio,
                f"{c.ratio:.1f}× (blocks {c.ratio_lo:.1f}–{c.ratio_hi:.1f}×)",
            )
            found["crowd_rt"] = (c.realtime, f"{c.realtime:.1f}×")
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
