"""Laws of the drawing, tested on the pixels a user sees: a capsule keeps its area and its outline
at every angle, a one-step force spike between two drawn frames is still drawn, the scope's m·g
line survives a spike, the legend lists only what is on screen."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pygame
import pymunk
import pytest
from numpy.typing import NDArray

from playground import Category, Stage, World
from playground.view import App, Camera, Show
from playground.view.arrows import arrow_length, body_size, weight_pixels
from playground.view.draw import COLOURS, draw_world
from playground.view.launcher import init_headless
from playground.view.scope import LINE_MG, Scope, draw_scope

SIZE = (640, 360)
TOL_AREA = 0.03  # relative: the bound on a capsule's pixel area across angles
ANGLES_DEG = (0.0, 30.0, 45.0, 90.0, 135.0)
OUTLINE_PX = 2  # px: an anti-aliased 1 px edge off the pixel grid spreads over two pixels
G = 9.81


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


def _capsule_pixels(angle_deg: float) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """A 1.2 m capsule of radius 0.3 m at 100 px/m turned by ``angle_deg``: (drawn, fill) masks."""
    w = World()
    # Static: a kinematic body would also get its spoke drawn over the fill.
    body = pymunk.Body(body_type=pymunk.Body.STATIC)
    body.angle = math.radians(angle_deg)
    w.add("capsule", body, pymunk.Segment(body, (-0.6, 0.0), (0.6, 0.0), 0.3))
    surf = pygame.Surface((300, 300))
    bg = COLOURS["background"]
    surf.fill(bg)
    draw_world(surf, Camera(size=(300, 300), pixels_per_metre=100.0), w)
    arr = pygame.surfarray.array3d(surf).astype(int)
    drawn = np.abs(arr - np.array(bg)).max(axis=2) > 0
    fill_colour = np.array([int(c * 0.45) for c in COLOURS["static"]])
    fill = np.abs(arr - fill_colour).max(axis=2) == 0
    return drawn, fill


def _touching(mask: NDArray[np.bool_], px: int = 1) -> NDArray[np.bool_]:
    """Pixels within ``px`` 4-neighbour steps of ``mask`` (not counting ``mask`` itself)."""
    grown = mask.copy()
    for _ in range(px):
        out = grown.copy()
        out[1:, :] |= grown[:-1, :]
        out[:-1, :] |= grown[1:, :]
        out[:, 1:] |= grown[:, :-1]
        out[:, :-1] |= grown[:, 1:]
        grown = out
    return grown & ~mask


def test_capsule_keeps_its_area_and_its_outline_at_every_angle() -> None:
    """Law: a capsule turned by 0°, 30°, 45°, 90° and 135° covers the same pixel area (within 3 %)
    and its outline lies on its fill: every outline pixel touches the fill, and no fill pixel
    touches the background (the outline closes around it, round ends included)."""
    areas = []
    for angle in ANGLES_DEG:
        drawn, fill = _capsule_pixels(angle)
        outline = drawn & ~fill
        assert fill.sum() > 0 and outline.sum() > 0, angle
        off = outline & ~_touching(fill, OUTLINE_PX)
        assert not off.any(), f"outline off the fill at {angle}°"
        assert not (fill & _touching(~drawn)).any(), f"fill meets the background at {angle}°"
        areas.append(int(drawn.sum()))
    expected = 120 * 60 + math.pi * 30**2  # px: the capsule's true area
    assert max(areas) / min(areas) - 1.0 <= TOL_AREA, areas
    assert abs(np.mean(areas) / expected - 1.0) <= TOL_AREA, (areas, expected)


# -- a one-step spike between two drawn frames --------------------------------------------------

SPIKE_WEIGHTS = 20.0  # the one-step push down, in weights
SPIKE_STEP = 61  # an odd step: not the last of a frame at two steps per frame


def _spike_show(name: str) -> Show:
    w = World()
    w.add_static_segment((-5.0, 0.0), (5.0, 0.0), radius=0.0)
    w.add_box("box", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    w.track("box")

    def kick(world: World) -> None:
        if world.steps + 1 == SPIKE_STEP:
            world.apply_force("box", (0.0, -SPIKE_WEIGHTS * 10.0 * G), category=Category.APPLIED)

    w.on(Stage.CONTROL, kick)
    return Show(name=name, world=w, title="Spike", follow="box", pixels_per_metre=40.0)


def _support_reach(app: App) -> float:
    """How far above the box's centre the raw support colour reaches, px."""
    arr = pygame.surfarray.array3d(app.render()).astype(int)
    hit = np.abs(arr - np.array(COLOURS["support"])).max(axis=2) <= 8
    body = app.world.body("box")
    cx, cy = app.camera.to_screen((body.position.x, body.position.y))
    band = hit[int(cx) - 15 : int(cx) + 15, :]
    rows = np.nonzero(band.any(axis=0))[0]
    return float(cy - rows.min()) if rows.size else 0.0


