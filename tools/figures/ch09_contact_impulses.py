"""Chapter 9, contact impulses (docs/chapters/09-contact-impulses.md): stale arbiters on a
falling platform in bare pymunk and in a World, and the chapter's figure."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import pymunk

from playground.world.config import WorldConfig
from playground.world.schedule import Stage
from playground.world.world import World
from tools.figures.plot import axes, save
from tools.figures.registry import figure, number
from tools.figures.runs import DT, Array, G

DROP_ACCELERATION = 3.0
"""m/s²: chapter 9's platform accelerates downward at this rate (less than g: the box rides it)."""

DROP_START = 0.5
"""s: when chapter 9's platform starts to fall."""


@cache
def stale_run(acceleration: float = DROP_ACCELERATION) -> Array:
    """A 10 kg box on a kinematic platform that starts falling at ``acceleration`` (m/s²), in bare
    pymunk (no playground code between the reader and the engine).

    Columns: t (s), reverse integration's vertical force m·(v₁ − v₀)/h + m·g, the sum of the
    box's ``Arbiter.total_impulse`` / h (vertical; N), and 1 where the box touched the platform
    in the step before the previous one but not in the previous one (a contact re-made while its
    arbiter was still cached), else 0.
    """
    space = pymunk.Space()
    space.gravity = (0.0, -G)
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    floor = pymunk.Poly.create_box(platform, (4.0, 0.2))
    floor.friction = 1.0
    space.add(platform, floor)
    m = 10.0
    box = pymunk.Body(m, pymunk.moment_for_box(m, (0.5, 0.5)))
    box.position = (0.0, 0.35)
    shape = pymunk.Poly.create_box(box, (0.5, 0.5))
    shape.friction = 1.0
    space.add(box, shape)
    rows: list[list[float]] = []
    touching: list[bool] = []
    for k in range(round(1.0 / DT)):
        t = k * DT
        platform.velocity = (0.0, -acceleration * max(t - DROP_START, 0.0))
        v0 = box.velocity.y
        space.step(DT)
        arbiters: list[pymunk.Arbiter] = []
        box.each_arbiter(arbiters.append)
        impulse = sum(
            (a.total_impulse.y if a.shapes[0].body is box else -a.total_impulse.y) for a in arbiters
        )
        remade = len(touching) >= 2 and not touching[-1] and bool(arbiters)
        touching.append(bool(arbiters))
        rows.append([t + DT, m * (box.velocity.y - v0) / DT + m * G, impulse / DT, float(remade)])
    return np.array(rows, dtype=np.float64)


def _stale_excess(acceleration: float = DROP_ACCELERATION) -> Array:
    r = stale_run(acceleration)
    out: Array = (r[:, 2] - r[:, 1]) / (10.0 * G)
    return out


@number
def ch9_max_excess() -> float:
    """Largest excess of the arbiter sum over the applied force, in units of m·g."""
    return float(np.max(np.abs(_stale_excess())))


@number
def ch9_stale_steps() -> float:
    """Steps (in the falling second) on which the arbiter sum is off by more than 1e-9·m·g."""
    return float(np.count_nonzero(np.abs(_stale_excess()) > 1e-9))


@number
def ch9_stale_steps_1() -> float:
    """The exercise: stale steps with the platform falling at 1 m/s²."""
    return float(np.count_nonzero(np.abs(_stale_excess(1.0)) > 1e-9))


@number
def ch9_max_excess_1() -> float:
    """The exercise: the largest excess at 1 m/s², m·g."""
    return float(np.max(np.abs(_stale_excess(1.0))))


@number
def ch9_contact_steps() -> float:
    """Steps on which the box touches the platform after it starts falling."""
    r = stale_run()
    return float(np.count_nonzero((r[:, 0] > DROP_START) & (r[:, 2] != 0.0)))


