"""Laws of the controller as a whole: same inputs give the same trajectory bit for bit, and a
removed controller leaves the world with everything it put there."""

from __future__ import annotations

import pytest

from playground import Controller, Intent, Script, World
from playground.world import Stage


def flat_world() -> World:
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    return world


def test_same_inputs_give_bit_identical_trajectories() -> None:
    """Determinism: two runs of the same scene replay exactly."""

    def run() -> tuple[float, float, float]:
        world = flat_world()
        script = Script(((0.0, Intent(move=1.0)), (0.5, Intent(jump=True)), (1.0, Intent())))
        player = Controller(world, "player", (0.0, 1.0), source=script)
        world.run(2.0)
        return (player.body.position.x, player.body.position.y, player.body.angle)

    assert run() == run()


def test_a_removed_controller_leaves_the_world() -> None:
    """remove(): the body and shape go and the world keeps stepping without it."""
    world = flat_world()
    player = Controller(world, "player", (0.0, 1.0), source=Script(((0.0, Intent(move=1.0)),)))
    world.run(0.5)
    player.remove()
    assert "player" not in world.names
    world.run(0.5)
    assert player.removed


def test_a_removed_controller_takes_its_hooks_with_it() -> None:
    """remove() also unregisters the controller's input and control hooks (World.off): nothing
    of it runs any more, so a world left with no effect steps bare again."""
    world = flat_world()
    player = Controller(world, "player", (0.0, 1.0), source=Script(((0.0, Intent(move=1.0)),)))
    world.run(0.1)
    player.remove()
    for stage, hook in ((Stage.INPUTS, player.read_source), (Stage.CONTROL, player.step)):
        with pytest.raises(ValueError, match="not registered"):
            world.off(stage, hook)
