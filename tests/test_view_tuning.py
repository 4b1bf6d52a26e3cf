"""Laws of the live tuning panel: a slider moved with the mouse changes the hover spring, the 1€
filter or the step from the next step on; the hover frequency never passes its stability limit,
which the panel draws; R restores the level's values; a new dt continues time without a jump."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator

import numpy as np
import pygame
import pytest

from playground import World, WorldConfig
from playground.controller import hover_limit
from playground.view import App
from playground.view.draw import COLOURS
from playground.view.launcher import init_headless, show_level
from playground.view.tuning import SAFE_FRACTION, SLIDERS

SIZE = (1280, 720)
TOL_TIME_S = 1e-12
"""s: world time after a dt change is epoch + k·dt, a couple of roundings from the sum."""
COLOUR_TOL = 12  # per channel


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


def panel_app(level: str = "rest") -> App:
    app = App(show_level, level, size=SIZE)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_t, mod=0, unicode="t"))
    app.render()  # lays the panel out
    assert app.tuning.visible and app.tuning.rect.width > 0
    return app


def slide(app: App, field: str, fraction: float) -> None:
    """Press on ``field``'s track at ``fraction`` of its length, then release."""
    track = app.tuning._tracks[field]
    pos = (round(track.x + fraction * track.width), track.centery)
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=pos))
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=pos))


def test_hover_sliders_retune_the_players_spring_at_the_next_step() -> None:
    """Law: moving the hover frequency and damping sliders sets the controller's config and its
    spring constants k = m·(2πf)², c = 2ζ·m·2πf when the next frame runs — not before."""
    app = panel_app()
    ctrl = app.session.player
    before = ctrl.config.hover_frequency
    slide(app, "hover_frequency", 0.75)
    slide(app, "hover_damping", 0.25)
    assert ctrl.config.hover_frequency == before  # nothing applied until the next step
    app.frame(1.0 / 60.0)
    f, zeta = app.tuning.knobs.hover_frequency, app.tuning.knobs.hover_damping
    assert ctrl.config.hover_frequency == f != before
    assert ctrl.config.hover_damping == zeta == pytest.approx(0.5, abs=0.02)
    m, w = ctrl.config.mass, 2.0 * math.pi * f
    assert ctrl.hover_stiffness == pytest.approx(m * w * w, rel=1e-12)
    assert ctrl.hover_damping_coefficient == pytest.approx(2.0 * zeta * m * w, rel=1e-12)


def test_hover_frequency_stops_below_its_stability_limit_and_the_limit_is_drawn() -> None:
    """Law: at the largest dt and ζ = 0 the frequency slider pushed to its end stays below
    SAFE_FRACTION of the limit hover_limit(ζ)/(2π·dt), and the refused part of the track is
    drawn in the warning colour."""
    app = panel_app()
    slide(app, "hover_damping", 0.0)
    slide(app, "dt", 1.0)
    slide(app, "hover_frequency", 1.0)
    app.frame(1.0 / 60.0)
    dt = app.world.config.dt
    assert dt == pytest.approx(SLIDERS[4].high)
    ceiling = hover_limit(0.0) / (2.0 * math.pi * dt)
    f = app.session.player.config.hover_frequency
    assert f == pytest.approx(SAFE_FRACTION * ceiling, rel=1e-9)
    surf = app.render()
    track = app.tuning._tracks["hover_frequency"]
    x = track.x + SLIDERS[0].fraction(ceiling) * track.width
    stripe = pygame.surfarray.pixels3d(surf)[round(x) + 3 : track.right, track.y - 2].astype(int)
    near = np.abs(stripe - np.array(COLOURS["grip"])).max(axis=1) <= COLOUR_TOL
    assert near.mean() > 0.5


