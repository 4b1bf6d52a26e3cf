"""Faults: named breaks of one feature each, and the matrix of which level checks catch them.

A *break* is a small, reversible change to one feature of the playground — the hover's reaction
cut, the drive reading the world instead of the ground, the inner ear turned by 30° — applied as a
context manager that patches one method or one config value of a class and restores it on exit.
It never touches a file. A level declares the breaks its checks must catch (``catches = [...]``);
:func:`matrix` runs each level clean and under each declared break and reports which checks
caught it. A check that passes while its feature is broken checks nothing.

Patches are process-wide (class attributes): run one broken scene at a time, in one thread.

>>> from playground.movers import Spin
>>> with apply("ring_spin_stopped"):
...     Spin(rate=1.5).pose(2.0)
((0.0, 0.0), 0.0)
>>> Spin(rate=1.5).pose(2.0)
((0.0, 0.0), 3.0)
"""

from __future__ import annotations

import dataclasses
import inspect
import math
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import AbstractContextManager, contextmanager
from dataclasses import dataclass
from typing import Any

from playground import movers as movers_mod
from playground import perception as perception_mod
from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.forces.ledger import Category
from playground.gravity import GravityRule
from playground.level.document import Level
from playground.world import force_api, gravity_stage
from playground.world import world as world_mod

__all__ = [
    "BREAKS",
    "Break",
    "BreakError",
    "Outcome",
    "Row",
    "apply",
    "matrix",
    "names",
    "run",
]

Patch = Callable[[], AbstractContextManager[None]]


class BreakError(Exception):
    """A break could not be applied (the method or value it patches is gone or changed)."""


@dataclass(frozen=True, slots=True)
class Break:
    """One named break: ``patch()`` is a context manager that breaks the feature while open."""

    name: str
    patch: Patch

    @property
    def doc(self) -> str:
        """What it breaks: the first paragraph of its docstring, on one line."""
        text = inspect.getdoc(self.patch) or ""
        return " ".join(text.split("\n\n")[0].split())


BREAKS: dict[str, Break] = {}
"""Every break by name, in the order they are defined."""


def _register(name: str) -> Callable[[Callable[[], Iterator[None]]], Patch]:
    def register(fn: Callable[[], Iterator[None]]) -> Patch:
        patch = contextmanager(fn)
        BREAKS[name] = Break(name, patch)
        return patch

    return register


def names() -> list[str]:
    """The names of every break, in registry order."""
    return list(BREAKS)


def apply(name: str) -> AbstractContextManager[None]:
    """The context manager of the break ``name`` (KeyError listing the valid names)."""
    try:
        return BREAKS[name].patch()
    except KeyError:
        raise KeyError(f"no break named {name!r} (known: {', '.join(BREAKS)})") from None


# -- patching ------------------------------------------------------------------------------------


@contextmanager
def _replaced(owner: type, attr: str, make: Callable[[Any], Any]) -> Iterator[None]:
    """Replace the class attribute ``owner.attr`` by ``make(original)``; restore it on exit."""
    if attr not in vars(owner):
        raise BreakError(f"{owner.__name__}.{attr} no longer exists: the break cannot follow it")
    original = vars(owner)[attr]
    setattr(owner, attr, make(original))
    try:
        yield
    finally:
        setattr(owner, attr, original)


def _parameter(fn: Callable[..., Any], owner: type, param: str) -> inspect.Signature:
    """The signature of ``fn``, checked to take ``param``."""
    sig = inspect.signature(fn)
    if param not in sig.parameters:
        raise BreakError(
            f"{owner.__name__}.{fn.__name__} no longer takes {param!r}: the break cannot follow it"
        )
    return sig


def _with_argument(
    owner: type, method: str, param: str, change: Callable[[Any], Any]
) -> AbstractContextManager[None]:
    """Call ``owner.method`` with its argument ``param`` replaced by ``change(value)``."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        sig = _parameter(original, owner, param)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            bound = sig.bind(*args, **kwargs)
            bound.apply_defaults()
            bound.arguments[param] = change(bound.arguments[param])
            return original(*bound.args, **bound.kwargs)

        return wrapped

    return _replaced(owner, method, make)


def _after(
    owner: type,
    method: str,
    needs: Sequence[str],
    then: Callable[[dict[str, Any], Any], Any],
) -> AbstractContextManager[None]:
    """Run ``owner.method``, then ``then(arguments by name, result)``; return what it returns.
    ``needs``: the parameters ``then`` reads."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        sig = inspect.signature(original)
        for param in needs:
            _parameter(original, owner, param)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            result = original(*args, **kwargs)
            return then(dict(sig.bind(*args, **kwargs).arguments), result)

        return wrapped

    return _replaced(owner, method, make)


