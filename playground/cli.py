"""The ``playground`` command: list, check and run levels headless, export the level schema.

Each subcommand is a function ``cmd_<name>(args) -> exit code`` registered in :func:`parser`.

``playground run LEVEL --json`` prints one JSON object::

    {"level", "dt", "steps", "sim_seconds", "wall_seconds",
     "checks": [{"name", "passed", "detail"}],
     "bodies": {NAME: {"mass", "position", "velocity", "angle", "state",
                       "force": {"engine", "contact", "constraint", "support", "support_filtered"},
                       "perceived_gravity"}}}

for every tracked body, at the last step, SI units, vectors as ``[x, y]``. ``state`` is null for a
body without a controller; ``contact`` and ``constraint`` are null unless the level sets
``settings.contact_split``, and on a step whose split is unknown; ``support_filtered`` is
−m · ``perceived_gravity`` (the 1€-filtered support force).

Exit codes, for every command: 0 ok; 1 a check failed (or a level did not validate, for
``check``); 2 bad input or environment (a malformed level, an unusable path, a missing optional
dependency); 130 interrupted (Ctrl-C). :func:`main` maps every such error to a one-line message on
stderr in one place; nothing ends in a traceback.

>>> main(["check", "incline"])
ok      incline: Incline
0
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import importlib
import json
import math
import signal
import sys
import threading
import time
import types
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from playground import __version__
from playground._preflight import UsageError, writable
from playground.bench import cli as bench_cli
from playground.guard import RunawayError
from playground.level.document import schema
from playground.level.errors import LevelError
from playground.level.files import find, shipped
from playground.level.loading import load
from playground.limits import MAX_DT, MAX_SECONDS, MAX_TIME, MIN_DT

__all__ = ["EXIT_FAILED", "EXIT_INTERRUPTED", "EXIT_OK", "EXIT_USAGE", "main", "parser"]

Command = Callable[[argparse.Namespace], int]

EXIT_OK = 0
"""Everything ran and every check passed."""
EXIT_FAILED = 1
"""A check failed (or, for ``check``, a level file has problems)."""
EXIT_USAGE = 2
"""Bad input or environment: a malformed level, an unusable path, a missing optional dependency."""
EXIT_INTERRUPTED = 130
"""Interrupted by Ctrl-C (128 + SIGINT, as shells report it)."""

EXTRAS = {"pygame": "view", "PIL": "view", "matplotlib": "bench"}
"""Optional dependencies by module, and the extra of ``pymunk-playground`` that installs each."""


def cmd_list(args: argparse.Namespace) -> int:
    """Print the shipped levels with their titles."""
    levels = shipped()
    width = max((len(n) for n in levels), default=0)
    for name, path in levels.items():
        try:
            title = load(path).title
        except LevelError as exc:
            title = f"(invalid: {len(exc.problems)} problem(s); run playground check)"
        print(f"{name:<{width}}  {title}")
    return 0


def cmd_check(args: argparse.Namespace) -> int:
    """Validate level files; print every problem; exit 1 if any file has one."""
    failed = False
    for item in args.files:
        try:
            path = find(item)
            level = load(path)
            print(f"ok      {item}: {level.title}")
        except LevelError as exc:
            failed = True
            where = f" (line {exc.line}, column {exc.column})" if exc.line is not None else ""
            print(f"FAILED  {exc.source}{where}: {len(exc.problems)} problem(s)", file=sys.stderr)
            for problem in exc.problems:
                print(f"  {problem}", file=sys.stderr)
    return 1 if failed else 0


def _num(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def _vec(v: Sequence[float]) -> list[float | None] | None:
    out = [float(x) if math.isfinite(x) else None for x in v]
    return None if all(x is None for x in out) else out


def cmd_run(args: argparse.Namespace) -> int:
    """Run a level headless, report its checks (and bodies with --json); exit 1 on a failure."""
    from playground.expectations import watch
    from playground.recording import check_output, recording
    from playground.scene import build

    if args.record is not None:
        try:
            check_output(args.record, force=args.force)
        except ValueError as exc:
            raise UsageError(str(exc)) from None
    path = find(args.level)
    level = load(path)
    scene = build(level)
    seconds = level.settings.seconds if args.seconds is None else args.seconds
    longest = MAX_TIME if args.long else MAX_SECONDS
    if not (math.isfinite(seconds) and 0 <= seconds <= longest):
        more = "" if args.long else f" (up to {MAX_TIME:g} s with --long)"
        raise UsageError(
            f"--seconds: expected a number of seconds in [0, {longest:g}]{more}, got {seconds:g}"
        )
    if args.replay is not None:
        covered = _replay(args.replay, path.stem, scene)
        if covered is None:
            return 2
        seconds = covered if args.seconds is None else seconds
    checks = watch(scene)
    if args.profile:
        scene.world.config = dataclasses.replace(scene.world.config, timing=True)
    _progress_bar(scene, seconds, enabled=not args.no_progress)
    start = time.perf_counter()
    try:
        if args.record is not None:
            with recording(scene, args.record, force=args.force):
                scene.run(seconds)
        else:
            scene.run(seconds)
    except RunawayError as exc:
        # The recording (closed on the way out) keeps every step before this one.
        print(f"playground run: {path.stem}: {exc}", file=sys.stderr)
        return 1
    wall = time.perf_counter() - start
    results = checks.results()
    world = scene.world
    profile = _profile(path, seconds) if args.profile else []
    if args.json:
        bodies: dict[str, Any] = {}
        for name in scene.tracked:
            body = world.body(name)
            f = world.forces(name)
            bodies[name] = {
                "mass": body.mass,
                "position": _vec(body.position),
                "velocity": _vec(body.velocity),
                "angle": _num(body.angle),
                "state": scene.state(name),
                "force": {
                    "engine": _vec(f.engine),
                    "contact": _vec(f.contact),
                    "constraint": _vec(f.constraint),
                    "support": _vec(f.support),
                    "support_filtered": _vec(scene.support_filtered(name)),
                },
                "perceived_gravity": _vec(world.perceived_gravity(name)),
            }
        report = {
            "level": path.stem,
            "dt": level.settings.dt,
            "steps": world.steps,
            "sim_seconds": world.time,
            "wall_seconds": wall,
            "checks": [{"name": r.name, "passed": r.passed, "detail": r.detail} for r in results],
            "bodies": bodies,
        }
        if args.profile:
            from playground.bench.profiler import stage_costs

            report["profile"] = {
                "stages": [dataclasses.asdict(c) for c in stage_costs(world)],
                "functions": [dataclasses.asdict(f) for f in profile],
            }
        # Strict JSON: no NaN or Infinity slips out (vectors and angles go through _vec, _num).
        print(json.dumps(report, indent=2, allow_nan=False))
    else:
        print(f"{level.title}: {world.steps} steps, {world.time:g} s simulated in {wall:.3f} s")
        for r in results:
            print(f"  {'pass' if r.passed else 'FAIL'}  {r.detail}")
    if args.profile and not args.json:
        _print_profile(world, profile)
    return 0 if all(r.passed for r in results) else 1


def _profile(path: Path, seconds: float) -> list[Any]:
    """The top functions of a second run of the level under cProfile."""
    from playground.bench.profiler import top_functions
    from playground.scene import build

    again = build(load(path))
    return top_functions(lambda: again.run(seconds))


def _print_profile(world: Any, functions: list[Any]) -> None:
    from playground.bench.profiler import function_table, stage_table

    print(f"\nstages over {world.steps} steps (World.timings):")
    print(stage_table(world))
    print("\ntop functions by own time (a second run under cProfile, which slows every Python")
    print("call: for ranking, not for quoting):")
    print(function_table(functions))


PROGRESS_MIN_STEPS = 2400
"""Runs shorter than this many steps (20 s at the default dt, about a second of wall time) get
no progress bar."""


def _progress_bar(scene: Any, seconds: float, *, enabled: bool) -> None:
    """A progress bar (simulated seconds) on stderr for a long run, when stderr is a terminal."""
    from playground.world.schedule import Stage

    steps = round(seconds / scene.world.config.dt)
    if not enabled or steps < PROGRESS_MIN_STEPS or not sys.stderr.isatty():
        return
    from tqdm import tqdm

    bar = tqdm(total=steps, unit="step", desc="run", leave=False)
    every = max(1, steps // 200)

    def advance(world: Any) -> None:
        if world.steps % every == 0 or world.steps >= steps:
            bar.update(min(world.steps, steps) - bar.n)
            if bar.n >= steps:
                bar.close()

    scene.world.on(Stage.OBSERVE, advance)


def _replay(file: str, name: str, scene: Any) -> float | None:
    """Let a replay drive the scene's player; the seconds it covers (None after an error)."""
    from playground.replay import Playback, Replay, ReplayError

    try:
        replay = Replay.load(file)
        Playback(replay, name, scene)
    except (ReplayError, ValueError) as exc:
        print(f"playground run: {exc}", file=sys.stderr)
        return None
    return replay.steps * replay.dt


