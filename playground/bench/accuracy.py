"""The accuracy sweep: error against exact answers, filter jitter and lag, and cost per step.

One *point* is a scene (:mod:`playground.bench.scenes`), solver knobs (dt, substeps, iterations)
and a force estimator; it is simulated once, then every filter is run over the recorded signal.
Points are independent, so the sweep runs on any :class:`concurrent.futures.Executor`: a
``ProcessPoolExecutor`` by default, or a cluster's (Dask's ``Client.get_executor()``) unchanged.

Definitions (all per point and filter; docs/accuracy.md states them for readers):

* **error**: RMS over the measured window of |F̂ − F*| / scale, F̂ the filtered reading and F* the
  exact force (N); for the landing scene |Σ F̂·dt − Σ F*·dt| / (m·√(2gh)), the impulse error.
* **jitter**: standard deviation over the window of the residual F̂ − F*, / scale; for a static
  scene that is the spread of the filtered signal at rest, the 1€ paper's jitter (NaN for the
  landing scene, whose force is meant to change).
* **lag**: the delay (s) with which the filter follows a ramp of |g| per second in specific force
  (m/s²), once the ramp has run one second: (x(t) − x̂(t)) / slope.
* **cost**: µs per step of stepping the world and taking the reading, median of repeated blocks,
  plus the filter's µs per call; **bare** is a copy of the same space stepped by pymunk alone in
  blocks interleaved with the world's, so their ratio holds on a busy machine.

>>> rows = measure(Point("rest", Knobs(dt=1 / 60), "reverse"), filters=("none",), repeats=1)
>>> rows[0].error < 1e-6
True
"""

from __future__ import annotations

import importlib
import math
import os
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import Executor, Future, ProcessPoolExecutor
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from playground.bench.scenes import SCENES, Knobs, Scene, build
from playground.filters.chain import FilterChain
from playground.filters.median import Median3
from playground.filters.one_euro import ExponentialMovingAverage, OneEuroFilter
from playground.filters.row_filter import Filter
from playground.gravity import STANDARD_GRAVITY

__all__ = [
    "ESTIMATORS",
    "FILTERS",
    "Point",
    "Result",
    "filter_lag",
    "measure",
    "plan",
    "sweep",
]

Estimator = Literal["reverse", "contact", "finite-difference"]

ESTIMATORS: tuple[Estimator, ...] = ("reverse", "contact", "finite-difference")
"""reverse: reverse integration (``forces().support``); contact: the arbiter-impulse sum
(``forces().contact`` with the contact split on) plus our support forces; finite-difference:
m·(x_{k} − 2x_{k−1} + x_{k−2})/dt² − m·g, centred on x_{k−1} (the end of the step before), so
it is compared with the exact answer there, the mean of the two mid-step answers around it."""

FILTERS: dict[str, Callable[[], Filter] | None] = {
    "none": None,
    "ema 5 Hz": lambda: ExponentialMovingAverage(cutoff=5.0),
    "1€ 1 Hz β0": lambda: OneEuroFilter(min_cutoff=1.0, beta=0.0),
    "1€ 2 Hz β0.05": lambda: OneEuroFilter(min_cutoff=2.0, beta=0.05),
    "1€ 5 Hz β0.5": lambda: OneEuroFilter(min_cutoff=5.0, beta=0.5),
    "med3 + 1€ 2 Hz β0.05": lambda: FilterChain(Median3(), OneEuroFilter(2.0, 0.05)),
}
"""The filters compared, applied to the specific force (m/s²) as perception does; by label."""

RAMP_SLOPE = STANDARD_GRAVITY
"""Slope of the lag test's ramp, m/s² per second (gravity turning over in about a second)."""

RAMP_TIME = 1.0
"""Seconds the ramp runs before its lag is read (every filter here has settled by then)."""

BLOCK_STEPS = 50
"""Steps per timed block; the cost is the median over blocks."""


@dataclass(frozen=True, slots=True)
class Point:
    """One simulation of the sweep: a scene, its knobs and an estimator."""

    scene: str
    knobs: Knobs
    estimator: Estimator


@dataclass(frozen=True, slots=True)
class Result:
    """One row of the sweep's table (see the module doc for the definitions).

    Attributes:
        scene, dt (s), substeps, iterations, estimator, filter: the point and filter.
        error: relative error (1 = 100 %).  jitter: relative.  lag: s.
        cost_us: µs per step with the reading and filter.  bare_us: bare pymunk, µs per step.
        ratio: cost_us / bare_us.
    """

    scene: str
    dt: float
    substeps: int
    iterations: int
    estimator: str
    filter: str
    error: float
    jitter: float
    lag: float
    cost_us: float
    bare_us: float
    ratio: float


def _positions(scene: Scene) -> NDArray[np.float64]:
    """Σ m_i·x_i over the measured bodies, kg·m."""
    out = np.zeros(2)
    for name in scene.bodies:
        b = scene.world.body(name)
        out += b.mass * np.array([b.position.x, b.position.y])
    return out


