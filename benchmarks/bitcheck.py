"""The bit-for-bit check of every shipped level: record each level's run, every step, and hash it.

A change that must not alter behaviour (a refactor, a fast path) runs this before and after and
compares the two digest files; any difference names the level.

    python benchmarks/bitcheck.py --out before.json          # on the base commit
    python benchmarks/bitcheck.py --out after.json --against before.json

Each level is run as a user runs it, ``playground run NAME --record FILE.csv --json``; the digest
covers the recording (every step, every column) and the JSON summary without its wall-clock time.
Exit status: 0 identical, 1 a level differs, 2 bad arguments.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys
import tempfile
from pathlib import Path


def shipped_levels() -> list[str]:
    """The names that ``playground list`` prints, in its order."""
    out = subprocess.run(
        [sys.executable, "-m", "playground", "list"], check=True, capture_output=True, text=True
    ).stdout
    return [line.split()[0] for line in out.splitlines() if line.strip()]


def digest(level: str, folder: Path) -> str:
    """The SHA-256 of one level's recording and JSON summary (wall time left out)."""
    csv = folder / f"{level}.csv"
    command = ["run", level, "--record", str(csv), "--force", "--no-progress", "--json"]
    run = subprocess.run(
        [sys.executable, "-m", "playground", *command],
        capture_output=True,
        text=True,
    )
    summary = json.loads(run.stdout) if run.stdout.strip().startswith("{") else {"raw": run.stdout}
    summary.pop("wall_seconds", None)
    h = hashlib.sha256()
    h.update(csv.read_bytes() if csv.exists() else b"no recording")
    h.update(json.dumps(summary, sort_keys=True).encode())
    h.update(str(run.returncode).encode())
    return h.hexdigest()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="write the digests here (JSON)")
    parser.add_argument("--against", type=Path, help="compare with an earlier --out file")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        digests = {level: digest(level, Path(tmp)) for level in shipped_levels()}
    args.out.write_text(json.dumps(digests, indent=2) + "\n")
    if args.against is None:
        print(f"{len(digests)} levels hashed into {args.out}")
        return 0
    before = json.loads(args.against.read_text())
    # A level that is new since the earlier file has nothing to be identical to: it is listed,
    # not failed. A level that differs, or one that is gone, fails the comparison.
    for level in sorted(digests.keys() - before.keys()):
        print(f"NEW {level}")
    differ = sorted(k for k in before if before[k] != digests.get(k))
    for level in differ:
        print(f"DIFFERS {level}" if level in digests else f"GONE {level}")
    print("IDENTICAL" if not differ else f"{len(differ)} of {len(before)} levels differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
