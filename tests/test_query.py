"""The shared plumbing of the nearest-hit queries: where cffi refuses a callback there is none
(the queries then ask pymunk), and a query's handle leads back to its best-so-far list."""

from __future__ import annotations

import pymunk
import pytest

from playground import _query
from playground._query import NearestQuery, c_callback, from_handle


def _keep(*_: object) -> None:
    """A callback that keeps nothing."""


def test_a_callback_is_made_where_cffi_allows() -> None:
    assert c_callback("cpSpacePointQueryFunc", _keep) is not None


@pytest.mark.parametrize("refusal", [MemoryError, RuntimeError])
def test_where_cffi_refuses_callbacks_there_is_none(
    monkeypatch: pytest.MonkeyPatch, refusal: type[Exception]
) -> None:
    def refuse(*_: object) -> None:
        raise refusal("write+execute memory refused")

    monkeypatch.setattr(_query, "_new_callback", refuse)
    assert c_callback("cpSpacePointQueryFunc", _keep) is None


def test_the_handle_leads_to_the_best_so_far() -> None:
    best: list[object] = [1.0, None]
    query = NearestQuery(pymunk.Space(), pymunk.ShapeFilter(group=3), best)
    assert from_handle(query._data) is best
    assert query._filter_c[0].group == 3
