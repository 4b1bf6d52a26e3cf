"""Laws of the batch plumbing (playground/_engine/batch.py): rows keyed by id in the engine's
order, the same ids array while the order holds, each read with its own ids."""

from __future__ import annotations

import pymunk

from playground._engine.batch import BodyRows


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
