"""Chapter 10, staying stable (docs/chapters/10-stability.md): the hard scenes' stability
matrix, where each breaks as the step grows, the guards removed, and the chapter's figure."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import pymunk

from playground.controller.spring import hover_spring
from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World
from tools.figures.plot import save
from tools.figures.registry import figure, number
from tools.figures.runs import Array

CH10_DTS = (1 / 60, 1 / 240)
"""s: the stability matrix's steps (as tests/test_stability.py)."""

CH10_ITERATIONS = (2, 10)
"""The matrix's solver iterations (as tests/test_stability.py)."""

CH10_SUBSTEPS = (1, 4)
"""The matrix's substeps (the chapter adds them to the tests' matrix)."""

CH10_RATES = (60.0, 30.0, 20.0, 15.0, 10.0)
"""Hz: the steps, ever coarser, at which each hard scene is run to find where it breaks (1/10 s
is the largest step a world accepts)."""


@dataclass(frozen=True, slots=True)
class HardOutcome:
    """One run of a hard scene: what broke first (``None``: nothing), at which step, and the
    deepest penetration seen before (m)."""

    broke: str | None
    step: int
    penetration: float


@cache
def hard_run(scene: str, dt: float, iterations: int = 10, substeps: int = 1) -> HardOutcome:
    """Run the hard scene ``scene`` with every invariant checked (see
    :mod:`tools.stability`); the runtime guard's stop counts as a breach too."""
    from playground.world.guard import RunawayError
    from tools.stability import SCENES as HARD
    from tools.stability import InvariantError, run_checked

    hard = HARD[scene](WorldConfig(dt=dt, iterations=iterations, substeps=substeps))
    try:
        worst = run_checked(hard)
    except InvariantError as exc:
        return HardOutcome(exc.invariant, exc.step, math.nan)
    except RunawayError:
        return HardOutcome("runaway", hard.world.steps, math.nan)
    return HardOutcome(None, 0, worst["penetration"])


def hard_scenes() -> tuple[str, ...]:
    """The hard scenes' names, in the stability suite's order."""
    from tools.stability import SCENES as HARD

    return tuple(HARD)


def breaking_rate(scene: str, iterations: int = 10) -> float:
    """The finest of :data:`CH10_RATES` (Hz) at which ``scene`` breaks an invariant, stepping
    ever coarser; 0 if it holds at all of them."""
    for rate in CH10_RATES:
        if hard_run(scene, 1.0 / rate, iterations).broke is not None:
            return rate
    return 0.0


@number
def ch10_runs() -> float:
    """Runs in the chapter's matrix: scenes × dt × iterations × substeps."""
    return float(len(hard_scenes()) * len(CH10_DTS) * len(CH10_ITERATIONS) * len(CH10_SUBSTEPS))


@number
def ch10_matrix_breaches() -> float:
    """Runs of the matrix that break an invariant."""
    return float(
        sum(
            hard_run(sc, dt, it, sub).broke is not None
            for sc in hard_scenes()
            for dt in CH10_DTS
            for it in CH10_ITERATIONS
            for sub in CH10_SUBSTEPS
        )
    )


@number
def ch10_chaos_penetration_mm() -> float:
    """Deepest overlap in elastic chaos at 1/60 s, 2 iterations, 1 substep, mm."""
    return 1000.0 * hard_run("elastic chaos", 1 / 60, 2, 1).penetration


@number
def ch10_chaos_penetration_sub_mm() -> float:
    """The same with 4 substeps, mm."""
    return 1000.0 * hard_run("elastic chaos", 1 / 60, 2, 4).penetration


@number
def ch10_break_crusher() -> float:
    """:func:`breaking_rate` of the hard crusher, Hz."""
    return breaking_rate("crusher")


@number
def ch10_break_ring() -> float:
    """:func:`breaking_rate` of the hard spinning ring, Hz."""
    return breaking_rate("spinning ring")


