"""Recordings: every step of every tracked body, as CSV or NPZ, streamed to disk.

One row per tracked body per step (long format): time (s), body, position (m), velocity (m/s),
angle (rad), the force readings raw and filtered (N), perceived gravity (m/s²) and the controller
state. Memory stays bounded however long the run: each step's rows are written and flushed at
once, so a process killed at any moment (even by SIGKILL) leaves every complete step readable
with :func:`read`.

A CSV file is written row by row; floats are written with ``repr``, so it reads back bit for bit.
An NPZ file is a zip and cannot grow step by step: while recording, the rows go to
``FILE.npz.partial`` (a JSON header line, then one float64 record per row), and closing the
recorder turns it into ``FILE.npz`` — :func:`recording` closes it in a ``finally``, so Ctrl-C
still leaves a complete NPZ. After a kill, ``read("FILE.npz")`` reads the partial file. An
existing recording is never overwritten unless ``force`` is given.

>>> import tempfile, pathlib
>>> from playground.level import find, load
>>> from playground.scene import build
>>> scene = build(load(find("incline")))
>>> path = pathlib.Path(tempfile.mkdtemp()) / "incline.csv"
>>> with recording(scene, path):
...     scene.run(0.05)
>>> path.read_text().splitlines()[0].split(",")[:4]
['time', 'body', 'x', 'y']
>>> columns = read(path)
>>> len(columns["time"]), str(columns["body"][0])
(6, 'crate')
"""

from __future__ import annotations

import csv
import errno
import io
import json
import math
import os
import zipfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any

import numpy as np
from numpy.typing import NDArray

from playground.controller.states import State
from playground.quantities import RECORDED, Quantity, Value
from playground.scene import Scene
from playground.scene.readings import sample
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = ["COLUMNS", "PARTIAL", "Recorder", "check_output", "read", "recording"]

COLUMNS = ("time", "body", *(column for q in RECORDED for column in q.columns))
"""The columns, in order; ``state`` is empty for a body without a controller."""

TEXT_COLUMNS = ("body", *(c for q in RECORDED if q.kind == "text" for c in q.columns))
"""Columns of names; the partial file stores their index in the header's lists."""

PARTIAL = ".partial"
"""Suffix of the file an NPZ recording streams into until it is closed."""

BLOCK_ROWS = 8192
"""Rows converted at a time from the partial file into the NPZ (bounds the memory used)."""

_MAGIC = "playground-recording"
_STATES = ("", *(s.value for s in State))

Row = tuple[float | str, ...]


def check_output(path: str | os.PathLike[str], *, force: bool = False) -> Path:
    """The recording's path if it can be written: ``.csv`` or ``.npz``, in an existing folder, not
    already there (unless ``force``). Call it before a long run to fail at once.

    Raises ``ValueError`` for a wrong suffix and ``OSError`` (naming the file) otherwise.
    """
    p = Path(path)
    if p.suffix.lower() not in (".csv", ".npz"):
        raise ValueError(f"record: expected a file ending in .csv or .npz, got {str(p)!r}")
    folder = p.parent
    if not folder.is_dir():
        raise FileNotFoundError(errno.ENOENT, "no such folder", str(folder))
    if p.is_dir():
        raise IsADirectoryError(errno.EISDIR, "is a folder", str(p))
    if not force:
        for existing in (p, _partial(p)):
            # A dangling symlink counts: writing through it would create its target.
            if existing.exists() or existing.is_symlink():
                raise FileExistsError(
                    errno.EEXIST, "already exists (use --force to overwrite)", str(existing)
                )
    return p


def _partial(path: Path) -> Path:
    return path.with_name(path.name + PARTIAL)


