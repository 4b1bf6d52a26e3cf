"""Laws of replays (:mod:`playground.scene.replay`), headless: a replay drives a level without
pygame-ce, bit for bit as with it; its intents written as a level's ``[[inputs]]`` give the same
run; bad replay files say which entry is wrong; lookups are exact."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
import tomli_w

from playground.controller.mouse import Grab
from playground.intents import Intent
from playground.level import LevelError, find, load, loads
from playground.scene import Scene, build
from playground.scene.replay import Playback, Replay, ReplayError

NO_PYGAME = (
    "import sys; sys.modules['pygame'] = None; "
    "from playground.cli import main; sys.exit(main(sys.argv[1:]))"
)
"""A ``python -c`` program: the command line with pygame made unimportable (``import pygame``
raises ModuleNotFoundError, as where pygame-ce is not installed)."""


def sandbox_replay() -> Replay:
    """Half a second of the sandbox: walk right, jump, walk back, while the mouse lifts the
    crate."""
    dt = load(find("sandbox")).settings.dt
    changes = (
        (0, Intent(move=1.0)),
        (20, Intent(move=1.0, jump=True)),
        (24, Intent(move=-0.5)),
        (50, Intent()),
    )
    grabs = ((10, Grab("crate", (0.0, 0.0), (2.5, 1.5))), (45, None))
    return Replay(level="sandbox", dt=dt, steps=60, changes=changes, grabs=grabs)


def played(replay: Replay) -> Scene:
    scene = build(load(find(replay.level)))
    Playback(replay, replay.level, scene)
    for _ in range(replay.steps):
        scene.world.step()
    return scene


def state(scene: Scene) -> list[float]:
    w = scene.world
    out: list[float] = [w.time, float(w.steps)]
    for n in w.names:
        b = w.body(n)
        out += [*b.position, *b.velocity, b.angle, b.angular_velocity]
    return out


def run_json(args: list[str], *, pygame: bool) -> dict[str, object]:
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy"}
    prefix = ["-m", "playground"] if pygame else ["-c", NO_PYGAME]
    done = subprocess.run(
        [sys.executable, *prefix, *args], capture_output=True, text=True, env=env, check=False
    )
    assert done.returncode in (0, 1), done.stderr[-2000:]
    report: dict[str, object] = json.loads(done.stdout)
    report.pop("wall_seconds")
    return report


def test_run_replay_needs_no_pygame(tmp_path: Path) -> None:
    """Law: ``playground run LEVEL --replay FILE`` completes where pygame cannot be imported, and
    reports exactly what the same command reports with pygame present; the replay did drive the
    run (a run without it ends elsewhere)."""
    path = tmp_path / "sandbox.json"
    sandbox_replay().save(path)
    args = ["run", "sandbox", "--replay", str(path), "--json", "--no-progress"]
    without = run_json(args, pygame=False)
    assert without == run_json(args, pygame=True)
    assert without["steps"] == 60
    plain = run_json(["run", "sandbox", "--seconds", "0.5", "--json"], pygame=False)
    bodies = without["bodies"]
    assert isinstance(bodies, dict) and isinstance(plain["bodies"], dict)
    assert bodies["player"]["position"] != plain["bodies"]["player"]["position"]
    assert bodies["crate"]["position"] != plain["bodies"]["crate"]["position"]


def test_the_no_pygame_program_really_hides_pygame() -> None:
    """The shim above does what it claims: ``import pygame`` fails under it."""
    code = NO_PYGAME.replace("from playground.cli import main; sys.exit(main(sys.argv[1:]))", "")
    done = subprocess.run(
        [sys.executable, "-c", code + "import pygame"], capture_output=True, text=True, check=False
    )
    assert done.returncode != 0 and "ModuleNotFoundError" in done.stderr


def test_playback_lifts_what_the_mouse_held() -> None:
    """Law: a replay's grabs are pulled as the view pulls them: the crate held above the floor
    from step 10 to 45 is lifted."""
    replay = sandbox_replay()
    lifted = played(replay).world.body("crate").position.y
    dropped = played(Replay(replay.level, replay.dt, 30, replay.changes)).world.body("crate")
    assert lifted > dropped.position.y + 0.2


def test_replay_as_level_inputs_gives_the_same_run() -> None:
    """Law: a replay's intents written as ``[[inputs]]`` (TOML, by :meth:`Replay.to_inputs`) and
    appended to its level give a scripted run that ends exactly where the replay's run ends."""
    replay = sandbox_replay()
    replay = Replay(replay.level, replay.dt, replay.steps, replay.changes)
    doc = tomllib.loads(find(replay.level).read_text(encoding="utf-8"))
    # The sandbox's own script drives the player: the replay's inputs replace it.
    doc["inputs"] = tomllib.loads(replay.to_inputs())["inputs"]
    scripted = build(loads(tomli_w.dumps(doc), "sandbox+replay"))
    for _ in range(replay.steps):
        scripted.world.step()
    assert state(scripted) == state(played(replay))


