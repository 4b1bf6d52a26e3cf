"""Laws of perceived gravity on its own: −specific force filtered, an "up" held through weak
readings, rows that follow the tracked bodies, and the configuration's checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from playground.filters.one_euro import OneEuroFilter
from playground.gravity import PerceivedGravity, Perception

DT = 1 / 120  # s, a level's step
G = 9.81  # m/s², the specific force of a body at rest on flat ground (up)


def perceiving(n: int, **config: float | bool) -> PerceivedGravity:
    pg = PerceivedGravity(Perception(**config))  # type: ignore[arg-type]
    pg.resize(np.full(n, -1, dtype=np.intp))
    return pg


def feed(pg: PerceivedGravity, specific: list[list[float]], steps: int = 1) -> None:
    for _ in range(steps):
        pg.update(np.array(specific), np.ones(len(specific), dtype=bool), DT)


def test_perceived_gravity_is_minus_the_filtered_specific_force() -> None:
    """Without the spike stage the perceived gravity is exactly −1€(specific force) with the
    configured parameters, row by row."""
    rng = np.random.default_rng(3)
    specific = rng.normal(0.0, 3.0, size=(50, 2, 2)) + np.array([0.0, G])
    pg = perceiving(2, spike_filter=False, min_cutoff=1.5, beta=0.2, d_cutoff=0.8)
    ref = OneEuroFilter(1.5, 0.2, 0.8)
    for s in specific:
        pg.update(s, np.array([True, True]), DT)
        np.testing.assert_array_equal(pg.gravity, ref.filter(-s, DT))


def test_up_is_the_unit_opposite_of_perceived_gravity() -> None:
    pg = perceiving(2)
    feed(pg, [[0.0, G], [3.0, 4.0]])
    np.testing.assert_allclose(pg.up, [[0.0, 1.0], [0.6, 0.8]], rtol=0, atol=1e-15)
    assert pg.up_complete


def test_up_holds_while_the_reading_is_weak() -> None:
    """Below ``up_threshold`` (free fall, a flip through zero) up keeps its last direction, so
    it is never NaN or zero-length once it has been defined."""
    pg = perceiving(1, spike_filter=False, min_cutoff=1e6, up_threshold=1.0)  # passes the input
    feed(pg, [[2.0, 0.0]])
    np.testing.assert_allclose(pg.up, [[1.0, 0.0]], atol=1e-12)
    feed(pg, [[0.0, 0.5]], steps=3)  # weak: held
    np.testing.assert_allclose(pg.up, [[1.0, 0.0]], atol=1e-12)
    np.testing.assert_allclose(pg.gravity, [[0.0, -0.5]], atol=1e-5)  # gravity itself follows
    feed(pg, [[0.0, -5.0]])  # strong again: up follows
    np.testing.assert_allclose(pg.up, [[0.0, -1.0]], atol=1e-5)


def test_a_row_that_never_felt_a_strong_reading_has_no_up() -> None:
    """A new row's up is NaN until a reading above the threshold, and ``up_complete`` says so
    (the world then supplies the field's up)."""
    pg = perceiving(2, spike_filter=False)
    feed(pg, [[0.0, G], [0.0, 0.2]])
    assert np.isfinite(pg.up[0]).all() and np.isnan(pg.up[1]).all()
    assert not pg.up_complete
    # The second row's first strong reading while the first row's is weak (held): complete.
    pg = perceiving(2, spike_filter=False, min_cutoff=1e6)  # passes the input
    feed(pg, [[0.0, G], [0.0, 0.2]])
    feed(pg, [[0.0, 0.2], [0.0, G]])
    assert pg.up_complete and np.isfinite(pg.up).all()


def test_invalid_rows_hold_and_valid_rows_move_on() -> None:
    """A row without a reading this step (``valid`` False) keeps its gravity and up; the other
    rows are not disturbed."""
    pg = perceiving(2, spike_filter=False)
    feed(pg, [[0.0, G], [G, 0.0]], steps=20)
    before = pg.gravity.copy(), pg.up.copy()
    pg.update(np.array([[0.0, -50.0], [0.0, G]]), np.array([False, True]), DT)
    np.testing.assert_array_equal(pg.gravity[0], before[0][0])
    np.testing.assert_array_equal(pg.up[0], before[1][0])
    assert not np.array_equal(pg.gravity[1], before[0][1])


def test_resize_keeps_each_bodys_history() -> None:
    """Re-indexing after tracked bodies changed keeps each row's state with its body; a new row
    starts from its first reading."""
    pg = perceiving(3, spike_filter=False)
    feed(pg, [[0.0, 1.0 * G], [0.0, 2.0 * G], [0.0, 3.0 * G]], steps=5)
    before = pg.gravity.copy()
    pg.resize(np.array([2, -1, 0], dtype=np.intp))
    np.testing.assert_array_equal(pg.gravity[[0, 2]], before[[2, 0]])
    assert np.isnan(pg.up[1]).all()
    feed(pg, [[0.0, 3.0 * G], [0.0, 7.0], [0.0, 1.0 * G]])
    np.testing.assert_array_equal(pg.gravity[1], [0.0, -7.0])  # a first sample passes as is
    np.testing.assert_allclose(pg.gravity[[0, 2]], before[[2, 0]], rtol=1e-12)
    with pytest.raises(ValueError, match="call resize first"):
        pg.update(np.zeros((2, 2)), np.ones(2, dtype=bool), DT)


def test_tune_keeps_the_state_and_the_spike_stage_is_fixed() -> None:
    """New 1€ parameters act from the next step without a restart; the spike stage cannot be
    added or removed by tuning."""
    pg = perceiving(1, spike_filter=False, min_cutoff=0.5)
    feed(pg, [[0.0, G]], steps=10)
    pg.tune(Perception(spike_filter=False, min_cutoff=1e6))
    feed(pg, [[0.0, 2.0 * G]])
    np.testing.assert_allclose(pg.gravity, [[0.0, -2.0 * G]], rtol=1e-4)
    with pytest.raises(ValueError, match=r"^spike_filter: "):
        pg.tune(Perception(spike_filter=True))


@pytest.mark.parametrize(
    ("field", "bad"),
    [
        ("min_cutoff", 0.0),
        ("d_cutoff", -1.0),
        ("up_threshold", math.nan),
        ("beta", -0.1),
        ("beta", math.inf),
    ],
)
def test_a_bad_perception_names_the_field(field: str, bad: float) -> None:
    with pytest.raises(ValueError, match=rf"^{field}: expected"):
        Perception(**{field: bad})  # type: ignore[arg-type]
