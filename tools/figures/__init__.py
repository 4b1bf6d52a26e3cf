"""The teaching chapters' figures and numbers (docs/chapters), made by the code itself.

One module per chapter (``ch01_kinematic_vs_force_driven`` … ``ch10_stability``) declares the
numbers its text quotes with :func:`~tools.figures.registry.number` and its figure with
:func:`~tools.figures.registry.figure`; importing this package imports them all, so
:data:`NUMBERS` (name → value, in the unit the text states) and :data:`FIGURES` (file name →
draws a PNG) are complete. The simulations behind them run once per process (cached) and
headless; matplotlib is imported only when a figure is drawn (it is in the ``bench`` extra).
``python -m tools figures`` regenerates every figure.

>>> round(NUMBERS["ch5_k"](), 1)
69087.2
"""

from __future__ import annotations

import importlib
import pkgutil
from pathlib import Path

from tools.figures.registry import FIGURES, NUMBERS

__all__ = ["CHAPTERS", "FIGURES", "NUMBERS", "make_all"]

CHAPTERS = tuple(
    importlib.import_module(f"{__name__}.{module.name}")
    for module in sorted(pkgutil.iter_modules(__path__), key=lambda module: module.name)
    if module.name.startswith("ch")
)
"""The chapter modules (``chNN_…``, every one the package holds), in reading order: importing them
fills the registries."""


def make_all(out: Path, progress: bool = False) -> list[Path]:
    """Draw every figure into directory ``out`` (created if needed); the paths written.

    With ``progress`` a bar on stderr names the figure being drawn (the simulations behind some
    take tens of seconds); it needs tqdm, in the same ``bench`` extra as matplotlib.
    """
    out.mkdir(parents=True, exist_ok=True)
    items = sorted(FIGURES.items())
    if not progress:
        return [draw(out / name) for name, draw in items]
    tqdm = importlib.import_module("tqdm").tqdm  # untyped; the bench extra installs it
    written = []
    with tqdm(items, unit="figure", desc="figures") as bar:
        for name, draw in bar:
            bar.set_postfix_str(name)
            written.append(draw(out / name))
    return written
