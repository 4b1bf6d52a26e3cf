"""Laws of the installed tool: the wheel holds the package, its levels and its schema and none of
the repository's tooling (tools/: the page writers, the goals, the chapter figures); a
``pip install --user`` works from any directory, and so do a fresh venv's ``playground bench
overhead --quick`` and ``playground faults``.

The wheel is built without network (setuptools comes with the test extras) from a copy of the
files a build reads, so a stale ``build/`` folder in the checkout cannot leak into it. The user
install goes into a temporary user base with ``--no-deps``: its dependencies (pymunk, numpy,
pydantic) are taken from this environment's site-packages on ``PYTHONPATH``, so the test runs
offline, and it checks that ``playground`` itself is imported from the user base.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

import playground

ROOT = Path(__file__).resolve().parent.parent
BUILD_INPUTS = ("pyproject.toml", "README.md", "LICENSE", "playground", "levels")
"""What the build backend reads: everything else in a checkout stays out of the wheel."""


def _readme_levels() -> int:
    """The rows of the README's table of levels (``| `name` | ...``, after its header)."""
    lines = (Path(__file__).parent.parent / "README.md").read_text(encoding="utf-8").splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("| level | what it shows"))
    rows = 0
    for line in lines[start + 2 :]:
        if not line.startswith("| `"):
            break
        rows += 1
    return rows


SHIPPED_LEVELS = _readme_levels()
"""The README's table of levels."""


