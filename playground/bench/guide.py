"""The settings guide: what each knob does to what a player feels, and what it costs per frame.

Four game-felt scenarios, each a shipped level run with the real controller:

* **platform** (moving_platform): how far the player drifts relative to a platform that speeds up
  at 1 m/s², cm;
* **ring** (spinning_ring): the angle between the perceived up and the exact one (away from the
  ring's floor, along the radius through the player's centre), RMS once settled, degrees;
* **room** (rotating_room): the largest angle between the perceived gravity and the field while
  the field turns, degrees;
* **landing** (rest, dropped from 1 m): the largest tilt after touchdown, degrees, and the deepest
  overlap of the capsule with the ground, mm.

Each knob is moved one at a time from the defaults (:data:`KNOBS`, fifteen of them). All the runs
of a scenario advance in lockstep, a quarter of a simulated second at a time, each timed, so a busy
spell of the machine hits every setting alike: the cost is the median over those blocks, with the
10th and 90th percentiles as its spread; each block is divided by the defaults' block of the same
round (paired, so the machine's changing load cancels) and scaled by the defaults' median.

>>> [k.name for k in KNOBS][:4]
['dt', 'substeps', 'iterations', 'collision_slop']
"""

from __future__ import annotations

import dataclasses
import math
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from playground.level.document import Level

__all__ = [
    "FRAME",
    "KNOBS",
    "SCENARIOS",
    "THRESHOLDS",
    "Knob",
    "Run",
    "guide",
    "hover_table",
]

FRAME = 1.0 / 60.0
"""s: the display frame the cost is compared with (60 Hz)."""

BLOCK = 0.25
"""s of simulated time per timed block (every run of a scenario advances one block per round)."""


@dataclass(frozen=True, slots=True)
class Knob:
    """One setting the guide moves: where it lives and the values tried (the default first).

    ``where`` is ``settings`` (the level's [settings]), ``perception`` ([tracking.perception]),
    ``controller`` (every actor's controller parameters) or ``world`` (the world's config after
    building: ``sleep_time``).
    """

    name: str
    where: str
    values: tuple[float | bool, ...]
    unit: str
    what: str


KNOBS: tuple[Knob, ...] = (
    Knob("dt", "settings", (1 / 120, 1 / 60, 1 / 240), "s", "the fixed step"),
    Knob("substeps", "settings", (1, 2, 4), "", "space.step calls per step"),
    Knob("iterations", "settings", (10, 4, 20), "", "solver iterations"),
    Knob("collision_slop", "settings", (0.005, 0.001, 0.02), "m", "allowed overlap"),
    Knob("sleep_time", "world", (math.inf, 0.5), "s", "idle time before a body sleeps"),
    Knob("min_cutoff", "perception", (2.0, 1.0, 5.0), "Hz", "1€ cutoff at rest"),
    Knob("beta", "perception", (0.05, 0.0, 0.5), "s²/m", "1€ speed coefficient"),
    Knob("d_cutoff", "perception", (1.0, 0.3, 5.0), "Hz", "1€ derivative cutoff"),
    Knob("spike_filter", "perception", (True, False), "", "median-of-3 before the 1€ filter"),
    Knob("hover_frequency", "controller", (5.0, 3.0, 8.0), "Hz", "hover spring"),
    Knob("hover_damping", "controller", (1.0, 0.5, 1.5), "", "hover damping ratio ζ"),
    Knob("ride_height", "controller", (0.95, 0.9, 1.0), "m", "centre above the ground"),
    Knob("probe_radius", "controller", (0.1, 0.05, 0.2), "m", "radius of the ground probe"),
    Knob("probe_length", "controller", (1.4, 1.2, 2.0), "m", "reach of the ground probe"),
    Knob("drive_time", "controller", (0.05, 0.025, 0.1), "s", "drive's time constant"),
)
"""The knobs, each with its default first."""


