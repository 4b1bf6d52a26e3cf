"""Laws of variants (:mod:`playground.level.variants`): a ``--set`` goes through the level model
like the file's own keys, names the file and the key when it is wrong, and a check stated in a
body's weight reads the same at any mass."""

from __future__ import annotations

import pytest

from playground.level import LevelError, find, load
from playground.level.variants import Setting, SettingError, apply, parse_set, parse_sets
from playground.scene import build
from playground.scene.checks import watch


def _failed(level_name: str, *sets: str) -> list[str]:
    """The checks of a shipped level's variant that fail."""
    level = load(find(level_name), parse_sets(sets))
    scene = build(level)
    checks = watch(scene)
    scene.run(level.settings.seconds)
    return [r.detail for r in checks.results() if not r.passed]


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("settings.substeps=2", 2),
        ("settings.dt=0.004166666666666667", 0.004166666666666667),
        ("settings.contact_split=true", True),
        ("actors.player.position=[1.0, 2.0]", [1.0, 2.0]),
        ('expect.0.equals="grounded"', "grounded"),
        ("expect.0.equals=grounded", "grounded"),
    ],
)
def test_a_value_is_read_as_toml(text: str, value: object) -> None:
    assert parse_set(text).value == value


@pytest.mark.parametrize("text", ["settings.substeps", "=2", "settings..dt=1", "settings.dt="])
def test_a_setting_that_cannot_be_read_says_what_a_setting_is(text: str) -> None:
    with pytest.raises(SettingError, match=r"^--set "):
        parse_set(text)


def test_named_items_and_indices_pick_the_same_table() -> None:
    data = {"actors": [{"name": "player"}, {"name": "weak"}]}
    by_name = apply(data, [Setting("actors.weak.controller.mass", 140.0)])
    by_index = apply(data, [Setting("actors.1.controller.mass", 140.0)])
    assert (
        by_name
        == by_index
        == {"actors": [{"name": "player"}, {"name": "weak", "controller": {"mass": 140.0}}]}
    )
    assert data == {"actors": [{"name": "player"}, {"name": "weak"}]}


@pytest.mark.parametrize(
    ("setting", "message"),
    [
        ("actors.plyer.controller.mass=1", "actors has no item named 'plyer' (did you mean"),
        ("actors.5.controller.mass=1", "actors has 1 item(s): no index 5"),
        ("settings.dt.x=1", "settings.dt is a value (0.01), not a table"),
    ],
)
def test_a_setting_that_names_no_key_of_the_level_says_where(setting: str, message: str) -> None:
    data = {"settings": {"dt": 0.01}, "actors": [{"name": "player"}]}
    with pytest.raises(SettingError) as info:
        apply(data, parse_sets([setting]))
    assert info.value.message.startswith(message), info.value.message


@pytest.mark.parametrize(
    ("setting", "problem"),
    [
        ("settings.substep=2", "settings.substep: unknown key (did you mean 'substeps'?)"),
        ("settings.substeps=0", "settings.substeps: expected greater than or equal to 1"),
        ('settings.dt="0.01"', "settings.dt: expected a number, got '0.01'"),
        ("actors.player.controller.mass=true", "actors.0.controller.mass: expected a number"),
        ("actors.ghost.controller.mass=1", "--set actors.ghost.controller.mass=1: actors has no"),
    ],
)
def test_a_bad_variant_is_a_problem_of_the_file_at_its_key(setting: str, problem: str) -> None:
    """Law: a variant is validated by the level model; its problems name the file, the setting and
    the key."""
    with pytest.raises(LevelError) as info:
        load(find("rest"), parse_sets([setting]))
    assert info.value.source.endswith(f"rest.toml (with --set {setting})"), info.value.source
    assert any(str(p).startswith(problem) for p in info.value.problems), info.value.problems


def test_a_variant_is_the_level_with_the_key_set() -> None:
    level = load(
        find("crusher"), parse_sets(["actors.weak.controller.mass=140", "settings.substeps=2"])
    )
    assert level.settings.substeps == 2
    assert [a.controller.mass for a in level.actors] == [70.0, 140.0]


@pytest.mark.parametrize("mass", [35.0, 140.0])
def test_a_check_in_weights_reads_the_same_at_any_mass(mass: float) -> None:
    """Law: ``rest`` states its support in the player's weights, so it passes at half and twice
    the player's mass, where one weight is m·g₀ of that mass; stated as another number of
    weights, it fails (the check can fail)."""
    assert _failed("rest", f"actors.player.controller.mass={mass}") == []
    wrong = _failed("rest", f"actors.player.controller.mass={mass}", "expect.0.equals=[0.0, 0.5]")
    assert len(wrong) == 1, wrong
    assert f"[0, {mass * 9.81 / 2:g}] N" in wrong[0], wrong[0]
    assert f"got [0, {mass * 9.81:g}] N" in wrong[0], wrong[0]
