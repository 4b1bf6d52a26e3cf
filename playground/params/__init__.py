"""A config's parameters: declared once with doc, unit and bounds, and checked.

:func:`param` declares a frozen config's parameter (:mod:`~playground.params.spec`); the level
format derives its tables from the declarations. The single-value checks
(:mod:`~playground.params.checks`) serve what a declaration cannot say. Imports nothing else of
playground: every layer above may use it.
"""

from playground.params.checks import (
    bounded,
    bounded_vec,
    finite,
    finite_vec,
    in_range,
    positive,
    unit,
)
from playground.params.spec import SPEC, Spec, check, param, spec

__all__ = [
    "SPEC",
    "Spec",
    "bounded",
    "bounded_vec",
    "check",
    "finite",
    "finite_vec",
    "in_range",
    "param",
    "positive",
    "spec",
    "unit",
]
