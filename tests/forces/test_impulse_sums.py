"""Laws of the arbiter sums read at once: on random piles, every tracked body's sums from one read
of every arbiter, in numpy (:class:`ImpulseSums`, the batch implementation) and in plain floats
(:class:`ContactSums` above its crossover, the scalar one, through the compiled helper of
:mod:`playground._engine.impulses` where it was built and through its Python fallback), equal the
sums of the walk over each body's arbiters (:class:`ContactSums` below it) bit for bit, substep
after substep."""

from __future__ import annotations

import math
import random
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager

import numpy as np
import pymunk
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from playground._engine import impulses
from playground._engine.arbiters import ArbiterRows
from playground.forces.impulse_sums import ImpulseSums
from playground.forces.scalar import contacts
from playground.forces.scalar.contacts import ContactSums
from playground.forces.scalar.row import Row

STEPS = 40
"""Steps of each random pile: bodies dropped from up to 3 m land, stack and push each other."""

EXAMPLES = 40
"""Random piles per run."""


def _pile(seed: int, bodies: int, spread: float) -> tuple[pymunk.Space, list[pymunk.Body]]:
    """Boxes and balls of random sizes and masses dropped over a floor between two walls, in
    ``spread`` metres: the narrower, the more of them rest on two or more others."""
    rng = random.Random(seed)
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    space.collision_persistence = 1
    for a, b in (((-spread, 0.0), (spread, 0.0)), ((-spread, 0.0), (-spread, 9.0)),
                 ((spread, 0.0), (spread, 9.0))):  # fmt: skip
        wall = pymunk.Segment(space.static_body, a, b, 0.05)
        wall.friction = 0.8
        space.add(wall)
    dynamic = []
    for _ in range(bodies):
        m = rng.uniform(0.2, 5.0)
        if rng.random() < 0.5:
            w, h = rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8)
            body = pymunk.Body(m, pymunk.moment_for_box(m, (w, h)))
            shape: pymunk.Shape = pymunk.Poly.create_box(body, (w, h))
        else:
            r = rng.uniform(0.1, 0.4)
            body = pymunk.Body(m, pymunk.moment_for_circle(m, 0.0, r))
            shape = pymunk.Circle(body, r)
        body.position = (rng.uniform(-spread + 0.5, spread - 0.5), rng.uniform(0.5, 3.0))
        body.angle = rng.uniform(0.0, math.pi)
        shape.friction = rng.uniform(0.0, 1.0)
        space.add(body, shape)
        dynamic.append(body)
    return space, dynamic


def _arbiter_count(body: pymunk.Body) -> int:
    arbiters: list[pymunk.Arbiter] = []
    body.each_arbiter(arbiters.append)
    return len(arbiters)


@contextmanager
def _crossover(min_rows: int, bodies_per_row: int) -> Iterator[None]:
    """The scalar contact sums' crossover set for the block (hypothesis runs many examples in one
    test, so not pytest's monkeypatch)."""
    saved = contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW
    contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW = min_rows, bodies_per_row
    try:
        yield
    finally:
        contacts.ONE_READ_MIN_ROWS, contacts.ONE_READ_BODIES_PER_ROW = saved


def _walking() -> AbstractContextManager[None]:
    return _crossover(10**9, 0)  # never one read: every row's arbiters walked


def _one_read() -> AbstractContextManager[None]:
    return _crossover(1, 10**9)  # always one read


@contextmanager
def _by_python() -> Iterator[None]:
    """The one read summed by the Python fallback of :mod:`playground._engine.impulses`, as where
    its compiled helper was not built."""
    saved = impulses._sums_c
    impulses._sums_c = None
    try:
        yield
    finally:
        impulses._sums_c = saved


def _bits(x: float) -> str:
    return float(x).hex()


def _compare(seed: int, bodies: int, spread: float, substeps: int, tracked_share: float) -> int:
    """Step a random pile, comparing the two sums after every substep; the substeps in which
    some tracked body had three or more terms."""
    space, dynamic = _pile(seed, bodies, spread)
    rng = random.Random(seed + 1)
    tracked = [b for b in dynamic if rng.random() < tracked_share] or dynamic[:1]
    ids = np.array([b.id for b in tracked], dtype=np.uintp)
    order = np.argsort(ids)
    batch = ImpulseSums()
    batch.reset(ids[order], order.astype(np.intp))
    arbiters = ArbiterRows()
    rows = [Row(b) for b in tracked]
    scalar = ContactSums()
    one_read, one_rows = ContactSums(), [Row(b) for b in tracked]
    fallback, fallback_rows = ContactSums(), [Row(b) for b in tracked]
    h = 1.0 / 120.0 / substeps
    stamp = heaped = 0
    for _ in range(STEPS):
        batch.begin()
        for r in (*rows, *one_rows, *fallback_rows):
            r.j = (0.0, 0.0, 0.0, 0.0)
        for sub in range(substeps):
            space.step(h)
            stamp += 1
            with _walking():
                scalar.accumulate(rows, space, stamp, rescaled=False)
            with _one_read():
                one_read.accumulate(one_rows, space, stamp, rescaled=False, fresh=sub == 0)
                with _by_python():
                    fallback.accumulate(fallback_rows, space, stamp, rescaled=False, fresh=sub == 0)
            arbiters.read(space)
            if len(arbiters.pairs):
                batch.add(arbiters.pairs, arbiters.values)
            for i, (r, q, p) in enumerate(zip(rows, one_rows, fallback_rows, strict=True)):
                want = [_bits(v) for v in r.j]
                assert [_bits(v) for v in batch.sums[i]] == want, (stamp, i)
                assert [_bits(v) for v in q.j] == want, (stamp, i)
                assert [_bits(v) for v in p.j] == want, (stamp, i)
            heaped += max(_arbiter_count(r.body) for r in rows) >= 3
    return heaped


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    seed=st.integers(0, 2**32 - 1),
    bodies=st.integers(1, 30),
    spread=st.floats(1.0, 6.0),
    substeps=st.integers(1, 3),
    tracked_share=st.floats(0.3, 1.0),
)
def test_batch_sums_equal_the_scalar_sums(
    seed: int, bodies: int, spread: float, substeps: int, tracked_share: float
) -> None:
    """Law: with some of a random pile's bodies tracked, after every substep each tracked body's
    Σ jx, jy, jnx, jny from one batch read of every arbiter equals, bit for bit, the sum the
    scalar implementation reads body by body (each body's terms in value order, summed over the
    step's substeps)."""
    _compare(seed, bodies, spread, substeps, tracked_share)


def test_a_narrow_pile_sorts_bodies_with_three_terms_or_more() -> None:
    """Law: the sums agree where the batch side must sort a body's terms, on a step's later
    substeps (two terms) and on a body resting on two others (three or more)."""
    assert _compare(seed=3, bodies=30, spread=1.2, substeps=3, tracked_share=1.0) > STEPS
