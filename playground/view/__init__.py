"""The desktop view (pygame-ce): the only part of playground that imports pygame.

``playground play [LEVEL]`` opens it (``--headless`` draws off screen; see
:mod:`playground.view.launcher`). The camera, drawing, HUD and app loop each have their own module:
``camera``, ``draw``, ``hud``, ``app``. Replays are core (:mod:`playground.replay`): re-exported
here for the view's users.
"""

import os

# pygame prints a banner on import; the view is a library, so it stays quiet.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from playground.replay import Recorder, Replay, ReplayError
from playground.view.app import CONTROLS, Accumulator, App, Keyboard, Session, Show
from playground.view.camera import Camera

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
