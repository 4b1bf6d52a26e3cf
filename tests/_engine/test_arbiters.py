"""Laws of the arbiter readers (:mod:`playground._engine.arbiters`): what they read is what
``pymunk.batch.get_space_arbiters`` reads, bit for bit, and their ids are kept while unchanged."""

from __future__ import annotations

import random
import struct

import numpy as np
import pymunk
import pymunk.batch as batch

from playground._engine.arbiters import ArbiterRows, ArbiterValues

STEPS = 120
"""1 s at 120 Hz: the bodies fall, land, stack and settle."""

_A = batch.ArbiterFields


def _scene(seed: int) -> pymunk.Space:
    rng = random.Random(seed)
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.add(pymunk.Segment(space.static_body, (-4.0, 0.0), (4.0, 0.0), 0.05))
    for _ in range(12):
        body = pymunk.Body(1.0, 1.0)
        body.position = (rng.uniform(-2.0, 2.0), rng.uniform(0.3, 3.0))
        shape = pymunk.Poly.create_box(body, (rng.uniform(0.2, 0.6), rng.uniform(0.2, 0.6)))
        shape.friction = 0.7
        space.add(body, shape)
    return space


def _reference(space: pymunk.Space, fields: batch.ArbiterFields) -> tuple[list[int], bytes]:
    buffer = batch.Buffer()
    batch.get_space_arbiters(space, fields, buffer)
    return list(memoryview(buffer.int_buf()).cast("P")), bytes(buffer.float_buf())


def test_readers_read_what_get_space_arbiters_reads() -> None:
    """Law: after every step of a settling pile, both readers give the ids, first-contact flags
    and float values of ``get_space_arbiters`` with the same fields, bit for bit; the id arrays
    stay the same objects while the ids read do not change, and are new when they do."""
    space = _scene(1)
    rows, values = ArbiterRows(), ArbiterValues()
    kept = changed = 0
    last: tuple[object, object, object, list[int]] | None = None
    for _ in range(STEPS):
        space.step(1.0 / 120.0)
        rows.read(space)
        values.read(space)
        ints, floats = _reference(
            space, _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.IS_FIRST_CONTACT | _A.NORMAL
        )
        expected = np.array(ints, dtype=np.uintp).reshape(-1, 3)
        assert rows.pairs.tolist() == expected[:, 0:2].tolist()
        assert rows.first.tolist() == (expected[:, 2] != 0).tolist()
        assert rows.values.tobytes() == floats
        ints, floats = _reference(space, _A.BODY_A_ID | _A.BODY_B_ID | _A.TOTAL_IMPULSE | _A.NORMAL)
        assert values.ids == ints
        flat = [v for row in values.values() for v in row]
        assert struct.pack(f"{len(flat)}d", *flat) == floats
        read = (rows.pairs.tolist(), rows.first.tolist())
        if last is not None:
            same = read == last[2]
            assert (rows.pairs is last[0]) == same
            assert (values.ids is last[1]) == (values.ids == last[3])
            kept += same
            changed += not same
        last = (rows.pairs, values.ids, read, list(values.ids))
    assert kept > STEPS // 2 and changed > 0
