"""What the settings guide moves (:mod:`tools.guide_settings`): at least twelve knobs,
the game ones among them, each with its default first."""

from __future__ import annotations

from tools.guide_settings import KNOBS


def test_the_guide_moves_at_least_twelve_knobs_including_the_game_ones() -> None:
    """Law: ≥ 12 knobs, among them the probe, ride height, hover f and ζ, d_cutoff, slop and
    sleeping; every knob's default comes first."""
    names = {k.name for k in KNOBS}
    assert len(names) >= 12
    assert {
        "probe_radius", "probe_length", "ride_height", "hover_frequency", "hover_damping",
        "d_cutoff", "collision_slop", "sleep_time", "dt",
    } <= names  # fmt: skip
    assert all(len(k.values) >= 2 for k in KNOBS)
