"""The runtime guard: a world that blows up stops with a RunawayError naming the body, the step, the
quantity and the likely cause, before anything non-finite is read."""

from __future__ import annotations

import math
from pathlib import Path

import pymunk
import pytest

from playground import World, WorldConfig
from playground.cli import main
from playground.world import world as world_mod
from playground.world.guard import GUARD_EVERY, RunawayError

STEPS = 400
"""Steps a blown-up spring is given: it is NaN within ~40 at 1/60 s."""


def _stiff_spring(config: WorldConfig, *, track: bool) -> World:
    """Two 1 kg boxes on a 1e9 N/m spring at 1/60 s: 2πf·dt ≈ 790, far past the limit of 2."""
    world = World(config, gravity=(0.0, 0.0))
    a = world.add_box("a", mass=1.0, size=(0.2, 0.2), position=(0.0, 0.0))
    b = world.add_box("b", mass=1.0, size=(0.2, 0.2), position=(1.0, 0.0))
    world.add_constraint(pymunk.DampedSpring(a, b, (0.0, 0.0), (0.0, 0.0), 0.5, 1e9, 0.0))
    if track:
        world.track("a")
    return world


def test_a_tracked_blow_up_stops_at_once_naming_body_step_quantity_and_cause() -> None:
    """Law: a tracked body's force reading beyond the runaway bound stops the step that made it,
    and the error says which body, which step, which quantity and what probably caused it."""
    world = _stiff_spring(WorldConfig(dt=1 / 60), track=True)
    with pytest.raises(RunawayError) as info:
        for _ in range(STEPS):
            world.step()
    err = info.value
    assert err.body == "'a'"
    assert err.quantity == "engine force"
    assert err.step == world.steps <= 3
    text = str(err)
    assert text.startswith(f"step {err.step} (t = ")
    assert "spring too stiff for this dt" in text
    # Nothing non-finite was read: the readings of the failing step are still finite numbers.
    assert all(math.isfinite(v) for v in world.forces("a").engine)


def test_an_untracked_blow_up_stops_within_the_guard_period() -> None:
    """Law: a body nobody tracks is checked every GUARD_EVERY steps (cheaply, in one batch read)."""
    world = _stiff_spring(WorldConfig(dt=1 / 60), track=False)
    with pytest.raises(RunawayError) as info:
        for _ in range(STEPS):
            world.step()
    assert info.value.body in ("'a'", "'b'")
    assert info.value.quantity in ("position", "velocity", "angle", "angular velocity")
    assert info.value.step == GUARD_EVERY


def test_the_bare_path_is_guarded_too() -> None:
    """Law: a scene with no effect (the bare ``space.step`` path) is checked as often."""
    world = World(gravity=(0.0, 0.0))
    body = world.add_box("a", mass=1.0, size=(0.2, 0.2), position=(0.0, 0.0))
    world.run(0.1)
    body.velocity = (math.nan, 0.0)  # behind the world's back, through pymunk
    with pytest.raises(RunawayError, match=r"'a': (position|velocity) x is nan"):
        world.run(GUARD_EVERY * world.config.dt)


def test_without_the_guard_the_blow_up_reaches_nan() -> None:
    """The guard is what stops it: switched off, the same scene ends in NaN."""
    world = _stiff_spring(WorldConfig(dt=1 / 60, guard=False), track=True)
    for _ in range(STEPS):
        world.step()
    assert math.isnan(world.body("a").position.x)


def test_the_cli_reports_a_runaway_with_exit_1_and_keeps_the_recording(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Law: ``playground run`` turns a RunawayError into one line and exit code 1, and the
    recording holds every step before the one that ran away. (The force bound is lowered to 1 N
    so that the shipped ``incline`` level trips it once its crate rests on the slope.)"""
    # The bound the world's step hands the tracked bodies, whichever implementation serves.
    monkeypatch.setattr(world_mod, "RUNAWAY_FORCE", 1.0)
    out = tmp_path / "incline.csv"
    code = main(["run", "incline", "--record", str(out)])
    err = capsys.readouterr().err
    assert code == 1
    assert err.startswith("playground run: incline: step ")
    assert err.count("\n") == 1
    assert "likely cause" in err
    step = int(err.split("step ")[1].split(" ")[0])
    rows = out.read_text().splitlines()
    assert len(rows) - 1 == step - 1  # one row per step before the one that failed
