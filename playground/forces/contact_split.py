"""The contact split: how much of a body's engine force came from contacts, and so from joints.

The reverse-integration solver (:mod:`playground.forces.solver`) recovers the whole force the
engine applied to a body; this part sums the body's arbiter impulses over the step, and the rest
of the engine force is what joints did. :class:`ContactSplit` keeps those sums for the tracked
bodies and says on which steps they cannot be trusted.
"""

from __future__ import annotations

from collections import deque

import numpy as np
import pymunk
from numpy.typing import NDArray

from playground._engine.arbiters import ArbiterRows
from playground._engine.batch import lookup
from playground.forces.impulse_sums import ImpulseSums

__all__ = ["ContactSplit"]


class ContactSplit:
    """Per tracked body, the sum of its arbiter impulses over one step, and whether it is known.

    The sum is over ``Arbiter.total_impulse``: the impulses Chipmunk accumulated on the
    arbiter's contacts (``jnAcc``, ``jtAcc``). They are the impulses it applied, except in two
    cases read from its sources (``cpArbiter.c``, ``cpSpaceStep.c``):

    - *a contact made again while its arbiter is still cached.* An arbiter outlives its contact
      by ``space.collision_persistence`` steps. When the shapes touch again, ``cpArbiterUpdate``
      copies the accumulated impulses of the old contacts into the new ones, but the arbiter is
      a first contact, so ``cpArbiterApplyCachedImpulse`` does not apply them: the copied impulse
      is reported and never applied (on a box riding a platform that accelerates downward, one
      step in three read up to 5·m·g of "joint" force with no joint in the scene). The world
      sets ``collision_persistence`` to 1, so no arbiter outlives a step without contact; with a
      larger value, a first contact between two bodies that had an arbiter within that many
      steps (but not in the step before) makes the split of both unknown for the step.
    - *a warm start rescaled.* A continuing contact is warm-started with its accumulated impulse
      times h/h_prev when the substep length changes, while the accumulated impulse itself is
      not rescaled: on the first substep at a new length, bodies with a continuing contact get
      no split.

    Such a body's split is unknown for the step: NaN with ``valid`` False — never a wrong number.

    Attributes (one row per tracked body, in the solver's order):
        contact: Σ arbiter impulses / dt, N; (N, 2).
        contact_normal: the contact force's part along the contact normals, N; (N, 2).
        constraint: engine − contact: what joints did, N; (N, 2).
        valid: the split is known this step; (N,). Where it is not, the three above are NaN.
    """

    def __init__(self) -> None:
        self._arbiters = ArbiterRows()
        self._keys = np.zeros(0, dtype=np.uintp)  # sorted body ids of the tracked bodies
        self._key_row = np.zeros(0, dtype=np.intp)  # tracked row of each sorted id
        self.contact = np.full((0, 2), np.nan)
        self.contact_normal = np.full((0, 2), np.nan)
        self.constraint = np.full((0, 2), np.nan)
        self.valid = np.zeros(0, dtype=bool)
        # This step's sums: Σ impulses and their normal parts (N·s), and the rows whose sums
        # may hold an impulse the engine did not apply.
        self._sums = ImpulseSums()
        self._unknown = np.zeros(0, dtype=bool)
        # Body pairs with an arbiter in each recent substep: (substep stamp, sorted pair keys),
        # newest last, kept only while collision_persistence > 1.
        self._pairs: deque[tuple[int, NDArray[np.uint64]]] = deque()

    def add_row(self) -> None:
        """A body was tracked: a row at the end, unknown."""
        for name in ("contact", "contact_normal", "constraint"):
            setattr(self, name, np.vstack([getattr(self, name), np.full((1, 2), np.nan)]))
        self.valid = np.append(self.valid, False)

    def remove_row(self, row: int) -> None:
        """A body was untracked: its row goes, the rows after it move up by one."""
        for name in ("contact", "contact_normal", "constraint", "valid"):
            setattr(self, name, np.delete(getattr(self, name), row, axis=0))

    def reset(self, keys: NDArray[np.uintp], key_row: NDArray[np.intp]) -> None:
        """Start over for a new tracked set: ``keys`` its sorted body ids, ``key_row`` the
        tracked row of each."""
        self._keys = keys
        self._key_row = key_row
        self._sums.reset(keys, key_row)
        self._unknown = np.zeros(len(keys), dtype=bool)
        # The world may have stepped bare (nothing tracked) since the pairs were recorded.
        self._pairs.clear()

    def begin(self) -> None:
        """Zero the sums before a step."""
        self._sums.begin()
        self._unknown.fill(False)

    def accumulate(self, space: pymunk.Space, stamp: int, rescaled: bool) -> None:
        """Add one substep's arbiter impulses (see ``ForceSolver.after_substep`` for the args)."""
        arbiters = self._arbiters
        arbiters.read(space)
        pairs, first = arbiters.pairs, arbiters.first
        stale = self._stale(pairs, first, stamp, int(space.collision_persistence), rescaled)
        if stale is not None:
            for col in (0, 1):
                hit = lookup(self._keys, pairs[stale, col])
                self._unknown[self._key_row[hit[hit >= 0]]] = True
        if len(pairs):
            self._sums.add(pairs, arbiters.values)

    def finish(self, ok: NDArray[np.bool_], engine: NDArray[np.float64], dt: float) -> None:
        """The split of this step for the rows ``ok`` that have a reading (``engine``: (N, 2)
        engine forces, N; ``dt``: the step, s); the other rows keep their last values."""
        sums = self._sums.sums
        if ok.all():
            split = sums / dt
            self.contact = split[:, 0:2]
            self.contact_normal = split[:, 2:4]
            self.constraint = engine - self.contact
            self.valid = np.ones(len(ok), dtype=bool)
        else:
            rows_ok = np.nonzero(ok)[0]
            self.contact[rows_ok] = sums[rows_ok, 0:2] / dt
            self.contact_normal[rows_ok] = sums[rows_ok, 2:4] / dt
            self.constraint[rows_ok] = engine[rows_ok] - self.contact[rows_ok]
            self.valid[rows_ok] = True
        if not self._unknown.any():
            return
        unknown = np.nonzero(ok & self._unknown)[0]
        if len(unknown):
            for name in ("contact", "contact_normal", "constraint"):
                getattr(self, name)[unknown] = np.nan
            self.valid[unknown] = False

    def forget(self) -> None:
        """The split was turned off: every row unknown."""
        for name in ("contact", "contact_normal", "constraint"):
            getattr(self, name).fill(np.nan)
        self.valid.fill(False)

    def _stale(
        self,
        pairs: NDArray[np.uintp],
        first: NDArray[np.bool_],
        stamp: int,
        persistence: int,
        rescaled: bool,
    ) -> NDArray[np.bool_] | None:
        """Which arbiters may report an impulse Chipmunk did not apply (None: none may).

        See the class docstring. A cached arbiter was last in contact between ``persistence`` and
        2 steps ago; when the recorded pairs do not cover those steps (recording just began, or
        a substep was not recorded), every first contact is suspect.
        """
        stale = ~first if rescaled and len(pairs) else None
        if persistence < 2:
            self._pairs.clear()
            return stale
        lo = np.minimum(pairs[:, 0], pairs[:, 1]).astype(np.uint64)
        hi = np.maximum(pairs[:, 0], pairs[:, 1]).astype(np.uint64)
        keys = (lo << np.uint64(32)) | hi
        history = self._pairs
        if history and history[-1][0] != stamp - 1:
            history.clear()  # a gap: the substeps in between were not seen
        if first.any():
            since = max(1, stamp - persistence)
            fits = not (hi >> np.uint64(32)).any()  # ids too large for a key: suspect all
            covered = fits and (stamp <= 1 or (bool(history) and history[0][0] <= since))
            old = [k for s, k in history if s <= stamp - 2]
            if not covered:
                cached = first
            elif old:
                cached = first & np.isin(keys, np.concatenate(old))
            else:
                cached = np.zeros_like(first)
            stale = cached if stale is None else stale | cached
        history.append((stamp, keys))
        while history[0][0] < stamp - persistence:
            history.popleft()
        return stale if stale is not None and stale.any() else None
