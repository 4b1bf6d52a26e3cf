"""A pymunk space that counts its removals, so the world learns at the cost of one integer
comparison a step that the game took a body out with ``space.remove`` (checking every named body
would cost a dictionary look-up each, every step).

Every removal goes through :meth:`pymunk.Space.remove`: one asked for inside ``space.step`` (from
a collision callback) is made at the end of that step, after the call was counted.

>>> space = CountingSpace()
>>> body = pymunk.Body(1.0, 1.0)                         # kg, kg·m²
>>> space.add(body)
>>> space.removals
0
>>> space.remove(body)
>>> space.removals, body.space is None
(1, True)
"""

from __future__ import annotations

import pymunk

__all__ = ["CountingSpace"]


class CountingSpace(pymunk.Space):
    """A :class:`pymunk.Space` whose :attr:`removals` counts the calls of :meth:`remove`."""

    removals: int = 0
    """How many times :meth:`remove` was called (a count that only grows)."""

    def remove(self, *objs: pymunk.Body | pymunk.Shape | pymunk.Constraint) -> None:
        """Remove shapes, bodies or joints, as :meth:`pymunk.Space.remove` does, and count it."""
        self.removals += 1
        super().remove(*objs)
