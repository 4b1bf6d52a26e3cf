"""Laws of patching: a break whose target is gone or changed says which and why instead of
giving a verdict."""

from __future__ import annotations

import dataclasses

import pytest

from playground import controller, faults
from playground.controller import GroundHit, Laws, Sensed
from playground.faults import patching
from playground.faults.catalog import BreakError
from playground.faults.patching import after, controller_laws, with_argument
from playground.level import find, load
from playground.vec import Vec


def test_a_break_that_cannot_apply_says_which_and_why(monkeypatch: pytest.MonkeyPatch) -> None:
    """When the method a break patches is gone (a refactor renamed it), the run reports the break
    and the missing method instead of a verdict."""
    monkeypatch.delattr(controller.Controller, "step")
    outcome = faults.run(load(find("rest")), "rest", "hover_reading")
    assert not outcome.ok
    assert outcome.error is not None
    assert "Controller.step" in outcome.error and "cannot apply" in outcome.error


def test_a_law_break_whose_parameter_is_gone_cannot_apply(monkeypatch: pytest.MonkeyPatch) -> None:
    """A break through the force laws checks the law it wraps when it opens: a default drive law
    that no longer takes ``hover`` (renamed in a refactor) makes ``traction_unbounded`` report
    the law and the parameter instead of a verdict."""

    def drive(sensed: Sensed, hit: GroundHit, move: float, traction: float, c: object) -> Vec:
        return (0.0, 0.0)

    monkeypatch.setattr(patching, "DEFAULT_LAWS", dataclasses.replace(Laws(), drive=drive))
    outcome = faults.run(load(find("null_enemy")), "null_enemy", "traction_unbounded")
    assert not outcome.ok
    assert outcome.error is not None
    assert "Laws.drive no longer takes 'hover'" in outcome.error


def test_a_law_break_naming_no_law_cannot_apply() -> None:
    """``controller_laws`` refuses a law the :class:`Laws` does not have, naming it."""
    with (
        pytest.raises(BreakError, match="Laws has no field 'walk'"),
        controller_laws(walk=lambda law: law),
    ):
        pass


class Door:
    """A class to patch: ``open`` returns the angle it is given, deg."""

    def open(self, angle: float) -> float:
        return angle


def test_a_patch_naming_a_parameter_the_method_does_not_take_cannot_apply() -> None:
    """``with_argument`` and ``after`` check the parameters they name before patching, and leave
    the class as it was."""
    before = dict(vars(Door))
    with (
        pytest.raises(BreakError, match=r"Door\.open no longer takes 'speed'"),
        with_argument(Door, "open", "speed", lambda s: s),
    ):
        pass
    with (
        pytest.raises(BreakError, match=r"Door\.open no longer takes 'speed'"),
        after(Door, "open", ("speed",), lambda a, r: r),
    ):
        pass
    assert dict(vars(Door)) == before


def test_after_sees_the_arguments_by_name_and_returns_what_it_returns() -> None:
    """``after`` runs the method, then hands its arguments by name and its result to ``then``,
    whose answer the caller gets; on exit the method is the original again."""
    with after(Door, "open", ("angle",), lambda a, r: (a["angle"], 2.0 * r)):
        assert Door().open(30.0) == (30.0, 60.0)
    assert Door().open(30.0) == 30.0