THRESHOLDS: dict[str, tuple[float, str]] = {
    "drift": (1.0, "cm"),
    "ring up": (2.0, "°"),
    "room up": (2.0, "°"),
    "landing tilt": (5.0, "°"),
    "penetration": (5.0, "mm"),
}
"""What a player notices, per measure: a centimetre of sliding on a platform; the camera's roll
off by two degrees (the ring, the room); a
landing that tips the body by five degrees; feet five millimetres inside the floor (the
default slop is 5 mm: more is visible overlap). A setting is "good" below all of them."""


@dataclass(frozen=True, slots=True)
class Run:
    """One scenario run at one setting (one knob moved from the defaults).

    Attributes:
        scenario: its name.  knob: the knob moved ("defaults" for none).  value: its value.
        measures: measure name → value, in the units of :data:`THRESHOLDS`.
        cost_us: µs per step, median over blocks.  cost_lo, cost_hi: 10th and 90th percentiles.
        dt: the step, s.
    """

    scenario: str
    knob: str
    value: float | bool
    measures: dict[str, float]
    cost_us: float
    cost_lo: float
    cost_hi: float
    dt: float

    @property
    def frame_share(self) -> float:
        """Cost as a fraction of a 60 Hz frame: µs per step × steps per frame / frame."""
        return self.cost_us * 1e-6 * (FRAME / self.dt) / FRAME

    @property
    def label(self) -> str:
        return "defaults" if self.knob == "defaults" else f"{self.knob} = {_fmt(self.value)}"


def _fmt(v: float | bool) -> str:
    """A knob value as the tables print it: on/off, never, 1/120, 0.05.

    >>> _fmt(1 / 120), _fmt(math.inf), _fmt(False), _fmt(0.05)
    ('1/120', 'never', 'off', '0.05')
    """
    if isinstance(v, bool):
        return "on" if v else "off"
    if math.isinf(v):
        return "never"
    if 0 < v < 0.02 and abs(1 / v - round(1 / v)) < 1e-6:
        return f"1/{round(1 / v)}"
    return f"{v:g}"


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


@dataclass(slots=True)
class _Live:
    """A scenario run in progress: its scene, what it has measured so far, its timed blocks."""

    knob: str
    value: float | bool
    scene: Any
    state: dict[str, float]
    blocks: list[float]


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


def _platform_observe(scene: Any, s: dict[str, float]) -> None:
    w = scene.world
    rel = w.body("player").position.x - w.body("platform").position.x
    s.setdefault("start", rel)
    s["drift"] = max(s.get("drift", 0.0), 100.0 * abs(rel - s["start"]))


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
    "platform": (_platform_level, _platform_observe, ("drift",)),
    "ring": (_ring_level, _ring_observe, ("ring up",)),
    "room": (_room_level, _room_observe, ("room up",)),
    "landing": (_landing_level, _landing_observe, ("landing tilt", "penetration")),
}
"""Scenario name → (its level, what it observes after every step, the measures it reports)."""


def _settings() -> list[tuple[Knob | None, float | bool]]:
    out: list[tuple[Knob | None, float | bool]] = [(None, 0.0)]
    for knob in KNOBS:
        out += [(knob, v) for v in knob.values[1:]]
    return out


def build_with(level: Level, knob: Knob | None, value: float | bool) -> Any:
    """Build ``level`` as a scene with ``knob`` set to ``value`` (None: the defaults)."""
    from playground.scene import build

    scene = build(_with(level, knob, value))
    if knob is not None and knob.where == "world":
        # The only world knob: sleeping, which the level format does not carry.
        scene.world.config = dataclasses.replace(scene.world.config, sleep_time=float(value))
    return scene


