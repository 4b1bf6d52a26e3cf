"""Laws of cross-references: a name a level uses must name a body of the right kind."""

from __future__ import annotations

import pytest

from playground.level import LevelError, loads


def test_references_must_name_bodies() -> None:
    """An expectation on a body that does not exist names the body and suggests one."""
    text = (
        'title = "x"\ndescription = "y"\n'
        '[[props]]\nname = "crate"\nposition = [0, 1]\nmass = 1\n'
        'shapes = [{kind = "circle", radius = 0.5}]\n'
        '[[expect]]\nbody = "crat"\nquantity = "position"\ncomponent = "y"\nt = 1\nbelow = 2\n'
    )
    with pytest.raises(LevelError, match=r"expect\.0\.body: no body named 'crat' \(did you mean"):
        loads(text)
