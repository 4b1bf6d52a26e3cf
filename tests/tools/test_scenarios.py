"""The settings guide's scenarios (:mod:`tools.scenarios`): a settings, perception,
controller and world knob each reach the built scene."""

from __future__ import annotations

from tools.guide_settings import KNOBS, Knob
from tools.scenarios import build_with


def _knob(name: str) -> Knob:
    return next(k for k in KNOBS if k.name == name)


def test_every_kind_of_knob_reaches_the_scene() -> None:
    """Law: a settings, perception, controller and world knob each change the built scene."""
    from playground.level import find, load

    level = load(find("rest"))
    cases = [
        ("sleep_time", 0.5, lambda sc: sc.world.config.sleep_time),
        ("dt", 1 / 60, lambda sc: sc.world.config.dt),
        ("d_cutoff", 5.0, lambda sc: sc.world.config.perception.d_cutoff),
        ("probe_radius", 0.2, lambda sc: sc.controllers["player"].config.probe_radius),
    ]
    for name, value, read in cases:
        assert read(build_with(level, _knob(name), value)) == value, name
        assert read(build_with(level, None, 0.0)) != value, name
