"""Recordings: every step of every tracked body, as CSV or NPZ, readable even after a crash.

One row per tracked body per step (long format): time (s), body, position (m), velocity (m/s),
angle (rad), the force readings raw and filtered (N), perceived gravity (m/s²) and the controller
state. A CSV file is flushed after every step; an NPZ file is rewritten atomically (a temporary
file, then ``os.replace``) every :data:`NPZ_EVERY` steps and when the recorder closes — and
:func:`recording` closes it in a ``finally``, so Ctrl-C still leaves a complete file. Floats are
written with ``repr``: a CSV reads back bit for bit.

>>> import tempfile, pathlib
>>> from playground.level import find, load
>>> from playground.scene import build
>>> scene = build(load(find("incline")))
>>> path = pathlib.Path(tempfile.mkdtemp()) / "incline.csv"
>>> with recording(scene, path):
...     scene.run(0.05)
>>> path.read_text().splitlines()[0].split(",")[:4]
['time', 'body', 'x', 'y']
"""

from __future__ import annotations

import csv
import math
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any

import numpy as np

from playground.scene import Scene
from playground.world import Stage, World

__all__ = ["COLUMNS", "NPZ_EVERY", "Recorder", "recording"]

COLUMNS = (
    "time",
    "body",
    "x",
    "y",
    "vx",
    "vy",
    "angle",
    "engine_x",
    "engine_y",
    "contact_x",
    "contact_y",
    "constraint_x",
    "constraint_y",
    "support_x",
    "support_y",
    "support_filtered_x",
    "support_filtered_y",
    "perceived_gravity_x",
    "perceived_gravity_y",
    "state",
)
"""The columns, in order; ``state`` is empty for a body without a controller."""

NPZ_EVERY = 1024
"""Steps between atomic rewrites of an NPZ recording."""

Row = tuple[float | str, ...]


class Recorder:
    """Writes one row per tracked body each step (OBSERVE stage) to ``path`` (.csv or .npz)."""

    def __init__(self, scene: Scene, path: str | os.PathLike[str]) -> None:
        self.scene = scene
        self.path = Path(path)
        suffix = self.path.suffix.lower()
        if suffix not in (".csv", ".npz"):
            raise ValueError(f"record: expected a file ending in .csv or .npz, got {self.path}")
        self._csv_file: IO[str] | None = None
        self._rows: list[Row] = []
        self._steps = 0
        self._closed = False
        if suffix == ".csv":
            self._csv_file = self.path.open("w", newline="", encoding="utf-8")
            self._csv = csv.writer(self._csv_file)
            self._csv.writerow(COLUMNS)
            self._csv_file.flush()
        scene.world.on(Stage.OBSERVE, self.observe)

    def _row(self, name: str) -> Row:
        scene = self.scene
        world = scene.world
        body = world.body(name)
        f = world.forces(name)
        perceiving = True
        try:
            pg = world.perceived_gravity(name)
        except KeyError:
            perceiving = False
        if not perceiving:
            pg = (math.nan, math.nan)
        sf = scene.support_filtered(name) if perceiving else (math.nan, math.nan)
        return (
            world.time,
            name,
            body.position.x,
            body.position.y,
            body.velocity.x,
            body.velocity.y,
            body.angle,
            *f.engine,
            *f.contact,
            *f.constraint,
            *f.support,
            *sf,
            *pg,
            scene.state(name) or "",
        )

    def observe(self, world: World) -> None:
        """Record the current step (a world hook)."""
        if self._closed:
            return
        rows = [self._row(name) for name in self.scene.tracked]
        self._steps += 1
        if self._csv_file is not None:
            self._csv.writerows(
                [repr(v) if isinstance(v, float) else v for v in row] for row in rows
            )
            self._csv_file.flush()
            return
        self._rows += rows
        if self._steps % NPZ_EVERY == 0:
            self._write_npz()

    def _write_npz(self) -> None:
        columns: dict[str, np.ndarray] = {}
        for i, name in enumerate(COLUMNS):
            values = [row[i] for row in self._rows]
            if name in ("body", "state"):
                columns[name] = np.array(values, dtype=np.str_)
            else:
                columns[name] = np.array(values, dtype=np.float64)
        tmp = self.path.with_name(self.path.name + ".partial")
        with tmp.open("wb") as fh:
            savez: Any = np.savez
            savez(fh, **columns)
        os.replace(tmp, self.path)

    def close(self) -> None:
        """Finish the file (idempotent)."""
        if self._closed:
            return
        self._closed = True
        if self._csv_file is not None:
            self._csv_file.close()
        else:
            self._write_npz()


@contextmanager
def recording(scene: Scene, path: str | os.PathLike[str]) -> Iterator[Recorder]:
    """Record ``scene`` to ``path`` while the block runs; the file is complete even if the block
    is interrupted (KeyboardInterrupt included)."""
    recorder = Recorder(scene, path)
    try:
        yield recorder
    finally:
        recorder.close()
