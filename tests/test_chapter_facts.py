"""Laws of the statements the chapters and the design notes had wrong once: each recomputed here,
from bare pymunk or a shipped level, apart from the figures' own code where it can be.

A document quotes such a number as ``<!-- fact:NAME -->9.2<!-- /fact -->`` (the value of
:data:`FACTS` ``[NAME]`` rounded to the digits shown) or ``<!-- bound:NAME -->1e-11<!-- /bound -->``
(an upper bound on it); every fact must be quoted in the documents :data:`FACTS` names, so a
statement put back the way it was, without its number, fails here too. The other laws check a
claim's shape: what a sentence says halves does halve, the engine is named as pymunk reports it.
"""

from __future__ import annotations

import itertools
import json
import math
import re
from collections.abc import Callable
from functools import cache
from pathlib import Path

import numpy as np
import pymunk
import pytest

from tools import figures

DOCS = Path(__file__).resolve().parent.parent / "docs"
FACT = re.compile(r"<!-- (fact|bound):(\w+) -->([^<]*)<!-- /\1 -->")
NUM = re.compile(r"<!-- num:(\w+) -->([^<]*)<!-- /num -->")

TOL_REL = 1e-9
"""Relative slack beyond the printed rounding: float noise across machines and BLAS builds."""

TOL_HALVING = 0.03
"""Relative, on the ratio 2 of consecutive values that are said to halve: at 1/30 s the engine's
own error leaves chapter 7's tangential part 2.7 % short of ω·dt/2 (the chapter says so)."""

TOL_SPRING_N = 1e-6
"""N: what the hover spring adds to the feed-forward in the spinning ring (measured 2e-8 N: the
spring rests, the feed-forward carries the whole push)."""

TOL_SAME_RUN = 1e-9
"""Relative: one computation run twice (the bench in its own process, the chapter in this one)."""

TOL_PULL = 1e-12
"""In m·g: how far below zero an impulse may read and still be no pull (round-off of a step)."""

# ---------------------------------------------------------------------------------------------
# The spinning ring (chapters 3 and 5): the hover carries m·ω²·r, the engine nothing.


@cache
def ring_readings() -> dict[str, float]:
    """spinning_ring once settled (after 1 s of its 10): the hover's mean push (N), its
    feed-forward m·w_n (N, the weight felt in the ground's frame along the normal), the largest
    spring part |hover − feed-forward| (N) and the largest engine force (N)."""
    from playground.level import find, load
    from playground.scene import build

    scene = build(load(find("spinning_ring")))
    world = scene.world
    player = scene.controllers["player"]
    hover, feed, spring, engine = [], [], [], []
    for k in range(round(10.0 / world.config.dt)):
        world.step()
        hit = player.probe
        if k * world.config.dt <= 1.0 or hit is None:
            continue
        gx, gy = world.gravity_at("player")
        ax, ay = hit.frame_acceleration
        nx, ny = hit.normal
        push = math.hypot(*player.last_forces.hover)
        weight = player.body.mass * max(0.0, -((gx - ax) * nx + (gy - ay) * ny))
        hover.append(push)
        feed.append(weight)
        spring.append(abs(push - weight))
        engine.append(math.hypot(*world.forces("player").engine))
    return {
        "hover": float(np.mean(hover)),
        "feed": float(np.mean(feed)),
        "spring": max(spring),
        "engine": max(engine),
    }


def ring_sag_without_frame_mm() -> float:
    """How far below ride height a spring fed forward with the gravity alone (zero in the ring)
    would sit to carry the same push: F/k, mm."""
    from playground.controller.config import ControllerConfig

    c = ControllerConfig()
    k = c.mass * (2.0 * math.pi * c.hover_frequency) ** 2
    return 1000.0 * ring_readings()["hover"] / k


# ---------------------------------------------------------------------------------------------
# Chapter 9's falling platform, in bare pymunk (the chapter's own script).

STEP = 1 / 120
"""s: chapter 9's step."""

BOX_MASS = 10.0
"""kg: chapter 9's box."""

FALL_FROM = 0.5
"""s: when chapter 9's platform starts to fall."""