def run_scenario(
    name: str, settings: Sequence[tuple[Knob | None, float | bool]] | None = None
) -> list[Run]:
    """Run scenario ``name`` at every setting (default: the defaults and each knob's other
    values), all in lockstep, and return one :class:`Run` each. The first setting is the
    reference the costs are paired with."""
    make, observe, measures = SCENARIOS[name]
    base = make()
    live = []
    for knob, value in settings if settings is not None else _settings():
        scene = build_with(base, knob, value)
        live.append(_Live("defaults" if knob is None else knob.name, value, scene, {}, []))
    seconds = base.settings.seconds
    rounds = math.ceil(seconds / BLOCK - 1e-9)
    for r in range(rounds):
        for run in live:
            world = run.scene.world
            steps = round(min(BLOCK, seconds - r * BLOCK) / world.config.dt)
            t0 = time.perf_counter()
            for _ in range(steps):
                world.step()
                observe(run.scene, run.state)
            if steps:
                run.blocks.append(1e6 * (time.perf_counter() - t0) / steps)
    # Each block against the defaults' block of the same round (the first run): the machine's
    # load changes from round to round, and a paired ratio cancels it.
    reference = live[0].blocks
    base_us = statistics.median(reference)
    out = []
    for run in live:
        if run is live[0]:
            q = np.percentile(reference, [10, 50, 90])  # its own blocks: paired with itself is 1
        else:
            ratios = [a / b for a, b in zip(run.blocks, reference, strict=True)]
            q = base_us * np.percentile(ratios, [10, 50, 90])
        out.append(
            Run(
                scenario=name,
                knob=run.knob,
                value=run.value,
                measures={m: run.state.get(m, math.nan) for m in measures},
                cost_us=float(q[1]),
                cost_lo=float(q[0]),
                cost_hi=float(q[2]),
                dt=run.scene.world.config.dt,
            )
        )
    return out


def guide(progress: bool = False) -> list[Run]:
    """Every scenario at every setting (a few hundred runs of a few seconds)."""
    bar = None
    if progress:
        import importlib

        bar = importlib.import_module("tqdm").tqdm(
            total=len(SCENARIOS), desc="guide", unit="scenario"
        )
    out: list[Run] = []
    for name in SCENARIOS:
        out += run_scenario(name)
        if bar is not None:
            bar.update(1)
    if bar is not None:
        bar.close()
    return out


HOVER_FREQUENCIES = (2.0, 5.0, 10.0, 20.0, 40.0)
"""Hz: the hover frequencies of the f × dt table."""

HOVER_DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240)
"""s: the steps of the f × dt table."""


def hover_error(frequency: float, damping: float, dt: float) -> float:
    """RMS over 1 s of (height − the continuous damped oscillator's) / drop, for a player released
    5 mm below its ride height; inf if the controller refuses the setting (beyond its limit)."""
    from playground.controller.config import ControllerConfig
    from playground.controller.controller import Controller
    from playground.world.config import WorldConfig
    from playground.world.world import World

    drop = 0.005
    try:
        cfg = ControllerConfig(hover_frequency=frequency, hover_damping=damping, lock_rotation=True)
        world = World(WorldConfig(dt=dt))
        world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
        player = Controller(world, "player", (0.0, 0.05 + cfg.ride_height - drop), config=cfg)
    except ValueError:
        return math.inf
    w0 = 2.0 * math.pi * frequency
    errs = []
    for _ in range(round(1.0 / dt)):
        world.step()
        t = world.time
        x = player.body.position.y - 0.05 - cfg.ride_height
        if damping < 1.0:
            wd = w0 * math.sqrt(1.0 - damping**2)
            exact = (
                -drop
                * math.exp(-damping * w0 * t)
                * (math.cos(wd * t) + damping * w0 / wd * math.sin(wd * t))
            )
        elif damping == 1.0:
            exact = -drop * math.exp(-w0 * t) * (1.0 + w0 * t)
        else:
            s = w0 * math.sqrt(damping**2 - 1.0)
            r1, r2 = -damping * w0 + s, -damping * w0 - s
            exact = -drop * (r2 * math.exp(r1 * t) - r1 * math.exp(r2 * t)) / (r2 - r1)
        errs.append((x - exact) / drop)
    return math.sqrt(statistics.fmean(e * e for e in errs))


