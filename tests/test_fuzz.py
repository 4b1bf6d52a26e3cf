"""A fuzzer over the level format: mutants of the shipped levels and levels built from scratch are
either refused with LevelError, or load, build and step one second with finite readings. No other
exception type ever escapes, nothing goes non-finite, nothing hangs.

Every run fuzzes :data:`CI_EXAMPLES` mutants with a fixed seed; the ``slow`` tier (CI, or
``pytest -m slow tests/test_fuzz.py``; see ``tests/conftest.py``) also runs :data:`SLOW_EXAMPLES`.
Every failing example found is kept under ``tests/regressions/`` and run by
:func:`test_regression_files`.
"""

from __future__ import annotations

import copy
import math
import signal
import tomllib
from collections.abc import Iterator
from pathlib import Path
from types import FrameType
from typing import Any

import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from playground.level import LevelError, loads, shipped, validate
from playground.scene import build

CI_EXAMPLES = 500
"""Mutants every run (about 10 s on one core)."""

SLOW_EXAMPLES = 5000
"""Mutants in the ``slow`` tier (about 100 s on one core)."""

SECONDS = 1.0
"""Simulated time each accepted mutant is stepped, s."""

STEP_BUDGET = 20.0
"""Wall seconds one mutant may take before it counts as a hang (a second of simulation takes
milliseconds; the slowest accepted settings — dt = 1e-4 s and 64 substeps — well under this)."""

REGRESSIONS = Path(__file__).parent / "regressions"

FUZZ_ACTORS = 8
"""Most actors a fuzzed level keeps: a crowd's other enemies repeat the same tables, and a mutant
of the 122 actors of ``crowd`` would cost seconds a run (the slow tier runs thousands)."""


def _fuzzable(doc: dict[str, Any]) -> dict[str, Any]:
    """``doc`` with a crowd cut to the actors its inputs and checks name (at most
    :data:`FUZZ_ACTORS`); a level with fewer actors as it is."""
    actors = doc.get("actors", [])
    if len(actors) <= FUZZ_ACTORS:
        return doc
    named = {
        v
        for table in (*doc.get("inputs", []), *doc.get("expect", []))
        for v in table.values()
        if isinstance(v, str)
    }
    kept = [a for a in actors if a["name"] in named or a["name"] == "player"]
    return {**doc, "actors": kept[:FUZZ_ACTORS]}


LEVELS = {
    name: _fuzzable(tomllib.loads(path.read_text(encoding="utf-8")))
    for name, path in shipped().items()
}

HOSTILE_NUMBERS = [
    0,
    -1,
    0.0,
    -1.0,
    1e308,
    -1e308,
    5e-324,
    math.nan,
    math.inf,
    -math.inf,
    1e16,
    -1e16,
    1e5,
    1e-9,
    2**63,
]
HOSTILE_VALUES: list[Any] = [
    *HOSTILE_NUMBERS,
    "",
    "x" * 10_000,
    "名前",
    "player",
    "static",
    True,
    False,
    [],
    {},
    [1.0, 2.0, 3.0],
    [math.nan, 0.0],
    [1e308, 1e308],
    {"kind": "box"},
]

# -- mutation ------------------------------------------------------------------------------------


