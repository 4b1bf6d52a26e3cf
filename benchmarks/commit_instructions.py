"""A level's step in instructions at each of several commits: which commit changed its cost.

For each commit a detached worktree is made under a temporary folder, its optional C helpers
built in place where it has them (``build_ext --inplace``: a tree without them answers through
its Python fallbacks and counts far more), and a child that builds the level as ``playground
run`` does and steps it is run under callgrind twice, with 0 and with ``--steps`` steps, from
the commit's tree (its library and its levels: ``PYTHONPATH``, ``PLAYGROUND_LEVELS``, working
directory). The difference of the two totals over the steps is one step's instructions, free of
imports and of building the level; a count, not a time, so it holds on a loaded machine.

    python benchmarks/commit_instructions.py --levels rest gravity_leap \\
        --commits 7ac9adb^ 7ac9adb 9201b57^ 9201b57

Columns: commit, level, instructions a step, and the change from the row before it (same
level). Needs valgrind; about half a minute a commit and level.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

_CHILD = """
import gc, sys
from playground.level import find, load
from playground.scene import build
world = build(load(find(sys.argv[1]))).world
gc.collect()
gc.disable()
for _ in range(int(sys.argv[2])):
    world.step()
"""

_TOTAL = re.compile(r"^summary:\s+(\d+)", re.MULTILINE)


def _instructions(tree: Path, level: str, steps: int) -> int:
    """callgrind's instruction total of the child stepping ``level`` ``steps`` times."""
    with tempfile.TemporaryDirectory() as out:
        env = {
            **os.environ,
            "PYTHONPATH": str(tree),
            "PLAYGROUND_LEVELS": str(tree / "levels"),
            "PYTHONHASHSEED": "0",
            "OPENBLAS_NUM_THREADS": "1",
        }
        subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}/cg.out",
             sys.executable, "-c", _CHILD, level, str(steps)],
            check=True, capture_output=True, cwd=tree, env=env,
        )  # fmt: skip
        match = _TOTAL.search(Path(out, "cg.out").read_text())
        assert match, "callgrind wrote no summary"
        return int(match.group(1))


def _tree(repo: Path, commit: str, folder: Path) -> Path:
    """A detached worktree of ``commit`` with its C helpers built in place (where it has any)."""
    tree = folder / commit.replace("^", "_parent").replace("/", "_")
    subprocess.run(
        ["git", "-C", str(repo), "worktree", "add", "-q", "--detach", str(tree), commit],
        check=True,
    )
    if list((tree / "playground" / "_engine").glob("*.c")):
        subprocess.run(
            [sys.executable, "-c", "from setuptools import setup; setup()",
             "build_ext", "--inplace", "-q"],
            check=True, capture_output=True, cwd=tree,
        )  # fmt: skip
    return tree


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--commits", nargs="+", required=True, help="commits, in order")
    parser.add_argument("--levels", nargs="+", default=["rest"])
    parser.add_argument("--steps", type=int, default=600)
    parser.add_argument("--repo", type=Path, default=Path(__file__).resolve().parents[1])
    args = parser.parse_args()
    last: dict[str, int] = {}
    with tempfile.TemporaryDirectory(prefix="commit-instructions-") as tmp:
        try:
            for commit in args.commits:
                tree = _tree(args.repo, commit, Path(tmp))
                for level in args.levels:
                    base = _instructions(tree, level, 0)
                    per_step = (_instructions(tree, level, args.steps) - base) // args.steps
                    before = last.get(level)
                    change = f"{100.0 * (per_step / before - 1.0):+.1f} %" if before else ""
                    last[level] = per_step
                    print(f"{commit:12s} {level:16s} {per_step:10d}  {change}", flush=True)
        finally:
            subprocess.run(["git", "-C", str(args.repo), "worktree", "prune"], check=False)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