class Recorder:
    """Writes one row per tracked body each step (OBSERVE stage) to ``path`` (.csv or .npz)."""

    def __init__(self, scene: Scene, path: str | os.PathLike[str], *, force: bool = False) -> None:
        self.scene = scene
        self.path = check_output(path, force=force)
        self.bodies = list(scene.tracked)
        self._closed = False
        self._csv_file: IO[str] | None = None
        self._raw: IO[bytes] | None = None
        if self.path.suffix.lower() == ".csv":
            self._csv_file = self.path.open("w", newline="", encoding="utf-8")
            self._csv_file.write(",".join(COLUMNS) + "\r\n")
            self._csv_file.flush()
        else:
            self._raw = _partial(self.path).open("wb")
            header = {"format": _MAGIC, "columns": COLUMNS, "bodies": self.bodies}
            self._raw.write(json.dumps({**header, "states": _STATES}).encode() + b"\n")
            self._raw.flush()
        scene.world.on(Stage.OBSERVE, self.observe)

    def _row(self, name: str) -> Row:
        scene = self.scene
        row: tuple[float | str, ...] = (scene.world.time, name)
        for q in RECORDED:
            row += _cells(q, sample(q, scene, name))
        return row

    def observe(self, world: World) -> None:
        """Record the current step (a world hook): one write and one flush per step."""
        if self._closed:
            return
        rows = [self._row(name) for name in self.bodies]
        if self._csv_file is not None:
            buffer: list[str] = []
            writer = csv.writer(_Lines(buffer))
            writer.writerows([repr(v) if isinstance(v, float) else v for v in row] for row in rows)
            self._csv_file.write("".join(buffer))
            self._csv_file.flush()
        elif self._raw is not None:
            record = np.array(
                [[self._code(i, v) for i, v in enumerate(row)] for row in rows], dtype="<f8"
            )
            self._raw.write(record.tobytes())
            self._raw.flush()

    def _code(self, column: int, value: float | str) -> float:
        if isinstance(value, str):
            names = self.bodies if COLUMNS[column] == "body" else _STATES
            return float(names.index(value))
        return value

    def close(self) -> None:
        """Finish the file (idempotent): an NPZ is written from the partial file, which goes."""
        if self._closed:
            return
        self._closed = True
        if self._csv_file is not None:
            self._csv_file.close()
        if self._raw is not None:
            self._raw.close()
            _npz_from_partial(_partial(self.path), self.path)
            _partial(self.path).unlink()


def _cells(q: Quantity, value: Value) -> Row:
    """A reading as its columns: NaN (numbers) or "" (text) where the body has none."""
    if value is None:
        return ("",) if q.kind == "text" else (math.nan,) * len(q.columns)
    return value if isinstance(value, tuple) else (value,)


class _Lines:
    """A file-like sink for ``csv.writer`` that collects the lines in a list."""

    def __init__(self, out: list[str]) -> None:
        self.out = out

    def write(self, line: str) -> int:
        self.out.append(line)
        return len(line)


@contextmanager
def recording(
    scene: Scene, path: str | os.PathLike[str], *, force: bool = False
) -> Iterator[Recorder]:
    """Record ``scene`` to ``path`` while the block runs; the file is complete even if the block
    is interrupted (KeyboardInterrupt included)."""
    recorder = Recorder(scene, path, force=force)
    try:
        yield recorder
    finally:
        recorder.close()


# -- reading -------------------------------------------------------------------------------------


def _open_partial(path: Path) -> tuple[io.BufferedReader, dict[str, Any], int]:
    """The partial file open after its header, the header, and its number of complete rows
    (whole steps only: a step cut by a kill is left out)."""
    fh = path.open("rb")
    header = json.loads(fh.readline())
    if header.get("format") != _MAGIC:
        fh.close()
        raise ValueError(f"{path}: not a playground recording")
    start = fh.tell()
    size = path.stat().st_size - start
    per_step = max(1, len(header["bodies"]))
    rows = size // (8 * len(COLUMNS)) // per_step * per_step
    return fh, header, rows


