"""Checks: a level's expectations, watched every step of a scene and judged at the end of a run.

Each :class:`playground.level.Expectation` becomes a :class:`Check` that samples one body's
quantity in the OBSERVE stage — at a time, always or eventually within a window, as a mean over
it, or a force's impulse over it — and ends as a :class:`CheckResult` whose detail reads like a
test failure: the check, what was expected, what happened, and when.

>>> from playground.level import find, load
>>> from playground.scene import build
>>> scene = build(load(find("incline")))
>>> checks = watch(scene)
>>> scene.run(scene.level.settings.seconds)
>>> all(r.passed for r in checks.results())
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from playground.controller.config import G0
from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import OneEuroFilter
from playground.level.document import Level
from playground.level.expect import Expectation, Reading
from playground.level.naming import check_names, name_of
from playground.level.timeline import Spawn
from playground.quantities import CHECKED
from playground.scene import Scene
from playground.scene.readings import READERS
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = [
    "UNITS",
    "Check",
    "CheckResult",
    "Checks",
    "check_names",
    "mass_of",
    "read",
    "watch",
]

Value = float | tuple[float, float] | str

UNITS = {q.name: q.unit for q in CHECKED}
"""The unit of each quantity, for messages."""


@dataclass(frozen=True, slots=True)
class CheckResult:
    """The verdict on one expectation: its name, whether it passed, and why."""

    name: str
    passed: bool
    detail: str


def read(scene: Scene, body: str, quantity: str) -> Value:
    """The current value of a quantity of a body (raw readings; SI; "" for no state)."""
    value = READERS[quantity](scene, body)
    return "" if value is None else value


def mass_of(level: Level, body: str) -> float:
    """A body's mass as the level declares it, kg (a prop's, a spawned prop's or an actor's; a
    variant's, with ``--set``): with :data:`G0`, the unit of a check in ``weights_of`` or
    ``per_mass_of`` a body.

    >>> from playground.level import find, load
    >>> mass_of(load(find("crusher")), "crate") * G0
    2452.5
    """
    for actor in level.actors:
        if actor.name == body:
            return float(actor.controller.mass)
    props = [*level.props, *(e.prop for e in level.events if isinstance(e, Spawn))]
    for prop in props:
        if prop.name == body:
            return prop.mass
    raise KeyError(f"{body!r} has no mass in the level (a prop, a spawned prop or an actor)")


def _own_terms(exp: Expectation, level: Level) -> tuple[float, str]:
    """What one of a check's numbers stands for, N or N·s (1 for newtons, newton-seconds), and
    its name."""
    seconds = "·s" if exp.check == "impulse" else ""
    if exp.weights_of is not None:
        return mass_of(level, exp.weights_of) * G0, f"weights{seconds} of {exp.weights_of}"
    if exp.per_mass_of is not None:
        return mass_of(level, exp.per_mass_of), f"N{seconds}/kg of {exp.per_mass_of}"
    return 1.0, ""


def _fmt(value: Value, unit: str) -> str:
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, tuple):
        return f"[{value[0]:.6g}, {value[1]:.6g}] {unit}".rstrip()
    return f"{value:.6g} {unit}".rstrip()


def _scaled(
    number: float | tuple[float, float] | str | None, per: float
) -> float | tuple[float, float] | str | None:
    """A check's number (or vector) times ``per``; a state name or None as it is."""
    if per == 1.0 or number is None or isinstance(number, str):
        return number
    if isinstance(number, tuple):
        return (number[0] * per, number[1] * per)
    return number * per


def _minus(a: Value, b: Value) -> Value:
    """``a − b`` for numbers and vectors."""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return (a[0] - b[0], a[1] - b[1])
    if isinstance(a, float) and isinstance(b, float):
        return a - b
    raise ValueError(f"cannot subtract {b!r} from {a!r}")


