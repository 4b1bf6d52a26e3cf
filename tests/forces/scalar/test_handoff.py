"""Laws of the hand-off between the implementations: the state loaded from the batch one and stored
back is the state it had, readings, split, recent pairs and filter included."""

from __future__ import annotations

import numpy as np

from playground import World, WorldConfig
from playground.filters.chain import FilterChain
from playground.forces.batch import BatchBodies
from playground.forces.scalar import handoff
from playground.gravity import Perception


def _batch(world: World) -> BatchBodies:
    """The world's batch implementation (it holds the arrays whether it serves or not)."""
    batch = world._physics.tracked._batch
    assert isinstance(batch, BatchBodies)
    return batch


def _arrays(world: World) -> dict[str, object]:
    solver, perceived = _batch(world).solver, _batch(world).perceived
    chain = perceived._filter
    stages = chain.stages if isinstance(chain, FilterChain) else (chain,)
    out: dict[str, object] = {
        name: np.copy(getattr(solver, name))
        for name in ("_engine3", "_support3", "_specific2", "_passive3", "_applied3", "valid",
                     "contact", "contact_normal", "constraint", "split_valid")
    }  # fmt: skip
    out["gravity"], out["up"] = np.copy(perceived.gravity), np.copy(perceived.up)
    out["pairs"] = [
        (s, set(k.tolist())) for s, k in solver._split._pairs
    ]  # order and repeats: no matter
    for i, stage in enumerate(stages):
        for name in ("_xh", "_dxh", "_s0", "_s1", "_s2", "_init"):
            if hasattr(stage, name):
                out[f"{i}{name}"] = np.copy(getattr(stage, name))
    return out


def _equal(a: dict[str, object], b: dict[str, object]) -> bool:
    return a.keys() == b.keys() and all(
        np.array_equal(a[k], b[k], equal_nan=True) if isinstance(a[k], np.ndarray) else a[k] == b[k]
        for k in a
    )


def test_load_then_store_gives_back_the_state() -> None:
    """Law: on a world run on the batch implementation (split on, arbiters kept three steps, a
    median-of-3 before the 1€), loading and storing changes no array; the rows hold the values
    the arrays hold."""
    world = World(WorldConfig(contact_split=True, perception=Perception(spike_filter=True)))
    world.space.collision_persistence = 3
    world.scalar_max_bodies = 0
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    for i in range(3):
        world.add_box(f"b{i}", mass=1.0 + i, size=(0.5, 0.5), position=(0.0, 0.3 + 0.6 * i))
    world.track(*world.names)
    world.run(0.5)
    before = _arrays(world)
    assert before["pairs"]  # the recent pairs are there to move
    solver, perceived = _batch(world).solver, _batch(world).perceived
    rows, _, median, history = handoff.load(solver, perceived)
    assert median
    assert [(r.ex, r.ey, r.split) for r in rows] == [
        (float(e[0]), float(e[1]), bool(v))
        for e, v in zip(solver.engine, solver.split_valid, strict=True)
    ]
    handoff.store(rows, history, solver, perceived)
    assert _equal(_arrays(world), before)
