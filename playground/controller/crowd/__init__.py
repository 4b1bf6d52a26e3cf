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

The package, a concept a module: :mod:`~playground.controller.crowd.crowd` (:class:`Crowd`: its
step, read top-down), :mod:`~playground.controller.crowd.members` (who the members are, whether
the crowd runs them, their state between steps as arrays),
:mod:`~playground.controller.crowd.groups` (members sharing a config),
:mod:`~playground.controller.crowd.gravity` (the gravity they feel, on arrays),
:mod:`~playground.controller.crowd.grounds` (what the probes found),
:mod:`~playground.controller.crowd.step_up` (the tread ahead, on arrays),
:mod:`~playground.controller.crowd.acting` (deciding and acting, per config group),
:mod:`~playground.controller.crowd.readings` (the readings built when read) and
:mod:`~playground.controller.crowd.codes` (a member's state as a code).
"""

from playground.controller.crowd.crowd import Crowd
from playground.controller.crowd.members import CROWD_MIN_ACTORS

__all__ = ["CROWD_MIN_ACTORS", "Crowd"]
