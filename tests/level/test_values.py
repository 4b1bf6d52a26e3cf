"""Laws of the value types: an absurd number in a level file is refused at load with its key
path."""

from __future__ import annotations

import pytest

from playground.level import LevelError, loads

BASE = 'title = "Hostile"\ndescription = "A crate."\n'
"""A valid level: every case adds one absurd number to it."""

CRATE = (
    '\n[[props]]\nname = "crate"\nposition = [0.0, 0.5]\nmass = 10.0\n'
    'shapes = [{kind = "box", size = [1.0, 1.0]}]\n'
)


@pytest.mark.parametrize(
    ("extra", "path"),
    [
        ("[settings]\ndt = 1e-9\n", "settings.dt"),
        ("[settings]\ndt = 1.0\n", "settings.dt"),
        ("[settings]\nseconds = 1e15\n", "settings.seconds"),
        ("[gravity]\nkind = 'uniform'\ng = [0.0, -1e308]\n", "gravity.g.1"),
        ("[gravity]\nkind = 'radial'\nsurface_gravity = 1e5\n", "gravity.surface_gravity"),
        ("[view]\ncamera = [1e16, 0.0]\n", "view.camera.0"),
        (CRATE.replace("mass = 10.0", "mass = 1e308"), "props.0.mass"),
        (CRATE.replace("mass = 10.0", "mass = 5e-324"), "props.0.mass"),
        (CRATE.replace("[0.0, 0.5]", "[1e308, 0.5]"), "props.0.position.0"),
        (CRATE.replace("size = [1.0, 1.0]", "size = [1e308, 1.0]"), "props.0.shapes.0.size.0"),
        (CRATE + "velocity = [1e5, 0.0]\n", "props.0.velocity.0"),
        (CRATE + "angular_velocity = 1e9\n", "props.0.angular_velocity"),
        (
            "[[actors]]\nname = 'player'\nposition = [0.0, 1.0]\ncontroller = { mass = 1e308 }\n",
            "actors.0.controller",
        ),
        (
            "[[joints]]\nkind = 'pivot'\na = 'crate'\nb = 'static'\nanchor = [1e308, 0.0]\n"
            + CRATE,
            "joints.0.anchor.0",
        ),
        (
            "[[events]]\nkind = 'impulse'\nt = 0.5\nbody = 'crate'\nimpulse = [1e9, 0.0]\n" + CRATE,
            "events.0.impulse.0",
        ),
        ("[[events]]\nkind = 'set_gravity'\nt = 0.5\ng = [0.0, 1e4]\n", "events.0.g.1"),
    ],
)
def test_an_absurd_number_is_refused_at_load_with_its_key_path(extra: str, path: str) -> None:
    """Law: a number outside its plausible range (playground.limits) is a LevelError naming its
    key path, not something pymunk finds later."""
    with pytest.raises(LevelError) as info:
        loads(BASE + extra)
    paths = [p.path for p in info.value.problems]
    assert any(p.startswith(path) for p in paths), paths