@number
def ch9_fresh_error() -> float:
    """Largest |arbiter sum − reverse integration| on the steps that are not re-made contacts,
    in units of m·g."""
    r = stale_run()
    return float(np.max(np.abs(_stale_excess()[r[:, 3] == 0.0])))


@number
def ch9_excess_vs_two_back() -> float:
    """Largest |excess − the arbiter sum two steps earlier| on re-made contacts, m·g."""
    r = stale_run()
    idx = np.nonzero(r[:, 3] == 1.0)[0]
    excess = _stale_excess()
    return float(np.max(np.abs(excess[idx] - r[idx - 2, 2] / (10.0 * G))))


@cache
def stale_world_run() -> tuple[int, float]:
    """Chapter 9's falling platform in a :class:`World` with the contact split on: (steps whose
    split is known, largest |contact sum − engine force| on them in m·g) over one second."""
    world = World(WorldConfig(contact_split=True))
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    floor = pymunk.Poly.create_box(platform, (4.0, 0.2))
    floor.friction = 1.0
    world.add("platform", platform, floor)
    world.add_box("box", mass=10.0, size=(0.5, 0.5), position=(0.0, 0.35), friction=1.0)
    world.track("box")

    def fall(w: World) -> None:
        platform.velocity = (0.0, -DROP_ACCELERATION * max(w.time - DROP_START, 0.0))

    world.on(Stage.CONTROL, fall)
    known, worst = 0, 0.0
    for _ in range(round(1.0 / DT)):
        world.step()
        f = world.forces("box")
        if f.split_valid:
            known += 1
            worst = max(worst, abs(f.contact[1] - f.engine[1]) / (10.0 * G))
    return known, worst


@number
def ch9_world_known_steps() -> float:
    """Steps (of 120) on which the World's contact split is known on the falling platform."""
    return float(stale_world_run()[0])


@number
def ch9_world_worst() -> float:
    """Largest |contact sum − engine force| on those steps, m·g."""
    return stale_world_run()[1]


@number
def ch9_weight_share() -> float:
    """(g − a)/g: the share of its weight the falling platform carries on average."""
    return (G - DROP_ACCELERATION) / G


@figure("09-contact-impulses.png")
def fig_ch9(path: Path) -> Path:
    """The arbiter sum against reverse integration on a falling platform; the stale excess."""
    r = stale_run()
    mg = 10.0 * G
    fig, (a, b) = axes(2, height=3.0)
    a.plot(r[:, 0], r[:, 2] / mg, "k.-", lw=0.8, ms=5, label="Σ Arbiter.total_impulse / h")
    a.plot(r[:, 0], r[:, 1] / mg, "o", ms=6, mfc="none", color="C0", label="reverse integration")
    stale = r[:, 3] == 1.0
    a.plot(r[stale, 0], r[stale, 2] / mg, "v", color="C3", ms=8, label="contact re-made (stale)")
    a.axhline(ch9_weight_share(), color="C2", ls="--", lw=1, label="(g − a)/g, the mean")
    a.set_xlim(DROP_START - 0.1, r[-1, 0])
    a.set_xlabel("time (s)")
    a.set_ylabel("vertical contact force / m·g")
    a.set_title(
        f"a box on a platform falling at {DROP_ACCELERATION:g} m/s² from t = {DROP_START:g} s"
    )
    a.legend(fontsize=8, ncol=2, loc="upper left")
    excess = _stale_excess()
    idx = np.nonzero(stale)[0]
    two_back = r[idx - 2, 2] / mg
    b.plot(two_back, excess[idx], "v", color="C3", ms=8, label="re-made contacts")
    top = float(max(np.max(two_back), np.max(excess[idx]))) * 1.1
    b.plot([0.0, top], [0.0, top], "k--", lw=1, label="excess = the sum two steps earlier")
    b.set_xlabel("arbiter sum two steps earlier / m·g")
    b.set_ylabel("arbiter sum − applied / m·g")
    b.set_title("the excess is the old contact's impulse, reported again")
    b.legend(fontsize=8)
    return save(fig, path)