def hover_table(damping: float = 1.0) -> dict[tuple[float, float], float]:
    """(frequency Hz, dt s) → :func:`hover_error`, over HOVER_FREQUENCIES × HOVER_DTS."""
    return {(f, dt): hover_error(f, damping, dt) for f in HOVER_FREQUENCIES for dt in HOVER_DTS}


# -- report ---------------------------------------------------------------------------------------


COST_TIE = 0.1
"""Relative: costs closer than this count as equal (the paired ratios' run-to-run noise on a shared
machine), so the front is not decided by timing noise between settings that cost the same."""


def front(points: Sequence[tuple[float, float]], tie: float = COST_TIE) -> list[int]:
    """Indices of the (cost, measure) points that no other point dominates, by rising cost.

    ``j`` dominates ``i`` when it is no worse on the measure and costs no more than ``i`` (within
    the relative ``tie``), and is strictly better on one of them.

    >>> front([(1.0, 5.0), (2.0, 3.0), (3.0, 4.0), (4.0, 1.0)], tie=0.0)
    [0, 1, 3]
    >>> front([(1.0, 5.0), (1.05, 3.0)], tie=0.1)    # 5 % dearer counts as the same cost
    [1]
    """

    def dominates(j: int, i: int) -> bool:
        (cj, mj), (ci, mi) = points[j], points[i]
        cheap = cj <= ci * (1.0 + tie)
        return cheap and mj <= mi and (mj < mi or cj < ci / (1.0 + tie))

    n = range(len(points))
    keep = [i for i in n if not any(dominates(j, i) for j in n if j != i)]
    return sorted(keep, key=lambda i: (points[i][0], points[i][1]))


def _by_setting(runs: Sequence[Run]) -> dict[str, dict[str, Run]]:
    """Setting label → scenario → its run."""
    out: dict[str, dict[str, Run]] = {}
    for r in runs:
        out.setdefault(r.label, {})[r.scenario] = r
    return out


def worst_case(runs: Sequence[Run]) -> list[tuple[str, float, float]]:
    """Per setting: (label, mean share of a 60 Hz frame over the scenarios, worst measure over
    its threshold across every measure of every scenario)."""
    out = []
    for label, per in _by_setting(runs).items():
        if len(per) < len(SCENARIOS):
            continue
        worst = max(r.measures[m] / THRESHOLDS[m][0] for r in per.values() for m in r.measures)
        share = statistics.fmean(r.frame_share for r in per.values())
        out.append((label, share, worst))
    return out


def advice(runs: Sequence[Run]) -> list[tuple[str, str]]:
    """The "if you want X, set Y" rows: for each measure, the cheapest tried setting that keeps
    it under its threshold (or the best one, if none does), read off the runs."""
    rows = []
    wants = {
        "drift": "the player to stay put on an accelerating platform (drift under {t} {u})",
        "ring up": "a steady camera in a spinning room (perceived up within {t} {u})",
        "room up": "the camera to follow a turning room (within {t} {u})",
        "landing tilt": "running landings that stay upright (tilt under {t} {u})",
        "penetration": "feet that never sink into the floor (under {t} {u})",
    }
    for measure, text in wants.items():
        limit, unit = THRESHOLDS[measure]
        cands = [r for r in runs if measure in r.measures and math.isfinite(r.measures[measure])]
        if not cands:
            continue
        base = next((r for r in cands if r.knob == "defaults"), None)
        ok = [r for r in cands if r.measures[measure] < limit]
        if base is not None and base.measures[measure] < limit:
            y = f"the defaults ({base.measures[measure]:.3g} {unit})"
        elif ok:
            best = min(ok, key=lambda r: r.frame_share)
            y = (
                f"{best.label} ({best.measures[measure]:.3g} {unit}, "
                f"{100 * best.frame_share:.1f} % of a 60 Hz frame)"
            )
        else:
            best = min(cands, key=lambda r: r.measures[measure])
            y = (
                f"no single knob tried gets there; the best is {best.label} "
                f"({best.measures[measure]:.3g} {unit}"
                + (f", defaults {base.measures[measure]:.3g}" if base is not None else "")
                + ")"
            )
        rows.append((text.format(t=f"{limit:g}", u=unit), y))
    return rows