def _controller_config(**change: Callable[[float], float]) -> AbstractContextManager[None]:
    """Controllers built while open get their config fields changed: ``field=f(old value)``."""
    known = {f.name for f in dataclasses.fields(ControllerConfig)}
    for key in change:
        if key not in known:
            raise BreakError(f"ControllerConfig has no field {key!r}: the break cannot follow it")

    def make(original: Callable[..., None]) -> Callable[..., None]:
        def init(self: Any, *args: Any, **kwargs: Any) -> None:
            original(self, *args, **kwargs)
            new = {k: f(getattr(self.config, k)) for k, f in change.items()}
            self.config = dataclasses.replace(self.config, **new)

        return init

    return _replaced(Controller, "__init__", make)


def _rotate(v: tuple[float, float], angle: float) -> tuple[float, float]:
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])


# -- the breaks ----------------------------------------------------------------------------------

HOVER_REACTION_SCALE = 0.05
"""What is left of the hover's reaction on the ground under ``hover_reaction`` (5 %)."""
DRIVE_SLOWDOWN = 2.0
"""``drive_slowed`` multiplies the drive's time constant by this (half as fast)."""
TRACTION_FREE_HOVER = math.inf
"""``traction_unbounded`` tells the drive the hover pushes with this much (no traction bound)."""
GRIP_READING_SCALE = 0.5
"""``grip_reading`` scales the controller's grip reading by this."""
HOVER_READING_SCALE = 0.5
"""``hover_reading`` scales the controller's hover reading by this."""
GRIP_FORCE = 700.0
"""``grip_weakened`` sets the grip budget to this, N: above a 70 kg player's weight (686.7 N),
below what a climb at 1 m/s² needs (756.7 N)."""
NULLIFY_LEFT = 0.03
"""``nullify_leaks`` leaves this fraction of gravity on a nullified body."""
PERCEIVED_ROTATION = math.radians(30.0)
"""``perceived_gravity_rotated`` turns the perceived gravity and up by this, rad (CCW)."""
BYPASS_CUTOFF = 1e9
"""``filter_bypassed`` sets the 1€ minimum cutoff to this, Hz: the filter passes every sample."""


@_register("hover_reaction")
def _hover_reaction() -> Iterator[None]:
    """The hover's reaction on the ground is cut to 5 % (Newton's third law broken): a plank,
    a crate or a raft no longer feels the player standing on it."""
    keep = HOVER_REACTION_SCALE

    def then(a: dict[str, Any], force: float) -> float:
        hit = a["hit"]
        nx, ny = hit.normal
        back = (1.0 - keep) * force
        a["world"].apply_force(
            hit.body, (back * nx, back * ny), point=hit.point, category=Category.SUPPORT
        )
        return force

    with _after(Controller, "_hover", ("world", "hit"), then):
        yield


@_register("hover_removed")
def _hover_removed() -> Iterator[None]:
    """No hover spring at all: the capsule stands on its own end cap, and with no hover force
    the drive has no traction."""
    with _replaced(Controller, "_hover", lambda _: lambda *a, **k: 0.0):
        yield


@_register("hover_reading")
def _hover_reading() -> Iterator[None]:
    """The controller's own hover reading is halved (the force it applies is unchanged)."""

    def then(a: dict[str, Any], result: None) -> None:
        me = a["self"]
        hx, hy = me.last_forces.hover
        k = HOVER_READING_SCALE
        me.last_forces = dataclasses.replace(me.last_forces, hover=(k * hx, k * hy))

    with _after(Controller, "_control", ("self",), then):
        yield


@_register("drive_world_frame")
def _drive_world_frame() -> Iterator[None]:
    """The drive works relative to the world instead of the ground under the feet: standing still
    means standing still in the world, so a platform slides away under the player."""

    def still(hit: Any) -> Any:
        motion = {
            f.name: (0.0, 0.0)
            for f in dataclasses.fields(hit)
            if f.name.endswith(("velocity", "acceleration"))
        }
        return dataclasses.replace(hit, **motion)

    with _with_argument(Controller, "_drive", "hit", still):
        yield