def cmd_faults(args: argparse.Namespace) -> int:
    """Run levels clean and under each break they declare (see :mod:`playground.faults`); exit 1
    when a declared break goes uncaught, a clean run fails or a break cannot be applied."""
    from playground import faults

    known = faults.names()
    if args.list:
        width = max(len(name) for name in known)
        for name in known:
            print(f"{name:<{width}}  {faults.BREAKS[name].doc}")
        return 0
    unknown = [b for b in args.breaks or [] if b not in known]
    if unknown:
        print(
            f"playground faults: no break named {', '.join(map(repr, unknown))} "
            f"(valid: {', '.join(known)})",
            file=sys.stderr,
        )
        return 2
    try:
        items = args.levels or list(shipped())
        levels = [(_level_name(item), load(find(item))) for item in items]
    except LevelError as exc:
        print(f"playground faults: {exc}", file=sys.stderr)
        return 2
    total = sum(1 + len(args.breaks or level.catches) for _, level in levels)
    bar = _progress(total, "faults") if sys.stderr.isatty() and not args.no_progress else None
    start = time.perf_counter()
    rows = faults.matrix(
        levels, args.breaks, progress=None if bar is None else lambda label: bar.update(1)
    )
    if bar is not None:
        bar.close()
    wall = time.perf_counter() - start
    ok = all(row.ok for row in rows)
    if args.json:
        print(json.dumps(_faults_report(rows, ok, wall), indent=2))
    else:
        _print_matrix(rows, wall)
    return 0 if ok else 1


