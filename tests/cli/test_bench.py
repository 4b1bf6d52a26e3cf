"""The ``bench`` command line parses every subcommand with its options."""

from __future__ import annotations

import argparse
from pathlib import Path

from playground.cli.bench import configure


def test_cli_parses_both_subcommands() -> None:
    """Law: the bench parser accepts accuracy, overhead and docs with their options."""
    parser = argparse.ArgumentParser()
    configure(parser)
    args = parser.parse_args(["accuracy", "--quick", "--workers", "0", "--json"])
    assert (args.bench, args.quick, args.workers, args.json) == ("accuracy", True, 0, True)
    assert parser.parse_args(["overhead", "--quick"]).bench == "overhead"
    assert parser.parse_args(["docs"]).dir == Path("docs")