def test_one_euro_sliders_retune_the_filter_without_resetting_it() -> None:
    """Law: the 1€ sliders change the world's perception config and its filter's parameters;
    the filtered perceived gravity goes on from where it was (the filter keeps its state)."""
    app = panel_app()
    for _ in range(30):
        app.frame(1.0 / 60.0)
    before = app.world.perceived_gravity("player")
    slide(app, "min_cutoff", 0.9)
    slide(app, "beta", 0.5)
    app.frame(0.0)  # applies the knobs without a step
    p = app.world.config.perception
    assert p.min_cutoff == app.tuning.knobs.min_cutoff != 2.0
    assert p.beta == pytest.approx(0.5, abs=0.02)
    # The 1€ stage both implementations of the tracked bodies filter with.
    chain = app.world._physics.tracked._batch.perceived._filter
    one_euro = chain.stages[-1]
    assert (one_euro.min_cutoff, one_euro.beta) == (p.min_cutoff, p.beta)
    assert app.world.perceived_gravity("player") == before
    app.frame(1.0 / 60.0)
    # Still warm: a fresh filter's first output is its sample, −specific force.
    sx, sy = app.world.forces("player").specific
    assert app.world.perceived_gravity("player") != (-sx, -sy)


def test_dt_and_substeps_sliders_change_the_step_and_time_goes_on() -> None:
    """Law: the dt and substeps sliders set the world's config and the accumulator's step; the
    world's time continues from where it was at the new step."""
    app = panel_app()
    for _ in range(30):
        app.frame(1.0 / 60.0)
    t0 = app.world.time
    slide(app, "dt", 0.2)
    slide(app, "substeps", 1.0)
    app.frame(0.0)
    dt = app.world.config.dt
    assert dt == app.accumulator.dt == app.tuning.knobs.dt != 1.0 / 120.0
    assert app.world.config.substeps == SLIDERS[5].high
    steps = app.world.steps
    for _ in range(10):
        app.step()
    assert app.world.time == pytest.approx(t0 + (app.world.steps - steps) * dt, abs=TOL_TIME_S)


def test_r_restores_the_levels_values() -> None:
    """Law: after tuning, R restarts the level with its own values, and the panel shows them."""
    app = panel_app()
    level = app._knobs()
    slide(app, "dt", 0.9)
    slide(app, "hover_frequency", 0.1)
    app.frame(0.0)
    assert app._knobs() != level
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_r, mod=0, unicode="r"))
    assert app._knobs() == level
    assert app.tuning.knobs == level


def test_world_time_after_a_dt_change_is_epoch_plus_steps_times_dt() -> None:
    """Law: changing dt mid-run moves the time epoch; time never jumps and never drifts."""
    world = World(WorldConfig(dt=0.01))
    world.run(1.0)
    assert world.time == 1.0
    world.config = dataclasses.replace(world.config, dt=0.02)
    world.run(1.0)
    assert world.steps == 150
    assert world.time == pytest.approx(2.0, abs=TOL_TIME_S)


def test_a_held_slider_follows_the_drag_across_frames() -> None:
    """Law: pressed at 20 % of the hover damping track and dragged to 70 % with frames run in
    between (each applying the change), the slider ends where the mouse is (defect: applying a
    change dropped the held slider, so a drag stayed at its first value)."""
    app = panel_app()
    slider = next(s for s in SLIDERS if s.field == "hover_damping")
    track = app.tuning._tracks["hover_damping"]
    at = [round(track.x + f * track.width) for f in (0.2, 0.35, 0.5, 0.7)]
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=(at[0], track.centery)))
    for x in at[1:]:
        app.frame(1.0 / 60.0)
        app.render()
        move = pygame.event.Event(pygame.MOUSEMOTION, pos=(x, track.centery), buttons=(1, 0, 0))
        app.handle(move)
    app.frame(1.0 / 60.0)
    app.handle(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=(at[-1], track.centery)))
    expected = slider.value((at[-1] - track.x) / track.width)
    assert app.session.player.config.hover_damping == pytest.approx(expected, rel=1e-12)


def test_the_gravity_slider_scales_a_uniform_field_and_keeps_its_direction() -> None:
    """Law: the gravity slider at half its track sets a uniform field's magnitude to half the
    range, pointing the way it pointed, from the next step on; a level whose field is not
    uniform (planet) has no gravity knob."""
    from playground.gravity import Uniform

    app = panel_app()
    slider = next(s for s in SLIDERS if s.field == "gravity")
    slide(app, "gravity", 0.5)
    assert app.world.gravity.g == (0.0, -9.81)
    app.frame(1.0 / 60.0)
    field = app.world.gravity
    assert isinstance(field, Uniform)
    assert field.g[0] == 0.0 and field.g[1] == pytest.approx(-slider.value(0.5), rel=1e-12)
    assert panel_app("planet").tuning.knobs.gravity is None
