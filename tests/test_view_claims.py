"""Each shipped level visibly shows its claim: the level is rendered off screen at its ``[view]``
moment with its own view hints (zoom, roll, overlays), and the claimed thing is found by its
colour where it must be — the friction arrow along the incline, the grip between hand and whale,
the hover's reaction pushing the seesaw's plank down, the outward perceived gravity in the ring,
the nullify marker on the enemy, world up turned over on the compass after a gravity flip."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pygame
import pytest
from numpy.typing import NDArray

from playground.view import App
from playground.view.arrows import arrow_length, body_size, weight_pixels
from playground.view.draw import COLOURS
from playground.view.force_arrows import support_point
from playground.view.launcher import init_headless, level_names, show_level

SIZE = (960, 540)
FRAME = 1.0 / 60.0  # s: one headless frame
COLOUR_TOL = 10  # per channel: anti-aliased edges blend; an arrow's body is its exact colour
MIN_PIXELS = 20  # pixels of a colour that make a drawn thing (an arrow 2 px wide and 10 px long)
BAND_PX = 14.0  # px: half-width of the strip along which an arrow is looked for
HEAD_SEEN = 0.6  # share of an arrow's length found in its exact colour: the head's tip blends
TOL_DIR_RAD = math.radians(12.0)  # a drawn direction within this of the claimed one
RING_TOL_PX = 5.0  # px: the ring is 3 px wide inward from its radius; its centre is rounded
# to whole pixels and its edge pixels spread by one more
LEVELS = level_names()

Vec = tuple[float, float]


@pytest.fixture(scope="module", autouse=True)
def headless() -> Iterator[None]:
    init_headless()
    yield


def at_moment(level: str, t: float | None = None) -> App:
    """The level rendered at ``t`` (default: its ``[view]`` moment) with its own view hints."""
    app = App(show_level, level, levels=LEVELS, size=SIZE)
    moment = app.session.show.scene.level.view.moment if t is None else t
    assert moment is not None, f"{level}: its [view] table names no moment"
    app.run_frames(round(moment / FRAME))
    app.render()
    return app


def mask(app: App, kind: str) -> NDArray[np.bool_]:
    """Pixels of ``COLOURS[kind]`` outside the HUD panels and the arrows' value labels (x, y
    indexing)."""
    arr = pygame.surfarray.array3d(app.surface).astype(int)
    hit = np.abs(arr - np.array(COLOURS[kind])).max(axis=2) <= COLOUR_TOL
    for r in [*app.hud.rects, *(rect for _, _, rect in app.painter.labels)]:
        hit[r.left : r.right, r.top : r.bottom] = False
    return hit


def in_rect(app: App, kind: str, rect: pygame.Rect) -> NDArray[np.bool_]:
    """Pixels of ``COLOURS[kind]`` inside ``rect`` only (a HUD panel, for instance)."""
    arr = pygame.surfarray.array3d(app.surface).astype(int)
    hit = np.abs(arr - np.array(COLOURS[kind])).max(axis=2) <= COLOUR_TOL
    out = np.zeros_like(hit)
    out[rect.left : rect.right, rect.top : rect.bottom] = hit[
        rect.left : rect.right, rect.top : rect.bottom
    ]
    return out


def reach(hit: NDArray[np.bool_], origin: Vec, direction: Vec) -> float:
    """How far (px) pixels of ``hit`` reach from ``origin`` along ``direction`` (screen), within
    BAND_PX of that ray; 0 if none."""
    n = math.hypot(*direction)
    ux, uy = direction[0] / n, direction[1] / n
    xs, ys = np.nonzero(hit)
    dx, dy = xs - origin[0], ys - origin[1]
    along = dx * ux + dy * uy
    across = np.abs(dx * uy - dy * ux)
    sel = (across <= BAND_PX) & (along > 0.0)
    return float(along[sel].max()) if sel.any() else 0.0


def screen(app: App, name: str) -> Vec:
    b = app.world.body(name)
    c = b.local_to_world(b.center_of_gravity)
    return app.camera.to_screen((c.x, c.y))


def foot(app: App, name: str) -> Vec:
    """Where the support acts on ``name`` on screen (its hand or the hover's foot), px."""
    ctrl = app.session.show.controllers[name]
    return app.camera.to_screen(support_point(ctrl, app.world.body(name)))


def weight_px(app: App, name: str) -> float:
    return weight_pixels(body_size(app.world.body(name)), app.camera.zoom)


def direction_of(hit: NDArray[np.bool_]) -> float:
    """The main direction (rad, screen, 0..π) of the pixels of ``hit`` (their principal axis)."""
    xs, ys = np.nonzero(hit)
    pts = np.column_stack([xs - xs.mean(), ys - ys.mean()]).astype(float)
    _, vecs = np.linalg.eigh(pts.T @ pts)
    vx, vy = vecs[:, -1]
    return math.atan2(vy, vx) % math.pi


def angle_between(a: float, b: float) -> float:
    """Unsigned difference of two undirected angles (rad, modulo π)."""
    d = abs(a - b) % math.pi
    return min(d, math.pi - d)


def compass_up(app: App) -> Vec:
    """The screen direction in which the compass's world-up arrow points (from its centre)."""
    rect = app.painter.compass_rect
    assert rect is not None, "no compass on screen"
    hit = in_rect(app, "up", rect)
    xs, ys = np.nonzero(hit)
    assert xs.size >= MIN_PIXELS
    cx, cy = app.painter.compass_centre
    far = np.argmax((xs - cx) ** 2 + (ys - cy) ** 2)
    return (float(xs[far] - cx), float(ys[far] - cy))


def test_every_level_has_a_moment() -> None:
    """Every shipped level names the moment that shows its claim (its screenshot and its test)."""
    for level in LEVELS:
        assert show_level(level).scene.level.view.moment is not None, level


# -- one test per level --------------------------------------------------------------------------


def test_bounce_draws_a_one_step_bounce_spike() -> None:
    """bounce: the frame holding ball4's first bounce (one physics step, an odd one, not the
    frame's last) shows its support arrow several weights long, straight up."""
    app = at_moment("bounce")
    ball = "ball4"
    assert app.world.steps % 2 == 0 and math.hypot(*app.world.forces(ball).support) < 1.0
    w = weight_px(app, ball)
    up = reach(mask(app, "support"), screen(app, ball), (0.0, -1.0))
    m = app.world.body(ball).mass
    assert up >= arrow_length(3.0 * m * 9.81, m, w), (up, w)


def test_crusher_shows_the_crate_pressing_on_the_player() -> None:
    """crusher: the player reports being crushed and the contact overlay draws the crate's load
    pressing on its head: a normal force coming down from above onto the top of the capsule,
    over a weight long; at the end the crate lies on the floor beside the upright player."""
    app = at_moment("crusher")
    ctrl = app.session.show.controllers["player"]
    assert ctrl.state.value == "crushed"
    p = app.world.body("player").position
    head = app.camera.to_screen((p.x, p.y + ctrl.config.half_length + ctrl.config.radius))
    normal = mask(app, "normal")
    assert reach(normal, head, (0.0, -1.0)) >= weight_px(app, "player")
    # Its tip is on the head: the pressing arrow does not run on through the body (nor does the
    # floor's, whose tip is at the feet).
    feet = app.camera.to_screen((p.x, p.y - ctrl.config.half_length - ctrl.config.radius))
    x0, x1 = int(head[0] - BAND_PX), int(head[0] + BAND_PX)
    assert not normal[x0:x1, int(head[1]) + 6 : int(feet[1]) - 6].any()
    # Heaving, the crate pushes back on it: that push is drawn pressing down onto where it
    # pushes (at its head), not from its centre down through the floor.
    heave = at_moment("crusher", 2.3)
    q = heave.world.body("player").position
    top = heave.camera.to_screen((q.x, q.y + ctrl.config.half_length + ctrl.config.radius))
    bottom = heave.camera.to_screen((q.x, q.y - ctrl.config.half_length - ctrl.config.radius))
    push = mask(heave, "push")
    assert reach(push, top, (0.0, -1.0)) >= weight_px(heave, "player")
    assert reach(push, bottom, (0.0, 1.0)) == 0.0
    end = at_moment("crusher", 5.0)
    assert end.session.show.controllers["player"].state.value == "grounded"
    player, crate = screen(end, "player"), screen(end, "crate")
    assert crate[0] - player[0] >= end.camera.pixels(0.75)
    fill = tuple(int(c * 0.45) for c in COLOURS["dynamic"])
    assert tuple(end.surface.get_at((int(crate[0]), int(crate[1]))))[:3] == fill


def test_elevator_support_grows_above_the_weight() -> None:
    """elevator: accelerating up, the filtered support arrow is longer than the weight arrow by
    about (g + a)/g = 1.2."""
    app = at_moment("elevator")
    c = screen(app, "player")
    up = reach(mask(app, "support_filtered"), foot(app, "player"), (0.0, -1.0))
    down = reach(mask(app, "gravity"), c, (0.0, 1.0))
    assert down > 0.0 and up / down >= 1.1, (up, down)


def test_flying_whale_draws_the_grip_between_hand_and_whale() -> None:
    """flying_whale: hanging, the hand and arm fill the gap between the top of the capsule and
    the whale's underside, and the joint force is drawn there pointing up."""
    app = at_moment("flying_whale")
    ctrl = app.session.show.controllers["player"]
    assert ctrl.joint is not None
    p = app.world.body("player").position
    top = app.camera.to_screen((p.x, p.y + ctrl.config.half_length + ctrl.config.radius))
    whale = app.world.body("whale")
    bottom = max(
        app.camera.to_screen((v.x, v.y))[1]
        for s in whale.shapes
        for v in (whale.local_to_world(u) for u in s.get_vertices())  # type: ignore[attr-defined]
    )
    hand = mask(app, "hand")
    gap = hand[int(top[0]) - 6 : int(top[0]) + 7, int(bottom) + 1 : int(top[1])]
    assert gap.shape[1] > 0 and gap.any(axis=0).mean() >= 0.8, "the gap is not bridged"
    assert reach(mask(app, "joint_force"), (top[0], bottom), (0.0, -1.0)) > 10.0


def test_gravity_flip_shows_world_up_turned_over() -> None:
    """gravity_flip: standing on the old ceiling, the camera has rolled over, the compass shows
    world up pointing down the screen, and the support points up the screen."""
    app = at_moment("gravity_flip")
    ux, uy = compass_up(app)
    assert math.atan2(ux, uy) == pytest.approx(0.0, abs=TOL_DIR_RAD * 2)
    up = reach(mask(app, "support_filtered"), foot(app, "player"), (0.0, -1.0))
    assert up >= 0.8 * weight_px(app, "player")


def test_gravity_leap_shows_the_player_on_the_creatures_underside() -> None:
    """gravity_leap: landed on the creature's underside, the player stands upright on screen
    (support up), while the compass shows world up more than 120° away from screen up."""
    app = at_moment("gravity_leap")
    assert app.session.show.controllers["player"].state.value == "grounded"
    ux, uy = compass_up(app)
    assert abs(math.atan2(ux, -uy)) >= math.radians(120.0)
    up = reach(mask(app, "support_filtered"), foot(app, "player"), (0.0, -1.0))
    assert up >= 0.8 * weight_px(app, "player")


def test_incline_draws_friction_along_the_slope() -> None:
    """incline: the contact overlay draws a friction arrow along the 30° slope and a normal
    arrow square to it."""
    app = at_moment("incline")
    friction, normal = mask(app, "friction"), mask(app, "normal")
    assert friction.sum() >= MIN_PIXELS and normal.sum() >= MIN_PIXELS
    slope = math.radians(-30.0) % math.pi  # screen y points down: the slope rises to the right
    assert angle_between(direction_of(friction), slope) <= TOL_DIR_RAD
    assert angle_between(direction_of(normal), slope + math.pi / 2) <= TOL_DIR_RAD


def test_moving_platform_draws_the_drive_carrying_the_player() -> None:
    """moving_platform: while the platform speeds up to the right, the drive arrow at the
    player's feet points right, labelled with its value; the camera stays still in the world, so
    a second later the player is seen farther right (the claim is motion)."""
    app = at_moment("moving_platform")
    ctrl = app.session.show.controllers["player"]
    probe = ctrl.probe
    assert probe is not None
    at = app.camera.to_screen(probe.point)
    drive = mask(app, "drive")
    m = app.world.body("player").mass
    length = arrow_length(math.hypot(*ctrl.last_forces.drive), m, weight_px(app, "player"))
    assert length >= 8.0
    assert reach(drive, at, (1.0, 0.0)) >= HEAD_SEEN * length
    assert reach(drive, at, (-1.0, 0.0)) <= 3.0
    assert "drive" in {kind for kind, _, _ in app.painter.labels}
    x0 = screen(app, "player")[0]
    app.run_frames(60)
    assert app.camera.centre == tuple(app.session.show.camera)
    assert screen(app, "player")[0] - x0 >= app.camera.pixels(0.5)


def test_null_enemy_marks_the_enemy_until_nullified() -> None:
    """null_enemy: before t = 1 s the ring marks the enemy X would nullify; once its gravity is
    nullified X would do nothing more, so the ring is gone (and so is its weight arrow)."""
    app = at_moment("null_enemy")
    ring = mask(app, "nullify")
    e = screen(app, "enemy")
    r = app.painter.nullify_px
    xs, ys = np.nonzero(ring)
    assert xs.size >= MIN_PIXELS
    # A ring around the enemy: nearly all its pixels at the ring's radius from the enemy, on
    # both sides of it.
    d = np.hypot(xs - e[0], ys - e[1])
    assert np.mean(np.abs(d - r) <= RING_TOL_PX) >= 0.95
    assert xs.min() < e[0] - 0.8 * r and xs.max() > e[0] + 0.8 * r
    later = at_moment("null_enemy", 2.0)
    assert later.world.gravity_rule("enemy").scale == 0.0
    assert not mask(later, "nullify").any()
    assert "nullify" not in {e.kind for e in later.painter.legend()}


def test_planet_keeps_the_walker_upright_as_world_up_turns() -> None:
    """planet: the walker has gone round part of the planet; the camera rolls with it, so its
    weight points down the screen while the compass shows world up turned by the roll."""
    app = at_moment("planet")
    roll = app.camera.roll
    assert abs(roll) >= math.radians(15.0)
    ux, uy = compass_up(app)
    expected = app.camera.vector((0.0, 1.0))
    got = math.atan2(uy, ux)
    assert abs(math.remainder(got - math.atan2(expected[1], expected[0]), math.tau)) <= TOL_DIR_RAD
    c = screen(app, "player")
    assert reach(mask(app, "gravity"), c, (0.0, 1.0)) >= 0.8 * weight_px(app, "player")


def test_rest_support_balances_the_weight() -> None:
    """rest: the filtered support arrow up from the hover's foot is as long as the weight arrow
    down from the centre (one weight), each labelled with its value, 687 N = 1.00 m·g; the raw
    support and the hover, the same force at rest, are drawn beside it rather than hidden."""
    app = at_moment("rest")
    c = screen(app, "player")
    f = foot(app, "player")
    w = weight_px(app, "player")
    up = reach(mask(app, "support_filtered"), f, (0.0, -1.0))
    down = reach(mask(app, "gravity"), c, (0.0, 1.0))
    assert up == pytest.approx(w, rel=0.1) and down == pytest.approx(w, rel=0.1)
    for kind in ("support", "hover"):
        hit = mask(app, kind)[int(f[0] - BAND_PX) : int(f[0] + BAND_PX)]
        rows = hit.any(axis=0)[int(f[1] - w * 0.8) : int(f[1])]
        assert rows.mean() >= 0.95, (kind, rows.mean())
    labels = {kind: text for kind, text, _ in app.painter.labels}
    assert labels["gravity"] == labels["support_filtered"] == "687 N = 1.00 m·g"


def test_rotating_room_rolls_the_camera_with_gravity() -> None:
    """rotating_room: after the field turned by 0.5 rad the camera has rolled with the player's
    up (the compass shows it), and its weight still points down the screen."""
    app = at_moment("rotating_room")
    assert abs(app.camera.roll) == pytest.approx(0.5, abs=0.1)
    compass_up(app)
    c = screen(app, "player")
    assert reach(mask(app, "gravity"), c, (0.0, 1.0)) >= 0.8 * weight_px(app, "player")


def test_sandbox_draws_every_kind_of_body() -> None:
    """sandbox: the player, the enemy, the kinematic platform, dynamic bodies and the seesaw's
    pivot are each drawn in their own colour."""
    app = at_moment("sandbox")
    app.camera.zoom_by(0.5)
    app.render()
    for kind in ("player", "enemy", "kinematic", "dynamic", "joint"):
        assert mask(app, kind).sum() >= MIN_PIXELS / 4, kind


def test_seesaw_draws_the_hover_reaction_on_the_plank() -> None:
    """seesaw: the reaction overlay draws the hover's push on the plank, at the probe's hit
    point, pointing down, at least half a weight long."""
    app = at_moment("seesaw")
    probe = app.session.show.controllers["player"].probe
    assert probe is not None and probe.body is app.world.body("plank")
    at = app.camera.to_screen(probe.point)
    assert reach(mask(app, "reaction"), at, (0.0, 1.0)) >= 0.5 * weight_px(app, "player")


def test_spinning_ring_draws_perceived_gravity_outward() -> None:
    """spinning_ring: the perceived gravity arrow points away from the ring's centre."""
    app = at_moment("spinning_ring")
    c = screen(app, "player")
    o = screen(app, "ring")
    out = (c[0] - o[0], c[1] - o[1])
    hit = mask(app, "perceived")
    assert reach(hit, c, out) >= 0.8 * weight_px(app, "player")
    assert reach(hit, c, (-out[0], -out[1])) <= 3.0


# -- readable forces (issue 26): bodies seen under their arrows, values, markers, insets --------

EDGE_SEEN = 0.9
"""Share of a body's outline points that must show its edge colour within 1 px after the arrows
are drawn (the rest may lie under a hand, a label or a crossing arrow head)."""


def edge_seen(app: App, name: str, kind: str) -> float:
    """The share of ``name``'s outline points (every shape, on screen) where a pixel of
    ``COLOURS[kind]`` lies within 1 px."""
    arr = pygame.surfarray.array3d(app.surface).astype(int)
    hit = np.abs(arr - np.array(COLOURS[kind])).max(axis=2) <= COLOUR_TOL
    body = app.world.body(name)
    cam = app.camera
    pts: list[Vec] = []
    for s in body.shapes:
        if hasattr(s, "get_vertices"):
            corners = [body.local_to_world(v) for v in s.get_vertices()]
            for a, b in zip(corners, corners[1:] + corners[:1], strict=True):
                pts += [cam.to_screen((a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t))
                        for t in np.linspace(0.1, 0.9, 9)]  # fmt: skip
        else:
            a, b = body.local_to_world(s.a), body.local_to_world(s.b)  # type: ignore[attr-defined]
            r = s.radius  # type: ignore[attr-defined]
            for t in np.linspace(0.0, 1.0, 9):
                x, y = a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t
                nx, ny = -(b.y - a.y), b.x - a.x
                n = math.hypot(nx, ny)
                for side in (1.0, -1.0):
                    pts.append(cam.to_screen((x + side * r * nx / n, y + side * r * ny / n)))
    seen = [
        bool(hit[max(int(x) - 1, 0) : int(x) + 2, max(int(y) - 1, 0) : int(y) + 2].any())
        for x, y in pts
    ]
    return float(np.mean(seen))


def test_planet_bundles_the_small_walkers_arrows_off_its_body() -> None:
    """planet: at 16 px/m the walker is ~30 px tall; its arrows are bundled (gravity and the
    support only) and start at its outline, so its own edge is seen all round (defect: 4–7
    arrows from its centre hid it)."""
    app = at_moment("planet")
    assert app.painter.bundled == {"player"}
    assert not mask(app, "hover").any()
    assert edge_seen(app, "player", "player") >= EDGE_SEEN


def test_crusher_draws_the_push_into_the_crate() -> None:
    """crusher: heaving, the player's push is drawn from its head up into the crate, labelled
    "push (on what it pushes)" (defect: a "push on itself" arrow no one understood)."""
    heave = at_moment("crusher", 2.3)
    texts = {e.text for e in heave.painter.legend()}
    assert "push (on what it pushes)" in texts and "push on itself" not in texts


def test_null_enemy_marks_the_nullified_enemy_with_what_it_still_pushes_with() -> None:
    """null_enemy: once nullified, the enemy is ringed in its own dashed mark and tagged with
    its hover and drive forces (defect: after X it looked like nothing at all)."""
    app = at_moment("null_enemy", 2.0)
    e = screen(app, "enemy")
    ring = mask(app, "nullified")
    xs, ys = np.nonzero(ring)
    assert xs.size >= MIN_PIXELS and xs.min() < e[0] < xs.max() and ys.min() < e[1]
    (tag,) = app.painter.tags
    assert tag[0] == "enemy" and "gravity nullified" in tag[1]
    assert "hover" in tag[1] and "drive" in tag[1]
    assert "nullified" in {e.kind for e in app.painter.legend()}


def test_a_player_out_of_the_window_gets_a_marker_and_a_fast_one_is_kept_in_view() -> None:
    """rest: G sends the player up for good; the camera keeps it inside the window however
    fast it goes; looked at from far away, a marker at the window's edge points at it
    (defect: the camera lost it and nothing said where it went)."""
    app = App(show_level, "rest", levels=LEVELS, size=SIZE)
    app.run_frames(30)
    app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_g))
    app.handle(pygame.event.Event(pygame.KEYUP, key=pygame.K_g))
    app.run_frames(240)
    p = screen(app, "player")
    assert app.world.body("player").velocity.y > 10.0
    assert app.surface.get_rect().collidepoint(p)
    app.camera.centre = (app.camera.centre[0], app.camera.centre[1] - 100.0)
    app.render()
    (marker,) = app.painter.markers
    assert marker[0] == "player" and marker[1][1] < SIZE[1] / 4
    x, y = (int(c) for c in marker[1])
    near = mask(app, "player")[x - 16 : x + 17, max(y - 16, 0) : y + 17]
    assert near.sum() >= MIN_PIXELS


