"""What a crowd's probes found (:class:`Grounds`): the grounds hit, a row a shape."""

from __future__ import annotations

import struct
from typing import Any

import numpy as np
import pymunk

from playground._engine.state import body_motion
from playground._engine.sweep import sharp

__all__ = ["Grounds"]

STATIC = pymunk.Body.STATIC
_MOTION = struct.Struct("3d")  # a body's (vx, vy, w) as bytes, compared bit for bit


class Grounds:
    """What a crowd's probes found, by the shape hit (:attr:`Hits.shapes
    <playground._engine.sweep.Hits.shapes>`; most hit one floor), a row each, and a last row
    for :data:`~playground._engine.sweep.NO_HIT` (-1), where nothing was found; made from what
    :meth:`read` reads of the shapes, and made again only when that changes (most steps every
    probe finds the one floor, as it was)."""

    __slots__ = ("bodies", "kinds", "motion", "readings")

    @staticmethod
    def read(shapes: list[pymunk.Shape]) -> list[tuple[Any, ...]]:
        """What the rows are made of, a tuple a shape: the shape, its body and, if it has one,
        whether the body is static and does not turn, its motion (:data:`_MOTION`: bit for
        bit) and whether the shape has sharp corners."""
        readings: list[tuple[Any, ...]] = []
        for s in shapes:
            b = s.body
            if b is None:
                readings.append((s, None))
                continue
            kind, vx, vy, w = body_motion(b)
            readings.append((s, b, kind == STATIC and w == 0.0, _MOTION.pack(vx, vy, w), sharp(s)))
        return readings

    def __init__(self, readings: list[tuple[Any, ...]]) -> None:
        self.readings = readings
        """What it was made of (:meth:`read`)."""
        bodies: list[pymunk.Body | None] = []
        kinds: list[tuple[bool, bool, bool]] = []
        motion: list[tuple[float, ...]] = []
        for shape_reading in readings:
            if shape_reading[1] is None:
                bodies.append(None)
                kinds.append((False, False, False))
                motion.append((0.0, 0.0, 0.0))
                continue
            _, b, still, moves, corners = shape_reading
            bodies.append(b)
            kinds.append((True, still, corners))
            motion.append(_MOTION.unpack(moves))
        bodies.append(None)
        kinds.append((False, False, False))
        motion.append((0.0, 0.0, 0.0))
        self.bodies = np.empty(len(bodies), dtype=object)
        """Its body (None: nothing found, or a shape without a body, which is no ground)."""
        for k, body in enumerate(bodies):  # one by one: a list would be searched for sequences
            self.bodies[k] = body
        self.kinds = np.array(kinds, dtype=bool)
        """Three columns: it has a body; that body is static and does not turn; the shape has
        sharp corners (:func:`~playground._engine.sweep.sharp`)."""
        self.motion = np.array(motion, dtype=np.float64)
        """Three columns: its body's velocity (m/s) and angular velocity (rad/s)."""
