"""Declared parameters: a config's doc, unit and bounds as dataclass metadata, and one check.

Each frozen config of the core (``WorldConfig``, ``Perception``, ``ControllerConfig``, the gravity
fields, the paths, ``Intent``) declares its parameters once, with :func:`param`; its
``__post_init__`` calls :func:`check`, which refuses a value outside the declared bounds with an
error naming the parameter. The level format derives its tables from the same declarations
(``playground.level``).

>>> from dataclasses import dataclass
>>> @dataclass(frozen=True)
... class Ball:
...     radius: float = param(0.5, doc="Radius.", unit="m", gt=0.0, le=10.0)
...     def __post_init__(self) -> None:
...         check(self)
>>> Ball(radius=0.0)
Traceback (most recent call last):
...
ValueError: radius: expected a number in (0, 10] m, got 0.0
>>> spec(Ball, "radius").unit
'm'
"""

from __future__ import annotations

import dataclasses
import math
import types
import typing
from collections.abc import Callable, Sequence
from typing import Any, Literal, Union

__all__ = ["Spec", "check", "param", "spec"]

SPEC = "playground.spec"
"""The metadata key under which a field's :class:`Spec` is stored."""


@dataclasses.dataclass(frozen=True, slots=True)
class Spec:
    """What one parameter is: its doc, its unit and the bounds of each number in it.

    ``ge``/``gt`` and ``le`` bound a number, or each component of a vector, or each point of a
    list of points. ``nonzero`` refuses 0 (a number) or (0, 0) (a vector); ``min_items`` is the
    fewest items of a list; ``inf`` admits ∞ (a default meaning "never" or "forever").
    """

    doc: str
    unit: str = ""
    ge: float | None = None
    gt: float | None = None
    le: float | None = None
    nonzero: bool = False
    min_items: int = 0
    inf: bool = False

    def admits(self, x: float, *, whole: bool = True) -> bool:
        """Whether the number ``x`` lies within the bounds (∞ only if ``inf``; 0 only if not
        ``nonzero``, unless ``x`` is one component of a vector: ``whole = False``)."""
        if math.isinf(x) and self.inf and x > 0:
            return True
        return (
            math.isfinite(x)
            and (self.ge is None or x >= self.ge)
            and (self.gt is None or x > self.gt)
            and (self.le is None or x <= self.le)
            and not (whole and self.nonzero and x == 0.0)
        )

    def expected(self, integer: bool = False) -> str:
        """The bounds in words: ``a number in (0, 10] m``."""
        what = "an integer" if integer else "a number"
        low = self.ge if self.ge is not None else self.gt
        opening = "[" if self.gt is None else "("
        unit = f" {self.unit}" if self.unit else ""
        if low is None and self.le is None:
            return f"a finite {what.split()[-1]}{unit}"
        if self.le is None:
            sign = ">=" if self.gt is None else ">"
            return f"{what} {sign} {low:g}{unit}"
        if low is None:
            return f"{what} <= {self.le:g}{unit}"
        return f"{what} in {opening}{low:g}, {self.le:g}]{unit}"


def param(
    default: Any = dataclasses.MISSING,
    *,
    doc: str,
    unit: str = "",
    ge: float | None = None,
    gt: float | None = None,
    le: float | None = None,
    nonzero: bool = False,
    min_items: int = 0,
    inf: bool = False,
    default_factory: Callable[[], Any] | Any = dataclasses.MISSING,
) -> Any:
    """A dataclass field with its :class:`Spec` (the bounds usually come from
    :mod:`playground.limits`, which gives each its reason)."""
    metadata = {SPEC: Spec(doc, unit, ge, gt, le, nonzero, min_items, inf)}
    if default_factory is not dataclasses.MISSING:
        return dataclasses.field(default_factory=default_factory, metadata=metadata)
    return dataclasses.field(default=default, metadata=metadata)


def spec(cls: type[Any], name: str) -> Spec:
    """The :class:`Spec` of field ``name`` of the dataclass ``cls``."""
    for f in dataclasses.fields(cls):
        if f.name == name:
            found: Spec = f.metadata[SPEC]
            return found
    raise KeyError(name)


