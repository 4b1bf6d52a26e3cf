"""How a break patches: replace a class attribute for as long as the break is open, call a
method with one argument changed, run something after a method, or change the config controllers
are built with. Each checks that what it patches still exists and still takes the parameters it
names, and raises :class:`~playground.faults.catalog.BreakError` otherwise.

>>> class Door:
...     def open(self, angle: float) -> float:
...         return angle
>>> with with_argument(Door, "open", "angle", lambda a: a / 2):
...     Door().open(90.0)
45.0
>>> Door().open(90.0)
90.0
"""

from __future__ import annotations

import dataclasses
import inspect
import math
from collections.abc import Callable, Iterator, Sequence
from contextlib import AbstractContextManager, contextmanager
from typing import Any

from playground.controller.config import ControllerConfig
from playground.controller.controller import Controller
from playground.faults.catalog import BreakError

__all__ = ["after", "controller_config", "parameter", "replaced", "rotate", "with_argument"]


@contextmanager
def replaced(owner: type, attr: str, make: Callable[[Any], Any]) -> Iterator[None]:
    """Replace the class attribute ``owner.attr`` by ``make(original)``; restore it on exit."""
    if attr not in vars(owner):
        raise BreakError(f"{owner.__name__}.{attr} no longer exists: the break cannot follow it")
    original = vars(owner)[attr]
    setattr(owner, attr, make(original))
    try:
        yield
    finally:
        setattr(owner, attr, original)


def parameter(fn: Callable[..., Any], owner: type, param: str) -> inspect.Signature:
    """The signature of ``fn``, checked to take ``param``."""
    sig = inspect.signature(fn)
    if param not in sig.parameters:
        raise BreakError(
            f"{owner.__name__}.{fn.__name__} no longer takes {param!r}: the break cannot follow it"
        )
    return sig


def with_argument(
    owner: type, method: str, param: str, change: Callable[[Any], Any]
) -> AbstractContextManager[None]:
    """Call ``owner.method`` with its argument ``param`` replaced by ``change(value)``."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        sig = parameter(original, owner, param)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            bound = sig.bind(*args, **kwargs)
            bound.apply_defaults()
            bound.arguments[param] = change(bound.arguments[param])
            return original(*bound.args, **bound.kwargs)

        return wrapped

    return replaced(owner, method, make)


def after(
    owner: type,
    method: str,
    needs: Sequence[str],
    then: Callable[[dict[str, Any], Any], Any],
) -> AbstractContextManager[None]:
    """Run ``owner.method``, then ``then(arguments by name, result)``; return what it returns.
    ``needs``: the parameters ``then`` reads."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        sig = inspect.signature(original)
        for param in needs:
            parameter(original, owner, param)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            result = original(*args, **kwargs)
            return then(dict(sig.bind(*args, **kwargs).arguments), result)

        return wrapped

    return replaced(owner, method, make)


def controller_config(**change: Callable[[float], float]) -> AbstractContextManager[None]:
    """Controllers built while open get their config fields changed: ``field=f(old value)``."""
    known = {f.name for f in dataclasses.fields(ControllerConfig)}
    for key in change:
        if key not in known:
            raise BreakError(f"ControllerConfig has no field {key!r}: the break cannot follow it")

    def make(original: Callable[..., None]) -> Callable[..., None]:
        def init(self: Any, *args: Any, **kwargs: Any) -> None:
            original(self, *args, **kwargs)
            new = {k: f(getattr(self.config, k)) for k, f in change.items()}
            self.config = dataclasses.replace(self.config, **new)

        return init

    return replaced(Controller, "__init__", make)


def rotate(v: tuple[float, float], angle: float) -> tuple[float, float]:
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])
