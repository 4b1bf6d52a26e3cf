"""The ``run`` command: a level headless, its checks, optionally a recording, a replay driving
its player, a progress bar and a profile.

``playground run LEVEL --json`` prints one JSON object::

    {"level", "dt", "steps", "sim_seconds", "wall_seconds",
     "checks": [{"name", "passed", "detail"}],
     "bodies": {NAME: {"mass", "position", "velocity", "angle",
                       "force": {"engine", "contact", "constraint", "support", "support_filtered"},
                       "perceived_gravity", "state"}}}

for every tracked body, at the last step, SI units, vectors as ``[x, y]``: the quantities of
:data:`playground.quantities.REPORTED`, read as a recording and the level's checks read them.
``state`` is null for a body without a controller; ``contact`` and ``constraint`` are null unless
the level sets ``settings.contact_split``, and on a step whose split is unknown;
``support_filtered`` is −m · ``perceived_gravity`` (the 1€-filtered support force).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from playground.cli.exits import EXIT_FAILED, EXIT_OK, EXIT_USAGE
from playground.cli.levelfiles import add_set_option, declared_notes
from playground.cli.preflight import UsageError
from playground.level.files import find
from playground.level.loading import load, variant_source
from playground.limits import MAX_DT, MAX_SECONDS, MAX_TIME, MIN_DT
from playground.quantities import REPORTED, Value
from playground.scene.readings import sample
from playground.world.guard import RunawayError

__all__ = ["PROGRESS_MIN_STEPS", "cmd_run", "configure"]


def _num(x: float) -> float | None:
    return float(x) if math.isfinite(x) else None


def _vec(v: Sequence[float]) -> list[float | None] | None:
    out = [float(x) if math.isfinite(x) else None for x in v]
    return None if all(x is None for x in out) else out


def cmd_run(args: argparse.Namespace) -> int:
    """Run a level headless, report its checks (and bodies with --json); exit 1 on a failure."""
    from playground.scene import build
    from playground.scene.checks import watch
    from playground.scene.recording import check_output, recording

    if args.record is not None:
        try:
            check_output(args.record, force=args.force)
        except ValueError as exc:
            raise UsageError(str(exc)) from None
    path = find(args.level)
    sets = tuple(args.sets)
    level = load(path, sets)
    scene = build(level, variant_source(str(path), sets))
    seconds = level.settings.seconds if args.seconds is None else args.seconds
    # Whichever set the length is named: the flag, the replay (its steps), or the level file
    # (check bounds settings.seconds to what run allows without --long).
    key = (
        "--seconds"
        if args.seconds is not None
        else f"{variant_source(str(path), sets)}: settings.seconds"
    )
    if args.replay is not None:
        covered = _replay(args.replay, path.stem, scene)
        if covered is None:
            return EXIT_USAGE
        if args.seconds is None:
            seconds, key = covered, f"{args.replay}: steps × dt"
    longest = MAX_TIME if args.long else MAX_SECONDS
    if not (math.isfinite(seconds) and 0 <= seconds <= longest):
        more = "" if args.long else f" (up to {MAX_TIME:g} s with --long)"
        raise UsageError(
            f"{key}: expected a number of seconds in [0, {longest:g}]{more}, got {seconds:g}"
        )
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
        return EXIT_FAILED
    wall = time.perf_counter() - start
    results = checks.results()
    world = scene.world
    profile = _profile(path, sets, seconds) if args.profile else []
    if args.json:
        bodies = {name: _body_report(scene, name) for name in scene.tracked}
        report = {
            "level": path.stem,
            "dt": level.settings.dt,
            "steps": world.steps,
            "sim_seconds": world.time,
            "wall_seconds": wall,
            **({"set": [str(s) for s in sets]} if sets else {}),
            "checks": [{"name": r.name, "passed": r.passed, "detail": r.detail} for r in results],
            **({"unsupported": declared_notes(level)} if declared_notes(level) else {}),
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
        for line in declared_notes(level):
            print(f"  note  {line}")
    if args.profile and not args.json:
        _print_profile(world, profile)
    return EXIT_OK if all(r.passed for r in results) else EXIT_FAILED


def _body_report(scene: Any, name: str) -> dict[str, Any]:
    """A tracked body's readings now, as ``--json`` reports them (a group such as ``force`` is an
    object of its own)."""
    out: dict[str, Any] = {}
    for q in REPORTED:
        group = out if not q.report else out.setdefault(q.report, {})
        group[q.name] = _json(sample(q, scene, name))
    return out


def _json(value: Value) -> Any:
    """A reading as strict JSON: a non-finite number is null, and a vector with no finite part."""
    if isinstance(value, tuple):
        return _vec(value)
    if isinstance(value, float):
        return _num(value)
    return value


def _profile(path: Path, sets: tuple[Any, ...], seconds: float) -> list[Any]:
    """The top functions of a second run of the level (its variant) under cProfile."""
    from playground.bench.profiler import top_functions
    from playground.scene import build

    again = build(load(path, sets), str(path))
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
    from playground.scene.replay import Playback, Replay, ReplayError

    try:
        replay = Replay.load(file)
        Playback(replay, name, scene)
    except (ReplayError, ValueError) as exc:
        print(f"playground run: {exc}", file=sys.stderr)
        return None
    return replay.steps * replay.dt


def configure(p: argparse.ArgumentParser) -> None:
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
    add_set_option(p)
    p.set_defaults(func=cmd_run)
