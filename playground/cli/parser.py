"""The command line's parser and dispatch: the table of commands (name, help, the module that
declares its arguments and runs it), and :func:`main`, the console script's entry point."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence

from playground import __version__
from playground.cli import bench as bench_cli
from playground.cli import breaks, levelfiles, pictures, running
from playground.cli.exits import guarded

__all__ = ["COMMANDS", "main", "parser"]

Command = Callable[[argparse.Namespace], int]


def _bench(p: argparse.ArgumentParser) -> None:
    bench_cli.configure(p)
    p.set_defaults(func=bench_cli.run)


COMMANDS: tuple[tuple[str, str, Callable[[argparse.ArgumentParser], None]], ...] = (
    ("list", "list the shipped levels with their titles", levelfiles.configure_list),
    ("check", "validate level files (exit 1 with all their errors)", levelfiles.configure_check),
    ("run", "run a level headless and report its checks", running.configure),
    ("faults", "run levels under the breaks they declare to catch", breaks.configure),
    ("play", "open a level in the desktop view (pygame-ce)", pictures.configure_play),
    ("gifs", "regenerate the seed sequences' animated GIFs (headless)", pictures.configure_gifs),
    ("schema", "print the level JSON Schema", levelfiles.configure_schema),
    ("bench", "what accuracy and each effect cost (docs/accuracy.md)", _bench),
)
"""Every command, in the order ``playground --help`` lists them: name, help line, and the function
that declares its arguments and sets ``func``, the function that runs it."""


def parser() -> argparse.ArgumentParser:
    """The argument parser: one subparser per command, each with ``func`` set."""
    top = argparse.ArgumentParser(
        prog="playground",
        description="A 2D game-physics playground for force-driven player bodies.",
    )
    top.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = top.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, help_line, configure in COMMANDS:
        configure(sub.add_parser(name, help=help_line))
    return top


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``playground`` console script; returns the exit code (see
    :mod:`playground.cli.exits`); argparse itself exits 2 on a malformed command line."""
    args = parser().parse_args(argv)
    func: Command = args.func
    return guarded(f"playground {args.command}", lambda: func(args))
