"""The commands that draw: ``play`` (the desktop view) and ``gifs`` (the seed sequences). Each
imports its optional dependencies only when it runs."""

from __future__ import annotations

import argparse
from pathlib import Path

from playground.cli.exits import EXIT_OK
from playground.cli.preflight import writable

__all__ = [
    "cmd_gifs",
    "cmd_play",
    "configure_gifs",
    "configure_play",
]


def cmd_play(args: argparse.Namespace) -> int:
    """Open a level in the desktop view (see :mod:`playground.view.launcher`)."""
    for option, path in (
        ("--replay-out", args.replay_out),
        ("--screenshot", args.screenshot),
        ("--gif", args.gif),
    ):
        if path is not None:
            writable(option, path, force=args.force)
    from playground.view.launcher import run_play

    return run_play(args)


def cmd_gifs(args: argparse.Namespace) -> int:
    """Regenerate the seed sequences' animated GIFs (docs/img/gifs) headless; needs the
    ``view`` extra (pygame-ce, Pillow)."""
    from playground.view.gallery import make_gifs

    for path in make_gifs(Path(args.out), args.levels or None):
        print(f"wrote {path} ({path.stat().st_size // 1024} KB)")
    return EXIT_OK


def configure_play(p: argparse.ArgumentParser) -> None:
    p.add_argument("level", nargs="?", default="sandbox", metavar="LEVEL", help="default sandbox")
    p.add_argument("--headless", action="store_true", help="draw off screen (no display needed)")
    p.add_argument("--frames", type=int, metavar="N", help="run N frames of 1/60 s, then exit")
    p.add_argument("--screenshot", metavar="PNG", help="save the last frame (.png, .bmp, .jpg)")
    p.add_argument("--gif", metavar="GIF", help="save the frames as an animated GIF (20 fps)")
    p.add_argument("--size", metavar="WxH", help="window or off-screen size in px (1280x720)")
    p.add_argument("--replay-out", metavar="FILE", help="write the session's inputs as a replay")
    p.add_argument("--replay", metavar="FILE", help="watch a replay instead of playing")
    p.add_argument(
        "--force", action="store_true", help="overwrite existing --replay-out, --screenshot, --gif"
    )
    p.set_defaults(func=cmd_play)


def configure_gifs(p: argparse.ArgumentParser) -> None:
    p.add_argument("levels", nargs="*", metavar="LEVEL", help="default: the seven sequences")
    p.add_argument("--out", default="docs/img/gifs", metavar="DIR", help="default: %(default)s")
    p.set_defaults(func=cmd_gifs)
