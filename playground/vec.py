"""The 2-vector of the core's signatures: ``Vec``, an (x, y) pair of floats.

Positions (m), velocities (m/s), forces (N), gravity (m/s²) and directions all pass as a plain
``tuple[float, float]`` in the world frame; each signature's docstring gives the unit. pymunk's
``Vec2d`` is such a tuple, so either can be passed.

>>> import pymunk
>>> v: Vec = pymunk.Vec2d(3.0, 4.0)
>>> isinstance(v, tuple), v[0] * v[0] + v[1] * v[1]
(True, 25.0)
"""

__all__ = ["Vec"]

Vec = tuple[float, float]