def _blocks(fh: io.BufferedReader, rows: int) -> Iterator[NDArray[np.float64]]:
    """The partial file's rows, ``BLOCK_ROWS`` at a time, read into one reused buffer (a fresh
    buffer per block would let the allocator's heap grow with the file)."""
    start = fh.tell()
    buffer = np.empty((BLOCK_ROWS, len(COLUMNS)), dtype="<f8")
    done = 0
    while done < rows:
        n = min(BLOCK_ROWS, rows - done)
        fh.readinto(buffer[:n].data.cast("B"))
        yield buffer[:n]
        done += n
    fh.seek(start)


def _npz_from_partial(partial: Path, out: Path) -> None:
    """Write the NPZ (one array per column) from the partial file, a block of rows at a time,
    into a temporary file that replaces ``out`` when complete."""
    fh, header, rows = _open_partial(partial)
    tmp = out.with_name(out.name + ".tmp")
    with fh, zipfile.ZipFile(tmp, "w", zipfile.ZIP_STORED, allowZip64=True) as zf:
        for i, name in enumerate(COLUMNS):
            dtype: np.dtype[Any]
            if name in TEXT_COLUMNS:
                names = header["bodies"] if name == "body" else header["states"]
                vocabulary = np.array(names, dtype=np.str_)
                dtype = vocabulary.dtype
            else:
                dtype = np.dtype("<f8")
            column = np.empty(BLOCK_ROWS, dtype=dtype)
            with zf.open(f"{name}.npy", "w", force_zip64=True) as member:
                np.lib.format.write_array_header_2_0(
                    member,
                    {
                        "descr": np.lib.format.dtype_to_descr(dtype),
                        "fortran_order": False,
                        "shape": (rows,),
                    },
                )
                for block in _blocks(fh, rows):
                    n = len(block)
                    if name in TEXT_COLUMNS:
                        np.take(vocabulary, block[:, i].astype(np.intp), out=column[:n])
                    else:
                        np.copyto(column[:n], block[:, i])
                    member.write(column[:n].data.cast("B"))
    os.replace(tmp, out)


def read(path: str | os.PathLike[str]) -> dict[str, NDArray[Any]]:
    """Every complete step of a recording, column by column (floats; ``body`` and ``state`` as
    strings). An NPZ recording still being written (or killed) is read from its partial file.

    Raises ``OSError`` if there is no such recording.
    """
    p = Path(path)
    if p.suffix.lower() == ".csv":
        return _read_csv(p)
    if p.exists():
        with np.load(p) as data:
            return {name: data[name] for name in COLUMNS}
    fh, header, rows = _open_partial(_partial(p))
    with fh:
        table = np.frombuffer(fh.read(rows * 8 * len(COLUMNS)), dtype="<f8")
    table = table.reshape(rows, len(COLUMNS))
    out: dict[str, NDArray[Any]] = {}
    for i, name in enumerate(COLUMNS):
        if name in TEXT_COLUMNS:
            names = header["bodies"] if name == "body" else header["states"]
            out[name] = np.array(names, dtype=np.str_)[table[:, i].astype(np.intp)]
        else:
            out[name] = table[:, i].copy()
    return out


def _read_csv(path: Path) -> dict[str, NDArray[Any]]:
    with path.open(newline="", encoding="utf-8") as fh:
        text = fh.read()
    # A kill may cut the last line, and the last step may lack some of its bodies.
    complete = text[: text.rfind("\n") + 1]
    rows = list(csv.reader(complete.splitlines()))[1:]
    if rows:
        first_step = sum(1 for r in rows if r[0] == rows[0][0])
        rows = rows[: len(rows) // first_step * first_step]
    out: dict[str, NDArray[Any]] = {}
    for i, name in enumerate(COLUMNS):
        values = [r[i] for r in rows]
        if name in TEXT_COLUMNS:
            out[name] = np.array(values, dtype=np.str_)
        else:
            out[name] = np.array([float(v) for v in values], dtype=np.float64)
    return out
