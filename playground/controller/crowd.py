"""A crowd: the controllers of one world run as one, their states as arrays, above a measured
number of actors (:data:`CROWD_MIN_ACTORS`; below it each controller runs its own step).

Each step the crowd reads every member's body in one batch call (:class:`Poses`), their
perceived gravity as arrays (:meth:`World.perceived_block`) and which bodies touch anything (one
batch read of the arbiters); their probes are cast in one call
(:class:`~playground._engine.sweep.Sweeps`: still a Chipmunk query each, a query cannot be
batched). The state machine's two common states and the force laws run on arrays, through
the very functions one controller uses (:mod:`~playground.controller.laws` over
:data:`~playground.controller.elementwise.ARRAYS`), and the forces enter the ledger as one block
of rows (:class:`~playground.forces.ledger.ForceRows`).

A member runs its own scalar step this step (in member order, among the others) unless all of
these hold: it was GROUNDED or AIRBORNE (no worse footing pending), holds no grip, is not taking
off or rising, has no jump pending (its last press older than ``jump_buffer``) and no balance
about to be lost; its intent is a plain move (no jump, grab, push or gravity switch); it follows
the default laws (:data:`~playground.controller.controller.DEFAULT_LAWS`: a break patches them)
under an unpatched ``Controller.step``; its body touches nothing (no arbiter) nor has within
``PUSH_ECHO`` while it leans beyond ``max_lean``; its probe finds nothing (while airborne) or a
walkable static ground that does not turn (and finds one if it stood), where
:mod:`~playground.controller.stairs` changes nothing (no corner's face, no tread ahead); and its
forces are within the runaway bounds. The whole crowd runs scalar while the field is not uniform,
bodies may sleep, a step has substeps (a contact of an earlier substep counts in the load), or the
gravity rules change during the stage (a switch of a member that runs scalar comes first).

A batch member's readings (:attr:`Controller.sensed`, ``control_state``, ``last_forces``,
``transition``) are built from the arrays when first read. They are the values the scalar step
gives: ``tests/controller/test_crowd.py`` runs random crowds both ways and compares them step by
step, to the last bit.
"""

from __future__ import annotations

import math
import struct
import sys
from typing import TYPE_CHECKING, Any

import numpy as np
import pymunk
import pymunk.batch as pbatch
from numpy.typing import NDArray

from playground._engine.batch import Poses, touching_ids
from playground._engine.inertia import Inertia
from playground._engine.state import BodyState, body_motion, space_gravity
from playground._engine.sweep import NO_HIT, Sweeps, sharp
from playground.controller import laws as law
from playground.controller import stairs
from playground.controller._vec import ZERO, unit_or
from playground.controller.action import ControllerForces
from playground.controller.config import ControllerConfig
from playground.controller.elementwise import ARRAYS
from playground.controller.sensing import (
    PUSH_ECHO,
    GroundHit,
    Sensed,
    effort,
    effort_on,
    lean,
)
from playground.controller.states import AIRBORNE, GROUNDED, ControllerState, Transition
from playground.forces.ledger import Category, ForceRows, RowBodies
from playground.intents import Intent
from playground.limits import MAX_COORDINATE, RUNAWAY_FORCE
from playground.world.schedule import Stage
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["CROWD_MIN_ACTORS", "Crowd"]

CROWD_MIN_ACTORS = 14
"""Fewest controllers a world runs as a crowd: measured with ``python
benchmarks/crowd_crossover.py --actors 11 12 13 14 --repeats 21`` (the crowd's step against each
controller's own, patrolling actors in their steady state), where the crowd pays in every block
(0.89×, blocks 0.79–0.97, at 14; 1.00× at 12)."""

SUPPORT = Category.SUPPORT
APPLIED = Category.APPLIED
STATIC = pymunk.Body.STATIC
_CODES = {GROUNDED: 1, AIRBORNE: 2}
_STATES = (None, GROUNDED, AIRBORNE)
_GROUNDED_CODE, _AIRBORNE_CODE = np.int8(_CODES[GROUNDED]), np.int8(_CODES[AIRBORNE])
_STANDING = ControllerState(GROUNDED)
"""The state the hover reads of a batch member (it reads only whether it is getting up)."""
_RUNAWAY_TORQUE = RUNAWAY_FORCE * MAX_COORDINATE
_COS_CORNER_TILT = math.cos(stairs.CORNER_TILT)
_COS_TREAD_PARALLEL = math.cos(stairs.TREAD_PARALLEL)
_NO_CONFIG = ControllerConfig()  # held by no member: its groups are made on its first step
_MOTION = struct.Struct("3d")  # a body's (vx, vy, w) as bytes, compared bit for bit