def test_rest_free_body_inset_balances_gravity_and_the_hover() -> None:
    """rest: the free-body inset draws the player's gravity down and the hover up, of one
    length (they balance), and the sum m·a as nearly nothing."""
    app = at_moment("rest")
    diagram = app.picture().free_body
    assert diagram is not None
    forces = dict(diagram.forces)
    assert forces["gravity"][1] == pytest.approx(-forces["hover"][1], rel=0.01)
    assert math.hypot(*diagram.net) <= 0.01 * math.hypot(*forces["gravity"])
    inset = [r for r in app.hud.rects if r.width == r.height and r.width >= 120]
    assert len(inset) == 1
    for kind in ("gravity", "hover"):
        assert in_rect(app, kind, inset[0]).sum() >= MIN_PIXELS, kind


def test_seesaw_draws_the_pivots_force_with_its_arrow() -> None:
    """seesaw: the pivot's force on the plank is drawn as an arrow at the pivot, not only as a
    number (defect: "883 N" without an arrow)."""
    app = at_moment("seesaw")
    plank = app.world.body("plank")
    (joint,) = [
        c for c in app.world.space.constraints if plank in (c.a, c.b) and hasattr(c, "anchor_a")
    ]
    local = joint.anchor_a if joint.a is plank else joint.anchor_b
    p = plank.local_to_world(local)
    at = app.camera.to_screen((p.x, p.y))
    assert reach(mask(app, "joint_force"), at, (0.0, -1.0)) >= 0.5 * weight_px(app, "plank")