def _paths(doc: Any, prefix: tuple[Any, ...] = ()) -> Iterator[tuple[Any, ...]]:
    """Every key path in a parsed document (tables and arrays), depth first."""
    yield prefix
    if isinstance(doc, dict):
        for k, v in doc.items():
            yield from _paths(v, (*prefix, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            yield from _paths(v, (*prefix, i))


def _parent(doc: Any, path: tuple[Any, ...]) -> Any:
    for k in path[:-1]:
        doc = doc[k]
    return doc


def _mutate(doc: dict[str, Any], data: st.DataObject) -> None:
    """One mutation at a drawn key path: delete, duplicate, replace with a hostile value, nudge a
    number by a huge factor, swap a type, or invert a pair."""
    paths = [p for p in _paths(doc) if p]
    if not paths:
        return
    path = data.draw(st.sampled_from(paths), label="path")
    parent = _parent(doc, path)
    key = path[-1]
    value = parent[key]
    kind = data.draw(
        # Plausible nudges (scale, random) reach the physics; hostile values test the refusals.
        st.sampled_from(
            [
                "scale",
                "scale",
                "scale",
                "random",
                "delete",
                "duplicate",
                "hostile",
                "swap",
                "invert",
            ]
        ),
        label="kind",
    )
    if kind == "delete":
        del parent[key]
    elif kind == "duplicate" and isinstance(parent, list):
        parent.insert(key, copy.deepcopy(value))
    elif kind == "duplicate" and isinstance(parent, dict):
        parent[f"{key}_"] = copy.deepcopy(value)
    elif kind == "scale" and isinstance(value, int | float) and not isinstance(value, bool):
        factors = [-1.0, 0.0, 0.5, 2.0, 10.0, 100.0, 1e3, 1e6, 1e-3, 1e-6, 1e300]
        parent[key] = value * data.draw(st.sampled_from(factors), label="factor")
    elif kind == "swap":
        parent[key] = str(value) if not isinstance(value, str) else 1.0
    elif kind == "invert" and isinstance(value, list) and len(value) == 2:
        parent[key] = [value[1], value[0]]
    elif kind == "random":
        parent[key] = data.draw(
            st.one_of(
                st.floats(-1e3, 1e3),
                st.floats(allow_nan=True, allow_infinity=True),
                st.integers(-(2**70), 2**70),
                st.text(max_size=20),
                st.lists(st.floats(-1e3, 1e3), max_size=5),
            ),
            label="random",
        )
    elif kind == "hostile":
        parent[key] = copy.deepcopy(data.draw(st.sampled_from(HOSTILE_VALUES), label="value"))


@st.composite
def mutants(draw: st.DrawFn) -> dict[str, Any]:
    """A shipped level with one to four mutations."""
    name = draw(st.sampled_from(sorted(LEVELS)), label="level")
    doc = copy.deepcopy(LEVELS[name])
    data = draw(st.data())
    for _ in range(draw(st.integers(1, 4), label="mutations")):
        _mutate(doc, data)
    return doc


COORD = st.one_of(st.floats(-20.0, 20.0), st.sampled_from(HOSTILE_NUMBERS))
SIZE = st.one_of(st.floats(0.01, 5.0), st.sampled_from(HOSTILE_NUMBERS))
NAMES = st.sampled_from(["player", "crate", "plank", "ghost", "static"])


def _shape() -> st.SearchStrategy[dict[str, Any]]:
    return st.one_of(
        st.fixed_dictionaries(
            {"kind": st.just("box"), "size": st.lists(SIZE, min_size=2, max_size=2)}
        ),
        st.fixed_dictionaries({"kind": st.just("circle"), "radius": SIZE}),
        st.fixed_dictionaries({"kind": st.just("capsule"), "length": SIZE, "radius": SIZE}),
        st.fixed_dictionaries(
            {
                "kind": st.just("polygon"),
                "points": st.lists(st.lists(COORD, min_size=2, max_size=2), min_size=3, max_size=5),
            }
        ),
    )


@st.composite
def scratch(draw: st.DrawFn) -> dict[str, Any]:
    """A level built from parts: geometry, props, an actor, joints, events."""
    doc: dict[str, Any] = {"title": "Fuzz", "description": "Built from scratch."}
    if draw(st.booleans()):
        doc["settings"] = {"dt": draw(st.sampled_from([1 / 120, 1 / 60, 1e-3, *HOSTILE_NUMBERS]))}
    if draw(st.booleans()):
        doc["gravity"] = {"kind": "uniform", "g": [draw(COORD), draw(COORD)]}
    doc["geometry"] = [
        {"kind": "segment", "a": [draw(COORD), draw(COORD)], "b": [draw(COORD), draw(COORD)]}
    ]
    props = []
    for name in draw(
        st.lists(st.sampled_from(["crate", "plank", "ghost"]), max_size=3, unique=True)
    ):
        props.append(
            {
                "name": name,
                "position": [draw(COORD), draw(COORD)],
                "mass": draw(st.one_of(st.floats(0.1, 500.0), st.sampled_from(HOSTILE_NUMBERS))),
                "shapes": [draw(_shape())],
            }
        )
    doc["props"] = props
    if draw(st.booleans()):
        doc["actors"] = [{"name": "player", "position": [draw(COORD), draw(COORD)]}]
    names = [p["name"] for p in props] + ["static"]
    if len(names) > 1 and draw(st.booleans()):
        kind = draw(st.sampled_from(["pivot", "pin", "spring"]))
        joint: dict[str, Any] = {"kind": kind, "a": names[0], "b": draw(NAMES)}
        if kind == "pivot":
            joint["anchor"] = [draw(COORD), draw(COORD)]
        else:
            joint["anchor_a"] = [draw(COORD), draw(COORD)]
            joint["anchor_b"] = [draw(COORD), draw(COORD)]
        if kind == "spring":
            joint["stiffness"] = draw(
                st.one_of(st.floats(1.0, 1e4), st.sampled_from(HOSTILE_NUMBERS))
            )
        doc["joints"] = [joint]
    if props and draw(st.booleans()):
        doc["events"] = [
            {
                "kind": "impulse",
                "t": draw(st.floats(0.0, 0.9)),
                "body": draw(NAMES),
                "impulse": [draw(COORD), draw(COORD)],
            }
        ]
    return doc


# -- the property ----------------------------------------------------------------------------------


class HangError(Exception):
    """A mutant took longer than :data:`STEP_BUDGET` wall seconds."""


def _alarm(signum: int, frame: FrameType | None) -> None:
    raise HangError(f"over {STEP_BUDGET} s")


def check(doc: object) -> str:
    """Load (a parsed document, or TOML text), build and step one second; ``"refused"`` or
    ``"ran"``. Anything else raises."""
    try:
        level = loads(doc, "<fuzz>") if isinstance(doc, str) else validate(doc, "<fuzz>")
    except LevelError:
        return "refused"
    try:
        scene = build(level)
    except LevelError:
        return "refused"
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, STEP_BUDGET)
    try:
        scene.run(SECONDS)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, old)
    world = scene.world
    for name in world.names:
        body = world.body(name)
        state = (*body.position, *body.velocity, body.angle, body.angular_velocity)
        assert all(math.isfinite(v) for v in state), (name, state)
    for name in scene.tracked:
        f = world.forces(name)
        for reading in (f.engine, f.support):
            assert all(math.isfinite(v) for v in reading), (name, reading)
        assert all(math.isfinite(v) for v in world.perceived_gravity(name)), name
    for ctrl in scene.controllers.values():
        assert all(math.isfinite(v) for v in ctrl.up), ctrl.name
    return "ran"


