"""The view's tests draw off screen: pygame is initialised headless (display and font only) once
for the folder."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from playground.view.launcher import init_headless


@pytest.fixture(scope="session", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield
