"""The crowd (:class:`Crowd`): its members (:class:`~playground.controller.crowd.members.Members`)
run as one by its step, which reads top-down: who may go batch, sensing, deciding and acting
(:mod:`~playground.controller.crowd.acting`), the forces, the walk in member order (each member
that runs its own step runs it there) and the commit of the batch members' state. The package's
docstring (:mod:`playground.controller.crowd`) says when a member runs its own step."""

from __future__ import annotations

import itertools
import math
import operator
from typing import Any

import numpy as np
import pymunk
import pymunk.batch as pbatch
from numpy.typing import NDArray

from playground._engine.batch import Poses, touching_ids
from playground._engine.state import BodyState
from playground._engine.sweep import NO_HIT, Sweeps
from playground.controller import stairs
from playground.controller.config import ControllerConfig
from playground.controller.crowd.acting import act
from playground.controller.crowd.gravity import Gravities, below
from playground.controller.crowd.grounds import Grounds
from playground.controller.crowd.groups import ConfigArrays, Group
from playground.controller.crowd.members import Members
from playground.controller.crowd.readings import own_forces, own_torque, step_efforts
from playground.controller.crowd.step_up import may_step_up
from playground.controller.elementwise import ARRAYS
from playground.controller.sensing import PUSH_ECHO, GroundHit, Sensed, effort, lean
from playground.forces.ledger import ForceRows, RowBodies
from playground.intents import Intent
from playground.world.world import World

__all__ = ["Crowd"]

_COS_CORNER_TILT = math.cos(stairs.CORNER_TILT)
_STATE = ("ux", "uy", "short", "saturated", "grounded_at")
"""The state arrays a step makes for its batch members (their push is 0 after it)."""

# The values the laws read and the lean, called on arrays (typed for floats, written for both).
_GroundHit: Any = GroundHit
_Sensed: Any = Sensed
_BodyState: Any = BodyState
_lean: Any = lean


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