def _run(examples: int) -> dict[str, int]:
    """Fuzz ``examples`` documents with a fixed seed; the tally of outcomes."""
    tally: dict[str, int] = {}

    @settings(
        max_examples=examples,
        derandomize=True,
        deadline=None,
        suppress_health_check=list(HealthCheck),
        database=None,
    )
    @given(doc=st.one_of(mutants(), scratch()))
    def run(doc: dict[str, Any]) -> None:
        outcome = check(doc)
        tally[outcome] = tally.get(outcome, 0) + 1

    run()
    return tally


@pytest.mark.filterwarnings("error::RuntimeWarning")  # an overflow on the way is a failure too
def test_fuzz_ci() -> None:
    """Law: every one of :data:`CI_EXAMPLES` documents is refused with LevelError or runs a second
    with finite readings (and enough of them run for the law to say something)."""
    tally = _run(CI_EXAMPLES)
    print(f"fuzz: {tally}")
    assert sum(tally.values()) >= CI_EXAMPLES
    assert tally.get("ran", 0) >= CI_EXAMPLES // 10


@pytest.mark.slow
def test_fuzz_slow() -> None:
    """The same law over :data:`SLOW_EXAMPLES` documents (the ``slow`` tier: CI, or ``-m slow``)."""
    tally = _run(SLOW_EXAMPLES)
    print(f"fuzz (slow): {tally}")
    assert sum(tally.values()) >= SLOW_EXAMPLES


@pytest.mark.parametrize("path", sorted(REGRESSIONS.glob("*.toml")), ids=lambda p: p.stem)
def test_regression_files(path: Path) -> None:
    """Every failing example found (by the issue's fuzz run and by this one) stays fixed: its first
    line says ``# expect: refused`` or ``# expect: ran``, and that is what it does."""
    text = path.read_text(encoding="utf-8")
    expected = text.splitlines()[0].removeprefix("# expect: ").split(" ")[0]
    assert expected in ("refused", "ran"), path
    assert check(text) == expected


# -- playing accepted mutants ----------------------------------------------------------------------


PLAY_SAMPLE = 20
"""Accepted mutants played headless in CI."""

PLAY_FRAMES = 20
"""Frames each is played for (a third of a second at 60 fps)."""

PLAY_TIMEOUT = 30.0
"""Wall seconds before a played mutant counts as a hang (20 frames take well under a second)."""


def _accepted_sample(n: int) -> list[dict[str, Any]]:
    found: list[dict[str, Any]] = []

    @settings(
        max_examples=400,
        derandomize=True,
        deadline=None,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(doc=mutants())
    def collect(doc: dict[str, Any]) -> None:
        if len(found) < n and check(doc) == "ran":
            found.append(doc)

    collect()
    return found


def test_accepted_mutants_play_headless(tmp_path: Path) -> None:
    """Law: accepted mutants open in the view and play a few frames headless with no hang and no
    traceback (the view clamps what it draws); a runaway is one line and exit code 1."""
    pytest.importorskip("pygame")
    from playground.view.launcher import play

    sample = _accepted_sample(PLAY_SAMPLE)
    assert len(sample) == PLAY_SAMPLE
    old = signal.signal(signal.SIGALRM, _alarm)
    try:
        for i, doc in enumerate(sample):
            path = tmp_path / f"mutant{i}.toml"
            path.write_text(tomli_w.dumps(doc), encoding="utf-8")
            signal.setitimer(signal.ITIMER_REAL, PLAY_TIMEOUT)
            try:
                code = play(str(path), headless=True, frames=PLAY_FRAMES)
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0.0)
            assert code in (0, 1), path.read_text(encoding="utf-8")
    finally:
        signal.signal(signal.SIGALRM, old)


def test_the_view_clamps_a_far_away_camera() -> None:
    """Law: a body at 1e16 m (past where adding the grid's spacing changes a float) does not hang
    the grid drawing: the camera stops at its limit. Broken on purpose (no clamp), this hangs."""
    pygame = pytest.importorskip("pygame")
    from playground.view.camera import CENTRE_LIMIT, Camera
    from playground.view.draw import draw_grid

    cam = Camera(size=(200, 100), pixels_per_metre=50.0)
    cam.follow((1e16, -1e16), 1.0)
    cam.follow((math.nan, math.inf), 1.0)
    assert cam.centre == (CENTRE_LIMIT, -CENTRE_LIMIT)
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, PLAY_TIMEOUT)
    try:
        draw_grid(pygame.Surface((200, 100)), cam)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, old)
