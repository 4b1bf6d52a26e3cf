"""The chapters' figure style (docs/chapters): stacked panels with a light grid, saved as PNG at
one resolution. matplotlib is imported only here and only when a figure is drawn (it is in the
``bench`` extra), so the numbers need nothing beyond the core."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def axes(rows: int, cols: int = 1, height: float = 3.0) -> tuple[Any, Any]:
    """A matplotlib figure (headless Agg backend) and its axes, as a flat list."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, grid = plt.subplots(rows, cols, figsize=(7.5 * cols, height * rows), squeeze=False)
    for ax in grid.flat:
        ax.grid(True, alpha=0.3)
    return fig, list(grid.flat)


def save(fig: Any, path: Path) -> Path:
    """Lay ``fig`` out, write it to ``path`` as PNG and close it; ``path``."""
    import matplotlib.pyplot as plt

    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