class _Reader:
    """Takes one estimator's reading of the summed support force (N) after each step."""

    def __init__(self, scene: Scene, estimator: Estimator) -> None:
        self.scene = scene
        self.estimator = estimator
        self.mass = scene.mass
        g = scene.world.gravity_at(scene.bodies[0])
        self.weight = np.array(g) * self.mass
        self.history: list[NDArray[np.float64]] = [_positions(scene)]

    def read(self) -> NDArray[np.float64]:
        world = self.scene.world
        if self.estimator == "finite-difference":
            self.history.append(_positions(self.scene))
            if len(self.history) > 3:
                del self.history[0]
            if len(self.history) < 3:
                return np.full(2, np.nan)
            x2, x1, x0 = self.history
            dt = world.config.dt
            accel_times_mass: NDArray[np.float64] = (x0 - 2.0 * x1 + x2) / (dt * dt)
            return accel_times_mass - self.weight
        out = np.zeros(2)
        for name in self.scene.bodies:
            f = world.forces(name)
            if self.estimator == "reverse":
                out += f.support
            else:
                out += np.array(f.contact) + np.array(f.support) - np.array(f.engine)
        return out


def filter_lag(make: Callable[[], Filter] | None, dt: float) -> float:
    """Delay (s) of a filter following a ramp of :data:`RAMP_SLOPE` after :data:`RAMP_TIME`.

    >>> round(filter_lag(lambda: ExponentialMovingAverage(cutoff=1.0), 1e-3), 3)
    0.159
    """
    if make is None:
        return 0.0
    f = make()
    n = round(RAMP_TIME / dt)
    y = 0.0
    for k in range(n + 1):
        y = f.filter(RAMP_SLOPE * k * dt, dt)
    return (RAMP_SLOPE * n * dt - y) / RAMP_SLOPE


def _run_filter(
    make: Callable[[], Filter] | None, raw: NDArray[np.float64], dt: float
) -> NDArray[np.float64]:
    if make is None:
        return raw
    f = make()
    return np.array([f.filter(row.reshape(1, 2), dt)[0] for row in raw], dtype=np.float64)


def _filter_cost(make: Callable[[], Filter] | None, dt: float, repeats: int) -> float:
    """µs per call of the filter on one 2-vector row."""
    if make is None:
        return 0.0
    f = make()
    x = np.array([[0.0, -STANDARD_GRAVITY]])
    f.filter(x, dt)
    blocks = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(BLOCK_STEPS):
            f.filter(x, dt)
        blocks.append((time.perf_counter() - t0) / BLOCK_STEPS)
    return 1e6 * statistics.median(blocks)


def _step_costs(scene: Scene, reader: _Reader, repeats: int) -> tuple[float, float]:
    """(world µs per step with the reading, bare pymunk µs per step), interleaved blocks."""
    world = scene.world
    bare = world.space.copy()
    h = world.config.dt / world.config.substeps
    substeps = range(world.config.substeps)
    ours, theirs = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(BLOCK_STEPS):
            world.step()
            reader.read()
        ours.append((time.perf_counter() - t0) / BLOCK_STEPS)
        t0 = time.perf_counter()
        for _ in range(BLOCK_STEPS):
            for _ in substeps:
                bare.step(h)
        theirs.append((time.perf_counter() - t0) / BLOCK_STEPS)
    return 1e6 * statistics.median(ours), 1e6 * statistics.median(theirs)


def measure(
    point: Point, filters: Sequence[str] = tuple(FILTERS), repeats: int = 5
) -> list[Result]:
    """Simulate one point and evaluate every filter in ``filters``: one :class:`Result` each."""
    for name in filters:
        if name not in FILTERS:
            raise ValueError(f"filters: expected names from {list(FILTERS)}, got {name!r}")
    if point.estimator not in ESTIMATORS:
        raise ValueError(f"estimator: expected one of {ESTIMATORS}, got {point.estimator!r}")
    knobs = point.knobs
    if point.estimator == "contact" and not knobs.contact_split:
        knobs = Knobs(knobs.dt, knobs.substeps, knobs.iterations, contact_split=True)
    scene = build(point.scene, knobs)
    world = scene.world
    dt = knobs.dt
    n_settle = round(scene.settle / dt)
    n_total = n_settle + round(scene.measure / dt)
    reader = _Reader(scene, point.estimator)
    raw = np.empty((n_total, 2))
    exact = np.empty((n_total, 2))
    for k in range(n_total):
        world.step()
        raw[k] = reader.read()
        exact[k] = scene.exact(world)
    if point.estimator == "finite-difference":
        # Against its own centre, the start of the step: compared with the step's middle, a
        # force that turns at ω would show a half-step time offset as an error of ω·dt/2.
        exact[1:] = 0.5 * (exact[1:] + exact[:-1])
    step_us, bare_us = _step_costs(scene, reader, repeats)
    results = []
    mass = scene.mass
    for name in filters:
        make = FILTERS[name]
        smooth = _run_filter(make, raw / mass, dt) * mass
        residual = (smooth - exact)[n_settle:]
        if scene.integral:
            total = np.nansum(residual, axis=0) * dt
            error = float(np.hypot(*total)) / scene.scale
        else:
            error = float(np.sqrt(np.nanmean(np.sum(residual**2, axis=1)))) / scene.scale
        if scene.integral:
            jitter = math.nan  # the force is meant to change: no "at rest" to measure
        else:
            spread = residual - np.nanmean(residual, axis=0)
            jitter = float(np.sqrt(np.nanmean(np.sum(spread**2, axis=1)))) / scene.scale
        cost = step_us + _filter_cost(make, dt, repeats)
        results.append(
            Result(
                scene=point.scene,
                dt=dt,
                substeps=knobs.substeps,
                iterations=knobs.iterations,
                estimator=point.estimator,
                filter=name,
                error=error,
                jitter=jitter,
                lag=filter_lag(make, dt),
                cost_us=cost,
                bare_us=bare_us,
                ratio=cost / bare_us,
            )
        )
    return results