def _angle(a: tuple[float, float], b: tuple[float, float]) -> float:
    """The angle between two vectors, rad in [0, π]; NaN if either has no direction.

    >>> round(_angle((1.0, 0.0), (1.0, 1.0)), 6)
    0.785398
    """
    if a == (0.0, 0.0) or b == (0.0, 0.0):
        return math.nan
    return abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))


class Check:
    """One expectation, fed a sample every step by :meth:`observe`."""

    def __init__(self, exp: Expectation, scene: Scene) -> None:
        self.exp = exp
        self.name = name_of(exp)
        self.unit = "rad" if exp.angle_to is not None else UNITS[exp.quantity]
        if exp.check == "impulse":
            self.unit += "·s"
        self.dt: float = scene.level.settings.dt
        self._window = exp.window or (0.0, scene.level.settings.seconds)
        # The check's numbers in the reading's unit: newtons for a check in a body's own terms.
        per, self._terms = _own_terms(exp, scene.level)
        self._per = per
        self._equals = _scaled(exp.equals, per)
        self._above = None if exp.above is None else exp.above * per
        self._below = None if exp.below is None else exp.below * per
        self._tolerance = exp.tolerance * per
        self._filter: FilterChain | OneEuroFilter | None = None
        if exp.filtered and exp.quantity != "support":
            p = scene.level.tracking.perception
            one_euro = OneEuroFilter(p.min_cutoff, p.beta, p.d_cutoff)
            self._filter = FilterChain(Median3(), one_euro) if p.spike_filter else one_euro
        self._origin: Value | None = None
        self._taken: tuple[float, Value] | None = None
        self._first_bad: tuple[float, Value] | None = None
        self._first_good: tuple[float, Value] | None = None
        self._closest: tuple[float, float, Value] | None = None
        self._sum: np.ndarray | None = None
        self._count = 0
        self._last_time = -math.inf

    # -- sampling --------------------------------------------------------------------------------

    def _raw(self, scene: Scene) -> Value | None:
        """The quantity now (filtered, relative to another body if asked), or None if absent."""
        exp = self.exp
        if exp.body not in scene.world.names:
            return None
        if exp.quantity == "support" and exp.filtered:
            raw: Value = scene.support_filtered(exp.body)
        else:
            raw = read(scene, exp.body, exp.quantity)
        if exp.relative_to is not None:
            if exp.relative_to not in scene.world.names:
                return None
            raw = _minus(raw, read(scene, exp.relative_to, exp.quantity))
        if exp.minus is not None:
            other = self._reading(scene, exp.minus)
            if other is None:
                return None
            raw = _minus(raw, other)
        if self._filter is not None:
            assert isinstance(raw, tuple)
            out = self._filter.filter(np.array(raw, dtype=np.float64), self.dt)
            raw = (float(out[0]), float(out[1]))
        if exp.angle_to is not None:
            ref = exp.angle_to
            to = self._reading(scene, ref) if isinstance(ref, Reading) else ref
            if to is None:
                return None
            assert isinstance(raw, tuple) and isinstance(to, tuple)
            raw = _angle(raw, to)
        return raw

    @staticmethod
    def _reading(scene: Scene, r: Reading) -> Value | None:
        """``r.scale`` × another body's reading now, or None if the body is absent."""
        if r.body not in scene.world.names:
            return None
        v = read(scene, r.body, r.quantity)
        if isinstance(v, tuple):
            return (r.scale * v[0], r.scale * v[1])
        assert isinstance(v, float)
        return r.scale * v

    def _project(self, raw: Value) -> Value:
        """Apply ``change`` (minus the window's first value) and ``component``."""
        if self._origin is not None:
            raw = _minus(raw, self._origin)
        if isinstance(raw, tuple) and self.exp.component is not None:
            if self.exp.component == "x":
                return raw[0]
            if self.exp.component == "y":
                return raw[1]
            return math.hypot(*raw)
        return raw

    def _in(self, t: float) -> bool:
        half = self.dt / 2
        return self._window[0] - half <= t <= self._window[1] + half

    def observe(self, scene: Scene) -> None:
        """Sample the quantity at the world's current time."""
        t = scene.world.time
        exp = self.exp
        wanted = (
            abs(t - exp.t) <= self.dt / 2 and self._taken is None
            if exp.check == "at" and exp.t is not None
            else self._in(t)
        )
        if not wanted and self._filter is None:
            return
        raw = self._raw(scene)
        if raw is None or not wanted:
            return
        if exp.change and self._origin is None:
            self._origin = raw
        value = self._project(raw)
        self._last_time = t
        if exp.check == "at":
            self._taken = (t, value)
            return
        if exp.check == "mean" or exp.check == "impulse":
            # An impulse takes the steps after the window's start: a reading is its step's mean
            # force, and the step that ends at the start lies before it.
            if exp.check == "impulse" and t < self._window[0] + self.dt / 2:
                return
            v = np.asarray(value, dtype=np.float64)
            self._sum = v if self._sum is None else self._sum + v
            self._count += 1
            return
        ok, miss = self._compare(value)
        if exp.check == "always":
            if not ok and self._first_bad is None:
                self._first_bad = (t, value)
        elif ok:
            if self._first_good is None:
                self._first_good = (t, value)
        elif self._closest is None or miss < self._closest[1]:
            self._closest = (t, miss, value)

    # -- judging ---------------------------------------------------------------------------------

    def _compare(self, value: Value) -> tuple[bool, float]:
        """Whether ``value`` passes, and by how much it misses (0 when it passes)."""
        exp = self.exp
        if exp.quantity == "state":
            wanted = exp.one_of if exp.one_of is not None else [str(exp.equals)]
            return (value in wanted, 0.0 if value in wanted else 1.0)
        if self._equals is not None:
            assert not isinstance(self._equals, str) and not isinstance(value, str)
            e = np.asarray(self._equals, dtype=np.float64)
            v = np.asarray(value, dtype=np.float64)
            off = float(np.hypot(*(v - e))) if e.ndim else abs(float(v - e))
            allowed = self._allowed()
            return (off <= allowed, max(0.0, off - allowed))
        assert isinstance(value, float)
        miss = 0.0
        if self._above is not None and not value > self._above:
            miss = max(miss, self._above - value)
        if self._below is not None and not value < self._below:
            miss = max(miss, value - self._below)
        return (miss == 0.0 and math.isfinite(value), miss if math.isfinite(value) else math.inf)

    def _allowed(self) -> float:
        exp = self.exp
        equals = self._equals
        assert equals is not None and not isinstance(equals, str)
        size = math.hypot(*equals) if isinstance(equals, tuple) else abs(equals)
        return self._tolerance + exp.relative * size

    def _expected(self) -> str:
        exp = self.exp
        if exp.quantity == "state":
            if exp.one_of is not None:
                return f"one of {exp.one_of}"
            return repr(exp.equals)
        if self._equals is not None:
            assert not isinstance(self._equals, str)
            want = f"{_fmt(self._equals, self.unit)} ± {self._allowed():.3g} {self.unit}".rstrip()
            return want + self._in_weights(exp.equals)
        parts = []
        if self._above is not None:
            parts.append(f"> {self._above:g} {self.unit}{self._in_weights(exp.above)}".rstrip())
        if self._below is not None:
            parts.append(f"< {self._below:g} {self.unit}{self._in_weights(exp.below)}".rstrip())
        return " and ".join(parts)

    def _in_weights(self, number: float | tuple[float, float] | str | None) -> str:
        """`` (3 weights of player)``: what a number of a check in a body's terms stood for."""
        if not self._terms or number is None or isinstance(number, str):
            return ""
        shown = _fmt(number, "").strip()
        return f" ({shown} {self._terms})"

    def _off(self, value: Value) -> str:
        if self._equals is None or isinstance(self._equals, str) or isinstance(value, str):
            return ""
        e = np.asarray(self._equals, dtype=np.float64)
        v = np.asarray(value, dtype=np.float64)
        off = float(np.hypot(*(v - e))) if e.ndim else abs(float(v - e))
        unit = f" {self.unit}" if self.unit else ""
        return f" (off by {off:.3g}{unit})"

    def result(self, end: float) -> CheckResult:
        """The verdict after a run that ended at ``end`` s."""
        exp = self.exp
        want = self._expected()
        if exp.check == "at":
            if self._taken is None:
                return self._fail(
                    f"expected {want} at t = {exp.t:g} s, but the run ended at "
                    f"{end:g} s without reaching it (or the body was absent)"
                )
            t, value = self._taken
            ok, _ = self._compare(value)
            got = f"got {_fmt(value, self.unit)}{'' if ok else self._off(value)}"
            return self._verdict(ok, f"expected {want} at t = {t:.4g} s, {got}")
        start, stop = self._window
        span = f"[{start:g}, {stop:g}] s"
        if self._last_time == -math.inf:
            return self._fail(
                f"expected {want} in {span}, but no step fell in the window "
                f"(the run ended at {end:g} s)"
            )
        short = stop - end > self.dt / 2
        tail = f"; the run ended at {end:g} s, before the window closed" if short else ""
        if exp.check == "mean" or exp.check == "impulse":
            if self._sum is None:
                return self._fail(
                    f"expected the {exp.check} over {span} to be {want}, but no "
                    f"step ended in the window after its start{tail}"
                )
            m = self._sum / self._count if exp.check == "mean" else self._sum * self.dt
            total: Value = (float(m[0]), float(m[1])) if m.ndim else float(m)
            ok, _ = self._compare(total)
            got = f"got {_fmt(total, self.unit)}{'' if ok else self._off(total)}"
            return self._verdict(
                ok and not short,
                f"expected the {exp.check} over {span} to be {want}, {got} "
                f"({self._count} steps){tail}",
            )
        if exp.check == "always":
            if self._first_bad is not None:
                t, value = self._first_bad
                return self._fail(
                    f"expected {want} always in {span}, first broken at t = {t:.4g} s: "
                    f"got {_fmt(value, self.unit)}{self._off(value)}"
                )
            return self._verdict(not short, f"expected {want} always in {span}: held{tail}")
        if self._first_good is not None:
            t, value = self._first_good
            return self._verdict(
                True,
                f"expected {want} eventually in {span}: first at t = {t:.4g} s "
                f"({_fmt(value, self.unit)})",
            )
        closest = ""
        if self._closest is not None:
            t, _, value = self._closest
            closest = f"; closest at t = {t:.4g} s: got {_fmt(value, self.unit)}{self._off(value)}"
        return self._fail(f"expected {want} eventually in {span}, never happened{closest}{tail}")

    def _verdict(self, ok: bool, detail: str) -> CheckResult:
        return CheckResult(self.name, ok, f"{self.name}: {detail}")

    def _fail(self, detail: str) -> CheckResult:
        return self._verdict(False, detail)


class Checks:
    """All the checks of a scene, observing every step."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.checks = [Check(exp, scene) for exp in scene.level.expect]
        for check, name in zip(self.checks, check_names(scene.level), strict=True):
            check.name = name

    def observe(self, world: World) -> None:
        for check in self.checks:
            check.observe(self.scene)

    def results(self) -> list[CheckResult]:
        """Every check's verdict, in the level's order."""
        end = self.scene.world.time
        return [check.result(end) for check in self.checks]


def watch(scene: Scene) -> Checks:
    """Attach a scene's expectations to its world (OBSERVE stage) and return them."""
    checks = Checks(scene)
    if checks.checks:
        scene.world.on(Stage.OBSERVE, checks.observe)
    return checks
