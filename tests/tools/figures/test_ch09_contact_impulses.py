"""Laws of chapter 9's numbers (:mod:`tools.figures.ch09_contact_impulses`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

import numpy as np

from tools.figures import ch09_contact_impulses as ch9
from tools.figures.runs import G

TOL_IMPULSE = 1e-12
"""In units of m·g: reverse integration against the arbiter sum on a contact that is not re-made
(round-off of a velocity difference divided by the step; measured 6e-15)."""


def test_chapter_9_stale_steps_are_exactly_the_remade_contacts() -> None:
    """Chapter 9: the arbiter sum differs from what was applied exactly on re-made contacts, by the
    arbiter sum of two steps earlier; everywhere else it equals reverse integration."""
    r = ch9.stale_run()
    mg = 10.0 * G
    excess = (r[:, 2] - r[:, 1]) / mg
    remade = r[:, 3] == 1.0
    assert np.all(np.abs(excess[~remade]) < TOL_IMPULSE)
    assert np.all(np.abs(excess[remade]) > TOL_IMPULSE)
    idx = np.nonzero(remade)[0]
    assert np.all(np.abs(excess[idx] - r[idx - 2, 2] / mg) < TOL_IMPULSE)
    assert ch9.ch9_stale_steps() == np.count_nonzero(remade) > 0
