"""A crowd's readings built when read: a batch member's :attr:`Controller.sensed`,
``control_state``, ``last_forces`` and ``transition`` made from the arrays of its last batch step
(:func:`build_readings`), the values its own step gives; and what the crowd's next step reads of
that step without building them (its forces, its legs' effort)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from playground._engine.state import BodyState
from playground.controller._vec import ZERO
from playground.controller.action import ControllerForces
from playground.controller.config import ControllerConfig
from playground.controller.crowd.codes import STATES
from playground.controller.elementwise import ARRAYS
from playground.controller.sensing import GroundHit, Sensed, effort_on
from playground.controller.states import ControllerState, Transition
from playground.forces.ledger import Category

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["build_readings", "own_forces", "own_torque", "step_efforts"]

SUPPORT = Category.SUPPORT
APPLIED = Category.APPLIED

_effort_on: Any = effort_on  # called on arrays (typed for floats, written for both)


def build_readings(
    c: Controller, i: int, nxt: dict[str, Any] | None, last_ground: NDArray[np.object_]
) -> None:
    """Build ``c``'s readings (member ``i``) of its last batch step from the arrays of that
    step (``nxt``, its view; None: it ran none); ``last_ground`` holds each member's last
    ground, where the view it stood on is replaced by the hit built from it."""
    if nxt is None:
        return
    body, t, dt, substeps, gx, gy, pux, puy, grounded_before = nxt["sensed"]
    state_body = BodyState(
        float(body.x[i]), float(body.y[i]), float(body.vx[i]), float(body.vy[i]),
        float(body.cos[i]), float(body.sin[i]), float(body.spin[i]), float(body.mass[i]),
        float(body.moment[i]),
    )  # fmt: skip
    up = (float(nxt["ux"][i]), float(nxt["uy"][i]))
    hit = _hit_of(nxt, i)
    perceived = (float(pux[i]), float(puy[i])) if grounded_before[i] and pux is not None else None
    short_before = float(nxt["short_before"][i])
    last_short = None if short_before < 0.0 else short_before == 1.0
    px, py = nxt["push"]
    load = 0.0 + max(0.0, -(float(px[i]) * up[0] + float(py[i]) * up[1]))
    c.sensed = Sensed(
        state_body, up, t, dt, substeps, (float(gx[i]), float(gy[i])), perceived, hit,
        None, 0.0, load, False, last_short, 0.0, 0.0, None, ZERO, None, None,
        (float(nxt["lx"][i]), float(nxt["ly"][i])),
    )  # fmt: skip
    code = int(nxt["code"][i])
    new_state = STATES[code]
    old_state = STATES[int(nxt["code_before"][i])]
    assert new_state is not None and old_state is not None
    last = last_ground[i]
    if isinstance(last, dict):
        last = hit if last is nxt else _hit_of(last, i)
        last_ground[i] = last
    before = c.control_state  # its unchanging fields are as they were
    c.control_state = ControllerState(
        new_state, False, before.jump_pressed_at, float(nxt["grounded_at"][i]), False,
        last, float(nxt["saturated"][i]), before.still, 0.0, before.getup_at,
        before.getup_from, None, None, None, None, None, 0.0, before.touched_at,
    )  # fmt: skip
    grounded = code == 1
    hover = (float(nxt["hover_x"][i]), float(nxt["hover_y"][i])) if grounded else ZERO
    own = own_forces(nxt, i)
    drive = (float(nxt["drive_x"][i]), float(nxt["drive_y"][i])) if nxt["drive_on"][i] else ZERO
    short = float(nxt["short"][i])
    locked = short < 0.0  # no balance acts
    torque = None if locked else float(nxt["balance"][i])
    c.last_forces = ControllerForces(
        hover, drive, ZERO, ZERO, 0.0 if torque is None else torque, own, torque, None, [],
        None, None, None, None if locked else short == 1.0,
    )  # fmt: skip
    changed = new_state is not old_state
    c.transition = Transition(t, old_state, new_state) if changed else None


def _hit_of(view: dict[str, Any], i: int) -> GroundHit | None:
    """Member ``i``'s ground in the step of ``view`` (None: none found)."""
    ground_body = view["ground"][i]
    if ground_body is None:
        return None
    hx, hy, nx, ny, gvx, gvy, gw, dist, walkable = view["hits"]
    return GroundHit(
        ground_body, (float(hx[i]), float(hy[i])), (float(nx[i]), float(ny[i])),
        float(dist[i]), bool(walkable[i]), (float(gvx[i]), float(gvy[i])), (0.0, 0.0),
        (0.0, 0.0), float(gw[i]), False,
    )  # fmt: skip


def step_efforts(view: dict[str, Any]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The legs' effort (sensing.effort, N) of every member in the batch step of ``view`` (of
    its batch members: a member that ran its own step reads its own), on arrays: made when
    first read, once a step for all its members."""
    efforts: tuple[NDArray[np.float64], NDArray[np.float64]] | None = view.get("effort")
    if efforts is None:
        drive_on = view["drive_on"]
        drive = (
            np.where(drive_on, view["drive_x"], 0.0),
            np.where(drive_on, view["drive_y"], 0.0),
        )
        _, _, nx, ny, *_ = view["hits"]
        body, _, _, _, gx, gy, *_ = view["sensed"]
        holding = view["hit"] & drive_on
        efforts = view["effort"] = _effort_on(drive, (nx, ny), (gx, gy), body.mass, ARRAYS, holding)
    return efforts


def own_forces(nxt: dict[str, Any], i: int) -> list[tuple[float, float, Category]]:
    """Member ``i``'s forces in the step of ``nxt``, in order: the hover where it pushes, the
    drive (or, airborne, the air steering) where it is not 0."""
    own: list[tuple[float, float, Category]] = []
    grounded = bool(nxt["on_ground"][i])
    if grounded and nxt["hover"][i] > 0.0:
        own.append((float(nxt["hover_x"][i]), float(nxt["hover_y"][i]), SUPPORT))
    if nxt["drive_on"][i]:
        kind = SUPPORT if grounded else APPLIED
        own.append((float(nxt["drive_x"][i]), float(nxt["drive_y"][i]), kind))
    return own


def own_torque(nxt: dict[str, Any], i: int, config: ControllerConfig) -> float | None:
    """Member ``i``'s balance torque in the step of ``nxt``, N·m (None: its config locks its
    rotation, no balance acts)."""
    return None if config.lock_rotation else float(nxt["balance"][i])