def _level_name(item: str) -> str:
    return Path(item).stem if item.endswith(".toml") else item


def _progress(total: int, desc: str) -> Any:
    """A tqdm progress bar on stderr (None if tqdm, a dependency, cannot be imported)."""
    try:
        tqdm = importlib.import_module("tqdm").tqdm
    except ImportError:
        return None
    return tqdm(total=total, desc=desc, unit="run", leave=False)


def _outcome(o: Any) -> dict[str, Any]:
    return {
        "break": o.fault,
        "declared": o.declared,
        "ok": o.ok,
        "caught": bool(o.failed) and o.error is None,
        "caught_by": list(o.failed),
        "error": o.error,
        "wall_seconds": o.seconds,
    }


def _faults_report(rows: Sequence[Any], ok: bool, wall: float) -> dict[str, Any]:
    return {
        "ok": ok,
        "wall_seconds": wall,
        "levels": [
            {
                "level": row.level,
                "ok": row.ok,
                "checks": row.clean.checks,
                "clean": {
                    "passed": row.clean.ok,
                    "failed": list(row.clean.failed),
                    "error": row.clean.error,
                },
                "breaks": [_outcome(o) for o in row.breaks],
            }
            for row in rows
        ],
    }


def _print_matrix(rows: Sequence[Any], wall: float) -> None:
    """One line per level (its clean run) and one per break tried: which checks caught it."""
    width = max((len(o.fault or "") for row in rows for o in row.breaks), default=0)
    width = max(width, len("(clean)"))
    runs = 0
    for row in rows:
        clean = row.clean
        runs += 1 + len(row.breaks)
        if clean.error is not None:
            verdict = f"ERROR  {clean.error}"
        elif clean.failed:
            verdict = f"FAIL   {len(clean.failed)} check(s) fail: {'; '.join(clean.failed)}"
        else:
            verdict = f"ok     all {clean.checks} checks pass"
        print(f"{row.level}")
        print(f"  {'(clean)':<{width}}  {verdict}")
        for o in row.breaks:
            if o.error is not None:
                verdict = f"ERROR  {o.error}"
            elif o.failed:
                verdict = f"caught by {'; '.join(o.failed)}"
                verdict = f"{'ok' if o.declared else '(ok)':<6} {verdict}"
            elif o.declared:
                verdict = "MISSED no check failed"
            else:
                verdict = "-      not declared; no check failed"
            print(f"  {o.fault:<{width}}  {verdict}")
    bad = sum(1 for row in rows for o in (row.clean, *row.breaks) if not o.ok)
    summary = "all declared breaks caught" if bad == 0 else f"{bad} run(s) not ok"
    print(f"{len(rows)} level(s), {runs} runs in {wall:.1f} s: {summary}")