@cache
def falling_platform() -> tuple[tuple[float, bool, float, float], ...]:
    """Chapter 9's 120 steps: (time at the step's start (s), touching?, applied impulse and
    reported arbiter impulse on the box (both in m·g·h))."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    floor = pymunk.Poly.create_box(platform, (4.0, 0.2))
    box = pymunk.Body(BOX_MASS, pymunk.moment_for_box(BOX_MASS, (0.5, 0.5)))
    box.position = (0.0, 0.35)
    shape = pymunk.Poly.create_box(box, (0.5, 0.5))
    floor.friction = shape.friction = 1.0
    space.add(platform, floor, box, shape)
    weight_step = BOX_MASS * 9.81 * STEP
    rows = []
    for k in range(120):
        t = k * STEP
        platform.velocity = (0.0, -3.0 * max(t - FALL_FROM, 0.0))
        v0 = box.velocity.y
        space.step(STEP)
        applied = BOX_MASS * (box.velocity.y - v0) + weight_step
        arbiters: list[pymunk.Arbiter] = []
        box.each_arbiter(arbiters.append)
        reported = sum(
            a.total_impulse.y if a.shapes[0].body is box else -a.total_impulse.y for a in arbiters
        )
        touching = any(a.contact_point_set.points for a in arbiters)
        rows.append((t, touching, applied / weight_step, reported / weight_step))
    return tuple(rows)


def stale_steps() -> list[float]:
    """Excess of the reported over the applied impulse on the steps where they differ, m·g."""
    return [rep - app for _, _, app, rep in falling_platform() if abs(rep - app) > TOL_REL]


def fall_steps() -> list[tuple[float, bool, float, float]]:
    """The steps during which the platform falls."""
    return [row for row in falling_platform() if row[0] >= FALL_FROM]


def parting(persistence: int) -> float:
    """Chapter 9's second script: the impulse (N·s) applied to a box put back on the floor
    already moving away at 0.5 m/s, one step after it was lifted clear of a contact it had been
    pressed into; ``persistence`` is ``Space.collision_persistence``."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.collision_persistence = persistence
    ground = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0)
    box = pymunk.Body(BOX_MASS, pymunk.moment_for_box(BOX_MASS, (0.5, 0.5)))
    box.position = (0.0, 0.25)
    shape = pymunk.Poly.create_box(box, (0.5, 0.5))
    ground.friction = shape.friction = 1.0
    space.add(ground, box, shape)
    for _ in range(60):
        box.apply_force_at_local_point((0.0, -5000.0))
        space.step(STEP)
    resting = box.position
    box.position, box.velocity = resting + pymunk.Vec2d(0.0, 0.2), (0.0, 0.0)
    space.step(STEP)
    box.position, box.velocity = resting, (0.0, 0.5)
    space.step(STEP)
    return BOX_MASS * (box.velocity.y - 0.5) + BOX_MASS * 9.81 * STEP


# ---------------------------------------------------------------------------------------------
# Chapter 10's matrix: where substeps do not shrink the overlap.


def deeper_with_substeps() -> list[tuple[str, float, int, float, float]]:
    """The matrix's cells (scene, dt, iterations, overlap with 1 and with 4 substeps, mm) whose
    overlap is deeper with 4 substeps than with 1."""
    from tools.figures.ch10_stability import CH10_DTS, CH10_ITERATIONS, hard_run, hard_scenes

    out = []
    for scene in hard_scenes():
        for dt in CH10_DTS:
            for it in CH10_ITERATIONS:
                one = 1000.0 * hard_run(scene, dt, it, 1).penetration
                four = 1000.0 * hard_run(scene, dt, it, 4).penetration
                if four > one:
                    out.append((scene, dt, it, one, four))
    return out


def squeeze_at_60(substeps: int) -> float:
    """The squeeze's deepest overlap at 1/60 s, 2 iterations, mm."""
    from tools.figures.ch10_stability import hard_run

    return 1000.0 * hard_run("squeeze", 1 / 60, 2, substeps).penetration


# ---------------------------------------------------------------------------------------------