def check(obj: Any) -> None:
    """Raise ``ValueError`` naming the first field of ``obj`` whose value its spec refuses."""
    for name, field_spec, shape in _checks(type(obj)):
        _check_value(name, getattr(obj, name), field_spec, shape)


Shape = Literal["number", "integer", "vector", "points", "choice", "other"]
FieldCheck = tuple[str, Spec, tuple[Shape, bool, tuple[Any, ...]]]
_CHECKS: dict[type[Any], tuple[FieldCheck, ...]] = {}


def _checks(cls: type[Any]) -> tuple[FieldCheck, ...]:
    """For each declared field: its name, spec and shape (what kind of value, whether None is
    allowed, the choices of a Literal), worked out once per class."""
    known = _CHECKS.get(cls)
    if known is not None:
        return known
    hints = typing.get_type_hints(cls)
    out = []
    for f in dataclasses.fields(cls):
        if SPEC in f.metadata:
            out.append((f.name, f.metadata[SPEC], shape_of(hints[f.name])))
    _CHECKS[cls] = tuple(out)
    return _CHECKS[cls]


def shape_of(hint: Any) -> tuple[Shape, bool, tuple[Any, ...]]:
    """What a field's type says its value is: ``(shape, optional, choices)``.

    >>> shape_of(tuple[float, float] | None)
    ('vector', True, ())
    """
    alts = [hint]
    if typing.get_origin(hint) in (Union, types.UnionType):
        alts = list(typing.get_args(hint))
    optional = type(None) in alts
    alts = [a for a in alts if a is not type(None)]
    base = alts[0] if len(alts) == 1 else hint
    origin, args = typing.get_origin(base), typing.get_args(base)
    if base is float:
        return ("number", optional, ())
    if base is int:
        return ("integer", optional, ())
    if origin is Literal:
        return ("choice", optional, args)
    if origin is tuple and args == (float, float):
        return ("vector", optional, ())
    listed = origin is tuple and len(args) == 2 and args[1] is Ellipsis
    if listed and shape_of(args[0])[0] == "vector":
        return ("points", optional, ())
    return ("other", optional, ())


def _check_value(
    name: str, value: Any, s: Spec, shape: tuple[Shape, bool, tuple[Any, ...]]
) -> None:
    kind, optional, choices = shape
    if value is None and optional:
        return
    if kind == "number":
        _number(name, value, s)
    elif kind == "integer":
        if isinstance(value, bool) or not isinstance(value, int) or not s.admits(value):
            raise ValueError(f"{name}: expected {s.expected(integer=True)}, got {value!r}")
    elif kind == "vector":
        _vector(name, value, s)
    elif kind == "points":
        if len(value) < s.min_items:
            raise ValueError(f"{name}: expected at least {s.min_items} points, got {len(value)}")
        for i, point in enumerate(value):
            _vector(f"{name}[{i}]", point, s)
    elif kind == "choice" and value not in choices:
        listing = ", ".join(repr(c) for c in choices)
        raise ValueError(f"{name}: expected one of {listing}, got {value!r}")


def _number(name: str, value: Any, s: Spec) -> None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not s.admits(value):
        raise ValueError(f"{name}: expected {s.expected()}, got {value!r}")


def _vector(name: str, value: Sequence[float], s: Spec) -> None:
    try:
        n = len(value)
    except TypeError:
        n = -1
    if n != 2:
        raise ValueError(f"{name}: expected a 2-vector (x, y), got {value!r}")
    for i, x in enumerate(value):
        # A component may be 0 (nonzero is about the whole vector).
        if isinstance(x, bool) or not isinstance(x, int | float) or not s.admits(x, whole=False):
            raise ValueError(f"{name}[{i}]: expected {s.expected()}, got {x!r}")
    if s.nonzero and value[0] == 0.0 and value[1] == 0.0:
        raise ValueError(f"{name}: expected a non-zero vector, got {tuple(value)!r}")
