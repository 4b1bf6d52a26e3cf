"""Law (issue 24): every public class and function of playground that the examples use has a
docstring with a runnable example (run by ``--doctest-modules`` with the suite).

:data:`USED` is the audit, name by name. The examples are run headless for a few frames under a
profiler that records every playground function they call directly (a method, a property, a
constructor), so the audit stays whole: what they call is listed, and what is listed they call.
"""

from __future__ import annotations

import ast
import importlib.util
import inspect
import os
import sys
from collections.abc import Callable
from pathlib import Path
from types import FrameType
from typing import Any

import pytest

import playground

pytest.importorskip("pygame")

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
PACKAGE = Path(playground.__file__).resolve().parent
FRAMES = 30
"""Frames each example runs under the profiler: every call they make happens in their first
frame (building, the input, the step, the drawing)."""

USED: dict[str, tuple[str, ...]] = {
    "World": (
        "add",
        "add_mover",
        "add_static",
        "add_static_segment",
        "forces",
        "perceived_up",
        "step",
    ),
    "Controller": ("axis", "config", "state"),
    "ControllerConfig": (),
    "Intent": (),
    "State": (),
    "FixedStep": ("advance",),
    "Waypoints": (),
    "Radial": (),
    "ForceSensor": ("readings", "step", "track"),
    # What World.forces and ForceSensor.readings return: the examples read its fields.
    "BodyForces": (),
}
"""Each class the examples use → the methods and properties they call."""


def _run(name: str) -> None:
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
    spec = importlib.util.spec_from_file_location(f"audit_{name}", EXAMPLES / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.main(frames=FRAMES)


@pytest.fixture(scope="module")
def called() -> set[str]:
    """The qualified names of the playground functions the examples' own code calls."""
    found: set[str] = set()

    def profile(frame: FrameType, event: str, arg: Any) -> None:
        caller = frame.f_back
        if event != "call" or caller is None:
            return
        if Path(caller.f_code.co_filename).parent == EXAMPLES and Path(
            frame.f_code.co_filename
        ).is_relative_to(PACKAGE):
            found.add(frame.f_code.co_qualname)

    previous: Callable[..., Any] | None = sys.getprofile()
    sys.setprofile(profile)
    try:
        for path in sorted(EXAMPLES.glob("*.py")):
            _run(path.stem)
    finally:
        sys.setprofile(previous)
    return found


def test_the_audit_holds_every_name_the_examples_import() -> None:
    imported = {
        alias.name
        for path in EXAMPLES.glob("*.py")
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("playground")
        for alias in node.names
    }
    assert imported and imported <= set(USED), imported - set(USED)


def test_the_audit_lists_what_the_examples_call_and_no_more(called: set[str]) -> None:
    """Each call is a listed member or a listed class's constructor (``__init__`` or its
    ``__post_init__`` check); each listed member is called."""
    listed = {f"{name}.{member}" for name, members in USED.items() for member in members}
    built = {f"{name}.{init}" for name in USED for init in ("__init__", "__post_init__")}
    assert called - listed - built == set()
    assert listed - called == set()


@pytest.mark.parametrize(
    ("name", "member"),
    [(n, None) for n in USED] + [(n, m) for n, ms in USED.items() for m in ms],
    ids=lambda x: x or "",
)
def test_each_has_a_docstring_with_a_runnable_example(name: str, member: str | None) -> None:
    obj = getattr(playground, name)
    if member is not None:
        static = inspect.getattr_static(obj, member)
        obj = static.fget if isinstance(static, property) else static
    assert ">>> " in (inspect.getdoc(obj) or ""), f"{name}.{member}" if member else name