def cmd_play(args: argparse.Namespace) -> int:
    """Open a level in the desktop view (see :mod:`playground.view.launcher`)."""
    if args.replay_out is not None:
        writable("--replay-out", args.replay_out)
    from playground.view.launcher import run_play

    return run_play(args)


def cmd_figures(args: argparse.Namespace) -> int:
    """Regenerate the teaching chapters' figures (docs/chapters) headless; needs matplotlib and
    tqdm (the ``bench`` extra)."""
    from playground.figures import make_all

    try:
        paths = make_all(Path(args.out), progress=not args.no_progress)
    except ImportError as exc:
        print(
            f"playground figures: needs matplotlib and tqdm: pip install 'pymunk-playground[bench]'"
            f" ({exc})",
            file=sys.stderr,
        )
        return 2
    for path in paths:
        print(f"wrote {path}")
    return 0


def cmd_gifs(args: argparse.Namespace) -> int:
    """Regenerate the seed sequences' animated GIFs (docs/img/gifs) headless; needs the
    ``view`` extra (pygame-ce, Pillow)."""
    from playground.view.gallery import make_gifs

    for path in make_gifs(Path(args.out), args.levels or None):
        print(f"wrote {path} ({path.stat().st_size // 1024} KB)")
    return 0


def cmd_schema(args: argparse.Namespace) -> int:
    """Print the level JSON Schema, or write it to --output."""
    text = schema_text()
    if args.output is None:
        sys.stdout.write(text)
    else:
        writable("--output", args.output).write_text(text, encoding="utf-8")
    return 0


def schema_text() -> str:
    """The JSON Schema as the committed ``levels/level.schema.json`` holds it."""
    return json.dumps(schema(), indent=2, ensure_ascii=False) + "\n"


