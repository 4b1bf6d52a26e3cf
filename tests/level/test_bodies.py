"""Laws of the body tables: an actor's controller parameters are ControllerConfig fields."""

from __future__ import annotations

import pytest

from playground.level import LevelError, loads


def test_unknown_controller_parameter_is_named() -> None:
    """Actor parameters are ControllerConfig fields; a typo is suggested its field."""
    text = (
        'title = "x"\ndescription = "y"\n'
        '[[actors]]\nname = "player"\nposition = [0, 1]\ncontroller = { mas = 70 }\n'
    )
    with pytest.raises(
        LevelError, match=r"actors\.0\.controller\.mas: unknown key \(did you mean 'mass'\?\)"
    ):
        loads(text)