@number
def ch10_break_tiny() -> float:
    """:func:`breaking_rate` of the hard tiny under heavy, Hz."""
    return breaking_rate("tiny under heavy")


@number
def ch10_holding_scenes() -> float:
    """Hard scenes that hold every invariant at every rate of :data:`CH10_RATES`."""
    return float(sum(breaking_rate(sc) == 0.0 for sc in hard_scenes()))


@number
def ch10_ring_20_substeps_holds() -> float:
    """The exercise: 1 if the hard spinning ring holds at 1/20 s with 4 substeps, else 0."""
    return 1.0 if hard_run("spinning ring", 1 / 20, 10, 4).broke is None else 0.0


@number
def ch10_ring_20_iterations_step() -> float:
    """The exercise: the step at which it breaks at 1/20 s with 40 iterations and 1 substep."""
    return float(hard_run("spinning ring", 1 / 20, 40, 1).step)


THIN_WALL = 0.1
"""m: ring_room's default half thickness of the wall (0.2 m thick), which the hard spinning ring
replaces by 0.3 m (0.6 m thick)."""

THIN_WALL_DT = 1 / 40
"""s: the step at which chapter 10 runs the hard spinning ring with the default wall."""


@cache
def thin_ring_outcome() -> HardOutcome:
    """The hard spinning ring at THIN_WALL_DT, 10 iterations, with ring_room's default wall."""
    from tools import stability

    saved = stability.RING_WALL
    stability.RING_WALL = THIN_WALL
    try:
        return hard_run.__wrapped__("spinning ring", THIN_WALL_DT, 10, 1)
    finally:
        stability.RING_WALL = saved


@number
def ch10_thin_wall_escape() -> float:
    """When a body leaves the ring through the default wall (THIN_WALL_DT, 10 iterations), s."""
    return thin_ring_outcome().step * THIN_WALL_DT


GUARD_OMEGA_DT = 2.1
"""The naive spring run without its guards: 2πf·dt just above the limit 2 of an undamped one."""


@cache
def runaway_run(guard: bool) -> tuple[Array, int, str]:
    """A 1 kg body on an undamped spring stepped beyond its stability limit (2πf·dt = 2.1) with
    the force read from the position the integrator is about to use (chapter 5's scheme, which is
    stable only below 2), tracked so its readings are checked.

    Returns (rows of step, |x| (m), |support| (N), |perceived gravity| (m/s²); the step at which
    the runtime guard stopped it, 0 if it did not; the guard's message).
    """
    from playground.world.guard import RunawayError

    world = World(WorldConfig(guard=guard), gravity=(0.0, 0.0))
    body = pymunk.Body(1.0, math.inf)
    world.add("bob", body)
    body.position = (0.01, 0.0)
    world.track("bob")
    w = GUARD_OMEGA_DT / world.config.dt

    def spring(wd: World) -> None:
        x, v = body.position.x, body.velocity.x
        if math.isfinite(x) and math.isfinite(v):
            wd.apply_force(body, (hover_spring(w * w, 0.0, 1.0, -x, v, wd.config.dt), 0.0))

    world.on(Stage.CONTROL, spring)
    rows: list[list[float]] = []
    # Unguarded, the numbers overflow on purpose: numpy's overflow warnings are the point, not news.
    for k in range(1, 1201):
        try:
            with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                world.step()
        except (RunawayError, ValueError) as exc:  # the runaway bounds: on state or on a force
            return np.array(rows, dtype=np.float64), k, str(exc)
        f = world.forces("bob")
        rows.append(
            [float(k), abs(body.position.x), float(np.hypot(*f.support)),
             float(np.hypot(*world.perceived_gravity("bob")))]
        )  # fmt: skip
    return np.array(rows, dtype=np.float64), 0, ""


@number
def ch10_guard_step() -> float:
    """The step at which the runtime guard stops the runaway spring."""
    return float(runaway_run(True)[1])


@number
def ch10_unguarded_last_step() -> float:
    """Without the guard: the last step the runaway spring completes before its own force
    overflows (a force that is not a finite number is refused even then)."""
    return float(runaway_run(False)[0][-1, 0])