def _run(*cmd: str | Path, cwd: Path, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    done = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True, check=False
    )
    assert done.returncode in (0, 1), f"{cmd}: exit {done.returncode}\n{done.stderr}"
    return done


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The project's wheel, built offline from a clean copy of its sources."""
    src = tmp_path_factory.mktemp("src")
    for name in BUILD_INPUTS:
        origin = ROOT / name
        if origin.is_dir():
            shutil.copytree(origin, src / name, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            shutil.copy2(origin, src / name)
    out = tmp_path_factory.mktemp("dist")
    env = {**os.environ, "PIP_NO_INDEX": "1"}
    _run(
        sys.executable,
        "-m",
        "pip",
        "wheel",
        "-q",
        "--no-deps",
        "--no-build-isolation",
        "-w",
        out,
        src,
        cwd=src,
        env=env,
    )
    (built,) = out.glob("pymunk_playground-*.whl")
    return built


def test_wheel_holds_every_subpackage_the_levels_and_the_schema(wheel: Path) -> None:
    """Every package of the source tree, py.typed, the 17 levels and the schema are in the
    wheel, under the distribution name ``pymunk-playground`` with its license file."""
    names = set(zipfile.ZipFile(wheel).namelist())
    packages = {
        p.parent.relative_to(ROOT).as_posix() for p in (ROOT / "playground").rglob("__init__.py")
    }
    for package in packages:
        assert f"{package}/__init__.py" in names, f"{package} is missing from the wheel"
    assert "playground/py.typed" in names
    assert "playground/levels/level.schema.json" in names
    levels = [n for n in names if n.startswith("playground/levels/") and n.endswith(".toml")]
    assert len(levels) == SHIPPED_LEVELS
    info = f"pymunk_playground-{playground.__version__}.dist-info"
    assert f"{info}/licenses/LICENSE" in names
    metadata = zipfile.ZipFile(wheel).read(f"{info}/METADATA").decode()
    assert "Name: pymunk-playground" in metadata
    assert "Classifier: Typing :: Typed" in metadata


def test_wheel_holds_none_of_the_repositorys_tools(wheel: Path) -> None:
    """Nothing of tools/ is in the wheel, under its own name or where the page writers, the goals
    and the figures were (``playground/bench/``, ``playground/figures/``)."""
    names = set(zipfile.ZipFile(wheel).namelist())
    assert not [n for n in names if n.startswith(("tools/", "playground/figures/"))]
    pages = {p.name for p in (ROOT / "tools").glob("*.py")} - {
        "__init__.py",
        "__main__.py",
        "cli.py",
    }
    assert {
        "goals.py",
        "performance_page.py",
        "accuracy_page.py",
        "guide.py",
        "stability.py",
    } <= pages
    bench = {
        n.removeprefix("playground/bench/") for n in names if n.startswith("playground/bench/")
    }
    assert not pages & bench, sorted(pages & bench)


def _clean_env() -> dict[str, str]:
    """This environment without its Python settings, offline: nothing points back at the
    checkout."""
    env = {
        k: v
        for k, v in os.environ.items()
        if k not in ("PYTHONPATH", "PYTHONHOME", "PYTHONNOUSERSITE", "VIRTUAL_ENV")
    }
    return env | {"PIP_NO_INDEX": "1"}


def test_a_fresh_venv_runs_the_benchmark_and_the_faults(wheel: Path, tmp_path: Path) -> None:
    """The wheel alone, in a fresh venv, from an empty directory: ``playground bench overhead
    --quick`` prints its tables and ``playground faults`` catches every declared break — nothing
    they run is left in the repository's tools/."""
    venv, elsewhere = tmp_path / "venv", tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = _clean_env()
    _run(_base_python(), "-m", "venv", "--without-pip", venv, cwd=elsewhere, env=env)
    python = venv / "bin" / "python"
    _run(sys.executable, "-m", "pip", "--python", python, "install", "-q", "--no-deps", wheel,
         cwd=elsewhere, env=env)  # fmt: skip
    # The dependencies (pymunk, numpy, pydantic, tqdm) come from this environment, offline.
    env["PYTHONPATH"] = sysconfig.get_paths()["purelib"]
    where = _run(python, "-c", "import playground; print(playground.__file__)", cwd=elsewhere,
                 env=env)  # fmt: skip
    assert Path(where.stdout.strip()).is_relative_to(venv)
    command = venv / "bin" / "playground"
    bench = _run(command, "bench", "overhead", "--quick", "--no-progress", cwd=elsewhere, env=env)
    assert bench.returncode == 0, bench.stderr
    assert "## Every shipped level" in bench.stdout and "| rest |" in bench.stdout
    faults = _run(command, "faults", "--no-progress", cwd=elsewhere, env=env)
    assert faults.returncode == 0, faults.stdout[-500:] + faults.stderr
    assert "all declared breaks caught" in faults.stdout


def _base_python() -> str:
    """The interpreter this venv was made from: a venv hides the user site, its base does not."""
    base: str = getattr(sys, "_base_executable", sys.executable)
    return base


def test_user_install_works_from_an_unrelated_directory(wheel: Path, tmp_path: Path) -> None:
    """``pip install --user`` into a fresh user base; from an empty directory ``playground list``
    shows the 17 levels, ``playground run rest --json`` passes, and ``python -m playground
    --version`` prints the version — all from the user base, not from this checkout."""
    userbase = tmp_path / "userbase"
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    deps = sysconfig.get_paths()["purelib"]
    env = _clean_env() | {"PYTHONUSERBASE": str(userbase)}
    # A distribution's Python may forbid --user installs (PEP 668); this one is a throwaway.
    env["PIP_BREAK_SYSTEM_PACKAGES"] = "1"
    python = _base_python()
    _run(
        sys.executable,
        "-m",
        "pip",
        "--python",
        python,
        "install",
        "-q",
        "--user",
        "--no-deps",
        wheel,
        cwd=elsewhere,
        env=env,
    )
    env["PYTHONPATH"] = deps
    env["PATH"] = os.pathsep.join([str(userbase / "bin"), env.get("PATH", "")])
    where = _run(
        python, "-c", "import playground; print(playground.__file__)", cwd=elsewhere, env=env
    )
    assert Path(where.stdout.strip()).is_relative_to(userbase)

    command = shutil.which("playground", path=str(userbase / "bin"))
    assert command is not None, "the console script is not in the user base's bin"
    listing = _run(command, "list", cwd=elsewhere, env=env)
    names = [line.split()[0] for line in listing.stdout.splitlines() if line.strip()]
    assert len(names) == SHIPPED_LEVELS and "rest" in names and "sandbox" in names

    report = _run(command, "run", "rest", "--json", cwd=elsewhere, env=env)
    assert report.returncode == 0, report.stderr
    checks = json.loads(report.stdout)["checks"]
    assert checks and all(c["passed"] for c in checks)

    version = _run(python, "-m", "playground", "--version", cwd=elsewhere, env=env)
    assert version.stdout.strip() == f"playground {playground.__version__}"