@_register("drive_slowed")
def _drive_slowed() -> Iterator[None]:
    """The drive closes the gap to its goal velocity half as fast (its time constant doubled)."""
    with _controller_config(drive_time=lambda t: t * DRIVE_SLOWDOWN):
        yield


@_register("ground_acceleration_ignored")
def _ground_acceleration_ignored() -> Iterator[None]:
    """The drive and the hover no longer feed the ground's own acceleration forward: on an
    accelerating platform the player lags behind it by its acceleration × the drive's time
    constant."""
    with _replaced(Controller, "_ground_acceleration", lambda _: lambda *a, **k: (0.0, 0.0)):
        yield


@_register("traction_unbounded")
def _traction_unbounded() -> Iterator[None]:
    """The drive is no longer bounded by traction × hover force (only by its budget): a body
    with no weight on its feet still pushes itself along the ground."""
    with _with_argument(Controller, "_drive", "hover", lambda _: TRACTION_FREE_HOVER):
        yield


@_register("balance_off")
def _balance_off() -> Iterator[None]:
    """No balance torque: the capsule no longer keeps itself upright."""
    with _replaced(Controller, "_balance", lambda _: lambda *a, **k: 0.0):
        yield


@_register("grip_reading")
def _grip_reading() -> Iterator[None]:
    """The controller's own grip reading is halved (the joint itself is unchanged)."""

    def make(original: property) -> property:
        assert original.fget is not None
        get = original.fget
        return property(lambda self: GRIP_READING_SCALE * get(self))

    with _replaced(Controller, "grip", make):
        yield


@_register("grip_weakened")
def _grip_weakened() -> Iterator[None]:
    """The grip joint's force budget drops to 700 N: it holds a 70 kg player's weight but not
    the extra a climbing flyer asks of it."""
    with _controller_config(grip_force=lambda _: GRIP_FORCE):
        yield


@_register("push_reaction_off")
def _push_reaction_off() -> Iterator[None]:
    """The push's reaction on the pusher is not applied (the pushed body still gets its push,
    and the controller still reports it)."""

    def then(a: dict[str, Any], force: tuple[float, float]) -> tuple[float, float]:
        me = a["self"]
        a["world"].apply_force(me.body, (-force[0], -force[1]), category=Category.SUPPORT)
        return force

    with _after(Controller, "_push", ("self", "world"), then):
        yield


@_register("nullify_leaks")
def _nullify_leaks() -> Iterator[None]:
    """Nullifying a body's gravity leaves 3 % of it on."""

    def leak(rule: GravityRule | None) -> GravityRule | None:
        if rule is not None and rule.scale == 0.0:
            return GravityRule(scale=NULLIFY_LEFT, direction=rule.direction)
        return rule

    with _with_argument(world_mod.World, "set_gravity_rule", "rule", leak):
        yield


@_register("own_gravity_ignored")
def _own_gravity_ignored() -> Iterator[None]:
    """The controller ignores its own-gravity switch (the intent's ``gravity``)."""
    with _with_argument(
        Controller,
        "_gravity_actions",
        "it",
        lambda it: dataclasses.replace(it, gravity=None),
    ):
        yield


@_register("perceived_gravity_rotated")
def _perceived_gravity_rotated() -> Iterator[None]:
    """The inner ear is turned by 30°: perceived gravity and perceived up, as the world reports
    them to controllers and checks, are rotated counter-clockwise."""

    def turned(original: Callable[..., tuple[float, float]]) -> Callable[..., tuple[float, float]]:
        return lambda self, name: _rotate(original(self, name), PERCEIVED_ROTATION)

    with (
        _replaced(force_api.ForceAPI, "perceived_gravity", turned),
        _replaced(force_api.ForceAPI, "perceived_up", turned),
    ):
        yield


@_register("filter_bypassed")
def _filter_bypassed() -> Iterator[None]:
    """Perceived gravity is not filtered: no median-of-3 stage and a 1€ cutoff so high that every
    raw sample (every bounce's spike) passes straight through."""
    with _with_argument(
        perception_mod.PerceivedGravity,
        "__init__",
        "config",
        lambda c: dataclasses.replace(c, min_cutoff=BYPASS_CUTOFF, spike_filter=False),
    ):
        yield


