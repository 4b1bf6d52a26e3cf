"""Benchmarks a user can rerun: what accuracy costs, and what each effect costs.

``python -m playground.bench accuracy`` sweeps dt, substeps, solver iterations, force estimators
and filters over scenes with exact answers; ``python -m playground.bench overhead`` times each
stage and effect as bodies grow. matplotlib (figures) and tqdm (progress) are optional:
``pip install 'pymunk-playground[bench]'``.
"""

from playground.bench.accuracy import ESTIMATORS, FILTERS, Point, Result, measure, plan, sweep
from playground.bench.scenes import SCENES, Knobs, Scene, build

__all__ = [
    "ESTIMATORS",
    "FILTERS",
    "SCENES",
    "Knobs",
    "Point",
    "Result",
    "Scene",
    "build",
    "measure",
    "plan",
    "sweep",
]
