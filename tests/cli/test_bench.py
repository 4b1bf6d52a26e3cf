"""The ``bench`` command line parses both subcommands with their options, and no other: the
page writers are the repository's tools (tests/tools/test_cli.py)."""

from __future__ import annotations

import argparse

import pytest

from playground.cli.bench import configure


def test_cli_parses_both_subcommands() -> None:
    """Law: the bench parser accepts accuracy and overhead with their options."""
    parser = argparse.ArgumentParser()
    configure(parser)
    args = parser.parse_args(["accuracy", "--quick", "--workers", "0", "--json"])
    assert (args.bench, args.quick, args.workers, args.json) == ("accuracy", True, 0, True)
    assert parser.parse_args(["overhead", "--quick"]).bench == "overhead"


@pytest.mark.parametrize("page", ["performance", "docs", "guide"])
def test_the_page_writers_are_not_bench_subcommands(page: str) -> None:
    """Law: ``bench`` has no page writer (they are ``python -m tools``'s, not installed)."""
    parser = argparse.ArgumentParser()
    configure(parser)
    with pytest.raises(SystemExit):
        parser.parse_args([page])
