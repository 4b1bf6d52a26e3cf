"""Readings: the reader of every quantity of :mod:`playground.quantities`, on a built scene.

One reader per quantity, so a level's checks, a recording and ``playground run --json`` read the
same value the same way (:func:`sample`). Values in the quantity's SI unit.

>>> from playground.level import find, load
>>> from playground.scene import build
>>> scene = build(load(find("rest")))
>>> scene.run(0.5)
>>> support, mass = QUANTITIES["support"], QUANTITIES["mass"]
>>> round(read(support, scene, "player")[1] / read(mass, scene, "player"), 2)
9.81
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from playground.quantities import QUANTITIES, Quantity, Value

if TYPE_CHECKING:
    from playground.scene.scene import Scene

__all__ = ["READERS", "Reader", "read", "sample"]

Reader = Callable[["Scene", str], Value]
"""``reader(scene, body)``: the body's current value (None where the body has none)."""


def _mass(scene: Scene, body: str) -> Value:
    return scene.world.body(body).mass


def _position(scene: Scene, body: str) -> Value:
    p = scene.world.body(body).position
    return (p.x, p.y)


def _velocity(scene: Scene, body: str) -> Value:
    v = scene.world.body(body).velocity
    return (v.x, v.y)


def _angle(scene: Scene, body: str) -> Value:
    return scene.world.body(body).angle


def _angular_velocity(scene: Scene, body: str) -> Value:
    return scene.world.body(body).angular_velocity


def _tilt(scene: Scene, body: str) -> Value:
    return scene.tilt(body)


def _up(scene: Scene, body: str) -> Value:
    return scene.up(body)


def _state(scene: Scene, body: str) -> Value:
    return scene.state(body)


def _solver(name: str) -> Reader:
    """The force solver's reading ``name`` (a field of :class:`playground.forces.Forces`)."""

    def read(scene: Scene, body: str) -> Value:
        vec: tuple[float, float] = getattr(scene.world.forces(body), name)
        return vec

    return read


def _perceived_gravity(scene: Scene, body: str) -> Value:
    return scene.world.perceived_gravity(body)


def _support_filtered(scene: Scene, body: str) -> Value:
    return scene.support_filtered(body)


def _controller(name: str) -> Reader:
    """The controller's own reading ``name`` of the force it put on its body last step."""

    def read(scene: Scene, body: str) -> Value:
        vec: tuple[float, float] = getattr(scene.controllers[body].last_forces, name)
        return vec

    return read


_BY_NAME: dict[str, Reader] = {
    "mass": _mass,
    "position": _position,
    "velocity": _velocity,
    "angle": _angle,
    "angular_velocity": _angular_velocity,
    "tilt": _tilt,
    "up": _up,
    "support_filtered": _support_filtered,
    "perceived_gravity": _perceived_gravity,
    "state": _state,
}


def _reader(q: Quantity) -> Reader:
    """A solver's or a controller's reading is read by its name; the others have their own."""
    if q.source == "solver":
        return _solver(q.name)
    if q.source == "controller":
        return _controller(q.name)
    return _BY_NAME[q.name]


READERS: dict[str, Reader] = {name: _reader(q) for name, q in QUANTITIES.items()}
"""The reader of every quantity, by name (every quantity has one: a missing one fails here, at
import)."""


def read(q: Quantity, scene: Scene, body: str) -> Value:
    """``q``'s reading of ``body`` now (None where the body has none)."""
    return READERS[q.name](scene, body)


def sample(q: Quantity, scene: Scene, body: str) -> Value:
    """``q``'s reading of ``body`` now, or None where the body has none (a perception reading of
    a body its world does not perceive)."""
    try:
        return READERS[q.name](scene, body)
    except KeyError:
        if q.source != "perception":
            raise
        return None