FACTS: dict[str, tuple[tuple[str, ...], Callable[[], float]]] = {
    # 1. The hover's feed-forward is the weight felt in the ground's frame, not m·g_n.
    "ring_hover_n": (
        ("chapters/05-floating-capsule.md", "chapters/03-perceived-gravity.md"),
        lambda: ring_readings()["feed"],
    ),
    "ring_sag_without_frame_mm": (("chapters/05-floating-capsule.md",), ring_sag_without_frame_mm),
    # 2. The ring's support is the controller's hover: the engine force is nil.
    "ring_engine_n": (("chapters/03-perceived-gravity.md",), lambda: ring_readings()["engine"]),
    # 3. The platform falls for half a second, not a second.
    "ch9_fall_seconds": (
        ("chapters/09-contact-impulses.md",),
        lambda: len(fall_steps()) * STEP,
    ),
    "ch9_fall_steps": (("chapters/09-contact-impulses.md",), lambda: float(len(fall_steps()))),
    # 4. Substeps do not shrink every overlap.
    "ch10_substeps_deeper": (
        ("chapters/10-stability.md",),
        lambda: float(len(deeper_with_substeps())),
    ),
    "ch10_squeeze_mm": (("chapters/10-stability.md",), lambda: squeeze_at_60(1)),
    "ch10_squeeze_sub_mm": (("chapters/10-stability.md",), lambda: squeeze_at_60(4)),
    # 5. The design notes' stale-impulse count, as chapter 9's bare pymunk run gives it.
    "ch9_stale_bare": (("design.md",), lambda: float(len(stale_steps()))),
    "ch9_steps_bare": (("design.md",), lambda: float(len(falling_platform()))),
    "ch9_contact_bare": (("design.md",), lambda: float(sum(r[1] for r in fall_steps()))),
    "ch9_excess_bare": (("design.md",), lambda: max(stale_steps())),
    # 7. A stale arbiter's applied impulse is not always right; on the platform it never pulls.
    "ch9_platform_pull": (
        ("chapters/09-contact-impulses.md",),
        lambda: max(0.0, -min(app for _, _, app, _ in falling_platform())),
    ),
}
"""Fact name → (the documents under docs/ that must quote it, its computation in the unit the
text states)."""


def quoted() -> list[tuple[str, str, str, str]]:
    """(document, kind, name, text) of every fact marker under docs/."""
    found = []
    for path in sorted(DOCS.rglob("*.md")):
        for kind, name, text in FACT.findall(path.read_text(encoding="utf-8")):
            found.append((str(path.relative_to(DOCS)), kind, name, text.strip()))
    return found


def printed_rounding(text: str) -> float:
    """Half a unit of the last printed digit of ``text`` ("9.2" → 0.05)."""
    digits = len(text.split(".")[1]) if "." in text else 0
    return 0.5 * 10.0**-digits


@pytest.mark.parametrize(
    ("doc", "name"), [(doc, name) for name, (docs, _) in FACTS.items() for doc in docs]
)
def test_each_fact_is_quoted_where_it_belongs(doc: str, name: str) -> None:
    """A corrected statement keeps its number: the document quotes the fact by name."""
    names = {n for d, _, n, _ in quoted() if d == doc}
    assert name in names, f"docs/{doc} no longer quotes {name}"


@pytest.mark.parametrize(("doc", "kind", "name", "text"), quoted())
def test_quoted_fact_is_what_is_recomputed(doc: str, kind: str, name: str, text: str) -> None:
    """A quoted fact is the recomputed value rounded to the digits shown (or a bound above it)."""
    assert name in FACTS, f"docs/{doc}: unknown fact {name!r}"
    value = FACTS[name][1]()
    if kind == "bound":
        assert value < float(text), f"docs/{doc}: {name} = {value!r} is not below {text}"
    else:
        slack = printed_rounding(text) + TOL_REL * abs(value)
        assert abs(value - float(text)) <= slack, f"docs/{doc}: {name} = {value!r}, text: {text}"


def test_the_ring_hover_rests_on_its_feed_forward() -> None:
    """Chapter 5: in the weightless ring the feed-forward alone carries the hover's push (the
    spring adds nothing), so it cannot be the gravity's m·g_n, which is zero there."""
    readings = ring_readings()
    assert readings["spring"] < TOL_SPRING_N
    assert readings["feed"] > 0.0


def test_a_stale_arbiter_can_apply_a_pull_and_a_fresh_one_cannot() -> None:
    """Chapter 9: from a stale accumulator the solver applies jnAcc − jnOld, which is negative
    when the bodies are parting; a fresh arbiter clamps at zero and applies nothing."""
    weight_step = BOX_MASS * 9.81 * STEP
    assert parting(3) < -weight_step  # a pull stronger than the box's own weight over the step
    assert abs(parting(1)) < TOL_PULL * weight_step


def test_only_the_squeeze_overlaps_deeper_with_substeps() -> None:
    """Chapter 10: the cells where 4 substeps overlap more than 1 are the squeeze's, as the text
    says."""
    assert {scene for scene, *_ in deeper_with_substeps()} == {"squeeze"}