def parser() -> argparse.ArgumentParser:
    """The argument parser: one subparser per command, each with ``func`` set."""
    top = argparse.ArgumentParser(
        prog="playground",
        description="A 2D game-physics playground for force-driven player bodies.",
    )
    top.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = top.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = sub.add_parser("list", help="list the shipped levels with their titles")
    p.set_defaults(func=cmd_list)

    p = sub.add_parser("check", help="validate level files (exit 1 with all their errors)")
    p.add_argument("files", nargs="+", metavar="FILE", help="level files or shipped names")
    p.set_defaults(func=cmd_check)

    p = sub.add_parser("run", help="run a level headless and report its checks")
    p.add_argument("level", metavar="LEVEL", help="a level file or a shipped level's name")
    p.add_argument(
        "--seconds",
        type=float,
        help=f"simulated seconds, 0 … {MAX_SECONDS:g} (default: the level's; dt is the level's, "
        f"{MIN_DT:g} … {MAX_DT:g} s)",
    )
    p.add_argument(
        "--long", action="store_true", help=f"allow --seconds up to {MAX_TIME:g} (a day)"
    )
    p.add_argument("--json", action="store_true", help="print one JSON object (see docs)")
    p.add_argument("--record", metavar="FILE", help="record every step to FILE (.csv or .npz)")
    p.add_argument("--replay", metavar="FILE", help="drive the player with a `play` replay")
    p.add_argument("--force", action="store_true", help="overwrite an existing --record file")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    p.add_argument(
        "--profile",
        action="store_true",
        help="print the time of each stage and the top functions (runs the level twice)",
    )
    p.set_defaults(func=cmd_run)

    p = sub.add_parser("faults", help="run levels under the breaks they declare to catch")
    p.add_argument("levels", nargs="*", metavar="LEVEL", help="default: every shipped level")
    p.add_argument(
        "--break",
        dest="breaks",
        action="append",
        metavar="NAME",
        help="try this break on every level, declared or not (repeatable)",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.add_argument("--list", action="store_true", help="list the breaks and what each breaks")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    p.set_defaults(func=cmd_faults)

    p = sub.add_parser("play", help="open a level in the desktop view (pygame-ce)")
    p.add_argument("level", nargs="?", default="sandbox", metavar="LEVEL", help="default sandbox")
    p.add_argument("--headless", action="store_true", help="draw off screen (no display needed)")
    p.add_argument("--frames", type=int, metavar="N", help="run N frames of 1/60 s, then exit")
    p.add_argument("--screenshot", metavar="PNG", help="save the last frame (.png, .bmp, .jpg)")
    p.add_argument("--gif", metavar="GIF", help="save the frames as an animated GIF (20 fps)")
    p.add_argument("--size", metavar="WxH", help="window or off-screen size in px (1280x720)")
    p.add_argument("--replay-out", metavar="FILE", help="write the session's inputs as a replay")
    p.add_argument("--replay", metavar="FILE", help="watch a replay instead of playing")
    p.set_defaults(func=cmd_play)

    p = sub.add_parser("figures", help="regenerate the teaching chapters' figures (headless)")
    p.add_argument("--out", default="docs/img/chapters", metavar="DIR", help="default: %(default)s")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    p.set_defaults(func=cmd_figures)

    p = sub.add_parser("gifs", help="regenerate the seed sequences' animated GIFs (headless)")
    p.add_argument("levels", nargs="*", metavar="LEVEL", help="default: the seven sequences")
    p.add_argument("--out", default="docs/img/gifs", metavar="DIR", help="default: %(default)s")
    p.set_defaults(func=cmd_gifs)

    p = sub.add_parser("schema", help="print the level JSON Schema")
    p.add_argument("--output", "-o", metavar="FILE", help="write it to FILE instead")
    p.set_defaults(func=cmd_schema)

    p = sub.add_parser("bench", help="what accuracy and each effect cost (docs/accuracy.md)")
    bench_cli.configure(p)
    p.set_defaults(func=bench_cli.run)
    return top


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``playground`` console script; returns the exit code.

    The one place where errors become a one-line message on stderr and an exit code (see the
    module docstring); argparse itself exits 2 on a malformed command line.
    """
    args = parser().parse_args(argv)
    func: Command = args.func
    who = f"playground {args.command}"
    try:
        with _interruptible():
            return func(args)
    except KeyboardInterrupt:
        print(f"{who}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except (LevelError, UsageError) as exc:
        print(f"{who}: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except ModuleNotFoundError as exc:
        print(f"{who}: {_missing(exc)}", file=sys.stderr)
        return EXIT_USAGE
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename is not None else ""
        print(f"{who}: {where}{exc.strerror or exc}", file=sys.stderr)
        return EXIT_USAGE


INTERRUPT_RETRY_S = 0.002
"""s before a Ctrl-C that arrived inside a pymunk callback is delivered again."""


def _on_interrupt(signum: int, frame: types.FrameType | None) -> None:
    """Raise KeyboardInterrupt, unless Python is inside a pymunk callback (called from C through
    cffi, which would print the exception and drop it): then try again in a moment."""
    f = frame
    while f is not None:
        if f.f_globals.get("__name__") == "pymunk._callbacks":
            signal.setitimer(signal.ITIMER_REAL, INTERRUPT_RETRY_S)
            return
        f = f.f_back
    raise KeyboardInterrupt


@contextlib.contextmanager
def _interruptible() -> Iterator[None]:
    """Ctrl-C (and its retry timer) through :func:`_on_interrupt` while a command runs.

    A process started with SIGINT ignored (``nohup``, a background job of a script) keeps
    ignoring it.
    """
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    ):
        yield
        return
    previous = {s: signal.signal(s, _on_interrupt) for s in (signal.SIGINT, signal.SIGALRM)}
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        for s, handler in previous.items():
            signal.signal(s, handler)


def _missing(exc: ModuleNotFoundError) -> str:
    """What to install for a missing module."""
    top = (exc.name or "").split(".")[0]
    extra = EXTRAS.get(top)
    if extra is None:
        return f"missing module {top!r} ({exc})"
    package = {"pygame": "pygame-ce", "PIL": "Pillow"}.get(top, top)
    return f"needs {package}: pip install 'pymunk-playground[{extra}]'"


if __name__ == "__main__":
    sys.exit(main())
