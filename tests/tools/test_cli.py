"""The repository tools' command line (:mod:`tools.cli`): every page and figure generator is a
subcommand of ``python -m tools``, run from the checkout."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tools.cli import TOOLS, parser

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("tool", ["performance", "costs", "docs", "guide", "figures"])
def test_every_generator_is_a_subcommand_with_a_function(tool: str) -> None:
    """Law: each generator parses and has the function that runs it."""
    args = parser().parse_args([tool])
    assert args.tool == tool and callable(TOOLS[tool])


def test_python_dash_m_tools_from_the_checkout() -> None:
    """``python -m tools --help`` from the checkout's root lists the five generators; an unknown
    one exits 2, as argparse does."""
    done = subprocess.run(
        [sys.executable, "-m", "tools", "--help"], cwd=ROOT, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    assert "{performance,costs,docs,guide,figures}" in done.stdout
    bad = subprocess.run(
        [sys.executable, "-m", "tools", "nonsense"], cwd=ROOT, capture_output=True, text=True
    )
    assert bad.returncode == 2 and "invalid choice" in bad.stderr
