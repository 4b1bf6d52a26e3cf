"""Laws of the breaks: each is reversible (every patched class is as it was after it, even after
an exception inside), documented, and leaves nothing behind (a clean run after a broken one is
the clean run bit for bit)."""

from __future__ import annotations

import pytest

from playground import controller, faults, movers, world
from playground.controller import switches
from playground.gravity import perception
from playground.level import find, load
from playground.world import gravity_stage

PATCHED = (
    controller.Controller,
    controller.ControllerConfig,
    world.World,
    gravity_stage.GravityStage,
    movers.Mover,
    movers.Spin,
    perception.PerceivedGravity,
    switches,
)
"""The classes (and the module) breaks patch."""


def _attributes() -> list[dict[str, object]]:
    return [dict(vars(cls)) for cls in PATCHED]


@pytest.mark.parametrize("name", faults.names())
def test_a_break_is_restored_on_exit_and_documented(name: str) -> None:
    """Entering and leaving a break leaves every patched class as it was, even after an
    exception inside; each break says what it breaks."""
    before = _attributes()
    with faults.apply(name):
        pass
    assert _attributes() == before
    with pytest.raises(RuntimeError), faults.apply(name):
        raise RuntimeError("inside the break")
    assert _attributes() == before
    assert len(faults.BREAKS[name].doc) > 20


def test_a_clean_run_after_a_broken_one_is_bit_for_bit_the_clean_run() -> None:
    """A break leaves nothing behind: the same level clean, before and after it, gives the same
    trajectory bit for bit."""
    from playground.scene import build

    level = load(find("seesaw"))

    def final() -> tuple[float, ...]:
        scene = build(level)
        scene.run(1.0)
        b = scene.world.body("player")
        return (b.position.x, b.position.y, b.angle, *scene.world.forces("plank").engine)

    clean = final()
    with faults.apply("hover_reaction"):
        broken = final()
    assert broken != clean
    assert final() == clean
