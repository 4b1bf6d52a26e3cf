"""The small costs the code is shaped by: each choice a comment gives a reason for (read an Enum
member once, key by the body and not its id, read Chipmunk through its C getters, build plain
dataclasses, probe and sum contacts with C callbacks, check every body rarely), timed against
the alternative it was chosen over, in alternating blocks in one process (µs per call).

The numbers go into docs/performance.md (``python -m tools costs`` writes docs/costs.json, and
``python -m tools performance`` reads it); the comments keep only the reason, and name the row.
"""

from __future__ import annotations

import dataclasses
import math
import statistics
import timeit
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pymunk
from pymunk import batch

from playground._engine import raw
from playground._engine.contacts import Contacts, load_by_pymunk
from playground._engine.sweep import Sweep, nearest_by_pymunk
from playground.bench.markdown import table
from playground.bench.performance import machine
from playground.forces.ledger import Category
from playground.world.guard import GUARD_EVERY, state_runaway
from playground.world.schedule import Stage

__all__ = ["COSTS", "Cost", "CostRow", "costs_markdown", "from_dict", "measure"]

REPEATS = 15
"""Alternating timed runs of each side (the figure is their median)."""

RUN_SECONDS = 0.002
"""Wall time of one timed run of one side, s: short, so a burst of load hits both sides alike."""


@dataclass(frozen=True, slots=True)
class Cost:
    """One choice the code makes, and how to time it.

    Attributes:
        key: short identifier, named by the comment that relies on it.
        what: what is timed, in words.  chosen: the way the code does it.  alternative: the way
            it does not (empty when the row times one thing).
        where: the modules whose comments give the reason.
        setup: builds the namespace the two statements run in.
        stmt: the chosen statement.  alt_stmt: the alternative's (empty: none).
    """

    key: str
    what: str
    chosen: str
    alternative: str
    where: str
    setup: Callable[[], dict[str, Any]]
    stmt: str
    alt_stmt: str = ""
    compare: Callable[[float, float], str] | None = None


def _cheaper(us: float, alt_us: float) -> str:
    """The default comparison: how many times the alternative costs what the choice does."""
    return f"{alt_us / us:.1f}× cheaper"


def _share_of_a_step(us: float, step_us: float) -> str:
    """The guard's comparison: one check against one bare step, and per step at its rate."""
    return (
        f"a check is {us / step_us:.2f} of a step; "
        f"{100 * us / step_us / GUARD_EVERY:.2f} % a step at one in {GUARD_EVERY}"
    )


@dataclass(frozen=True, slots=True)
class CostRow:
    """One measured :class:`Cost`: µs per call of each side, and their ratio (alternative /
    chosen, median of adjacent runs; NaN, as ``alt_us``, when the row has no alternative)."""

    key: str
    what: str
    chosen: str
    alternative: str
    where: str
    us: float
    alt_us: float
    ratio: float


@dataclass(slots=True)
class _Plain:
    a: float
    b: float
    c: float
    d: float
    e: float
    f: float


@dataclass(frozen=True, slots=True)
class _Frozen:
    a: float
    b: float
    c: float
    d: float
    e: float
    f: float


def _box_on_floor(dt: float = 1.0 / 120.0) -> tuple[pymunk.Space, pymunk.Body]:
    """A 1 kg box resting on a static floor, settled (its contacts made)."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    floor = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.05)
    body = pymunk.Body(1.0, pymunk.moment_for_box(1.0, (0.5, 0.5)))
    body.position = (0.0, 0.3)
    space.add(floor, body, pymunk.Poly.create_box(body, (0.5, 0.5)))
    for _ in range(120):
        space.step(dt)
    return space, body


def _pile(n: int) -> pymunk.Space:
    """``n`` boxes in a row on a floor."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.add(pymunk.Segment(space.static_body, (-1.0, 0.0), (n + 1.0, 0.0), 0.05))
    for i in range(n):
        body = pymunk.Body(1.0, pymunk.moment_for_box(1.0, (0.5, 0.5)))
        body.position = (float(i), 0.3)
        space.add(body, pymunk.Poly.create_box(body, (0.5, 0.5)))
    return space


def _enum() -> dict[str, Any]:
    return {"Stage": Stage, "CONTROL": Stage.CONTROL, "c": Category.PASSIVE}


def _body() -> dict[str, Any]:
    _, body = _box_on_floor()
    return {"body": body, "h": raw.handle(body), "raw": raw, "by_body": {body: 1}}


