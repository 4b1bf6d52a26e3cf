"""The crowd's batch reads (:class:`playground._engine.batch.Poses`, ``touching_ids``): the same
doubles as the bodies' properties, in the order asked for, whatever order the space keeps; and
cos/sin of the angle read are the bits of the body's rotation vector (the controller's
``BodyState.cos``/``sin``)."""

from __future__ import annotations

import math
import random

import numpy as np
import pymunk
import pymunk.batch

from playground._engine.batch import Poses, touching_ids


def test_poses_are_the_properties_in_the_order_asked() -> None:
    rnd = random.Random(7)
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    bodies = []
    for i in range(60):
        body = pymunk.Body(1.0 + i, 2.0)
        body.position = (rnd.uniform(-50, 50), rnd.uniform(0, 50))
        body.velocity = (rnd.uniform(-5, 5), rnd.uniform(-5, 5))
        body.angle = rnd.uniform(-20, 20)
        body.angular_velocity = rnd.uniform(-30, 30)
        space.add(body, pymunk.Circle(body, 0.2))
        bodies.append(body)
    for _ in range(30):
        space.step(1 / 120)
    asked = bodies[::-1][::2]
    ids = np.array([b.id for b in asked], dtype=np.uintp)
    rows = Poses().read(space, ids)
    for b, row in zip(asked, rows.tolist(), strict=True):
        assert row == [*b.position, b.angle, *b.velocity, b.angular_velocity]
        r = b.rotation_vector
        assert (float(np.cos(row[2])), float(np.sin(row[2]))) == (r.x, r.y)
        assert (math.cos(row[2]), math.sin(row[2])) == (r.x, r.y)


def test_touching_ids_names_the_bodies_of_each_contact() -> None:
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0))
    resting = pymunk.Body(1.0, 1.0)
    resting.position = (0.0, 0.5)
    flying = pymunk.Body(1.0, 1.0)
    flying.position = (0.0, 10.0)
    space.add(resting, pymunk.Poly.create_box(resting, (1.0, 1.0)))
    space.add(flying, pymunk.Poly.create_box(flying, (1.0, 1.0)))
    space.step(1 / 120)
    ids = set(touching_ids(space, pymunk.batch.Buffer()).tolist())
    assert resting.id in ids and flying.id not in ids