def test_elevator_is_seen_rising_against_a_still_camera() -> None:
    """elevator: the camera stays still in the world, so a second after the moment the player
    is higher on screen by the lift's climb (defect: the following camera hid the motion)."""
    app = at_moment("elevator")
    y0 = screen(app, "player")[1]
    z0 = app.world.body("player").position.y
    app.run_frames(60)
    climbed = app.world.body("player").position.y - z0
    assert app.camera.centre == tuple(app.session.show.camera)
    assert y0 - screen(app, "player")[1] == pytest.approx(app.camera.pixels(climbed), abs=1.0)


def test_crusher_draws_contact_forces_for_the_watched_body_only() -> None:
    """crusher: the contact overlay marks every body's contact points but draws the contact
    forces of the watched player only, so the weak player's crate is not hidden behind a second
    pair of long normals (defect: ~180 px normals over both crates); a click on the weak player
    watches it and draws its contacts' forces instead."""
    app = at_moment("crusher")
    weak = screen(app, "weak")
    span = int(app.camera.pixels(1.5))
    near = mask(app, "normal")[int(weak[0] - BAND_PX) : int(weak[0] + BAND_PX)]
    assert not near[:, max(int(weak[1]) - span, 0) : int(weak[1]) + span].any()
    assert mask(app, "contact")[int(weak[0]) - span : int(weak[0]) + span].sum() >= MIN_PIXELS
    app.select("weak")
    app.render()
    near = mask(app, "normal")[int(weak[0] - BAND_PX) : int(weak[0] + BAND_PX)]
    assert near.sum() >= MIN_PIXELS