def sentences_saying(doc: str, word: str) -> list[str]:
    """The sentences of ``doc`` (under docs/) that contain ``word`` as a word."""
    text = (DOCS / doc).read_text(encoding="utf-8")
    return [s for s in re.split(r"(?<=[.!?])\s+", text) if re.search(rf"\b{word}\b", s)]


@pytest.mark.parametrize("doc", ["chapters/07-what-accuracy-costs.md"])
def test_what_a_chapter_says_halves_halves(doc: str) -> None:
    """A sentence that says something halves when dt halves quotes (as numbers of the code) at
    least three values in a row, and each is half the one before."""
    said = sentences_saying(doc, "halves")
    assert said, f"docs/{doc}: no sentence says 'halves'"
    for sentence in said:
        values = [figures.NUMBERS[name]() for name, _ in NUM.findall(sentence)]
        assert len(values) >= 3, f"docs/{doc}: '{sentence[:80]}…' quotes no sequence"
        for a, b in itertools.pairwise(values):
            assert abs(a / b - 2.0) < 2.0 * TOL_HALVING, f"docs/{doc}: {a} → {b} is not a half"


ENGINE = re.compile(r"\b(Chipmunk|Munk2D)\s+(\d+(?:\.\d+)*)")

FORK_REACH = 40
"""Characters around a "Chipmunk 7" within which the text must say that Munk2D forks it."""


def test_the_engine_is_named_as_pymunk_reports_it() -> None:
    """Where a document names the engine's version, it is pymunk's ``chipmunk_version`` (Munk2D
    2.0.1 on pymunk 7.3), and "Chipmunk 7" only as what Munk2D forks."""
    version = pymunk.chipmunk_version.split("-")[0]
    for path in [*sorted(DOCS.rglob("*.md")), DOCS.parent / "README.md"]:
        text = path.read_text(encoding="utf-8")
        for found in ENGINE.finditer(text):
            name, number = found.groups()
            if name == "Munk2D":
                assert number == version, f"{path.name}: Munk2D {number}, pymunk has {version}"
            else:
                around = text[found.start() - FORK_REACH : found.end() + FORK_REACH]
                assert "fork" in around, f"{path.name}: '{found.group()}' named as the engine"


def test_chapters_agree_on_the_critically_damped_overshoot() -> None:
    """Chapter 5 and chapter 8 quote the same measured overshoot at ζ = 1 (not 'none')."""
    for doc in ("chapters/05-floating-capsule.md", "chapters/08-fixed-step.md"):
        names = [n for n, _ in NUM.findall((DOCS / doc).read_text(encoding="utf-8"))]
        assert "ch8_hover_overshoot_120" in names, f"docs/{doc} does not quote it"
    assert figures.NUMBERS["ch8_hover_overshoot_120"]() > 0.0


def estimator_table_ring() -> tuple[float, float, float]:
    """docs/accuracy.md's estimator table, its ring row: the reverse, contact and
    finite-difference errors as printed, %."""
    text = (DOCS / "accuracy.md").read_text(encoding="utf-8")
    table = text[text.index("### Force estimators") :]
    (row,) = re.findall(r"^\| ring \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$", table, re.MULTILINE)[:1]
    reverse, contact, fd = (float(cell.strip().rstrip(" %")) for cell in row)
    return reverse, contact, fd


def test_estimator_table_and_chapter_7_agree_on_finite_differences() -> None:
    """docs/accuracy.md compares finite differences with the exact force at their own centre,
    as chapter 7 does, not at the reverse reading's mid-step half a step away: the bench's ring
    error at 1/120 s is chapter 7's, in the committed JSON and in the printed table."""
    from playground.bench.accuracy import Point, measure
    from playground.bench.scenes import Knobs

    chapter = figures.NUMBERS["ch7_fd_own_120"]() / 100.0
    (measured,) = measure(Point("ring", Knobs(), "finite-difference"), ("none",), repeats=1)
    assert abs(measured.error - chapter) <= TOL_SAME_RUN * chapter
    rows = json.loads((DOCS / "accuracy.json").read_text(encoding="utf-8"))
    (stored,) = [
        r
        for r in rows
        if (r["scene"], r["estimator"], r["filter"]) == ("ring", "finite-difference", "none")
        and (r["substeps"], r["iterations"]) == (1, 10)
        and math.isclose(r["dt"], 1 / 120)
    ]
    assert abs(stored["error"] - chapter) <= TOL_SAME_RUN * chapter
    printed = estimator_table_ring()[2]
    assert abs(printed - 100.0 * chapter) <= printed_rounding(f"{printed:g}") + TOL_REL
