"""A crowd's members (:class:`Members`): who they are, whether the crowd runs them (from
:data:`CROWD_MIN_ACTORS` on) or each runs its own step, and their state between steps as arrays:
filled from a member's objects (as built, or after its own step) and built back into them when
read (:meth:`Members.materialize`). The step that runs them is
:class:`~playground.controller.crowd.crowd.Crowd`'s."""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from playground._engine.inertia import Inertia
from playground.controller.config import ControllerConfig
from playground.controller.crowd.codes import CODES
from playground.controller.crowd.readings import build_readings
from playground.forces.ledger import RowBodies
from playground.intents import Intent
from playground.world.schedule import Stage
from playground.world.world import World

if TYPE_CHECKING:
    from playground.controller.controller import Controller

__all__ = ["CROWD_MIN_ACTORS", "Members"]

CROWD_MIN_ACTORS = 14
"""Fewest controllers a world runs as a crowd: measured with ``python
benchmarks/crowd_crossover.py --actors 11 12 13 14 --repeats 21`` (the crowd's step against each
controller's own, patrolling actors in their steady state), where the crowd pays in every block
(0.89×, blocks 0.79–0.97, at 14; 1.00× at 12)."""

_NO_CONFIG = ControllerConfig()  # held by no member: its groups are made on its first step


class Members(ABC):
    """The controllers of one world and their state as arrays, run as one above
    :attr:`min_actors` by :meth:`step`."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.members: list[Controller] = []
        self.min_actors = CROWD_MIN_ACTORS
        """Fewest members run as a crowd (0: always; a change applies when one joins or
        leaves, or at once through :meth:`set_min_actors`)."""
        self.active = False
        """Whether the crowd's hook runs the members (else each runs its own)."""
        self._readers: list[Controller] = []
        """The members whose sources :meth:`read_sources` reads in place of their own INPUTS
        hooks (none: each reads its own)."""
        self._resize()

    @abstractmethod
    def step(self, world: World) -> None:
        """The CONTROL stage's hook of an active crowd."""

    # -- membership ------------------------------------------------------------------------------

    def join(self, controller: Controller) -> None:
        """Add a controller (it has registered its own hooks, or will at the step's end)."""
        self.members.append(controller)
        self._resize()
        world = self.world
        if self.active:
            world.off(Stage.CONTROL, controller.step)
            # Its source read with the others' if its hook runs right after theirs.
            readers = self._readers
            if (
                readers
                and controller.reads_source
                and world.replace_hooks(
                    Stage.INPUTS, [self.read_sources, controller.read_source], [self.read_sources]
                )
            ):
                self._readers = [*readers, controller]
        self._replan()

    def leave(self, controller: Controller) -> set[Stage]:
        """Take a controller out (it is being removed); the stages whose hook of its own is
        not registered (the crowd ran its CONTROL step, or read its source)."""
        owned = {Stage.CONTROL} if self.active else set()
        if any(c is controller for c in self._readers):
            owned.add(Stage.INPUTS)
            # A new list: a stage reading the old one goes on (the controller is removed).
            self._readers = [c for c in self._readers if c is not controller]
            if not self._readers:
                self.world.off(Stage.INPUTS, self.read_sources)
        self._fresh()
        self.members.remove(controller)
        self._resize()
        self._replan()
        return owned

    def read_sources(self, world: World) -> None:
        """The INPUTS stage's hook in place of the readers' own (:meth:`Controller.read_source
        <playground.controller.controller.Controller.read_source>`, which ran one right after
        another where this runs): each one's intent from its source, in their order, with the
        same checks, without a hook's call for each."""
        for c in self._readers:
            source = c.source
            assert source is not None
            if c.removed:
                continue
            intent = source.intent(world.time)
            if not isinstance(intent, Intent):
                # A duck-typed intent skips Intent's checks: a NaN move would win the budget.
                raise ValueError(f"{c.name}: the intent source returned {intent!r}, not an Intent")
            c.intent = intent

    def settings_changed(self) -> None:
        """A member's config or laws changed: the next step reads them again."""
        self._settings_changed = True

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
            # Their sources read in one hook where their own hooks run one right after another
            # (in member order), else each reads its own.
            readers = [c for c in self.members if c.reads_source]
            hooks = [c.read_source for c in readers]
            if readers and world.replace_hooks(Stage.INPUTS, hooks, [self.read_sources]):
                self._readers = readers
        else:
            world.off(Stage.CONTROL, self.step)
            for c in self.members:
                if c.stale is self:
                    self.materialize(c)
                world.on(Stage.CONTROL, c.step)
            if self._readers:
                hooks = [c.read_source for c in self._readers]
                world.replace_hooks(Stage.INPUTS, [self.read_sources], hooks)
                self._readers = []
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
        self._whole_step = False
        """Whether every member ran the last batch step and none was read since."""
        self._steps_run = getattr(self, "_steps_run", 0)
        self._rows_version = -1
        self._rows_key = b""
        self._rows_of = RowBodies([], self._ids[:0])
        # Each member's intent when its move was computed (None: not yet), and the configs the
        # groups were made of (a config no member holds: made on the first step).
        self._intents: Sequence[Intent | None] = [None] * n
        self._moves = np.zeros(n)
        self._configs = [_NO_CONFIG] * n
        # Which members follow other laws than the defaults, read with the configs when one
        # changes (Controller.config and .laws tell the crowd) or the members do.
        self._lawless: list[int] = []
        self._default_laws: Any = None
        self._settings_changed = True
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
        self._code[i] = CODES.get(state.state, 0) if ok else 0
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
        self._whole_step = False

    # -- readings built when read ----------------------------------------------------------------

    def materialize(self, c: Controller) -> None:
        """Build ``c``'s readings of its last batch step from the arrays (then it is fresh):
        :func:`~playground.controller.crowd.readings.build_readings`."""
        i = self._member_of[c.body]
        nxt = self._views[i]
        c.stale = None
        self._unread[i] = False
        self._whole_step = False
        build_readings(c, i, nxt, self._last_ground)
