"""``playground run LEVEL --profile`` (:mod:`playground.bench.profiler`): the stages that ran and
the top functions, as text and in the JSON report."""

from __future__ import annotations

import json
import re

import pytest

from playground.bench.profiler import TOP_FUNCTIONS
from playground.cli import main


def test_run_profile_prints_the_stages_and_the_top_functions(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """``playground run rest --profile``: after the checks, a row per stage that ran (with its
    calls: one per step) and the functions with the most own time, the world's among them."""
    assert main(["run", "rest", "--profile"]) == 0
    out = capsys.readouterr().out
    steps = re.search(r"(\d+) steps", out)
    assert steps is not None
    stages = out[out.index(f"stages over {steps[1]} steps") :]
    for stage in ("control", "physics", "forces", "filter"):
        assert re.search(rf"^{stage}\s+{steps[1]}\s", stages, re.MULTILINE), stage
    functions = out[out.index("top functions") :].splitlines()[3:]
    assert len(functions) == TOP_FUNCTIONS
    assert any("playground/" in line for line in functions)


def test_run_profile_json_holds_the_profile(capsys: pytest.CaptureFixture[str]) -> None:
    """With ``--json`` the profile is part of the one JSON object: stage shares sum to 1."""
    assert main(["run", "rest", "--profile", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    stages = {s["stage"]: s for s in report["profile"]["stages"]}
    assert stages["physics"]["calls"] == report["steps"]
    assert sum(s["share"] for s in stages.values()) == pytest.approx(1.0)
    assert len(report["profile"]["functions"]) == TOP_FUNCTIONS