def guide_markdown(
    runs: Sequence[Run], hover: dict[tuple[float, float], float], seconds: float
) -> str:
    """The settings guide's section of docs/accuracy.md (after its "if you want" table)."""
    measures = [m for m in THRESHOLDS if any(m in r.measures for r in runs)]
    per = _by_setting(runs)
    header = ["setting", *(f"{m} ({THRESHOLDS[m][1]})" for m in measures)]
    header += ["µs/step median [p10–p90]", "% of a 60 Hz frame"]
    body = []
    for label, scen in per.items():
        row = [label]
        for m in measures:
            vals = [r.measures[m] for r in scen.values() if m in r.measures]
            row.append(f"{vals[0]:.3g}" if vals else "–")
        costs = list(scen.values())
        med = statistics.median(r.cost_us for r in costs)
        lo = statistics.median(r.cost_lo for r in costs)
        hi = statistics.median(r.cost_hi for r in costs)
        share = statistics.median(r.frame_share for r in costs)
        row += [f"{med:.0f} [{lo:.0f}–{hi:.0f}]", f"{100 * share:.1f}"]
        body.append(row)
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in body]
    fronts = []
    for name, (_, _, ms) in SCENARIOS.items():
        rs = [r for r in runs if r.scenario == name]
        for m in ms:
            idx = front([(r.frame_share, r.measures[m]) for r in rs])
            items = ", ".join(
                f"{rs[i].label} ({rs[i].measures[m]:.3g} {THRESHOLDS[m][1]}, "
                f"{100 * rs[i].frame_share:.1f} %)"
                for i in idx
            )
            fronts.append(f"- **{name}, {m}**: {items}")
    wc = worst_case(runs)
    idx = front([(s, w) for _, s, w in wc])
    worst_items = ", ".join(
        f"{wc[i][0]} (worst {wc[i][2]:.2g}× its threshold, {100 * wc[i][1]:.1f} %)" for i in idx
    )
    knob_lines = "\n".join(
        f"| `{k.name}` | {k.what} | {', '.join(_fmt(v) for v in k.values)} | {k.unit or '–'} |"
        for k in KNOBS
    )
    hover_rows = []
    for f in HOVER_FREQUENCIES:
        cells = []
        for dt in HOVER_DTS:
            e = hover[(f, dt)]
            cells.append("refused (beyond the limit)" if math.isinf(e) else f"{100 * e:.2g} %")
        hover_rows.append(f"| {f:g} Hz | " + " | ".join(cells) + " |")
    hover_head = "| f \\ dt | " + " | ".join(f"1/{round(1 / dt)} s" for dt in HOVER_DTS) + " |"
    thresholds = ", ".join(f"{m} {t:g} {u}" for m, (t, u) in THRESHOLDS.items())
    return f"""## The settings guide (`playground bench guide`)

Four game-felt scenarios, each a shipped level run with the real controller (module
`playground.bench.guide`): **platform** (moving_platform: drift relative to the platform, cm),
**ring** (spinning_ring: RMS angle between the perceived up and the exact one once settled, °),
**room** (rotating_room: largest angle between perceived gravity and the field while it turns, °),
**landing** (rest, the player dropped {DROP:g} m with {RUN_SPEED:g} m/s sideways: largest tilt
after touchdown, °, and deepest overlap with the ground, mm). Fifteen knobs, each moved one at a
time from the defaults ({len(runs)} runs, {seconds:.0f} s on this machine):

| knob | what | values tried (default first) | unit |
|---|---|---|---|
{knob_lines}

Cost: all the runs of a scenario advance in lockstep, {BLOCK:g} s of simulated time at a time,
each block timed, so a busy spell of the machine hits every setting alike; the table gives the
median µs per step over those blocks with the 10th and 90th percentiles, each block paired with
the defaults' block of the same round (the spread is what is left of the machine's noise), and
the share of a 60 Hz frame the physics takes (µs per step ×
steps per frame / 16.7 ms). Thresholds (what a player notices): {thresholds}.

![each scenario's measure against its cost, fronts marked; the worst case](img/guide.png)

{chr(10).join(lines)}

### Fronts

For each measure, the settings no other beats on both the measure and the cost (cheapest first;
costs within {100 * COST_TIE:.0f} % count as equal, the timing noise on this shared machine):

{chr(10).join(fronts)}

**Worst case** (each setting's largest measure over its threshold, across every scenario, against
its mean frame share): {worst_items}.

### Hover frequency against dt

RMS height error over 1 s of the critically damped hover released 5 mm low, against the
continuous oscillator, as a share of the drop. The error is first order in dt and grows with f:
keep 2πf·dt small (≈ 0.26 at the default 5 Hz, 1/120 s); the controller refuses a frequency at or
beyond its stability limit.

{hover_head}
|---|{"---|" * len(HOVER_DTS)}
{chr(10).join(hover_rows)}
"""