# The laws and the values they read, called on arrays (typed for floats, written for both).
_law: Any = law
_GroundHit: Any = GroundHit
_Sensed: Any = Sensed
_BodyState: Any = BodyState
_lean: Any = lean
_effort_on: Any = effort_on


def _plain_move(intent: Intent) -> float:
    """The intent's move if it asks for nothing else (no jump, grab, push or switch), else
    NaN."""
    if (
        intent.jump
        or intent.grab
        or intent.push
        or intent.gravity is not None
        or intent.restore_gravity
        or intent.nullify is not None
    ):
        return math.nan
    return intent.move


class _Group:
    """Members sharing one config (equal configs: one group): their rows, a slice where they
    follow one another (one config for all: every row), which indexes a view, not a copy."""

    __slots__ = ("_gravity", "config", "cos_slope", "rows", "size")

    def __init__(self, config: ControllerConfig, rows: list[int]) -> None:
        self.config = config
        first, last = rows[0], rows[-1]
        self.rows: slice | NDArray[np.intp] = (
            slice(first, last + 1)
            if last - first + 1 == len(rows)
            else np.array(rows, dtype=np.intp)
        )
        self.size = len(rows)
        self.cos_slope = math.cos(config.max_slope)
        self._gravity: tuple[Any, ...] = (None,)

    def shared(self, body: Any, gravity: tuple[Any, Any]) -> tuple[Any, Any]:
        """The members' ``body`` and ``gravity`` (m/s²) for the laws, with the mass (kg) and
        each component of the gravity one float where every member of the group holds the
        same (to the bit): what follows from it alone the laws then work out once, not row by
        row. The gravity's arrays are made again when it changes: its floats are kept."""
        gx, gy = gravity
        if self._gravity[0] is not gx or self._gravity[1] is not gy:
            self._gravity = (gx, gy, (_one(gx, self.rows, gx), _one(gy, self.rows, gy)))
        m = _one(body.mass, self.rows, None)
        if m is not None:
            body = _BodyState(
                body.x, body.y, body.vx, body.vy, body.cos, body.sin, body.spin, m, body.moment
            )
        return body, self._gravity[2]


def _one(a: NDArray[np.float64], rows: slice | NDArray[np.intp], other: Any) -> Any:
    """The one value of ``a``'s ``rows`` as a float if they all hold it, bit for bit (0.0 is
    not -0.0), else ``other``."""
    values = a[rows]
    bits = values.view(np.int64)
    return float(values[0]) if (bits == bits[0]).all() else other


class _ConfigArrays:
    """What the crowd's arrays read of each member's config: its lengths of
    :mod:`~playground.controller.stairs` (m; ``front`` is radius + probe_radius, the sum
    :func:`~playground.controller.stairs.ahead` looks ahead from), its hover frequency (Hz),
    the cosine of its steepest walkable slope, its max_lean (rad) and a sine short of its sine
    (a perceived up whose cross product with the field's up is smaller is surely within
    max_lean of it); made when the configs change, for the tread ahead and the lean of many
    members at once."""

    __slots__ = (
        "clearance", "cos_slope", "front", "hover_frequency", "max_lean", "reach", "ride_height",
        "surely_inside",
    )  # fmt: skip

    def __init__(self, configs: list[ControllerConfig]) -> None:
        self.ride_height = np.array([c.ride_height for c in configs])
        self.front = np.array([c.radius + c.probe_radius for c in configs])
        self.reach = np.array([c.ride_height - c.half_length for c in configs])
        self.clearance = np.array([c.ride_height - 0.5 * c.height for c in configs])
        self.hover_frequency = np.array([c.hover_frequency for c in configs])
        self.cos_slope = np.array([math.cos(c.max_slope) for c in configs])
        self.max_lean = np.array([c.max_lean for c in configs])
        self.surely_inside = np.array([math.sin(c.max_lean) * (1.0 - 1e-9) for c in configs])


class _Rows:
    """Writes a config group's rows of the step's arrays into ``out`` (name → array, one
    element or row per member): with one group of every member its arrays themselves, else
    its rows of arrays of all members (zeros until filled)."""

    __slots__ = ("_n", "_out", "_whole")

    def __init__(self, out: dict[str, Any], n: int, groups: list[_Group]) -> None:
        self._out = out
        self._n = n
        rows = groups[0].rows if len(groups) == 1 else None
        self._whole = isinstance(rows, slice) and rows == slice(0, n)

    def __call__(self, key: str, rows: slice | NDArray[np.intp], value: NDArray[Any]) -> None:
        if self._whole:
            self._out[key] = value
            return
        a = self._out.get(key)
        if a is None:
            a = self._out[key] = np.zeros((self._n, *value.shape[1:]), dtype=value.dtype)
        a[rows] = value[rows]