class Crowd(Members):
    """The controllers of one world (:meth:`of`), run as one above :attr:`min_actors`."""

    def __init__(self, world: World) -> None:
        # What the step keeps between steps (the members' arrays are made below).
        self._poses = Poses()
        self._arbiters = pbatch.Buffer()
        self._grounds = Grounds([])
        self._configs: list[ControllerConfig] = []
        self._groups: list[Group] = []
        self._rows_version = -1
        self._rows = np.zeros(0, dtype=np.intp)
        self._gravities = Gravities()
        super().__init__(world)

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
        # Each member's intent as a plain move (NaN: it asks for more), computed again only
        # for the intents that changed (a patrol keeps its intent between turns; a keyboard
        # makes new ones), found in one pass in C. Which members follow other laws (they run
        # scalar) and the config groups are read again only when a member's laws or config
        # changed (Controller.config and .laws tell the crowd).
        if self._settings_changed or members[0].default_laws is not self._default_laws:
            self._read_settings()
        intents = [c.intent for c in members]
        moves = self._moves
        for i in itertools.compress(range(n), map(operator.is_not, intents, self._intents)):
            moves[i] = _plain_move(intents[i])
        self._intents = intents
        lawless = self._lawless
        ok = (self._code > 0) & (moves == moves)  # NaN is not equal to itself
        if lawless:
            ok[lawless] = False
        move = np.where(ok, moves, 0.0)
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
        gx, gy, gux, guy, has_g = self._gravities.read(world, self.members)
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
            weak = below(pg, wc.perception.up_threshold)
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
                    mass[rows] * self._gravities.weight_per_kg()[rows],
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
        # What they found, as last step while it is the same (Grounds.read).
        readings = Grounds.read(found.shapes)
        if readings != self._grounds.readings:
            self._grounds = Grounds(readings)
        grounds = self._grounds
        shape_of = found.shape
        # Grounded and finding nothing, its own step looks for a tread to step down to
        # (stairs.below); over a ground that moves, its own step. Where every probe found the
        # one same shape (the usual step: one floor), its kind is one value for all.
        one = len(found.shapes) == 1 and bool((shape_of == 0).all())
        solid: Any
        still: Any
        corners: Any
        lost: Any
        if one:
            solid, still, corners = grounds.kinds[0].tolist()
            lost = solid and not still
        else:
            solid, still, corners = grounds.kinds[shape_of].T
            lost = ((shape_of == NO_HIT) & grounded_before[of]) | (solid & ~still)
        # On stairs its own step's probe reads another ground: a corner's face, a tread to step
        # down to (grounded over unwalkable ground), a tread ahead to step up onto (for the
        # walking ones, below: may_step_up). stairs.face and stairs.walkable's own tests first,
        # the same float operations: most members stand on a face, square to up.
        along = found.nx * ux[of] + found.ny * uy[of]
        off = grounded_before[of] & ~(along >= self._per_config.cos_slope[of])
        on = solid & still
        if not one or (on and corners):
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
        on_ground[at] = grounds.bodies[0] if one else grounds.bodies[shape_of[kept]]
        ground: list[pymunk.Body | None] = on_ground.tolist()
        hit = np.zeros(n, dtype=bool)
        hit[at] = True
        cols = np.zeros((7, n))
        cols[:4, at] = found.point_normal[:, kept]
        cols[4:, at] = grounds.motion[0][:, None] if one else grounds.motion[shape_of[kept]].T
        hx, hy, nx, ny, gvx, gvy, gw = cols
        walking = ok & hit & (move != 0.0)
        if walking.any():
            ok &= ~may_step_up(self._sweeps, self._per_config, walking, x, y, vx - gvx, vy - gvy,
                               ux, uy, move, cols)  # fmt: skip
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
        guard = self.world.config.guard
        nxt = act(self._groups, cur, grounded_before, guard, sensed, hits, hit, move, ok, t,
                  dt, (lx, ly))  # fmt: skip
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
        every = len(rows) == n  # every member runs batch (the usual step)
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
        scalar = [] if every else np.flatnonzero(~ok).tolist()
        member_of = self._member_of
        start = 0
        for stop in [*scalar, n]:
            if block is not None:
                for b in ledger.entry_bodies():
                    j = member_of.get(b)
                    if j is not None and start <= j < stop and ok_list[j]:
                        ledger.drop_row(b)
                        ledger.add_all(b, own_forces(nxt, j), own_torque(nxt, j, members[j].config))
                lo, hi = (0, n) if every else np.searchsorted(rows, (start, stop))
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
        if every:  # (the walk turns members scalar only after a scalar member's switch)
            self._commit_all(nxt)
            return
        # New arrays, not written over: the views of this step read the ones before it (the
        # state, the balance's shortfall and the push before the step).
        for k in _STATE:
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
        self._whole_step = False

    def _commit_all(self, nxt: dict[str, Any]) -> None:
        """The commit of a step every member ran batch (the usual step): this step's arrays
        become the state as they are (the views of this step read the ones before it; a
        member's own step later writes only its own element), and every member's view is
        this step's."""
        cur = self.cur
        for k in _STATE:
            cur[k] = nxt[k]
        n = len(self.members)
        cur["push_x"], cur["push_y"] = np.zeros(n), np.zeros(n)
        self._code = nxt["code"]
        unread = self._unread
        for i in np.flatnonzero(~unread).tolist():
            self.members[i].stale = self
        unread.fill(True)
        self._steps_run += 1
        self._view_id.fill(self._steps_run)
        view = np.empty((), dtype=object)  # one object for a masked write (no sequence)
        view[()] = nxt
        self._views.fill(nxt)
        self._last_ground[nxt["on_ground"]] = view  # this step's hit, built when read
        self._whole_step = True

    def _row_bodies(self, rows: NDArray[np.intp]) -> RowBodies:
        """The bodies of the members ``rows``: the last step's again while they are the same."""
        key = rows.tobytes()
        if key != self._rows_key:
            self._rows_key = key
            self._rows_of = RowBodies(
                [self.members[i].body for i in rows.tolist()], self._ids[rows]
            )
        return self._rows_of

    def _read_settings(self) -> None:
        """Which members follow other laws than the crowd runs on arrays (they run their own
        step), and the config groups made again if a config changed."""
        members = self.members
        default_laws = members[0].default_laws
        self._default_laws = default_laws
        self._lawless = [i for i, c in enumerate(members) if c.laws is not default_laws]
        if not all(map(operator.is_, [c.config for c in members], self._configs)):
            self._regroup()
        self._settings_changed = False

    def _regroup(self) -> None:
        """The config groups and the arrays of the configs, made again (a config changed)."""
        configs = [c.config for c in self.members]
        self._configs = configs
        self._sweeps = Sweeps([c.senses.sweep for c in self.members])
        self._probe_length = np.array([cfg.probe_length for cfg in configs])
        self._probe_radius = np.array([cfg.probe_radius for cfg in configs])
        self._per_config = ConfigArrays(configs)
        by: dict[ControllerConfig, list[int]] = {}
        for i, cfg in enumerate(configs):
            by.setdefault(cfg, []).append(i)
        self._groups = [Group(cfg, rows) for cfg, rows in by.items()]

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
        (:func:`~playground.controller.crowd.readings.step_efforts`) without building its
        readings, or from its own scalar step's (then it is no longer ``stale``)."""
        if self._whole_step:
            # Every member's last step was the last batch step, and none was read since.
            step_x, step_y = step_efforts(self._views[0])
            return np.where(own, step_x[rows], 0.0), np.where(own, step_y[rows], 0.0)
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
            step_x, step_y = step_efforts(self._views[int(r[0])])
            ex[at], ey[at] = step_x[r], step_y[r]
        return ex, ey

    def _max_lean(self) -> NDArray[np.float64]:
        """Each member's max_lean, rad, by its config group (made when the configs change)."""
        return self._per_config.max_lean
