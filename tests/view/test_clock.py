"""The view's clock: physics steps follow wall time, not frames; a frame runs at most its cap of
steps and drops the backlog beyond it; a bad dt is refused by name."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground.view.clock import Accumulator


@settings(max_examples=100, deadline=None)
@given(st.lists(st.floats(0.0, 0.05), min_size=1, max_size=200))
def test_accumulator_steps_follow_time_not_frames(frames: list[float]) -> None:
    """Law: the physics steps run depend on the total wall time, not on how it is cut into frames
    (within the one step still in the accumulator)."""
    dt = 1.0 / 120.0
    acc = Accumulator(dt, max_steps=10_000)
    steps = sum(acc.advance(f) for f in frames)
    assert abs(steps - sum(frames) / dt) <= 1.0


def test_a_long_frame_runs_the_cap_and_drops_the_backlog() -> None:
    """A stall of a second at dt 0.01 runs 32 steps, not 100, and the next frame starts afresh."""
    acc = Accumulator(dt=0.01, max_steps=32)
    assert acc.advance(1.0) == 32
    assert acc.advance(0.015) == 1


@pytest.mark.parametrize("dt", [0.0, -0.01, float("nan"), float("inf")])
def test_a_bad_dt_is_refused_by_name(dt: float) -> None:
    with pytest.raises(ValueError, match="dt: expected a number of seconds > 0"):
        Accumulator(dt)