def test_the_free_body_inset_never_hides_an_actor() -> None:
    """null_enemy at its moment: the enemy stands where the inset would go at the right edge, so
    the inset moves to the left edge, clear of every actor and panel (it hid the enemy X would
    nullify)."""
    app = at_moment("null_enemy")
    insets = [r for r in app.hud.rects if r.width == r.height and r.width >= 120]
    assert len(insets) == 1
    inset = insets[0]
    assert inset.left < SIZE[0] / 2
    for name in ("player", "enemy"):
        assert not inset.collidepoint(screen(app, name)), name
    assert inset.collidelist([r for r in app.hud.rects if r is not inset]) < 0


def test_spinning_ring_support_points_to_the_centre_with_no_weight_reference() -> None:
    """spinning_ring: with the force vectors on (the level asks for them), the filtered support
    points from the player's foot toward the ring's centre; with no gravity there is no weight
    to compare with, so the scope draws no m·g line and the legend's scale bar is not called a
    weight (defect: the support needed V, and "m·g (687 N)" was drawn in a zero-g level)."""
    app = at_moment("spinning_ring")
    f = foot(app, "player")
    o = screen(app, "ring")
    inward = (o[0] - f[0], o[1] - f[1])
    assert reach(mask(app, "support_filtered"), f, inward) >= 0.8 * weight_px(app, "player")
    assert app.scope.weight == 0.0
    texts = [e.text for e in app.painter.legend()]
    assert not any("m·g" in t for t in texts) and any(t.startswith("scale ") for t in texts)
    labels = [text for kind, text, _ in app.painter.labels]
    assert labels and not any("m·g" in t for t in labels)


def test_incline_shows_weight_and_support_without_a_key() -> None:
    """incline: its own overlays draw the crate's weight down and its support up, each
    labelled with its value, besides the contact forces (defect: they needed V)."""
    app = at_moment("incline")
    c = screen(app, "crate")
    w = weight_px(app, "crate")
    assert reach(mask(app, "gravity"), c, (0.0, 1.0)) >= 0.8 * w
    assert reach(mask(app, "support_filtered"), c, (0.0, -1.0)) >= 0.5 * w
    kinds = {kind for kind, _, _ in app.painter.labels}
    assert {"gravity", "support_filtered", "normal", "friction"} <= kinds
