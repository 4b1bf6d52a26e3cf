"""Laws of forces on bodies: every force acts for the whole step, whoever set it, tracked or not.

A force (or torque) on a body when a step starts acts over the whole step, as it would over one
``space.step(dt)``: whether it went through ``World.apply_force``/``apply_torque`` or was set
straight on the pymunk body, whether the body is tracked or not, whatever the substeps.
"""

from __future__ import annotations

import pymunk
import pytest

from playground import Category, Stage, World, WorldConfig
from playground.controller import Controller
from playground.forces import ForceLedger
from playground.vec import Vec

TOL_REL = 1e-9
"""Relative: 120 steps of a constant force integrated by pymunk, float rounding only."""

FORCE = (2.0, -1.0)
"""N, on a 2 kg box: 1 m/s² along x, −0.5 m/s² along y."""

TORQUE = 0.5
"""N·m."""

_Forces = list[tuple[float, float, Category]]


def box_world(substeps: int, tracked: bool) -> tuple[World, pymunk.Body]:
    world = World(WorldConfig(substeps=substeps), gravity=(0.0, 0.0))
    box = world.add_box("box", mass=2.0, size=(1.0, 1.0), position=(0.0, 0.0))
    if tracked:
        world.track("box")
    return world, box


@pytest.mark.parametrize("tracked", [False, True], ids=["untracked", "tracked"])
@pytest.mark.parametrize("substeps", [1, 2, 3])
def test_a_force_set_on_the_body_acts_for_the_whole_step(substeps: int, tracked: bool) -> None:
    """Law: ``body.force`` and ``body.torque`` set before each step give v = F/m·t and
    ω = T/I·t, tracked or not, with any number of substeps."""
    world, box = box_world(substeps, tracked)

    def push(w: World) -> None:
        box.force = FORCE
        box.torque = TORQUE

    world.on(Stage.CONTROL, push)
    world.run(1.0)
    for got, want in (
        (box.velocity.x, FORCE[0] / box.mass),
        (box.velocity.y, FORCE[1] / box.mass),
        (box.angular_velocity, TORQUE / box.moment),
    ):
        assert abs(got - want) <= TOL_REL * abs(want), (got, want)
    if tracked:
        f = world.forces("box")
        assert f.applied == pytest.approx(FORCE, rel=TOL_REL)
        assert f.engine == pytest.approx((0.0, 0.0), abs=TOL_REL)


@pytest.mark.parametrize("substeps", [1, 3])
def test_apply_torque_acts_on_a_world_that_stepped_bare(substeps: int) -> None:
    """Law: a torque applied through the world after bare steps (nothing else in the scene)
    turns the body for the coming step and leaves the ledger empty."""
    world, box = box_world(substeps, tracked=False)
    world.run(0.1)
    world.apply_torque("box", TORQUE)
    world.step()
    want = TORQUE / box.moment * world.config.dt
    assert abs(box.angular_velocity - want) <= TOL_REL * want
    assert len(world.ledger) == 0
    world.step()
    assert abs(box.angular_velocity - want) <= TOL_REL * want  # one step only


def test_a_ledger_entry_acts_on_a_world_that_stepped_bare() -> None:
    """Law: a torque or force put straight into ``world.ledger`` after bare steps is flushed on
    the coming step (the ledger tells the world), and the ledger is empty after it."""
    world, box = box_world(1, tracked=False)
    world.run(0.1)
    world.ledger.add_torque(box, TORQUE, Category.APPLIED)
    world.ledger.add(box, FORCE)
    world.step()
    dt = world.config.dt
    assert abs(box.angular_velocity - TORQUE / box.moment * dt) <= TOL_REL * TORQUE
    assert abs(box.velocity.x - FORCE[0] / box.mass * dt) <= TOL_REL * FORCE[0]
    assert len(world.ledger) == 0


def test_the_controller_applies_its_torques_through_the_world(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Law: the balance torque (with the controller's own forces, ``World.apply_forces``) and
    its reaction on a dynamic ground (``World.apply_torque``) reach the ledger through the world
    (which checks them and plans the step around them), never around it."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0), radius=0.0)
    crate = world.add_box("crate", mass=200.0, size=(4.0, 0.5), position=(0.0, 0.25))
    player = Controller(world, "player", position=(0.3, 1.45), angle=0.2)
    through_world: list[tuple[pymunk.Body, float]] = []
    into_ledger: list[tuple[pymunk.Body, float]] = []
    apply_torque, apply_forces = World.apply_torque, World.apply_forces
    add_torque, add_all = ForceLedger.add_torque, ForceLedger.add_all

    def spy_world(
        self: World, body: pymunk.Body | str, torque: float, *, category: Category
    ) -> None:
        through_world.append((self.body(body) if isinstance(body, str) else body, torque))
        apply_torque(self, body, torque, category=category)

    def spy_world_all(
        self: World,
        body: pymunk.Body,
        forces: _Forces,
        torque: float | None = None,
        *,
        point: Vec | None = None,
    ) -> None:
        if torque is not None:
            through_world.append((body, torque))
        apply_forces(self, body, forces, torque, point=point)

    def spy_ledger(self: ForceLedger, body: pymunk.Body, torque: float, category: Category) -> None:
        into_ledger.append((body, torque))
        add_torque(self, body, torque, category)

    def spy_ledger_all(
        self: ForceLedger,
        body: pymunk.Body,
        forces: _Forces,
        torque: float | None = None,
        point: Vec | None = None,
    ) -> None:
        if torque is not None:
            into_ledger.append((body, torque))
        add_all(self, body, forces, torque, point)

    monkeypatch.setattr(World, "apply_torque", spy_world)
    monkeypatch.setattr(World, "apply_forces", spy_world_all)
    monkeypatch.setattr(ForceLedger, "add_torque", spy_ledger)
    monkeypatch.setattr(ForceLedger, "add_all", spy_ledger_all)
    world.run(0.5)
    assert any(b is player.body and t != 0.0 for b, t in into_ledger), "no balance torque"
    assert any(body is crate for body, _ in into_ledger), "no reaction on the ground"
    assert into_ledger == through_world
