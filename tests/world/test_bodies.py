"""Laws of the body checks and sleeping groups."""

from __future__ import annotations

import pymunk
import pytest

from playground.world.bodies import check_body, group


def test_a_group_is_the_dynamic_bodies_joined_or_touching() -> None:
    """Law: a body's group holds the dynamic bodies jointed to it, first the body itself, and
    never a static or kinematic body."""
    space = pymunk.Space()
    a, b, c = (pymunk.Body(1.0, 1.0) for _ in range(3))
    k = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    space.add(a, b, c, k, pymunk.PinJoint(a, b), pymunk.PinJoint(b, k), pymunk.PinJoint(k, c))
    assert group(a) == [a, b]
    assert group(c) == [c]


def test_a_body_already_in_a_space_is_refused() -> None:
    """Law: a body (or shape) that is in another space is refused, naming it."""
    space = pymunk.Space()
    body = pymunk.Body(1.0, 1.0)
    space.add(body)
    with pytest.raises(ValueError, match=r"^crate: the body is already in a space"):
        check_body("crate", body, ())