DTS = (1 / 30, 1 / 60, 1 / 120, 1 / 240, 1 / 480)
"""Steps swept, s."""

ITERATIONS = (1, 2, 4, 10, 20, 40)
"""Solver iterations swept (at dt = 1/120 s)."""

SUBSTEPS = (2, 4)
"""Substeps swept (at dt = 1/30 s, to compare with a smaller dt of the same inner step)."""


def plan(size: Literal["quick", "default"] = "default") -> list[Point]:
    """The points of a sweep, one knob at a time around dt = 1/120 s, 1 substep, 10 iterations.

    ``quick`` (for CI) keeps every scene but only dt ∈ {1/30, 1/120} s, iterations ∈ {2, 10} and
    the contact and finite-difference estimators at the base knobs only.

    >>> len(plan("quick")), len(plan("default"))
    (39, 276)
    """
    base = Knobs()
    if size == "quick":
        knobs = [Knobs(dt=1 / 30), Knobs(iterations=2), base]
        points = [Point(s, k, "reverse") for s in SCENES for k in knobs]
        for s, builder in SCENES.items():
            points.append(Point(s, base, "finite-difference"))
            if not builder(base).joints:
                points.append(Point(s, base, "contact"))
        return points
    if size != "default":
        raise ValueError(f"size: expected 'quick' or 'default', got {size!r}")
    grid: list[Knobs] = []
    for k in (
        *(Knobs(dt=dt) for dt in DTS),
        *(Knobs(iterations=i) for i in ITERATIONS),
        *(Knobs(dt=1 / 30, substeps=n) for n in SUBSTEPS),
    ):
        if k not in grid:
            grid.append(k)
    joints = {s: builder(base).joints for s, builder in SCENES.items()}
    return [
        Point(s, k, e)
        for s in SCENES
        for k in grid
        for e in ESTIMATORS
        if not (e == "contact" and joints[s])
    ]


def sweep(
    points: Iterable[Point],
    *,
    executor: Executor | None = None,
    workers: int | None = None,
    progress: bool = True,
    repeats: int = 5,
) -> list[Result]:
    """Measure every point on ``executor`` and return the rows in the order of ``points``.

    Without an executor a ``ProcessPoolExecutor`` of ``workers`` processes (default: the CPU
    count) is made and shut down; ``workers=0`` runs in this process. Any
    ``concurrent.futures.Executor`` works, e.g. Dask's ``Client(...).get_executor()``. The
    progress bar needs tqdm (``pip install 'pymunk-playground[bench]'``); without it there is none.
    """
    todo = list(points)
    bar = _progress(len(todo)) if progress else None
    if workers == 0 and executor is None:
        done = []
        for p in todo:
            done.append(measure(p, repeats=repeats))
            if bar is not None:
                bar.update(1)
        if bar is not None:
            bar.close()
        return [r for rows in done for r in rows]
    own = executor is None
    pool = executor if executor is not None else ProcessPoolExecutor(workers or os.cpu_count())
    futures: list[Future[list[Result]]] = []
    try:
        futures.extend(pool.submit(measure, p, tuple(FILTERS), repeats) for p in todo)
        if bar is not None:
            for f in futures:
                f.add_done_callback(lambda _: bar.update(1))
        rows = [r for f in futures for r in f.result()]
    except BaseException:
        # Ctrl-C (or a failed point): drop the points not started and stop the running ones,
        # rather than wait seconds for each point already submitted.
        for f in futures:
            f.cancel()
        if own:
            _abandon(pool)
        raise
    else:
        if own:
            pool.shutdown()
    finally:
        if bar is not None:
            bar.close()
    return rows


def _abandon(pool: Executor) -> None:
    """Shut a pool down at once: pending points cancelled, the worker processes terminated.

    ``shutdown(cancel_futures=True)`` alone still lets each running point finish, and the
    interpreter joins the workers at exit; a process pool's workers are ended here instead
    (``_processes`` is the standard library's own map of them, absent on other executors).
    """
    pool.shutdown(wait=False, cancel_futures=True)
    processes: dict[int, Any] = getattr(pool, "_processes", None) or {}
    for process in list(processes.values()):
        process.terminate()
    for process in list(processes.values()):
        process.join()


def _progress(total: int) -> Any:
    try:
        tqdm = importlib.import_module("tqdm").tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="point", desc="accuracy", leave=False, disable=None)