@number
def ch10_unguarded_log10_x() -> float:
    """Without the guard: log10 of |x| (m) at that last step."""
    return math.log10(runaway_run(False)[0][-1, 1])


@number
def ch10_guard_log10_x() -> float:
    """With the guard: log10 of |x| (m) at the last step before it stopped the world."""
    return math.log10(runaway_run(True)[0][-1, 1])


@figure("10-stability.png")
def fig_ch10(path: Path) -> Path:
    """The stability matrix; where each scene breaks as dt grows; the runaway guard."""
    import matplotlib.pyplot as plt

    scenes = hard_scenes()
    cols = [(dt, it, sub) for dt in CH10_DTS for it in CH10_ITERATIONS for sub in CH10_SUBSTEPS]
    pen = np.array([[hard_run(sc, *c).penetration * 1000.0 for c in cols] for sc in scenes])
    fig = plt.figure(figsize=(9.0, 10.5))
    grid = fig.add_gridspec(3, 1, height_ratios=[1.3, 1.0, 1.0])
    a = fig.add_subplot(grid[0])
    shown = np.where(np.isfinite(pen), np.log10(np.maximum(pen, 0.1)), np.nan)
    image = a.imshow(shown, cmap="viridis", aspect="auto", vmin=-1, vmax=3)
    for i in range(len(scenes)):
        for j in range(len(cols)):
            v = pen[i, j]
            text = "broke" if not np.isfinite(v) else f"{v:.0f}" if v >= 1 else f"{v:.1f}"
            a.text(j, i, text, ha="center", va="center", fontsize=8,
                   color="w" if np.isfinite(v) and shown[i, j] < 1.5 else "k")  # fmt: skip
    a.set_yticks(range(len(scenes)), scenes)
    a.set_xticks(
        range(len(cols)), [f"1/{round(1 / dt)} s\n{it} it\n×{sub}" for dt, it, sub in cols],
        fontsize=8,
    )  # fmt: skip
    a.set_title(
        "every invariant held in every cell; the number: deepest overlap into static ground (mm)",
        fontsize=10,
    )
    fig.colorbar(image, ax=a, label="log10 overlap (mm)")
    b = fig.add_subplot(grid[1])
    for i, sc in enumerate(scenes):
        for rate in CH10_RATES:
            out = hard_run(sc, 1.0 / rate)
            b.plot(rate, i, "o" if out.broke is None else "X",
                   color="C2" if out.broke is None else "C3", ms=9)  # fmt: skip
            if out.broke is not None:
                b.annotate(out.broke, (rate, i), xytext=(6, 4), textcoords="offset points",
                           fontsize=7)  # fmt: skip
    b.set_yticks(range(len(scenes)), scenes)
    b.set_xscale("log")
    b.set_xticks(CH10_RATES, [f"1/{r:g}" for r in CH10_RATES])
    b.minorticks_off()
    b.invert_xaxis()
    b.invert_yaxis()  # the matrix's order, top to bottom
    b.set_xlabel("dt (s), 10 iterations — green: holds, red: the first invariant it breaks")
    b.set_title("where each scene breaks as the step grows")
    b.grid(True, alpha=0.3)
    c = fig.add_subplot(grid[2])
    free, _, _ = runaway_run(False)
    held, stop, _ = runaway_run(True)
    c.plot(free[:, 0], np.log10(free[:, 1]), color="C3", label="runtime guard off")
    c.plot(held[:, 0], np.log10(held[:, 1]), color="C0", lw=4, label="guard on: the world stops")
    c.axvline(stop, color="C0", ls="--", lw=1)
    c.set_xlabel("step")
    c.set_ylabel("log10 |x| (x in m)")
    c.set_title(f"a spring stepped beyond its limit (2πf·dt = {GUARD_OMEGA_DT:g})")
    c.legend(fontsize=8)
    c.grid(True, alpha=0.3)
    return save(fig, path)