COMMITTED = Path(__file__).parents[2] / "docs" / "img" / "sandbox-replay.json"
"""A replay recorded by ``playground play`` before replays moved out of the view."""


def test_a_replay_written_before_the_move_still_plays() -> None:
    """The committed replay loads and drives its level: the player walks left for 500 steps."""
    replay = Replay.load(COMMITTED)
    start = load(find(replay.level)).actors[0].position[0]
    scene = played(replay)
    assert scene.world.steps == 500
    assert scene.world.body("player").position.x < start - 1.0


def test_a_replay_of_another_level_or_dt_is_refused() -> None:
    replay = sandbox_replay()
    scene = build(load(find("rest")))
    with pytest.raises(ReplayError, match="of level 'sandbox', not 'rest'"):
        Playback(replay, "rest", scene)
    other = Replay("rest", replay.dt / 2, 3, ())
    with pytest.raises(ReplayError, match="dt"):
        Playback(other, "rest", scene)
    nobody = Replay("rest", scene.world.config.dt, 3, (), actor="crate")
    with pytest.raises(ReplayError, match="'crate', not a controller"):
        Playback(nobody, "rest", scene)


def test_replay_lookup_matches_a_linear_scan() -> None:
    """Law: the replay's bisection over its precomputed change steps finds the intent a linear
    scan finds, at every step of a long replay with a change every other step."""
    changes = tuple((2 * k + 1, Intent(move=(-1.0) ** k)) for k in range(2000))
    replay = Replay(level="rest", dt=1 / 120, steps=4010, changes=changes)
    for step in range(0, 4010, 7):
        expected = Intent()
        for s, intent in changes:
            if s <= step:
                expected = intent
        assert replay.intent_at(step) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("[]", "format"),
        ('{"format": "playground-replay", "version": 9}', "version"),
        (
            '{"format": "playground-replay", "version": 1, "level": "x", "dt": 0.01, "steps": 3,'
            ' "changes": [[0, {"mvoe": 1.0}]]}',
            "mvoe",
        ),
        (
            '{"format": "playground-replay", "version": 1, "level": "x", "dt": 0.01, "steps": 3,'
            ' "changes": [[2, {}], [1, {}]]}',
            "increase",
        ),
        (
            '{"format": "playground-replay", "version": 1, "level": "x", "dt": 0.01, "steps": 3,'
            ' "changes": [[0, {"move": 3.0}]]}',
            "move",
        ),
    ],
)
def test_bad_replays_say_what_is_wrong(text: str, expected: str) -> None:
    with pytest.raises(ReplayError, match=expected):
        Replay.from_json(text, where="bad.json")


@pytest.mark.parametrize(
    ("grabs", "expected"),
    [
        ('[[0, {"body": "crate"}]]', "grabs[0]: expected"),
        ('[[0, {"body": "crate", "anchor": [0, 0], "target": [1, "x"]}]]', "grabs[0]"),
        ("[[5, null], [5, null]]", "steps must increase"),
        ('{"0": null}', "grabs: expected an array"),
    ],
)
def test_bad_grabs_in_a_replay_say_what_is_wrong(grabs: str, expected: str) -> None:
    """Law: a malformed ``grabs`` list is a ReplayError naming the entry and the shape wanted."""
    text = (
        '{"format": "playground-replay", "version": 1, "level": "sandbox", "dt": 0.01, '
        f'"steps": 10, "actor": "player", "changes": [], "grabs": {grabs}}}'
    )
    with pytest.raises(ReplayError, match=re.escape(expected)):
        Replay.from_json(text)


