"""The lean of the perceived up (:func:`~playground.controller.sensing.lean`) and the legs'
effort that explains it (:func:`~playground.controller.sensing.effort_on`) over
:data:`~playground.controller.elementwise.ARRAYS` give, row by row, the bits they give in floats
for one controller: a crowd's members lean as each would alone (its branches are selects there,
``Crowd.step`` calls the very functions)."""

from __future__ import annotations

import math
import struct
from typing import Any

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from playground.controller._vec import ZERO
from playground.controller.elementwise import ARRAYS
from playground.controller.sensing import effort_on, lean

_lean: Any = lean
_effort_on: Any = effort_on
"""The laws called on arrays (typed for floats, written for both)."""

MAX_LEAN = 0.6
"""rad: the largest max_lean drawn (the default config's is 0.1)."""


def bits(v: float) -> bytes:
    return struct.pack("<d", v)


def _unit(a: float) -> tuple[float, float]:
    return (math.cos(a), math.sin(a))


efforts = st.one_of(
    st.just(ZERO),
    st.tuples(st.floats(-3000.0, 3000.0), st.floats(-3000.0, 3000.0)),
)
"""N: none (standing, or pushed within PUSH_ECHO), or its legs' effort in its last step."""

rows = st.tuples(
    st.floats(-math.pi, math.pi),  # the field's up, rad
    st.one_of(st.floats(-math.pi, math.pi), st.sampled_from([0.0, -0.0])),  # perceived, off it
    efforts,
    st.floats(0.0, 5000.0),  # weight, N
    st.floats(0.0, MAX_LEAN),  # max_lean, rad
)


def _both(
    drawn: list[tuple[float, float, tuple[float, float], float, float]],
) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """Each row's lean in floats, and the rows' lean on arrays, as lists of pairs."""
    levels = [_unit(a) for a, *_ in drawn]
    perceived = [_unit(a + off) for a, off, *_ in drawn]
    want = [
        lean(p, q, e, w, m) for p, q, (_, _, e, w, m) in zip(perceived, levels, drawn, strict=True)
    ]
    column = [np.array(c, dtype=np.float64) for c in zip(*drawn, strict=True)]
    x, y = _lean(
        (np.array([p for p, _ in perceived]), np.array([q for _, q in perceived])),
        (np.array([p for p, _ in levels]), np.array([q for _, q in levels])),
        (np.array([e[0] for _, _, e, _, _ in drawn]), np.array([e[1] for _, _, e, _, _ in drawn])),
        column[3],
        column[4],
        ARRAYS,
    )
    return want, list(zip(x.tolist(), y.tolist(), strict=True))


@given(st.lists(rows, min_size=1, max_size=40))
def test_the_lean_on_arrays_is_the_lean_in_floats_row_by_row(
    drawn: list[tuple[float, float, tuple[float, float], float, float]],
) -> None:
    """Law: ``lean`` over ARRAYS = ``lean`` in floats on each row, to the bit: within
    ``max_lean``, held to it, leaning into its own step or held beyond it toward that step."""
    want, got = _both(drawn)
    assert [(bits(x), bits(y)) for x, y in got] == [(bits(x), bits(y)) for x, y in want]


def test_the_lean_on_arrays_holds_and_keeps_as_floats_do_in_every_case() -> None:
    """The law above over a dense draw that holds every case many times (a row held to
    max_lean without an effort of its own, one leaning into its own step as far as the
    perceived up, one held short of it, one within max_lean): bit for bit."""
    rng = np.random.default_rng(27)
    n = 4096
    pushes = rng.uniform(-3000.0, 3000.0, (n, 2)).tolist()
    drawn = [
        (a, off, ZERO if k % 3 == 0 else (ex, ey), w, m)
        for k, (a, off, w, m, (ex, ey)) in enumerate(
            zip(
                rng.uniform(-math.pi, math.pi, n).tolist(),
                rng.uniform(-1.2, 1.2, n).tolist(),
                rng.uniform(100.0, 2000.0, n).tolist(),
                rng.uniform(0.05, MAX_LEAN, n).tolist(),
                pushes,
                strict=True,
            )
        )
    ]
    want, got = _both(drawn)
    assert [(bits(x), bits(y)) for x, y in got] == [(bits(x), bits(y)) for x, y in want]
    cases = {"within": 0, "held": 0, "own, kept": 0, "own, held": 0}
    for (a, off, e, _, m), leaned in zip(drawn, want, strict=True):
        kept = leaned == _unit(a + off)
        if abs(off) < m * (1.0 - 1e-9):
            assert kept
            cases["within"] += 1
        elif abs(off) > m * (1.0 + 1e-9):
            if e is ZERO:
                assert not kept
                cases["held"] += 1
            else:
                cases["own, kept" if kept else "own, held"] += 1
    assert min(cases.values()) > 200, cases


@given(
    st.lists(
        st.tuples(
            st.one_of(st.just(ZERO), st.tuples(st.floats(-3000.0, 3000.0),
                                               st.floats(-3000.0, 3000.0))),
            st.one_of(st.none(), st.floats(-math.pi, math.pi)),  # the ground's normal, rad
            st.tuples(st.floats(-30.0, 30.0), st.floats(-30.0, 30.0)),  # gravity, m/s²
            st.floats(1.0, 500.0),  # mass, kg
        ),
        min_size=1,
        max_size=40,
    )
)  # fmt: skip
def test_the_effort_on_arrays_is_the_effort_in_floats_row_by_row(
    drawn: list[tuple[tuple[float, float], float | None, tuple[float, float], float]],
) -> None:
    """Law: ``effort_on`` over ARRAYS, its rows with no ground or no drive masked out by
    ``holding``, = ``effort_on`` in floats on each row, to the bit (signed zeros included: a
    drive along a flat floor has a −0.0 component, which the hold must not turn to +0.0)."""
    want = [effort_on(d, None if a is None else _unit(a), g, m) for d, a, g, m in drawn]
    # A row with no ground has a normal on arrays all the same (the masked row's): here (0, 1).
    normals = [_unit(a) if a is not None else (0.0, 1.0) for _, a, _, _ in drawn]
    holding = np.array([a is not None and d is not ZERO for d, a, _, _ in drawn])
    x, y = _effort_on(
        (np.array([d[0] for d, *_ in drawn]), np.array([d[1] for d, *_ in drawn])),
        (np.array([p for p, _ in normals]), np.array([q for _, q in normals])),
        (np.array([g[0] for _, _, g, _ in drawn]), np.array([g[1] for _, _, g, _ in drawn])),
        np.array([m for *_, m in drawn]),
        ARRAYS,
        holding,
    )
    got = list(zip(x.tolist(), y.tolist(), strict=True))
    assert [(bits(p), bits(q)) for p, q in got] == [(bits(p), bits(q)) for p, q in want]


def test_the_lean_in_floats_gives_back_the_perceived_up_itself() -> None:
    """Within max_lean, or leaning as far as its own step explains, the very tuple comes back
    (``Senses.sense`` asks ``is not`` whether it was held)."""
    perceived = (0.6, 0.8)
    assert lean(perceived, (0.0, 1.0), (515.0, 0.0), 686.7, 0.1) is perceived
    near = (math.sin(0.05), math.cos(0.05))
    assert lean(near, (0.0, 1.0), ZERO, 686.7, 0.1) is near
    assert lean(perceived, (0.0, 1.0), ZERO, 686.7, 0.1) is not perceived
