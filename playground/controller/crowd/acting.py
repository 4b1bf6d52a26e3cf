"""Deciding and acting for a crowd's batch members, on arrays, per config group (:func:`act`):
the state machine's two common states and the force laws, through the very functions one
controller uses (:mod:`~playground.controller.laws` over
:data:`~playground.controller.elementwise.ARRAYS`)."""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
from numpy.typing import NDArray

from playground.controller import laws as law
from playground.controller.crowd.codes import AIRBORNE_CODE, GROUNDED_CODE
from playground.controller.crowd.groups import Group, Rows
from playground.controller.elementwise import ARRAYS
from playground.controller.sensing import GroundHit, Sensed
from playground.controller.states import GROUNDED, ControllerState
from playground.limits import MAX_COORDINATE, RUNAWAY_FORCE

__all__ = ["act"]

_STANDING = ControllerState(GROUNDED)
"""The state the hover reads of a batch member (it reads only whether it is getting up)."""
_RUNAWAY_TORQUE = RUNAWAY_FORCE * MAX_COORDINATE

# The laws and the values they read, called on arrays (typed for floats, written for both).
_law: Any = law
_Sensed: Any = Sensed


def act(
    groups: list[Group],
    cur: dict[str, Any],
    grounded_before: NDArray[np.bool_],
    guard: bool,
    sensed: Sensed,
    hits: GroundHit,
    hit: NDArray[np.bool_],
    move: NDArray[np.float64],
    ok: NDArray[np.bool_],
    t: float,
    dt: float,
    level: tuple[NDArray[np.float64], NDArray[np.float64]],
) -> dict[str, Any]:
    """decide and act of the batch members, per config group; ``ok`` loses a member whose
    forces are beyond the runaway bounds, that finds ground too steep to stand on (it
    slides, or is about to) or that loses its ground (the state holds GROUNDED for
    ``footing_time``): the scalar step decides those. Slopes are measured against
    ``level`` (the field's up, or up). ``groups`` are the crowd's config groups, ``cur`` its
    arrays of the members' state, ``grounded_before`` which were GROUNDED before the step
    and ``guard`` the world's runaway guard.

    The readings read only when a member's are built
    (:func:`~playground.controller.crowd.readings.build_readings`: whether each force acts, the
    load) are left for then: the arrays hold what they are made of."""
    n = len(move)
    nx, ny = hits.normal
    ux, uy = sensed.up
    lx, ly = level
    out: dict[str, Any] = {"ux": ux, "uy": uy, "lx": lx, "ly": ly}
    out["push"] = (cur["push_x"], cur["push_y"])  # for the load (the commit makes new ones)
    # One config for every member (the usual crowd) takes each group's arrays as they are;
    # several fill their rows of arrays of all members.
    put = Rows(out, n, groups)
    bounded = True  # whether each member's torque is within t_cap (below) by its budget
    t_cap = _RUNAWAY_TORQUE if guard else math.inf
    for g in groups:
        cfg = g.config
        r = g.rows
        # (No ground: a normal of 0, and max_slope < π/2.)
        walkable = nx * lx + ny * ly >= g.cos_slope
        grounded = walkable  # on walkable ground, and not rising: a batch member never is
        # Ground too steep to stand on, or none where it stood: its own step decides.
        ok[r] &= (walkable | ~(hit | grounded_before))[r]
        short = cur["short"]
        saturated = np.where(short == 1.0, cur["saturated"] + dt, 0.0)
        saturated = np.where(short < 0.0, cur["saturated"], saturated)
        put("code", r, np.where(grounded, GROUNDED_CODE, AIRBORNE_CODE))
        put("grounded_at", r, np.where(grounded, t, cur["grounded_at"]))
        put("saturated", r, saturated)
        put("on_ground", r, grounded)
        put("walkable", r, walkable)
        # The laws read the values all the group's members share as one float (a mass, the
        # gravity): what follows from them alone is worked out once, not for every row.
        on = np.count_nonzero(grounded[r])
        body, gravity = g.shared(sensed.body, sensed.gravity)
        at = _Sensed(body, sensed.up, t, dt, sensed.substeps, gravity)
        parts = np.zeros((n, 6))  # [px, py, ax, ay, sx, sy]: no contact part
        if on:
            hover = _law.hover(at, _STANDING, hits, cfg, ARRAYS)
            if on < g.size:
                hover = np.where(grounded, hover, 0.0)
            hvx, hvy = hover * nx, hover * ny
            dvx, dvy = _law.drive(at, hits, move, hover, cfg, ARRAYS)
            # The same additions as add_all: 0.0, then each force in order. A force that
            # does not act adds 0.0 as well: its magnitude is 0 (a hover of 0 along the
            # normal is ±0.0; ops.vector's zero is 0.0), and 0.0 + x is never -0.0.
            np.add(0.0 + hvx, dvx, out=parts[:, 4])
            np.add(0.0 + hvy, dvy, out=parts[:, 5])
            put("hover", r, hover)
            put("hover_x", r, hvx)
            put("hover_y", r, hvy)
        else:
            dvx = dvy = parts[:, 4]
        if on < g.size:
            # Airborne and moving, the air steering (applied: a member has support or
            # applied forces, never both, so the other pair of parts is 0.0 and the force
            # their sum).
            svx, svy = _law.steer(at, move, cfg, ARRAYS)
            steer = ~grounded & (move != 0.0)
            ax, ay = np.where(steer, svx, 0.0), np.where(steer, svy, 0.0)
            parts[:, 2], parts[:, 3] = 0.0 + ax, 0.0 + ay
            dvx, dvy = np.where(grounded, dvx, ax), np.where(grounded, dvy, ay)
            put("force", r, parts[:, 4:6] + parts[:, 2:4])
        else:
            put("force", r, parts[:, 4:6])
        put("parts", r, parts)
        # The drive's or the steering's force (0.0 where none acts: ops.vector's zero).
        put("drive_x", r, dvx)
        put("drive_y", r, dvy)
        put("drive_on", r, (dvx != 0.0) | (dvy != 0.0))
        if cfg.lock_rotation:
            put("balance", r, np.zeros(n))
            put("torque", r, np.zeros(n))
            put("short", r, np.full(n, -1.0))  # no balance acts (read as locked)
        else:
            # Relative to the ground's spin (0 off the ground: the same subtraction).
            need = _law.balance(at, hits, cfg, ARRAYS)
            budget = cfg.balance_budget(body.mass)
            torque = ARRAYS.max(-budget, ARRAYS.min(budget, need))  # within ±budget
            bounded &= isinstance(budget, float) and budget <= t_cap
            short = np.abs(need) > budget
            if on < g.size:
                short &= grounded  # touching: nothing else touches a batch member
            put("short", r, short.astype(np.float64))
            put("balance", r, torque)
            put("torque", r, 0.0 + torque)
    # Within the runaway bounds: each part (the force is one of each pair), finite without
    # the guard (the largest float bounds them then), and the torque unless its budget is.
    cap = RUNAWAY_FORCE if guard else sys.float_info.max
    ok &= (np.abs(out["parts"]) <= cap).all(axis=1)
    if not bounded:
        ok &= np.abs(out["torque"]) <= t_cap
    return out
