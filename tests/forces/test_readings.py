"""Laws of one body's readings as plain values: they are the solver's rows, and they are frozen."""

from __future__ import annotations

import dataclasses

import pytest

from playground import World, WorldConfig
from playground.forces.readings import BodyForces


def test_a_reading_is_the_solver_row_and_friction_is_contact_minus_normal() -> None:
    """``World.forces`` gives the solver's row as floats; the contact's friction part is the
    contact force less its normal part (a box pushed along the floor has both)."""
    world = World(WorldConfig(contact_split=True))
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0), radius=0.05)
    world.add_box("box", mass=2.0, size=(0.5, 0.5), position=(0.0, 0.3))
    world.track("box")
    world.run(0.5)
    world.body("box").velocity = (3.0, 0.0)
    world.step()
    f = world.forces("box")
    assert isinstance(f, BodyForces) and f.valid and f.split_valid
    s = world.readings()
    assert f.engine == tuple(s.engine[0]) and f.support == tuple(s.support[0])
    assert f.contact == tuple(s.contact[0]) and f.constraint == tuple(s.constraint[0])
    assert f.contact_friction == tuple(s.contact[0] - s.contact_normal[0])
    assert f.contact_friction[0] < 0.0 < f.contact_normal[1], "sliding right: friction acts left"
    assert all(isinstance(v, float) for v in (*f.engine, *f.contact_friction, f.engine_torque))
    with pytest.raises(dataclasses.FrozenInstanceError):
        f.engine = (0.0, 0.0)  # type: ignore[misc]
