"""How a break patches: replace an attribute of a class or a module for as long as the break is
open, call a function with one argument changed, run something after a method, or change the
config or the force laws (:class:`~playground.controller.laws.Laws`) controllers are built with.
Each checks that what it patches still exists and still takes the parameters it names, and
raises :class:`~playground.faults.catalog.BreakError` otherwise.

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
from playground.controller.controller import DEFAULT_LAWS, Controller
from playground.controller.laws import Laws
from playground.faults.catalog import BreakError

__all__ = [
    "after",
    "argument_changed",
    "controller_config",
    "controller_laws",
    "parameter",
    "replaced",
    "rotate",
    "with_argument",
]


@contextmanager
def replaced(owner: Any, attr: str, make: Callable[[Any], Any]) -> Iterator[None]:
    """Replace the attribute ``owner.attr`` of a class or a module by ``make(original)``;
    restore it on exit."""
    if attr not in vars(owner):
        raise BreakError(f"{owner.__name__}.{attr} no longer exists: the break cannot follow it")
    original = vars(owner)[attr]
    setattr(owner, attr, make(original))
    try:
        yield
    finally:
        setattr(owner, attr, original)


def parameter(fn: Callable[..., Any], owner: Any, param: str) -> inspect.Signature:
    """The signature of ``fn``, checked to take ``param``."""
    sig = inspect.signature(fn)
    if param not in sig.parameters:
        raise BreakError(
            f"{owner.__name__}.{fn.__name__} no longer takes {param!r}: the break cannot follow it"
        )
    return sig


def with_argument(
    owner: Any, method: str, param: str, change: Callable[[Any], Any]
) -> AbstractContextManager[None]:
    """Call ``owner.method`` (of a class or a module) with its argument ``param`` replaced by
    ``change(value)``."""
    return replaced(owner, method, argument_changed(owner, param, change))


def argument_changed(
    owner: Any, param: str, change: Callable[[Any], Any]
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A maker for :func:`replaced` and :func:`controller_laws`: the function called with its
    argument ``param`` replaced by ``change(value)`` (``owner`` names it in errors)."""

    def make(original: Callable[..., Any]) -> Callable[..., Any]:
        sig = parameter(original, owner, param)

        def wrapped(*args: Any, **kwargs: Any) -> Any:
            bound = sig.bind(*args, **kwargs)
            bound.apply_defaults()
            bound.arguments[param] = change(bound.arguments[param])
            return original(*bound.args, **bound.kwargs)

        return wrapped

    return make


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
    _known(ControllerConfig, change)

    def built(controller: Controller) -> None:
        new: dict[str, Any] = {k: f(getattr(controller.config, k)) for k, f in change.items()}
        controller.config = dataclasses.replace(controller.config, **new)

    return _controllers_built(built)


def controller_laws(
    **make: Callable[[Callable[..., Any]], Callable[..., Any]],
) -> AbstractContextManager[None]:
    """Controllers built while open follow changed force laws: ``law=make(the law they had)``
    replaces that law of their :attr:`~playground.controller.Controller.laws`. Each maker is
    tried on the default law at once, so a law that no longer takes a parameter it names
    cannot apply."""
    _known(Laws, make)
    for name, maker in make.items():
        maker(getattr(DEFAULT_LAWS, name))

    def built(controller: Controller) -> None:
        laws = controller.laws
        controller.laws = dataclasses.replace(
            laws, **{name: maker(getattr(laws, name)) for name, maker in make.items()}
        )

    return _controllers_built(built)


def _known(cls: Any, change: dict[str, Any]) -> None:
    known = {f.name for f in dataclasses.fields(cls)}
    for key in change:
        if key not in known:
            raise BreakError(f"{cls.__name__} has no field {key!r}: the break cannot follow it")


def _controllers_built(built: Callable[[Controller], None]) -> AbstractContextManager[None]:
    """Run ``built(controller)`` on every controller built while open, after its own init."""

    def make(original: Callable[..., None]) -> Callable[..., None]:
        def init(controller: Controller, *args: Any, **kwargs: Any) -> None:
            original(controller, *args, **kwargs)
            built(controller)

        return init

    return replaced(Controller, "__init__", make)


def rotate(v: tuple[float, float], angle: float) -> tuple[float, float]:
    c, s = math.cos(angle), math.sin(angle)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1])
