"""Drives the lab panel in a real X window with real X mouse events (xdotool), for
tests/test_view_window.py. Run under Xvfb::

    xvfb-run -a python tests/lab_driver.py OUT_DIR

It opens ``rest``, shows the lab panel (L), clicks its pause button and its contacts checkbox,
drags the hover damping slider and picks ``seesaw`` in the level browser — each step checked
before the next — and writes what it saw to ``OUT_DIR/lab.json``.
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
SIZE = (1100, 700)


def main(out: Path) -> int:
    import pygame
    import pygame_gui

    from playground.view import App
    from playground.view.launcher import _open_window, level_names, show_level

    window = _open_window(SIZE)
    if window is None:
        return 2
    app = App(show_level, "rest", levels=level_names(), size=SIZE)
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
                raise SystemExit(f"lab driver: timed out waiting for {what}")
            pump()

    def xdo(*args: str) -> None:
        subprocess.run(["xdotool", *args], check=True, timeout=WAIT_S)

    def click(rect: pygame.Rect) -> None:
        xdo("mousemove", "--window", wid, str(rect.centerx), str(rect.centery))
        pump(3)
        xdo("click", "1")

    report: dict[str, Any] = {}
    pump(5)
    xdo("windowfocus", "--sync", wid)
    xdo("key", "l")
    until("the lab panel", lambda: app.lab.visible)
    pump(3)

    click(app.lab.buttons["pause"].rect)
    until("pause", lambda: app.paused)
    click(app.lab.buttons["pause"].rect)
    until("run again", lambda: not app.paused)
    report["pause"] = True

    click(app.lab.boxes["contacts"].rect)
    until("the contacts checkbox", lambda: app.overlay.contacts)
    report["contacts"] = app.overlay.contacts

    slider = app.lab.sliders["hover_damping"]
    button = slider.sliding_button
    assert button is not None
    before = app.session.player.config.hover_damping
    x, y = button.rect.center
    xdo("mousemove", "--window", wid, str(x), str(y))
    pump(3)
    xdo("mousedown", "1")
    pump(3)
    for k in range(1, 6):
        xdo("mousemove", "--window", wid, str(x + k * 20), str(y))
        pump(3)
    xdo("mouseup", "1")
    until("the damping", lambda: app.session.player.config.hover_damping != before)
    pump(5)
    report["damping"] = [before, app.session.player.config.hover_damping]
    report["knob"] = app.lab.knobs.hover_damping if app.lab.knobs is not None else None

    click(app.lab.browser.rect)
    pump(10)
    items = [
        e
        for e in app.lab.manager.get_sprite_group().sprites()
        if isinstance(e, pygame_gui.elements.UIButton) and e.text == "seesaw"
    ]
    assert items, "the level list did not open"
    click(items[0].rect)
    until("the level change", lambda: app.level == "seesaw")
    pump(5)
    report["level"] = app.level
    report["overlay_after"] = app.overlay.contacts

    (out / "lab.json").write_text(json.dumps(report, indent=1), encoding="utf-8")
    pygame.display.quit()
    return 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
