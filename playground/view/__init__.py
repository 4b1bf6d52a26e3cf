"""The desktop view (pygame-ce): the only part of playground that imports pygame.

``playground play [LEVEL]`` opens it; :func:`playground.view.headless.render_level` draws off
screen. The camera, drawing, HUD, app loop and replays each have their own module.
"""

import os

# pygame prints a banner on import; the view is a library, so it stays quiet.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from playground.view.app import CONTROLS, Accumulator, App, Keyboard, Session, Show
from playground.view.camera import Camera
from playground.view.replay import Recorder, Replay, ReplayError

__all__ = [
    "CONTROLS",
    "Accumulator",
    "App",
    "Camera",
    "Keyboard",
    "Recorder",
    "Replay",
    "ReplayError",
    "Session",
    "Show",
]