def _classes() -> dict[str, Any]:
    return {"Plain": _Plain, "Frozen": _Frozen}


def _arrays() -> dict[str, Any]:
    space = _pile(10)
    a = np.ones(10)
    return {"np": np, "a": a, "b": a.copy(), "out": a.copy(), "space": space, "batch": batch,
            "buf": batch.Buffer(), "fields": batch.BodyFields.POSITION}  # fmt: skip


def _probe() -> dict[str, Any]:
    space, _ = _box_on_floor()
    shape_filter = pymunk.ShapeFilter()
    return {"space": space, "sweep": Sweep(space, shape_filter), "nearest": nearest_by_pymunk,
            "f": shape_filter}  # fmt: skip


def _contacts() -> dict[str, Any]:
    _, body = _box_on_floor()
    return {"body": body, "c": Contacts(body), "load": load_by_pymunk}


def _guard() -> dict[str, Any]:
    space = _pile(10)
    for _ in range(30):
        space.step(1.0 / 120.0)
    return {"space": space, "check": state_runaway, "buf": batch.Buffer()}


def _timer() -> dict[str, Any]:
    import time

    return {"perf_counter": time.perf_counter}


COSTS = (
    Cost("enum_member", "an Enum member, read in the step", "a module-level name",
         "read off the Enum class", "world/world.py, world/gravity_stage.py", _enum,
         "CONTROL", "Stage.CONTROL"),
    Cost("enum_value", "an Enum member's number", "`member._value_` (an attribute)",
         "`member.value` (a property)", "forces/ledger.py", _enum, "c._value_", "c.value"),
    Cost("body_key", "find a body's ledger entry", "a dict keyed by the body",
         "`body.id` first (a call into Chipmunk)", "forces/ledger.py", _body,
         "by_body[body]", "body.id"),
    Cost("velocity", "a body's velocity", "Chipmunk's C getter (`_engine.raw.velocity`)",
         "pymunk's property `body.velocity` (a `Vec2d`)", "_engine/raw.py", _body,
         "raw.velocity(h)", "body.velocity"),
    Cost("plain_dataclass", "build a six-field state value", "a plain slots dataclass",
         "a frozen one", "controller/states.py, _engine/state.py", _classes,
         "Plain(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)", "Frozen(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)"),
    Cost("positional", "build the six-field value", "its fields in order, positionally",
         "the same with keywords",
         "controller/sensing.py, controller/decision.py, controller/action.py", _classes,
         "Plain(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)", "Plain(a=1.0, b=2.0, c=3.0, d=4.0, e=5.0, f=6.0)"),
    Cost("numpy_call", "one numpy call on 10 rows", "`np.multiply(a, b, out=out)`", "",
         "forces/scalar/bodies.py", _arrays, "np.multiply(a, b, out=out)"),
    Cost("batch_call", "one `pymunk.batch` read of 10 bodies' positions",
         "`batch.get_space_bodies`", "", "forces/scalar/bodies.py", _arrays,
         "buf.clear(); batch.get_space_bodies(space, fields, buf)"),
    Cost("probe", "the ground probe: nearest hit of a swept circle over one floor",
         "one C callback keeping the nearest (`_engine.sweep.Sweep`)",
         "pymunk's `segment_query`, walked in Python", "_engine/sweep.py", _probe,
         "sweep.nearest(0.0, 1.0, 0.0, -1.0, 0.1)",
         "nearest(space, (0.0, 1.0), (0.0, -1.0), 0.1, f)"),
    Cost("contacts", "the load on a box resting on a floor, through its contacts",
         "C callbacks made once (`_engine.contacts.Contacts`)",
         "pymunk's `each_arbiter` and `Arbiter` objects", "_engine/contacts.py, _engine/raw.py",
         _contacts, "c.load(0.0, 1.0, 1 / 120)", "load(body, 0.0, 1.0, 1 / 120)"),
    Cost("guard_check", "the guard's check of every body, 10 boxes",
         f"one batch read every {GUARD_EVERY} steps", "a bare `space.step` of the same boxes",
         "world/guard.py", _guard, "check(space, buf)", "space.step(1 / 120)",
         _share_of_a_step),
    Cost("stage_timer", "one `time.perf_counter()` call (two per timed stage)",
         "off unless `WorldConfig.timing`", "", "world/config.py, bench/performance.py", _timer,
         "perf_counter()"),
)  # fmt: skip
"""Every choice timed, in the order the page lists them."""


