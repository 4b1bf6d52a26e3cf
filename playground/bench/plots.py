"""matplotlib for the benchmark figures, imported only when a figure is drawn (it is in the
``bench`` extra): pyplot on the headless Agg backend, log-log axes, and a figure laid out, saved as
PNG and closed.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["log_axes", "pyplot", "save"]


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def log_axes(ax: Any, xlabel: str, ylabel: str, title: str) -> None:
    """Both of ``ax``'s axes logarithmic, labelled and titled."""
    ax.set(xscale="log", yscale="log", xlabel=xlabel, ylabel=ylabel, title=title)


def save(fig: Any, path: Path, dpi: int = 110) -> None:
    """Lay ``fig`` out, write it to ``path`` (its folder made if missing) and close it."""
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