@_register("mover_velocity_late")
def _mover_velocity_late() -> Iterator[None]:
    """Movers set the velocity of the step before: each kinematic body trails its path by one
    step (it starts a step late and never catches up)."""

    def make(original: Callable[..., None]) -> Callable[..., None]:
        _parameter(original, movers_mod.Mover, "t")
        _parameter(original, movers_mod.Mover, "dt")

        def drive(self: Any, t: float, dt: float) -> None:
            original(self, t=t - dt, dt=dt)

        return drive

    with _replaced(movers_mod.Mover, "drive", make):
        yield


@_register("gravity_rule_ignored")
def _gravity_rule_ignored() -> Iterator[None]:
    """The gravity stage ignores per-body rules (nullified, scaled or own gravity): every body
    falls in the field, while the world still reports each body's rule (so its controller
    believes it)."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        def without_rules(self: Any, *args: Any) -> Any:
            rules, self._rules = self._rules, {}
            try:
                return original(self, *args)
            finally:
                self._rules = rules

        return without_rules

    # apply: the corrections in a uniform field; forces_at: a field that varies in space, which
    # the physics stage evaluates after the gravity stage.
    with (
        _replaced(gravity_stage.GravityStage, "apply", make),
        _replaced(gravity_stage.GravityStage, "forces_at", make),
    ):
        yield


@_register("ring_spin_stopped")
def _ring_spin_stopped() -> Iterator[None]:
    """Spinning movers stand still: a ``spin`` path keeps its starting angle."""
    with _replaced(movers_mod.Spin, "pose", lambda _: lambda self, t: (self.position, self.angle)):
        yield


# -- the matrix ----------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Outcome:
    """One run of a level, clean (``fault`` None) or under a break.

    Attributes:
        level: the level's name.
        fault: the break applied, or None for the clean run.
        declared: the level declares the break in ``catches`` (True for the clean run).
        checks: how many checks the level has.
        failed: the names of the checks that failed.
        error: why the run could not be made (the break did not apply, or the run raised).
        seconds: wall-clock time of the run, s.
    """

    level: str
    fault: str | None
    declared: bool
    checks: int
    failed: tuple[str, ...]
    error: str | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """The clean run passes every check; a declared break is caught by at least one; an
        undeclared one only has to run."""
        if self.error is not None:
            return False
        if self.fault is None:
            return not self.failed
        return bool(self.failed) or not self.declared


@dataclass(frozen=True, slots=True)
class Row:
    """One level of the matrix: its clean run and one outcome per break tried."""

    level: str
    clean: Outcome
    breaks: tuple[Outcome, ...]

    @property
    def ok(self) -> bool:
        return self.clean.ok and all(o.ok for o in self.breaks)


def run(level: Level, name: str, fault: str | None = None) -> Outcome:
    """Build and run ``level`` (called ``name``) to its end, under the break ``fault`` if given,
    and say which checks failed."""
    from playground.expectations import watch
    from playground.scene import build

    declared = fault is None or fault in level.catches
    start = time.perf_counter()
    try:
        with apply(fault) if fault is not None else _nothing():
            scene = build(level)
            checks = watch(scene)
            scene.run(level.settings.seconds)
            results = checks.results()
    except BreakError as exc:
        return Outcome(name, fault, declared, len(level.expect), (), f"cannot apply: {exc}")
    except Exception as exc:  # a broken feature may raise anywhere: report it, keep going
        return Outcome(name, fault, declared, len(level.expect), (), f"{type(exc).__name__}: {exc}")
    failed = tuple(r.name for r in results if not r.passed)
    return Outcome(name, fault, declared, len(results), failed, seconds=time.perf_counter() - start)


@contextmanager
def _nothing() -> Iterator[None]:
    yield


def matrix(
    levels: Sequence[tuple[str, Level]],
    faults: Sequence[str] | None = None,
    progress: Callable[[str], None] | None = None,
) -> list[Row]:
    """Run each level clean and under each of its declared breaks (or under ``faults``, if
    given, declared or not); ``progress(label)`` is called before each run."""
    rows = []
    for name, level in levels:
        tried = list(level.catches) if faults is None else list(faults)
        if progress is not None:
            progress(f"{name} clean")
        clean = run(level, name)
        outcomes = []
        for fault in tried:
            if progress is not None:
                progress(f"{name} {fault}")
            outcomes.append(run(level, name, fault))
        rows.append(Row(name, clean, tuple(outcomes)))
    return rows