def guide_figure(runs: Sequence[Run], path: Any) -> None:
    """Each scenario's measures against the frame share, fronts marked; and the worst case."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [(n, m) for n, (_, _, ms) in SCENARIOS.items() for m in ms]
    fig, axes = plt.subplots(2, 3, figsize=(15, 8.5))
    flat = list(axes.flat)
    for ax, (name, m) in zip(flat, panels, strict=False):
        rs = [r for r in runs if r.scenario == name]
        if not rs:
            ax.axis("off")  # this scenario was not run
            continue
        x = [100 * r.frame_share for r in rs]
        y = [r.measures[m] for r in rs]
        lo = [100 * r.frame_share * r.cost_lo / r.cost_us for r in rs]
        hi = [100 * r.frame_share * r.cost_hi / r.cost_us for r in rs]
        ax.errorbar(
            x, y, xerr=np.maximum(0.0, [np.subtract(x, lo), np.subtract(hi, x)]), fmt="o",
            ms=4, alpha=0.5,
            elinewidth=0.6, label="settings (cost p10–p90)",
        )  # fmt: skip
        idx = front(list(zip(x, y, strict=True)))
        ax.plot([x[i] for i in idx], [y[i] for i in idx], "k-o", ms=5, label="front")
        ax.set_ylim(bottom=0.0)
        for i in idx:
            ax.annotate(rs[i].label, (x[i], y[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7)  # fmt: skip
        ax.axhline(THRESHOLDS[m][0], color="C3", ls="--", lw=1, label="what a player notices")
        ax.set(xscale="log", xlabel="% of a 60 Hz frame", ylabel=f"{m} ({THRESHOLDS[m][1]})",
               title=f"{name}: {m}")  # fmt: skip
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    ax = flat[len(panels)]
    wc = worst_case(runs)
    if wc:
        x = [100 * s for _, s, _ in wc]
        y = [w for _, _, w in wc]
        ax.plot(x, y, "o", ms=4, alpha=0.5)
        idx = front(list(zip(x, y, strict=True)))
        ax.plot([x[i] for i in idx], [y[i] for i in idx], "k-o", ms=5)
        for i in idx:
            ax.annotate(wc[i][0], (x[i], y[i]), xytext=(4, 4), textcoords="offset points",
                        fontsize=7)  # fmt: skip
        ax.axhline(1.0, color="C3", ls="--", lw=1)
        ax.set(xscale="log", xlabel="mean % of a 60 Hz frame", ylabel="worst measure / threshold",
               title="worst case over every scenario")  # fmt: skip
        ax.grid(True, alpha=0.3)
    else:
        ax.axis("off")  # not every scenario was run: no worst case
    for ax in flat[len(panels) + 1 :]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
