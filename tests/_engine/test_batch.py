"""Laws of the batch plumbing (playground/_engine/batch.py): rows keyed by id in the engine's
order, the same ids array while the order holds, each read with its own ids; forces written in
one batch call as the public setters write them."""

from __future__ import annotations

import math
import struct

import numpy as np
import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine.batch import BodyRows, ForceWrites


def _space(n: int) -> tuple[pymunk.Space, list[pymunk.Body]]:
    space = pymunk.Space()
    space.sleep_time_threshold = 1.0
    bodies = []
    for i in range(n):
        body = pymunk.Body(1.0, 1.0)
        body.position = (3.0 * i, 0.0)
        body.velocity = (float(i), 0.0)
        space.add(body, pymunk.Circle(body, 0.5))
        bodies.append(body)
    return space, bodies


def test_the_ids_array_is_kept_while_the_order_holds() -> None:
    """Law: a read whose ids are those of the last read hands the same (read-only) array, so a
    cache keyed by it is checked with ``is``; a new body gives a new array."""
    space, _ = _space(3)
    rows = BodyRows()
    rows.read(space)
    first = rows.ids
    assert not first.flags.writeable
    rows.read(space, positions=True)
    assert rows.ids is first
    ids, _ = rows.read_velocities(space)
    assert ids is first
    space.add(pymunk.Body(1.0, 1.0))
    rows.read(space)
    assert rows.ids is not first and len(rows.ids) == len(first) + 1


def test_a_velocities_read_in_another_order_keeps_the_state_read_whole() -> None:
    """Law: when a body falls asleep between the state read and a velocities read, the second
    read's ids follow its own rows and the state read's ids and rows stay as they were."""
    space, bodies = _space(3)
    rows = BodyRows()
    rows.read(space)
    before = rows.ids.tolist()
    state = rows.state.copy()
    bodies[0].sleep()  # asleep: listed after the awake bodies
    ids, vel = rows.read_velocities(space)
    assert rows.ids.tolist() == before
    assert (rows.state == state).all()
    assert ids.tolist() != before
    by_id = dict(zip(ids.tolist(), vel[:, 0].tolist(), strict=True))
    assert by_id == {b.id: b.velocity.x for b in bodies}


_FORCE = st.floats(-1e6, 1e6, allow_nan=False) | st.sampled_from((0.0, -0.0, 5e-324))


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 8), st.data())
def test_forces_written_in_one_batch_call_are_the_setters_ones(n: int, data: st.DataObject) -> None:
    """Law: ForceWrites sets the chosen bodies' force and torque to the bits
    ``body.force = …; body.torque = …`` sets, and leaves every other body's (dynamic, kinematic,
    the static body) as they were, whatever order the chosen ids come in; twice with the same ids
    array (its cached rows), the second values win."""
    space, bodies = _space(n)
    space.sleep_time_threshold = math.inf
    kinematic = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    space.add(kinematic)
    everyone = [*bodies, kinematic, space.static_body]
    for b in bodies:
        b.force = (data.draw(_FORCE), data.draw(_FORCE))
        b.torque = data.draw(_FORCE)
    chosen = data.draw(st.lists(st.sampled_from(bodies), unique=True, min_size=1))
    ids = np.array([b.id for b in chosen], dtype=np.uintp)
    writes = ForceWrites()
    for _ in range(2):
        force = np.array([[data.draw(_FORCE), data.draw(_FORCE)] for _ in chosen])
        torque = np.array([data.draw(_FORCE) for _ in chosen])
        expected = {id(b): (tuple(b.force), b.torque) for b in everyone}
        for b, (fx, fy), t in zip(chosen, force.tolist(), torque.tolist(), strict=True):
            expected[id(b)] = ((fx, fy), t)
        writes.write(space, ids, force, torque)
        got = {id(b): (tuple(b.force), b.torque) for b in everyone}
        assert _bits(got) == _bits(expected)


def _bits(forces: dict[int, tuple[tuple[float, float], float]]) -> dict[int, bytes]:
    return {k: struct.pack("3d", fx, fy, t) for k, ((fx, fy), t) in forces.items()}


def test_a_body_not_in_the_space_is_refused() -> None:
    space, _ = _space(2)
    stranger = pymunk.Body(1.0, 1.0)
    with pytest.raises(KeyError):
        ForceWrites().write(
            space, np.array([stranger.id], dtype=np.uintp), np.zeros((1, 2)), np.zeros(1)
        )