@pytest.mark.parametrize(
    "table",
    [
        {"move": 2.0},
        {"jump": 1},
        {"gravity": [0.0, 0.0]},
        {"climb": "up"},
        {"nullify": "no body!"},
        {"mvoe": 1.0},
    ],
)
def test_a_replay_and_a_level_refuse_a_bad_intent_alike(table: dict[str, object]) -> None:
    """Law: one model validates an intent wherever it is written: a replay's change and a
    level's ``[[inputs]]`` table with the same bad key get the same problem (the replay's names
    its file and entry, the level's its key path)."""
    change = json.dumps([0, table])
    text = (
        '{"format": "playground-replay", "version": 1, "level": "rest", "dt": 0.01, '
        f'"steps": 3, "changes": [{change}]}}'
    )
    with pytest.raises(ReplayError) as replay_error:
        Replay.from_json(text, where="mine.json")
    doc = {"title": "x", "description": "y", "inputs": [{"t": 0.0, **table}]}
    with pytest.raises(LevelError) as level_error:
        loads(tomli_w.dumps(doc), "mine.toml")
    (problem,) = level_error.value.problems
    key = str(problem).removeprefix("inputs.0.")
    assert str(replay_error.value) == f"mine.json: changes[0]: {key}"


def test_intents_keep_their_serialised_form() -> None:
    """A replay written today holds the same change entries a replay of version 1 held: only the
    keys that differ from the defaults, in the intent's order, vectors as lists."""
    replay = Replay("rest", 0.01, 2, ((0, Intent(gravity=(0.0, -1.0), move=0.5, nullify="crate")),))
    (entry,) = json.loads(replay.to_json())["changes"]
    assert entry == [0, {"move": 0.5, "gravity": [0.0, -1.0], "nullify": "crate"}]
    assert list(entry[1]) == ["move", "gravity", "nullify"]


def _head(**keys: object) -> str:
    doc = {"format": "playground-replay", "version": 1, "level": "rest", "dt": 1 / 120}
    doc.update({"steps": 3, "changes": [], **keys})
    return json.dumps(doc)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (_head(steps=10**15), "steps: expected less than or equal to 864000000"),
        (_head(steps=10**400), "steps: expected less than or equal to"),
        (_head(steps=-1), "steps: expected greater than or equal to 0"),
        (_head(steps=2.5), "steps: expected an integer"),
        (_head(dt=0.0), "dt: expected greater than or equal to 0.0001"),
        (_head(level=""), "level:"),
        (_head(actor="no body!"), "actor:"),
        (_head(stepz=3), "stepz: unknown key (did you mean 'steps'?)"),
        (_head(changes=[[10**400, {}]]), "changes[0]: expected [step"),
        (_head(grabs=[[-5, None]]), "grabs[0]: expected [step"),
        ('{"format": "playground-replay", "x": ' + "[" * 200_000 + "]" * 200_000 + "}", "deep"),
        ('{"format": "playground-replay", "steps": 1' + "0" * 5000 + "}", "not a replay"),
    ],
    ids=[
        "steps 1e15",
        "steps 1e400",
        "steps -1",
        "steps 2.5",
        "dt 0",
        "level empty",
        "actor",
        "unknown key",
        "change step 1e400",
        "grab step -5",
        "nested 200000 deep",
        "5000 digits",
    ],
)
def test_a_replay_is_a_bounded_document(text: str, expected: str) -> None:
    """Law: a replay is validated as a document, like a level: every number bounded (steps at
    most a day at the smallest dt), unknown keys refused, nesting and digits bounded; each
    refusal is a ReplayError naming the file and the key — never OverflowError, RecursionError
    or a hang later."""
    with pytest.raises(ReplayError, match=re.escape(expected)) as error:
        Replay.from_json(text, where="r.json")
    assert str(error.value).startswith("r.json: ")


def test_run_bounds_the_length_a_replay_sets(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Law: the run-length rule applies after a replay sets the run's length: a replay of
    10^8 steps (within the format, two weeks at this dt) is refused at once, exit 2, naming
    the replay, instead of running for weeks."""
    from playground.cli import EXIT_USAGE, main

    path = tmp_path / "long.json"
    path.write_text(_head(steps=10**8), encoding="utf-8")
    assert main(["run", "rest", "--replay", str(path)]) == EXIT_USAGE
    assert (
        f"{path}: steps × dt: expected a number of seconds in [0, 3600]" in capsys.readouterr().err
    )
