"""The ``slow`` tier of ``tests/conftest.py``: deselected by default, run by CI and by ``-m``."""

from __future__ import annotations

from pathlib import Path

import pytest

SUITE = """
import pytest

def test_quick():
    pass

@pytest.mark.slow
def test_long():
    pass
"""


@pytest.fixture
def suite(pytester: pytest.Pytester) -> pytest.Pytester:
    """A two-test suite (one quick, one ``slow``) under this project's conftest."""
    pytester.makeconftest((Path(__file__).parent / "conftest.py").read_text(encoding="utf-8"))
    pytester.makeini("[pytest]\nmarkers =\n    slow: long-running variants\n")
    pytester.makepyfile(test_suite=SUITE)
    return pytester


def test_slow_tests_are_deselected_by_default(
    suite: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("CI", raising=False)
    suite.runpytest("-p", "no:cacheprovider").assert_outcomes(passed=1, deselected=1)


def test_ci_runs_everything(suite: pytest.Pytester, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("CI", "true")
    suite.runpytest("-p", "no:cacheprovider").assert_outcomes(passed=2)


def test_a_marker_expression_selects_the_slow_tier(
    suite: pytest.Pytester, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("CI", raising=False)
    suite.runpytest("-p", "no:cacheprovider", "-m", "slow").assert_outcomes(passed=1, deselected=1)