class _Grounds:
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


class Crowd:
    """The controllers of one world (:meth:`of`), run as one above :attr:`min_actors`."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.members: list[Controller] = []
        self.min_actors = CROWD_MIN_ACTORS
        """Fewest members run as a crowd (0: always; a change applies when one joins or
        leaves, or at once through :meth:`set_min_actors`)."""
        self.active = False
        """Whether the crowd's hook runs the members (else each runs its own)."""
        self._poses = Poses()
        self._arbiters = pbatch.Buffer()
        self._grounds = _Grounds([])
        self._configs: list[ControllerConfig] = []
        self._groups: list[_Group] = []
        self._rows_version = -1
        self._rows = np.zeros(0, dtype=np.intp)
        self._gravity_key: tuple[int, float, float] | None = None
        self._g: tuple[Any, ...] = ()
        self._g_norm: tuple[Any, NDArray[np.float64]] = (None, np.zeros(0))
        self._resize()

    @classmethod
    def of(cls, world: World) -> Crowd:
        """The crowd of ``world`` (made on first use)."""
        # Kept by the world (World.crowd), not in a table of worlds: a table would keep every
        # world alive through its members.
        crowd = world.crowd
        if not isinstance(crowd, Crowd):
            crowd = cls(world)
            world.crowd = crowd
        return crowd

    # -- membership ------------------------------------------------------------------------------

    def join(self, controller: Controller) -> None:
        """Add a controller (it has registered its own CONTROL hook)."""
        self.members.append(controller)
        self._resize()
        if self.active:
            self.world.off(Stage.CONTROL, controller.step)
        self._replan()

    def leave(self, controller: Controller) -> bool:
        """Take a controller out (it is being removed); whether the crowd was running its
        CONTROL step (then its own hook is not registered)."""
        owned = self.active
        self._fresh()
        self.members.remove(controller)
        self._resize()
        self._replan()
        return owned

    def set_min_actors(self, most: int) -> None:
        """Set :attr:`min_actors` and apply it now."""
        self.min_actors = most
        self._replan()

    def _replan(self) -> None:
        want = len(self.members) >= self.min_actors and len(self.members) > 0
        if want == self.active:
            return
        world = self.world
        if want:
            # Its arrays are of when it last ran: each member's state of now (they ran alone).
            self._fresh()
            self._absorb_all()
            for c in self.members:
                world.off(Stage.CONTROL, c.step)
            world.on(Stage.CONTROL, self.step)
        else:
            world.off(Stage.CONTROL, self.step)
            for c in self.members:
                if c.stale is self:
                    self.materialize(c)
                world.on(Stage.CONTROL, c.step)
        self.active = want

    def _fresh(self) -> None:
        """Every member's readings built from the arrays (before the arrays change shape)."""
        for c in self.members:
            if c.stale is self:
                self.materialize(c)

    def _resize(self) -> None:
        """Arrays for the members, filled from each one's objects (their readings built first
        from the arrays they outgrow)."""
        if hasattr(self, "_views"):
            self._fresh()
        n = len(self.members)
        self._ids = np.array([c.body.id for c in self.members], dtype=np.uintp)
        self._inertia = Inertia([c.body for c in self.members])
        self._member_of = {c.body: i for i, c in enumerate(self.members)}
        self._code = np.zeros(n, dtype=np.int8)
        self._names = [c.name for c in self.members]
        z = np.zeros
        self.cur: dict[str, Any] = {
            k: z(n)
            for k in (
                "ux",
                "uy",
                "push_x",
                "push_y",
                "short",
                "saturated",
                "grounded_at",
                "pressed_at",
                "still",
                "getup_at",
                "getup_from",
                "touched_at",
            )
        }
        # Each member's last ground: a GroundHit, or the view of the batch step it stood on; and
        # the view of its last batch step (object arrays: a step writes its members at once).
        self._last_ground: NDArray[np.object_] = np.full(n, None, dtype=object)
        self._views: NDArray[np.object_] = np.full(n, None, dtype=object)
        # Which members' readings are unread arrays of a batch step (``stale`` is the crowd), and
        # which batch step's (a count of steps; -1: none): their efforts come from the arrays.
        self._unread = np.zeros(n, dtype=bool)
        self._view_id = np.full(n, -1, dtype=np.int64)
        self._steps_run = getattr(self, "_steps_run", 0)
        self._rows_version = -1
        self._rows_key = b""
        self._rows_of = RowBodies([], self._ids[:0])
        # Each member's intent when its move was computed (None: not yet), and the configs the
        # groups were made of (a config no member holds: made on the first step).
        self._intents: list[Intent | None] = [None] * n
        self._moves = np.zeros(n)
        self._configs = [_NO_CONFIG] * n
        self._absorb_all()

    def _absorb_all(self) -> None:
        for i in range(len(self.members)):
            self._absorb(i)

    def _absorb(self, i: int) -> None:
        """Copy member ``i``'s state (after a scalar step, or as built) into the arrays."""
        c = self.members[i]
        state = c.control_state
        sensed = c.sensed
        forces = c.last_forces
        ok = (
            state.grip is None
            and not state.rising
            and state.take_off_from is None
            and sensed.ground_motion is None
            and state.ledge is None
            and state.footing_lost == 0.0
        )
        self._code[i] = _CODES.get(state.state, 0) if ok else 0
        cur = self.cur
        cur["ux"][i], cur["uy"][i] = sensed.up
        cur["push_x"][i], cur["push_y"][i] = forces.push
        short = forces.balance_short
        cur["short"][i] = -1.0 if short is None else float(short)
        cur["saturated"][i] = state.saturated
        cur["grounded_at"][i] = state.grounded_at
        cur["pressed_at"][i] = state.jump_pressed_at
        cur["still"][i] = state.still
        cur["getup_at"][i] = state.getup_at
        cur["getup_from"][i] = state.getup_from
        cur["touched_at"][i] = state.touched_at
        self._last_ground[i] = state.last_ground
        self._views[i] = None
        self._unread[i] = False
        self._view_id[i] = -1

    # -- the step --------------------------------------------------------------------------------

    def _batch_allowed(self, world: World) -> bool:
        return (
            self.members[0].unpatched()
            and world.gravity.uniform
            and not math.isfinite(world.config.sleep_time)
            and world.config.substeps == 1
        )

    def step(self, world: World) -> None:
        """The CONTROL stage's hook of an active crowd."""
        members = self.members
        if not members:
            return
        if not self._batch_allowed(world):
            for i, c in enumerate(members):
                c.step(world)
                self._absorb(i)
            return
        n = len(members)
        t = world.time
        wc = world.config
        dt = wc.dt
        # -- who may go batch: intents, laws, states ---------------------------------------------
        # One pass over the members: each one's intent as a plain move (NaN: it asks for more),
        # computed again only when its intent changed (a patrol keeps its intent between turns;
        # a keyboard makes new ones); which follow other laws (NaN too: they run scalar; a move
        # is within [-1, 1]); whether a config changed (the groups are made again).
        default_laws = members[0].default_laws
        intents, moves, configs = self._intents, self._moves, self._configs
        lawless: list[int] = []
        regroup = False
        for i, c in enumerate(members):
            intent = c.intent
            if intent is not intents[i]:
                intents[i] = intent
                moves[i] = _plain_move(intent)
            if c.laws is not default_laws:
                lawless.append(i)
            if c.config is not configs[i]:
                regroup = True
        move = moves.copy()
        if lawless:
            move[lawless] = math.nan
        ok = (self._code > 0) & ~np.isnan(move)
        move[~ok] = 0.0
        if regroup:
            self._regroup()
        cur = self.cur
        for g in self._groups:
            cfg = g.config
            r = g.rows
            pending = t - cur["pressed_at"][r] <= cfg.jump_buffer
            losing = (cur["short"][r] == 1.0) & (cur["saturated"][r] + dt > cfg.balance_loss_time)
            ok[r] &= ~(pending | losing)
        # -- sensing ---------------------------------------------------------------------------
        poses = self._poses.read(world.space, self._ids)
        x, y, angle, vx, vy, spin = poses.T
        mass, moment = self._inertia.read()
        cos, sin = np.cos(angle), np.sin(angle)
        gx, gy, gux, guy, has_g = self._gravity(world)
        grounded_before = self._code == 1
        # Airborne: up against the field (the last up where there is none).
        ux = np.where(has_g, gux, cur["ux"])
        uy = np.where(has_g, guy, cur["uy"])
        pux = puy = None
        if grounded_before.any():
            pu, pg = world.perceived_block(self._tracked_rows(world))
            pux, puy = pu[:, 0], pu[:, 1]
            # Grounded: the perceived up where there is one, the last up where it is too weak.
            perceived = grounded_before & np.isfinite(pux) & np.isfinite(puy)
            weak = self._below(pg, wc.perception.up_threshold)
            ux = np.where(perceived, np.where(weak, cur["ux"], pux), ux)
            uy = np.where(perceived, np.where(weak, cur["uy"], puy), uy)
            # The perceived up is held to its lean (sensing.lean) and slopes are measured
            # against the field's up: where the perceived up is surely within max_lean of the
            # field's, lean returns it as it is.
            leaned = perceived & ~weak & has_g
            dot = gux * pux + guy * puy
            cross = gux * puy - guy * pux
            inside = (dot > 0.0) & (np.abs(cross) < self._per_config.surely_inside)
            # Beyond it (leaning into its step), the very function on arrays.
            rows = (leaned & ~inside & ok).nonzero()[0]
            if len(rows):
                # Standing, or pushed within PUSH_ECHO, no lean of its own (sensing.leaning);
                # a member touching anything now runs its own step (below).
                own = (move[rows] != 0.0) & ~(t - cur["touched_at"][rows] <= PUSH_ECHO)
                ux[rows], uy[rows] = _lean(
                    (pux[rows], puy[rows]),
                    (gux[rows], guy[rows]),
                    self._efforts(rows, own),
                    mass[rows] * self._weight_per_kg()[rows],
                    self._max_lean()[rows],
                    ARRAYS,
                )
            lx = np.where(leaned, gux, ux)
            ly = np.where(leaned, guy, uy)
        else:
            lx, ly = ux, uy
        touched = touching_ids(world.space, self._arbiters)
        if len(touched):
            ok &= ~np.isin(self._ids, touched)
        # Each probe is one Chipmunk query (a query is not batched), all of them in one call.
        probing = ok.nonzero()[0]
        # The probing members' rows of the arrays: where every member probes (the usual step),
        # every row, a view instead of a gather.
        of = slice(None) if len(probing) == n else probing
        found = self._sweeps.nearest(
            probing,
            x[of],
            y[of],
            (x - ux * self._probe_length)[of],
            (y - uy * self._probe_length)[of],
            self._probe_radius[of],
        )
        # What they found, as last step while it is the same (_Grounds.read).
        readings = _Grounds.read(found.shapes)
        if readings != self._grounds.readings:
            self._grounds = _Grounds(readings)
        grounds = self._grounds
        shape_of = found.shape
        solid, still, corners = grounds.kinds[shape_of].T
        # Grounded and finding nothing, its own step looks for a tread to step down to
        # (stairs.below); over a ground that moves, its own step.
        lost = ((shape_of == NO_HIT) & grounded_before[of]) | (solid & ~still)
        # On stairs its own step's probe reads another ground: a corner's face, a tread to step
        # down to (grounded over unwalkable ground), a tread ahead to step up onto (for the
        # walking ones, below: _may_step_up). stairs.face and stairs.walkable's own tests first,
        # the same float operations: most members stand on a face, square to up.
        along = found.nx * ux[of] + found.ny * uy[of]
        off = grounded_before[of] & ~(along >= self._per_config.cos_slope[of])
        on = solid & still
        for q in (on & ~off & (along < _COS_CORNER_TILT) & corners).nonzero()[0].tolist():
            i = int(probing[q])
            probed = (found.shapes[shape_of[q]], *found.point_normal[:, q].tolist())
            pose = (float(x[i]), float(y[i]), float(ux[i]), float(uy[i]))
            off[q] = stairs.face(probed, *pose, self._configs[i].probe_radius) is not probed
        ok[probing[lost | (on & off)]] = False
        # The members on a ground kept, as rows of the probes' answers (kept) and of the arrays
        # (at): every row where every member is (the usual step), copied without a gather.
        kept = (on & ~off).nonzero()[0]
        at = probing[kept]
        if len(at) == n:
            kept = at = slice(None)
        on_ground = np.empty(n, dtype=object)
        on_ground[at] = grounds.bodies[shape_of[kept]]
        ground: list[pymunk.Body | None] = on_ground.tolist()
        hit = np.zeros(n, dtype=bool)
        hit[at] = True
        cols = np.zeros((7, n))
        cols[:4, at] = found.point_normal[:, kept]
        cols[4:, at] = grounds.motion[shape_of[kept]].T
        hx, hy, nx, ny, gvx, gvy, gw = cols
        walking = ok & hit & (move != 0.0)
        if walking.any():
            ok &= ~self._may_step_up(walking, x, y, vx - gvx, vy - gvy, ux, uy, move, cols)
        # -- the scalar members first get their readings from the arrays of the last step -------
        for i in np.flatnonzero(~ok).tolist():
            c = members[i]
            if c.stale is self:
                self.materialize(c)
        # -- deciding and acting, on arrays, per config -------------------------------------------
        body = _BodyState(x, y, vx, vy, cos, sin, spin, mass, moment)
        zeros = np.zeros(n)
        frame_v = (gvx + zeros, gvy + zeros)
        hits = _GroundHit(
            None,
            (hx, hy),
            (nx, ny),
            (x - hx) * ux + (y - hy) * uy,
            False,
            frame_v,
            (0.0, 0.0),  # a batch member's ground does not turn nor move of itself
            (0.0, 0.0),
            gw,
            False,
        )
        sensed = _Sensed(body, (ux, uy), t, dt, wc.substeps, (gx, gy))
        nxt = self._act(sensed, hits, hit, move, ok, t, dt, (lx, ly))
        nxt["code_before"] = self._code  # the commit below makes new ones
        nxt["short_before"] = cur["short"]
        nxt["ground"] = ground
        nxt["hit"] = hit
        nxt["hits"] = (hx, hy, nx, ny, gvx, gvy, gw, hits.distance, nxt["walkable"])
        nxt["sensed"] = (body, t, dt, wc.substeps, gx, gy, pux, puy, grounded_before)
        # -- the forces: a row per batch member, each taking effect at its member's turn -------
        ledger = world.ledger
        rows = np.flatnonzero(ok)
        rows.flags.writeable = False
        block: ForceRows | None = None
        if len(rows):
            block = ForceRows(
                self._row_bodies(rows),
                nxt["force"][rows],
                nxt["torque"][rows],
                nxt["parts"][rows],
            )
            ledger.add_rows(block)
        # -- the walk, in member order: each scalar member's step runs where it stands; the batch
        # members' rows take effect in the stretch before it (its push on one of them then adds to
        # that row, as in member order); a force already on a batch member's body (an earlier hook
        # or scalar member) comes first, its own forces after it.
        version = world.gravity_version
        ok_list = ok.tolist()
        scalar = np.flatnonzero(~ok).tolist()
        member_of = self._member_of
        start = 0
        for stop in [*scalar, n]:
            if block is not None:
                for b in ledger.entry_bodies():
                    j = member_of.get(b)
                    if j is not None and start <= j < stop and ok_list[j]:
                        ledger.drop_row(b)
                        ledger.add_all(b, _own(nxt, j), _torque(nxt, j, members[j].config))
                lo, hi = np.searchsorted(rows, (start, stop))
                block.active[lo:hi] = True
            if stop == n:
                break
            members[stop].step(world)
            self._absorb(stop)
            start = stop + 1
            if world.gravity_version != version:
                # A switch just now: every member after it senses again, in floats.
                for j in range(start, n):
                    c = members[j]
                    if ok_list[j]:
                        ok[j] = ok_list[j] = False
                        ledger.drop_row(c.body)
                        if c.stale is self:
                            self.materialize(c)
                    c.step(world)
                    self._absorb(j)
                break
        # -- commit the batch members' state ----------------------------------------------------
        # New arrays, not written over: the views of this step read the ones before it (the
        # state, the balance's shortfall and the push before the step).
        for k in ("ux", "uy", "short", "saturated", "grounded_at"):
            cur[k] = np.where(ok, nxt[k], cur[k])
        cur["push_x"] = np.where(ok, 0.0, cur["push_x"])
        cur["push_y"] = np.where(ok, 0.0, cur["push_y"])
        self._code = np.where(ok, nxt["code"], self._code)
        # A member stays ``stale`` while nothing reads it: only those read since (or run scalar)
        # are marked again.
        unread = self._unread
        for i in np.flatnonzero(ok & ~unread).tolist():
            members[i].stale = self
        unread[ok] = True
        self._steps_run += 1
        self._view_id[ok] = self._steps_run
        view = np.empty((), dtype=object)  # one object for a masked write (no sequence)
        view[()] = nxt
        self._views[ok] = view
        self._last_ground[ok & nxt["on_ground"]] = view  # this step's hit, built when read

    def _row_bodies(self, rows: NDArray[np.intp]) -> RowBodies:
        """The bodies of the members ``rows``: the last step's again while they are the same."""
        key = rows.tobytes()
        if key != self._rows_key:
            self._rows_key = key
            self._rows_of = RowBodies(
                [self.members[i].body for i in rows.tolist()], self._ids[rows]
            )
        return self._rows_of

    def _regroup(self) -> None:
        """The config groups and the arrays of the configs, made again (a config changed)."""
        configs = [c.config for c in self.members]
        self._configs = configs
        self._sweeps = Sweeps([c.senses.sweep for c in self.members])
        self._probe_length = np.array([cfg.probe_length for cfg in configs])
        self._probe_radius = np.array([cfg.probe_radius for cfg in configs])
        self._per_config = _ConfigArrays(configs)
        by: dict[ControllerConfig, list[int]] = {}
        for i, cfg in enumerate(configs):
            by.setdefault(cfg, []).append(i)
        self._groups = [_Group(cfg, rows) for cfg, rows in by.items()]

    def _may_step_up(
        self,
        walking: NDArray[np.bool_],
        px: NDArray[np.float64],
        py: NDArray[np.float64],
        rvx: NDArray[np.float64],
        rvy: NDArray[np.float64],
        ux: NDArray[np.float64],
        uy: NDArray[np.float64],
        move: NDArray[np.float64],
        ground: NDArray[np.float64],
    ) -> NDArray[np.bool_]:
        """Which ``walking`` members (their probe found a walkable static ground, its hit point
        and normal in ``ground``'s first four rows; (rvx, rvy) their velocity relative to it,
        m/s) may find a tread ahead to step up onto (:func:`~playground.controller.stairs.
        step_up` not None): their own step runs. The ray and the tests are those of
        :func:`~playground.controller.stairs.ahead`, the same float operations on arrays, and
        the rays are cast in one call; a tread on a one-way platform counts as found (the
        platform may let the ray pass)."""
        k = self._per_config
        hx, hy, nx, ny = ground[0], ground[1], ground[2], ground[3]
        walk = walking & (nx * ux + ny * uy >= k.cos_slope)
        direction = np.sign(move)  # 1.0 or -1.0 where walking (move ≠ 0)
        speed = direction * ((rvx * ny) - (rvy * nx))
        tx, ty = direction * ny, -direction * nx
        d = k.front + ARRAYS.max(0.0, speed) * 0.5 / k.hover_frequency
        fx, fy = px - nx * k.ride_height, py - ny * k.ride_height
        ax, ay = fx + tx * d + nx * k.reach, fy + ty * d + ny * k.reach
        depth = (ax - hx) * nx + (ay - hy) * ny - k.clearance
        bx, by = ax - nx * depth, ay - ny * depth
        rows = (walk & (depth > 0.0)).nonzero()[0]
        may = np.zeros(len(walking), dtype=bool)
        if not len(rows):
            return may
        of = slice(None) if len(rows) == len(walking) else rows  # every row: a view
        treads = self._sweeps.nearest(rows, ax[of], ay[of], bx[of], by[of], 0.0)
        tread_of = treads.shape
        seen = tread_of != NO_HIT
        if not seen.any():
            return may
        r = rows[seen]
        sx, sy, mx, my = treads.point_normal[:, seen]
        no_body = np.array([s.body is None for s in treads.shapes], dtype=bool)
        hx, hy, nx, ny = hx[r], hy[r], nx[r], ny[r]
        no_step = (
            ((sx == bx[r]) & (sy == by[r]))
            | ((sx - hx) * nx + (sy - hy) * ny <= k.clearance[r])
            | (mx * nx + my * ny < _COS_TREAD_PARALLEL)
            | no_body[tread_of[seen]]
        )
        may[r] = ~no_step
        return may

    def _tracked_rows(self, world: World) -> NDArray[np.intp]:
        if world.tracked_version != self._rows_version:
            self._rows = world.tracked_rows(self._names)
            self._rows_version = world.tracked_version
        return self._rows

    def _efforts(
        self, rows: NDArray[np.intp], own: NDArray[np.bool_]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The legs' effort in their last step (sensing.effort) of the members ``rows`` where
        ``own``, else 0, N: read from the efforts of each one's last batch step
        (:func:`_step_efforts`) without building its readings, or from its own scalar step's
        (then it is no longer ``stale``)."""
        k = len(rows)
        ex, ey = np.zeros(k), np.zeros(k)
        fresh = own & self._unread[rows]
        members = self.members
        for j in (own & ~fresh).nonzero()[0].tolist():
            c = members[int(rows[j])]
            ex[j], ey[j] = effort(c.last_forces.drive, c.sensed)
        # The rows of one batch step at a time (all of them the last step's, but for a few).
        view_ids = self._view_id[rows]
        todo = fresh.nonzero()[0]
        while len(todo):
            same = view_ids[todo] == view_ids[todo[0]]
            at, todo = todo[same], todo[~same]
            r = rows[at]
            step_x, step_y = _step_efforts(self._views[int(r[0])])
            ex[at], ey[at] = step_x[r], step_y[r]
        return ex, ey

    def _weight_per_kg(self) -> NDArray[np.float64]:
        """Each member's |g| (``math.hypot``, as its own step), m/s²: read again with the
        gravity (:meth:`_gravity`)."""
        if self._g_norm[0] is not self._g:
            self._g_norm = (self._g, ARRAYS.hypot(self._g[0], self._g[1]))
        return self._g_norm[1]

    def _max_lean(self) -> NDArray[np.float64]:
        """Each member's max_lean, rad, by its config group (made when the configs change)."""
        return self._per_config.max_lean

    def _gravity(self, world: World) -> tuple[Any, Any, Any, Any, Any]:
        """Each member's gravity (its rule on the uniform field), the unit up against it, and
        whether it has any: read again only when the field or a rule changed."""
        g = space_gravity(world.space)
        key = (world.gravity_version, g[0], g[1])
        if key != self._gravity_key or len(self._g[0]) != len(self.members):
            gs = [world.gravity_rule(c.name).apply(g[0], g[1]) for c in self.members]
            ups = [unit_or(-a, -b, (math.nan, math.nan)) for a, b in gs]
            self._g = (
                np.array([a for a, _ in gs]),
                np.array([b for _, b in gs]),
                np.array([u for u, _ in ups]),
                np.array([v for _, v in ups]),
                np.array([not math.isnan(u) for u, _ in ups]),
            )
            self._gravity_key = key
        return self._g

    @staticmethod
    def _below(pg: NDArray[np.float64], threshold: float) -> NDArray[np.bool_]:
        """``math.hypot(gx, gy) < threshold`` row by row, to the last bit: the sum of squares
        decides all but the rows within 1e-12 of the threshold, which ``math.hypot`` does."""
        s = pg[:, 0] * pg[:, 0] + pg[:, 1] * pg[:, 1]
        lo, hi = (threshold * (1.0 - 1e-12)) ** 2, (threshold * (1.0 + 1e-12)) ** 2
        below = s < lo
        for i in ((s >= lo) & (s <= hi)).nonzero()[0].tolist():  # near it (NaN is not)
            below[i] = math.hypot(pg[i, 0], pg[i, 1]) < threshold
        return below

    def _act(
        self,
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
        ``level`` (the field's up, or up).

        The readings read only when a member's are built (:meth:`materialize`: whether each
        force acts, the load) are left for then: the arrays hold what they are made of."""
        n = len(move)
        cur = self.cur
        nx, ny = hits.normal
        ux, uy = sensed.up
        lx, ly = level
        grounded_before = self._code == 1
        out: dict[str, Any] = {"ux": ux, "uy": uy, "lx": lx, "ly": ly}
        out["push"] = (cur["push_x"], cur["push_y"])  # for the load (the commit makes new ones)
        # One config for every member (the usual crowd) takes each group's arrays as they are;
        # several fill their rows of arrays of all members.
        put = _Rows(out, n, self._groups)
        bounded = True  # whether each member's torque is within t_cap (below) by its budget
        t_cap = _RUNAWAY_TORQUE if self.world.config.guard else math.inf
        for g in self._groups:
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
            put("code", r, np.where(grounded, _GROUNDED_CODE, _AIRBORNE_CODE))
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
        cap = RUNAWAY_FORCE if self.world.config.guard else sys.float_info.max
        ok &= (np.abs(out["parts"]) <= cap).all(axis=1)
        if not bounded:
            ok &= np.abs(out["torque"]) <= t_cap
        return out

    # -- readings built when read ----------------------------------------------------------------

    def materialize(self, c: Controller) -> None:
        """Build ``c``'s readings of its last batch step from the arrays (then it is fresh)."""
        i = self._member_of[c.body]
        nxt = self._views[i]
        c.stale = None
        self._unread[i] = False
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
        perceived = (
            (float(pux[i]), float(puy[i])) if grounded_before[i] and pux is not None else None
        )
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
        new_state = _STATES[code]
        old_state = _STATES[int(nxt["code_before"][i])]
        assert new_state is not None and old_state is not None
        last = self._last_ground[i]
        if isinstance(last, dict):
            last = hit if last is nxt else _hit_of(last, i)
            self._last_ground[i] = last
        before = c.control_state  # its unchanging fields are as they were
        c.control_state = ControllerState(
            new_state, False, before.jump_pressed_at, float(nxt["grounded_at"][i]), False,
            last, float(nxt["saturated"][i]), before.still, 0.0, before.getup_at,
            before.getup_from, None, None, None, None, None, 0.0, before.touched_at,
        )  # fmt: skip
        grounded = code == 1
        hover = (float(nxt["hover_x"][i]), float(nxt["hover_y"][i])) if grounded else ZERO
        own = _own(nxt, i)
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


def _step_efforts(view: dict[str, Any]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
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


def _own(nxt: dict[str, Any], i: int) -> list[tuple[float, float, Category]]:
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


def _torque(nxt: dict[str, Any], i: int, config: ControllerConfig) -> float | None:
    return None if config.lock_rotation else float(nxt["balance"][i])
