"""Laws of ``--set`` on the command line: ``check``, ``run`` and ``faults`` take the same
variant, what ``check`` accepts ``run`` runs, and a bad setting names the file and the key."""

from __future__ import annotations

import json

import pytest

from playground.cli import main

VARIANT = ["--set", "actors.player.controller.mass=140", "--set", "settings.substeps=2"]


def test_check_accepts_and_run_runs_the_same_variant(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "rest", *VARIANT]) == 0
    assert main(["run", "rest", "--json", *VARIANT]) == 0
    report = json.loads(capsys.readouterr().out.split("\n", 1)[1])
    assert report["set"] == ["actors.player.controller.mass=140", "settings.substeps=2"]
    assert report["bodies"]["player"]["mass"] == 140.0
    assert all(c["passed"] for c in report["checks"])


def test_faults_run_a_variant(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["faults", "rest", "--no-progress", *VARIANT]) == 0
    assert "all declared breaks caught" in capsys.readouterr().out


@pytest.mark.parametrize("command", ["check", "run", "faults"])
def test_a_bad_setting_names_the_file_and_the_key(
    command: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main([command, "rest", "--set", "settings.substeps=0"])
    assert code == (1 if command == "check" else 2)
    err = capsys.readouterr().err
    assert "rest.toml (with --set settings.substeps=0)" in err, err
    assert "settings.substeps: expected greater than or equal to 1" in err, err


def test_a_setting_that_is_not_one_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as info:
        main(["run", "rest", "--set", "substeps"])
    assert info.value.code == 2
    assert "--set: expected KEY.PATH=VALUE" in capsys.readouterr().err
