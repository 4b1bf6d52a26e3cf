"""A level as the view runs it: the body the HUD watches by default, the overlays a level asks
for, the roles of its actors, the enemy X acts on, and a session that records every step's
intent and refuses a replay when there is no controller to drive."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from playground import World
from playground.gravity import GravityRule
from playground.scene.replay import Replay
from playground.view.overlay import Overlay
from playground.view.session import Session, Show, nearest, roles_of


def world() -> World:
    w = World()
    w.add_static_segment((-30.0, 0.0), (30.0, 0.0))
    w.add_box("player", mass=70.0, size=(0.6, 1.8), position=(0.0, 0.9))
    w.add_box("crate", mass=10.0, size=(1.0, 1.0), position=(2.0, 0.5))
    w.add_box("enemy", mass=50.0, size=(0.6, 1.8), position=(5.0, 0.9))
    return w


def test_watched_is_the_player_then_the_followed_body_then_the_first_tracked() -> None:
    w = world()
    w.track("crate", "enemy")
    show = Show(name="s", world=w, title="S", player="player", follow="enemy")
    assert show.watched() == "enemy", "the player is not tracked: the followed body"
    w.track("player")
    assert show.watched() == "player"
    assert Show(name="s", world=w, title="S").watched() == "crate"
    assert Show(name="s", world=World(), title="S").watched() is None


def test_overlays_come_from_the_levels_view_table_or_are_the_default() -> None:
    """Law: a level's overlays do not depend on what was on before it (defect: a level without
    ``[view] overlays`` kept the previous level's)."""
    plain = Show(name="s", world=World(), title="S")
    assert plain.overlays() == Overlay()
    level = SimpleNamespace(view=SimpleNamespace(overlays=["contacts"]))
    hinted = Show(name="s", world=World(), title="S", scene=SimpleNamespace(level=level))
    assert hinted.overlays() == Overlay(vectors=False, contacts=True)


def test_roles_default_to_player_and_other_unless_the_level_names_them() -> None:
    controllers = {"player": object(), "enemy": object(), "ally": object()}
    actors = [SimpleNamespace(name="enemy", role="enemy"), SimpleNamespace(name="ally", role=None)]
    scene = SimpleNamespace(level=SimpleNamespace(actors=actors))
    show = Show(name="s", world=World(), title="S", controllers=controllers, player="player")
    assert roles_of(show) == {"player": "player", "enemy": "other", "ally": "other"}
    show.scene = scene
    assert roles_of(show) == {"player": "player", "enemy": "enemy", "ally": "other"}


def test_nearest_picks_the_closest_candidate() -> None:
    assert nearest((0.0, 0.0), []) is None
    assert nearest((4.0, 0.0), [("a", (0.0, 0.0)), ("b", (5.0, 1.0))]) == "b"


def test_x_acts_on_the_nearest_enemy_whose_gravity_still_counts() -> None:
    w = world()
    w.add_box("far", mass=50.0, size=(0.6, 1.8), position=(9.0, 0.9))
    actors = [SimpleNamespace(name=n, role="enemy") for n in ("enemy", "far")]
    controllers = {"player": SimpleNamespace(), "enemy": object(), "far": object()}
    show = Show(
        name="s",
        world=w,
        title="S",
        controllers=controllers,
        player="player",
        scene=SimpleNamespace(level=SimpleNamespace(actors=actors)),
    )
    session = Session(show)
    assert session.nearest_enemy() == "enemy"
    w.set_gravity_rule("enemy", GravityRule(scale=0.0))
    assert session.nearest_enemy() == "far"


def test_a_replay_without_a_controller_to_drive_is_refused() -> None:
    show = Show(name="s", world=world(), title="S")
    replay = Replay(level="s", dt=1 / 120, steps=0, changes=())
    with pytest.raises(ValueError, match="the replay drives 'player', not a controller"):
        Session(show, replay)