def test_a_one_step_spike_on_an_odd_step_is_drawn() -> None:
    """Law: a force spike lasting one physics step that is not the last step of a drawn frame
    still appears in that frame: the raw support arrow reaches past three weights (it is one
    weight long at rest, and the step the frame ends on is back to rest)."""
    app = App(_spike_show, "spike", size=SIZE)
    assert app.world.config.dt == pytest.approx(1.0 / 120.0)
    while app.world.steps < SPIKE_STEP - 1:
        app.frame(1.0 / 60.0)
        app.render()
    rest = _support_reach(app)
    app.frame(1.0 / 60.0)
    assert app.world.steps > SPIKE_STEP, "the spike must not be the frame's last step"
    assert math.hypot(*app.world.forces("box").support) < 1.5 * 10.0 * G
    body = app.world.body("box")
    w_px = weight_pixels(body_size(body), app.camera.zoom)
    assert rest == pytest.approx(w_px, abs=12.0)
    spike = _support_reach(app)
    assert spike >= arrow_length(3.0 * 10.0 * G, 10.0, w_px), (rest, spike)


# -- the scope -----------------------------------------------------------------------------------

MIN_MG_HEIGHT = 0.2  # the m·g line's least height in the scope, as a fraction (the bound)


def test_scope_mg_line_stays_up_after_a_spike() -> None:
    """Law: after a 10·m·g one-step spike (raw and filtered alike, the worst case) the scope's
    m·g line stays above 20 % of its height, and the spike is drawn clipped at the top."""
    mg = 70.0 * G
    scope = Scope(seconds=4.0, dt=1.0 / 120.0, name="player", weight=mg)
    for k in range(480):
        v = 10.0 * mg if k == 300 else mg
        scope.push(v, v)
    surf = pygame.Surface((800, 120))
    surf.fill((0, 0, 0))
    rect = pygame.Rect(0, 0, 800, 120)
    font = pygame.font.Font(None, 20)
    layout = draw_scope(surf, font, scope, rect)
    assert layout.top < 10.0 * mg
    arr = pygame.surfarray.array3d(surf).astype(int)
    line = np.abs(arr - np.array(LINE_MG)).max(axis=2) == 0
    rows = np.nonzero(line[400:700, :].sum(axis=0) > 100)[0]
    assert rows.size == 1, rows
    plot_top, plot_bottom = layout.plot.top, layout.plot.bottom
    height = (plot_bottom - rows[0]) / (plot_bottom - plot_top)
    assert height >= MIN_MG_HEIGHT, height
    spike = np.abs(arr - np.array(COLOURS["support"])).max(axis=2) <= 8
    assert spike[:, plot_top : plot_top + 3].any(), "the clipped spike reaches the top"


# -- the legend ----------------------------------------------------------------------------------


def test_legend_lists_only_what_is_on_screen() -> None:
    """The legend names the kinds drawn this frame: the force vectors when they are on, nothing
    of them when they are off, and never a kind whose drawing is out of sight."""
    app = App(_spike_show, "spike", size=SIZE)
    app.run_frames(10)
    kinds = {e.kind for e in app.painter.legend()}
    assert {"support", "support_filtered", "gravity"} <= kinds
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_v))
    app.render()
    assert not app.painter.legend()
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_v))
    app.session.show.follow = None
    app.camera.centre = (1e4, 1e4)
    app.render()
    assert not app.painter.legend()


# -- the help overlay ----------------------------------------------------------------------------

HELP_SHOW_THROUGH = 16  # per channel: what a bright arrow behind the help panel may change in it


def test_help_reads_over_a_busy_scene() -> None:
    """The help panel is nearly opaque: drawing the force arrows behind it or not changes no pixel
    of it by more than HELP_SHOW_THROUGH, and its text is drawn in the bright text colour."""
    app = App(_spike_show, "spike", size=SIZE)
    app.run_frames(10)
    app.camera.zoom_by(4.0)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_h))
    busy = pygame.surfarray.array3d(app.render()).astype(int)
    rect = app.hud.rects[-1]
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_v))
    calm = pygame.surfarray.array3d(app.render()).astype(int)
    assert app.hud.rects[-1] == rect
    region = (slice(rect.left, rect.right), slice(rect.top, rect.bottom))
    assert np.abs(busy - calm).max() > 100, "the arrows must lie partly behind the panel"
    assert np.abs(busy[region] - calm[region]).max() <= HELP_SHOW_THROUGH
    text = np.abs(busy[region] - np.array(COLOURS["text"])).max(axis=2) <= 8
    assert text.sum() >= 200


def test_a_kinematic_ring_shows_its_turn() -> None:
    """A kinematic body (a square room of four walls) turned by 60° shows a spoke from its centre
    along its own x axis: kinematic-coloured pixels halfway out along 60°, none along 150°."""
    w = World()
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    body.angle = math.radians(60.0)
    corners = [(-2.0, -2.0), (2.0, -2.0), (2.0, 2.0), (-2.0, 2.0)]
    walls = [
        pymunk.Segment(body, a, b, 0.05)
        for a, b in zip(corners, corners[1:] + corners[:1], strict=True)
    ]
    w.add("room", body, *walls)
    surf = pygame.Surface((300, 300))
    surf.fill(COLOURS["background"])
    cam = Camera(size=(300, 300), pixels_per_metre=50.0)
    draw_world(surf, cam, w)
    arr = pygame.surfarray.array3d(surf).astype(int)
    hit = np.abs(arr - np.array(COLOURS["kinematic"])).max(axis=2) == 0

    def seen(angle_deg: float) -> bool:
        a = math.radians(angle_deg)
        x, y = cam.to_screen((1.0 * math.cos(a), 1.0 * math.sin(a)))
        return bool(hit[int(x) - 3 : int(x) + 4, int(y) - 3 : int(y) + 4].any())

    assert seen(60.0) and not seen(150.0)
