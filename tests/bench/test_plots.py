"""matplotlib for the bench figures (:mod:`playground.bench.plots`): log-log axes, and a figure
saved whole (its folder made) and closed."""

from __future__ import annotations

from pathlib import Path

import pytest

from playground.bench.plots import log_axes, pyplot, save


def test_log_axes_and_save(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    plt = pyplot()
    fig, ax = plt.subplots()
    ax.plot([1, 10, 100], [1, 100, 10_000])
    log_axes(ax, "bodies", "µs", "cost")
    assert (ax.get_xscale(), ax.get_yscale(), ax.get_title()) == ("log", "log", "cost")
    path = tmp_path / "deep" / "f.png"
    save(fig, path, dpi=50)
    assert path.read_bytes()[:4] == b"\x89PNG"
    assert not plt.fignum_exists(fig.number)
