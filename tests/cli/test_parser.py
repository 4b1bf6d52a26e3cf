"""Laws of the command line's parser (:mod:`playground.cli.parser`): every command is listed in
its order with its help line and runs through ``func``; ``playground``, ``python -m playground``
and ``python -m playground.cli`` are the same command."""

from __future__ import annotations

import subprocess
import sys

import pytest

from playground.cli import main, parser
from playground.cli.parser import COMMANDS

ORDER = ("list", "check", "run", "faults", "play", "gifs", "schema", "bench")
"""The commands in the order ``playground --help`` has always listed them."""


def test_help_lists_every_command_in_order(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as done:
        main(["--help"])
    assert done.value.code == 0
    out = capsys.readouterr().out
    where = [out.index(f"\n    {name} ") for name in ORDER]
    assert where == sorted(where)
    for name, help_line, _ in COMMANDS:
        assert help_line in out, name


@pytest.mark.parametrize("name", ORDER)
def test_every_command_has_a_function(name: str) -> None:
    """Each subparser sets ``func`` (what :func:`main` dispatches to)."""
    extra = {"check": ["rest"], "run": ["rest"], "bench": ["overhead"]}.get(name, [])
    args = parser().parse_args([name, *extra])
    assert args.command == name and callable(args.func)


@pytest.mark.parametrize("module", ["playground", "playground.cli"])
def test_python_dash_m_is_the_command(module: str) -> None:
    """``python -m MODULE check rest`` prints and exits as ``main`` does (0); a malformed command
    line exits 2, as argparse does."""
    done = subprocess.run(
        [sys.executable, "-m", module, "check", "rest"], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0 and done.stdout.startswith("ok      rest:"), done.stderr
    bad = subprocess.run(
        [sys.executable, "-m", module, "nonsense"], capture_output=True, text=True, check=False
    )
    assert bad.returncode == 2 and "invalid choice" in bad.stderr
