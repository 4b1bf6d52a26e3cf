"""Laws of the row layout the filters are built on: sample forms, packed rows, argument checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from playground.filters.rows import (
    Layout,
    as_rows,
    check_param,
    reindexed,
    row_index,
    shaped,
)


@pytest.mark.parametrize("k", [1, 2, 3])
def test_packing_round_trips_and_norms_are_euclidean(k: int) -> None:
    """unpack(pack(x)) is x, and the norm of a packed row is the Euclidean norm of the row."""
    rng = np.random.default_rng(k)
    x = rng.normal(size=(6, k)) * 10.0
    layout = Layout(k)
    packed = layout.pack(x)
    np.testing.assert_array_equal(layout.unpack(packed), x)
    np.testing.assert_allclose(layout.norm(packed), np.linalg.norm(x, axis=1), rtol=1e-15)
    assert layout.zeros(4).shape[0] == 4
    assert not layout.unpack(layout.zeros(4)).any()


def test_two_vectors_pack_without_a_copy() -> None:
    """The point of the complex layout: packing C-ordered (N, 2) floats is a view, so writing
    through the packed rows writes the floats."""
    x = np.zeros((3, 2))
    packed = Layout(2).pack(x)
    assert packed.dtype == np.complex128 and np.shares_memory(packed, x)
    packed[1] = 2.0 + 5.0j
    assert x[1].tolist() == [2.0, 5.0]


def test_sample_forms_come_back_as_given() -> None:
    """A float comes back a float, a k-vector a (k,) array, rows as (N, k)."""
    for sample in (2.5, [1.0, 2.0, 3.0], [[1.0, 2.0], [3.0, 4.0]]):
        rows, form = as_rows(sample)
        assert rows.ndim == 2
        back = shaped(rows, form)
        if isinstance(sample, float):
            assert back == sample and isinstance(back, float)
        else:
            assert np.asarray(back).tolist() == sample


@pytest.mark.parametrize("bad", [np.zeros((2, 2, 2)), np.zeros((3, 0)), np.zeros(0)])
def test_samples_of_other_shapes_are_refused(bad: np.ndarray) -> None:
    with pytest.raises(ValueError, match=r"^x: expected a float, a k-vector"):
        as_rows(bad)


def test_reindexed_takes_rows_and_zeroes_new_ones() -> None:
    """New row i takes old row src[...] where keep is true; new rows start at zero."""
    a = np.array([1.0 + 1j, 2.0 + 2j, 3.0 + 3j])
    keep = np.array([True, False, True, True])
    out = reindexed(a, keep, np.array([2, 0, 0]))
    assert out.tolist() == [3.0 + 3j, 0j, 1.0 + 1j, 1.0 + 1j]


@pytest.mark.parametrize("bad", [np.array([0.5, 1.0]), np.array([[0, 1]])])
def test_row_index_is_a_1d_integer_array(bad: np.ndarray) -> None:
    assert row_index(np.array([2, -1, 0])).dtype == np.intp
    assert row_index(np.array([], dtype=np.float64)).size == 0  # an empty list has no dtype
    with pytest.raises(ValueError, match=r"^rows: expected a 1-D integer array"):
        row_index(bad)


def test_parameters_are_checked_by_name() -> None:
    """Finite and >= 0, or > 0 when strictly positive; the message names the parameter."""
    assert check_param("beta", 0, "x", strictly_positive=False) == 0.0
    assert check_param("fc", 2, "x", strictly_positive=True) == 2.0
    for value, strict in ((0.0, True), (-1e-9, False), (math.nan, False), (math.inf, False)):
        with pytest.raises(ValueError, match=r"^fc: expected a frequency, got"):
            check_param("fc", value, "a frequency", strictly_positive=strict)
