"""Laws of the fixed step: time is conserved (stepped, banked or dropped), the cap holds, and a
world stepped through it is the world stepped by hand."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground import FixedStep, World

TOL_TIME = 1e-9
"""s: frame times are float sums; the bank's bookkeeping may differ from them by rounding only."""


class Counter:
    """A stand-in world: counts its steps."""

    class config:  # noqa: N801 - the shape of World.config
        dt = 0.01

    def __init__(self) -> None:
        self.steps = 0

    def step(self) -> None:
        self.steps += 1


frames = st.lists(st.floats(min_value=0.0, max_value=0.2), max_size=200)


@settings(deadline=None)
@given(frames, st.integers(min_value=1, max_value=40))
def test_every_second_is_stepped_banked_or_dropped(times: list[float], cap: int) -> None:
    """Law: Σ frame time = steps·dt + bank + Σ dropped; steps per frame ≤ cap; 0 ≤ alpha < 1."""
    world = Counter()
    clock = FixedStep(world, max_steps_per_frame=cap)
    dropped = 0.0
    for t in times:
        frame = clock.advance(t)
        assert 0 <= frame.steps <= cap
        assert 0.0 <= frame.alpha < 1.0
        assert math.isclose(frame.alpha, clock.bank / world.config.dt)
        dropped += frame.dropped
    total = world.steps * world.config.dt + clock.bank + dropped
    assert total == pytest.approx(math.fsum(times), abs=TOL_TIME)


@settings(deadline=None)
@given(frames)
def test_nothing_is_dropped_below_the_cap(times: list[float]) -> None:
    """Law: frames no longer than the cap's steps drop nothing (0.2 s ≤ 21 steps of 0.01 s)."""
    clock = FixedStep(Counter(), max_steps_per_frame=21)
    assert all(clock.advance(t).dropped == 0.0 for t in times)


def test_a_hitch_is_capped_and_the_rest_dropped() -> None:
    world = Counter()
    clock = FixedStep(world, max_steps_per_frame=4)
    frame = clock.advance(1.0)
    assert (frame.steps, world.steps) == (4, 4)
    assert frame.dropped == pytest.approx(0.96, abs=TOL_TIME)
    assert clock.advance(0.0).steps == 0  # the dropped time is not caught up later


def test_a_world_stepped_through_it_is_the_world_stepped_by_hand() -> None:
    """The same steps, whatever the frames: the crate's fall is the same bit for bit."""

    def fallen(frame_times: list[float] | None) -> tuple[float, float, int]:
        world = World()
        crate = world.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(0.0, 5.0))
        world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
        if frame_times is None:
            for _ in range(90):
                world.step()
            return crate.position.x, crate.position.y, 90
        clock = FixedStep(world)
        steps = sum(clock.advance(t).steps for t in frame_times)
        return crate.position.x, crate.position.y, steps

    by_hand = fallen(None)
    assert fallen([1 / 144] * 108) == by_hand  # 0.75 s of a 144 Hz display: 90 steps
    assert fallen([1 / 60] * 45) == by_hand


@pytest.mark.parametrize(
    ("frame_seconds", "message"),
    [(-0.01, "frame_seconds"), (math.nan, "frame_seconds"), (math.inf, "frame_seconds")],
)
def test_bad_frame_times_are_refused(frame_seconds: float, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        FixedStep(Counter()).advance(frame_seconds)


@pytest.mark.parametrize("cap", [0, -1, 2.5, True])
def test_a_bad_cap_is_refused(cap: object) -> None:
    with pytest.raises(ValueError, match="max_steps_per_frame"):
        FixedStep(Counter(), max_steps_per_frame=cap)  # type: ignore[arg-type]
