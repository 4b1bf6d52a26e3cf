"""Tables derived from the core's configs: one declaration of each field, read by the level format.

A table that names a core dataclass in ``__core__`` gets one key per declared field of it
(:func:`playground.params.param`): the field's type made strict, its bounds, its doc as the
description and its unit in the schema (``"unit"``), its default. The class body adds the keys
only a level has (a ``kind`` tag, an input's time) and may restate a key whose core type the
format cannot write (a gravity field stands for a tagged table). Once its keys are valid, the
table builds its core object, so every check of the core (a box's corners in order, a controller's
stability) runs at load and is reported at the table's key path; :func:`to_core` gives that object.

>>> from playground.level.settings import Perception
>>> table = Perception(min_cutoff=3.0)
>>> to_core(table)
Perception(min_cutoff=3.0, beta=0.05, d_cutoff=1.0, spike_filter=True, up_threshold=1.0)
>>> Perception.model_json_schema()["properties"]["min_cutoff"]["unit"]
'Hz'
"""

from __future__ import annotations

import dataclasses
import math
import types
import typing
from typing import TYPE_CHECKING, Annotated, Any, ClassVar, Literal, Union

from pydantic import AfterValidator, BaseModel, Field, Strict, model_validator
from pydantic._internal._model_construction import ModelMetaclass
from pydantic.config import JsonDict

from playground.level.values import PLAIN, Name, Table, Whole
from playground.params import SPEC, Spec

__all__ = ["Derived", "to_core"]

_MODELS: dict[type[Any], type[BaseModel]] = {}
"""The table derived from each core dataclass, for fields whose type is another config."""


class _Deriving(ModelMetaclass):
    """Adds the declared fields of ``__core__`` to the class body before pydantic reads it."""

    def __new__(
        mcs,
        cls_name: str,
        bases: tuple[type[Any], ...],
        namespace: dict[str, Any],
        **kwargs: Any,
    ) -> type:
        core = namespace.get("__core__")
        if core is not None:
            namespace = {**namespace, "__annotations__": dict(namespace.get("__annotations__", {}))}
            only = namespace.get("__only__")
            hints = typing.get_type_hints(core)
            for f in dataclasses.fields(core):
                if (
                    SPEC not in f.metadata  # the core's own (a cache), not a parameter
                    or (only is not None and f.name not in only)
                    or f.name in namespace["__annotations__"]
                ):
                    continue
                annotation, info = _field(f, hints[f.name])
                namespace["__annotations__"][f.name] = annotation
                namespace[f.name] = info
        cls = super().__new__(mcs, cls_name, bases, namespace, **kwargs)
        if core is not None:
            _MODELS[core] = cls
        return cls


class Derived(Table, metaclass=_Deriving):
    """A table whose keys are the declared fields of the core dataclass ``__core__`` (only those
    in ``__only__``, if given), plus the keys its class body adds."""

    __core__: ClassVar[type[Any] | None] = None
    __only__: ClassVar[tuple[str, ...] | None] = None

    @model_validator(mode="after")
    def _core_checks(self) -> Derived:
        to_core(self)
        return self

    if TYPE_CHECKING:
        # The keys are added when the class is made: a type checker sees them as Any.
        def __getattr__(self, name: str) -> Any: ...


def to_core(table: BaseModel) -> Any:
    """The core object a derived table describes (a key left out is the core's default)."""
    core = getattr(type(table), "__core__", None)
    if core is None:
        raise TypeError(f"{type(table).__name__} is not derived from a core config")
    fields = type(table).model_fields
    kwargs = {}
    for f in dataclasses.fields(core):
        value = getattr(table, f.name) if f.name in fields else None
        if value is not None:  # None stands for a default the format cannot write (∞)
            kwargs[f.name] = _core_value(value)
    return core(**kwargs)


def _core_value(value: Any) -> Any:
    if isinstance(value, BaseModel):
        return to_core(value)
    if isinstance(value, list):
        return tuple(_core_value(v) for v in value)
    return value


def _field(f: dataclasses.Field[Any], hint: Any) -> tuple[Any, Any]:
    """The annotation and pydantic field of one declared dataclass field."""
    spec: Spec = f.metadata[SPEC]
    annotation = _annotation(hint, spec)
    extra: JsonDict | None = {"unit": spec.unit} if spec.unit else None
    if f.default is not dataclasses.MISSING:
        default = f.default
        if isinstance(default, float) and not math.isfinite(default):
            # A file cannot write ∞: the key is left out instead.
            annotation, default = annotation | None, None
        elif isinstance(default, tuple) and typing.get_origin(_strip(annotation)) is list:
            return annotation, Field(
                default_factory=list, description=spec.doc, json_schema_extra=extra
            )
        return annotation, Field(default=default, description=spec.doc, json_schema_extra=extra)
    if f.default_factory is not dataclasses.MISSING:
        model = _MODELS[type(f.default_factory())]
        return annotation, Field(
            default_factory=model, description=spec.doc, json_schema_extra=extra
        )
    return annotation, Field(description=spec.doc, json_schema_extra=extra)


def _strip(annotation: Any) -> Any:
    return (
        typing.get_args(annotation)[0] if typing.get_origin(annotation) is Annotated else annotation
    )


def _annotation(hint: Any, spec: Spec) -> Any:
    """The strict pydantic type of a value of type ``hint`` within ``spec``'s bounds."""
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if origin in (Union, types.UnionType):
        alts = [_annotation(a, spec) for a in args if a is not type(None)]
        out = alts[0]
        for alt in alts[1:]:
            out = out | alt
        return out | None if type(None) in args else out
    if hint is float:
        return Annotated[float, *_bounds(spec)]
    if hint is int:
        return Annotated[Whole, Field(ge=spec.ge, gt=spec.gt, le=spec.le)]
    if hint is bool or origin is Literal:
        return hint
    if hint is str:
        return Name
    if origin is tuple and args and Ellipsis not in args:
        items = tuple(_annotation(a, dataclasses.replace(spec, nonzero=False)) for a in args)
        checks = [AfterValidator(_nonzero_vector)] if spec.nonzero else []
        # A TOML array is a list: fixed-length arrays are the one conversion allowed.
        return Annotated[tuple[items], Strict(False), *checks]  # type: ignore[valid-type]
    if origin is tuple:
        return Annotated[list[_annotation(args[0], spec)], Field(min_length=spec.min_items or None)]  # type: ignore[misc]
    if hint in _MODELS:
        return _MODELS[hint]
    raise TypeError(f"no level type for {hint!r}: restate the key in the table's class body")


def _bounds(spec: Spec) -> list[Any]:
    # Where the core leaves a side unbounded, a level's number is still a plain one (within
    # ±values.PLAIN): every number of a level file is bounded.
    ge = spec.ge if spec.ge is not None or spec.gt is not None else -PLAIN
    le = spec.le if spec.le is not None else PLAIN
    out: list[Any] = [Field(ge=ge, gt=spec.gt, le=le, allow_inf_nan=False)]
    if spec.nonzero:
        out.append(AfterValidator(_nonzero))
    return out


def _nonzero(value: float) -> float:
    if value == 0.0:
        raise ValueError("expected a non-zero number")
    return value


def _nonzero_vector(value: tuple[float, ...]) -> tuple[float, ...]:
    if all(v == 0.0 for v in value):
        raise ValueError("expected a non-zero vector")
    return value
