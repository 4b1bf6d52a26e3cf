"""Drives the demo in a real X window with real X input events (xdotool, through the X server's
XTEST extension), for tests/test_view_window.py. Run under Xvfb::

    xvfb-run -a python tests/window_driver.py OUT_DIR

It opens ``sandbox`` in a window, then — each step checked before the next — toggles every
overlay key, drags the crate up with the mouse, opens the tuning panel, clicks one slider and
drags another, zooms with the wheel, resizes the window, goes from ``incline`` to the next level
with PgDn and taps D while ``flying_whale``'s script hangs on. It writes what it saw to
``OUT_DIR/window.json`` and the window's pixels after the drag, the slider and the level change
to ``OUT_DIR/drag.png``, ``OUT_DIR/slider.png`` and ``OUT_DIR/level.png``.
"""

from __future__ import annotations

import json
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

WAIT_S = 20.0  # s of wall time to wait for an X event to reach the app (slow, shared CI machines)
LEVEL = "sandbox"
SIZE = (960, 600)
RESIZED = (800, 500)


def main(out: Path) -> int:
    import pygame

    from playground.view import App
    from playground.view.launcher import _open_window, level_names, show_level
    from playground.view.overlay import OVERLAY_KEYS

    window = _open_window(SIZE)
    if window is None:
        return 2
    app = App(show_level, LEVEL, levels=level_names(), size=SIZE)
    wid = str(pygame.display.get_wm_info()["window"])

    def pump(frames: int = 1) -> None:
        for _ in range(frames):
            for event in pygame.event.get():
                app.handle(event)
            app.frame(1.0 / 60.0)
            app.render()
            app._present()

    def until(what: str, ok: Callable[[], bool]) -> None:
        end = time.monotonic() + WAIT_S
        while not ok():
            if time.monotonic() > end:
                raise SystemExit(f"window driver: timed out waiting for {what}")
            pump()

    def xdo(*args: str) -> None:
        subprocess.run(["xdotool", *args], check=True, timeout=WAIT_S)

    def shot(name: str) -> None:
        surface = pygame.display.get_surface()
        assert surface is not None
        pygame.image.save(surface, str(out / name))

    report: dict[str, Any] = {"window": wid}
    pump(5)
    xdo("windowfocus", "--sync", wid)

    # Every overlay key: each press flips its overlay.
    toggles: dict[str, list[bool]] = {}
    for key, (field, _) in OVERLAY_KEYS.items():
        before = bool(getattr(app.painter.overlay, field))
        xdo("key", "--clearmodifiers", pygame.key.name(key))
        until(f"overlay {field}", lambda f=field, b=before: getattr(app.painter.overlay, f) != b)
        toggles[field] = [before, bool(getattr(app.painter.overlay, field))]
    report["toggles"] = toggles

    # Drag the crate 2.5 m up: press on it, move in steps, hold, release.
    crate = app.world.body("crate")
    start = (crate.position.x, crate.position.y)
    x, y = (round(c) for c in app.camera.to_screen(start))
    xdo("mousemove", "--window", wid, str(x), str(y))
    xdo("mousedown", "1")
    until("the press", lambda: app.pointer.press is not None)
    lift = round(app.camera.pixels(2.5))
    for k in range(1, 6):
        xdo("mousemove", "--window", wid, str(x), str(y - k * lift // 5))
        pump(2)
    until("the grab", lambda: app.session.grab is not None)
    pump(90)
    report["drag"] = {
        "start": start,
        "held": [crate.position.x, crate.position.y],
        "grabbed": app.session.grab.body if app.session.grab else None,
        "pull": list(app.session.pull[0]) if app.session.pull else None,
        "selected": app.selected,
        "mass": crate.mass,
        "on_screen": list(app.camera.to_screen((crate.position.x, crate.position.y))),
    }
    shot("drag.png")
    xdo("mouseup", "1")
    until("the release", lambda: app.session.grab is None)

    # The tuning panel: T opens it; a click on the 1€ min_cutoff track moves that slider.
    xdo("key", "t")
    until("the panel", lambda: app.tuning.visible and "min_cutoff" in app.tuning._tracks)
    track = app.tuning._tracks["min_cutoff"]
    before = app.world.config.perception.min_cutoff
    tx, ty = track.x + round(0.9 * track.width), track.centery
    xdo("mousemove", "--window", wid, str(tx), str(ty), "click", "1")
    until("the slider", lambda: app.world.config.perception.min_cutoff != before)
    pump(2)
    report["slider"] = {
        "before": before,
        "after": app.world.config.perception.min_cutoff,
        "knob": [tx, ty],
    }
    shot("slider.png")

    # A drag on the hover damping slider: the held knob follows the mouse across frames.
    track = app.tuning._tracks["hover_damping"]
    xs = [track.x + round(f * track.width) for f in (0.2, 0.35, 0.5, 0.7)]
    xdo("mousemove", "--window", wid, str(xs[0]), str(track.centery))
    xdo("mousedown", "1")
    until("the slider press", lambda: app.tuning._held == "hover_damping")
    for x in xs[1:]:
        xdo("mousemove", "--window", wid, str(x), str(track.centery))
        pump(3)
    xdo("mouseup", "1")
    until("the slider release", lambda: app.tuning._held is None)
    pump(2)
    report["slider_drag"] = {
        "track": [track.x, track.width],
        "to": xs[-1],
        "damping": app.session.player.config.hover_damping,
    }

    # The wheel zooms.
    zoom = app.camera.zoom
    xdo("mousemove", "--window", wid, str(SIZE[0] // 2), str(SIZE[1] // 2), "click", "4")
    until("the wheel", lambda: app.camera.zoom != zoom)
    report["zoom"] = [zoom, app.camera.zoom]

    # The window is resizable: the app draws at the new size.
    xdo("windowsize", "--sync", wid, str(RESIZED[0]), str(RESIZED[1]))
    until("the resize", lambda: app.size == RESIZED)
    pump(2)
    report["resized"] = [list(app.size), list(app.surface.get_size()), list(app.camera.size)]

    # A level reached with PgDn looks as it does started directly: the overlays the level before
    # moving_platform (in the shipped levels' order) declares do not carry over to it.
    from playground.level import shipped

    names = sorted(shipped())
    app.start(names[names.index("moving_platform") - 1])
    pump(5)
    xdo("key", "--clearmodifiers", "Next")
    until("the next level", lambda: app.level == "moving_platform")
    pump(30)
    report["level_change"] = {
        "level": app.level,
        "overlay": [
            f
            for f in ("vectors", "contacts", "joints", "reactions", "perceived")
            if getattr(app.overlay, f)
        ],
        "drawn": sorted(app.painter.drawn),
    }
    shot("level.png")

    # Taking over a scripted grip: a D tap at 1.6 s keeps the player hanging from the whale.
    app.start("flying_whale")
    ctrl = app.session.show.controllers["player"]
    until("1.6 s of flying_whale", lambda: app.world.time >= 1.6)
    xdo("key", "--clearmodifiers", "d")
    until("the takeover", lambda: app.session.keyboard.touched)
    pump(30)
    report["takeover"] = {
        "hanging": ctrl.joint is not None,
        "state": ctrl.state.value,
    }

    (out / "window.json").write_text(json.dumps(report, indent=1), encoding="utf-8")
    pygame.display.quit()
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