def _number(stmt: str, ns: dict[str, Any]) -> int:
    """Calls per timed run so that one run takes about :data:`RUN_SECONDS`."""
    timer = timeit.Timer(stmt, globals=ns)
    n, t = 1, 0.0
    while t < RUN_SECONDS / 10:
        n *= 10
        t = timer.timeit(n)
    return max(1, round(n * RUN_SECONDS / t))


def measure_one(cost: Cost, repeats: int = REPEATS) -> CostRow:
    """Time ``cost``'s two statements in alternating runs; µs per call of each."""
    ns = cost.setup()
    a = timeit.Timer(cost.stmt, globals=ns)
    b = timeit.Timer(cost.alt_stmt, globals=ns) if cost.alt_stmt else None
    na = _number(cost.stmt, ns)
    nb = _number(cost.alt_stmt, ns) if cost.alt_stmt else 1
    ta: list[float] = []
    tb: list[float] = []
    for i in range(repeats):
        first_a = i % 2 == 0  # alternate which goes first
        for side in ("a", "b") if first_a else ("b", "a"):
            if side == "a":
                ta.append(a.timeit(na) / na)
            elif b is not None:
                tb.append(b.timeit(nb) / nb)
    ratio = statistics.median(y / x for x, y in zip(ta, tb, strict=True)) if tb else math.nan
    alt = 1e6 * statistics.median(tb) if tb else math.nan
    return CostRow(cost.key, cost.what, cost.chosen, cost.alternative, cost.where,
                   1e6 * statistics.median(ta), alt, ratio)  # fmt: skip


def measure(repeats: int = REPEATS) -> dict[str, Any]:
    """Every :data:`COSTS` row, with the machine: the JSON of docs/costs.json.

    >>> data = measure(repeats=1)
    >>> [r["key"] for r in data["costs"]] == [c.key for c in COSTS]
    True
    """
    rows = [measure_one(c, repeats) for c in COSTS]
    return {
        "machine": machine(),
        "command": "python -m tools costs",
        "repeats": repeats,
        "costs": [_clean(dataclasses.asdict(r)) for r in rows],
    }


def _clean(row: dict[str, Any]) -> dict[str, Any]:
    return {k: None if isinstance(v, float) and not math.isfinite(v) else v for k, v in row.items()}


def from_dict(data: dict[str, Any], source: str = "<data>") -> list[CostRow]:
    """The rows back from :func:`measure`'s JSON; ``ValueError`` names ``source`` and the key."""

    def num(v: Any) -> float:
        return math.nan if v is None else float(v)

    try:
        return [
            CostRow(
                str(r["key"]),
                str(r["what"]),
                str(r["chosen"]),
                str(r["alternative"]),
                str(r["where"]),
                num(r["us"]),
                num(r["alt_us"]),
                num(r["ratio"]),
            )
            for r in data["costs"]
        ]
    except KeyError as exc:
        raise ValueError(f"{source}: expected the key {exc} (python -m tools costs)") from None
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{source}: not the output of python -m tools costs ({exc})") from None


def _us(v: float) -> str:
    if not math.isfinite(v):
        return ""
    return f"{v * 1000:.0f} ns" if v < 1.0 else f"{v:.2g} µs"


def costs_markdown(rows: Sequence[CostRow], data: dict[str, Any]) -> str:
    """The section of docs/performance.md: one row per choice, the machine it was timed on."""
    mc = data["machine"]
    how = {c.key: c.compare or _cheaper for c in COSTS}
    lines = [
        [
            r.what,
            r.chosen,
            _us(r.us),
            r.alternative,
            _us(r.alt_us),
            how.get(r.key, _cheaper)(r.us, r.alt_us) if math.isfinite(r.alt_us) else "",
            r.where,
        ]
        for r in rows
    ]
    return (
        "## The small costs the code is shaped by\n\n"
        "Comments in the code give the reason for each of these choices; the figures are here. "
        f"Timed by `{data['command']}` on {mc['cpu']}, load average {mc['load']}, Python "
        f"{mc['python']}, pymunk {mc['pymunk']}, {mc['date']}: each statement in "
        f"{data['repeats']} runs of about {1000 * RUN_SECONDS:.0f} ms alternating with its "
        "alternative's (`timeit`, wall time), the median of each and of their ratios.\n\n"
        + table(
            ["what", "the code does", "per call", "instead of", "per call", "so", "where"], lines
        )
        + "\n"
    )
