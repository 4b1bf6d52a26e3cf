"""The desktop view (pygame-ce): the only part of playground that imports pygame.

``playground play [LEVEL]`` opens it (``--headless`` draws off screen; see
:mod:`playground.view.launcher`). Each part has its own module: the app and its frame loop
(``app``), the picture of one frame (``frame``), the clock (``clock``), the keyboard
(``keyboard``), a level's run (``session``), the mouse (``pointer``; its spring is core,
:mod:`playground.controller.mouse`), the camera (``camera``), drawing (``draw``, ``arrows``), the
overlays (``overlay``), their painter (``painter``) and one body's arrows (``force_arrows``), the
HUD, scope and tuning panel (``hud``, ``scope``, ``tuning``). Replays are the scene's
(:mod:`playground.scene.replay`): re-exported here for the view's users.
"""

import os

# pygame prints a banner on import; the view is a library, so it stays quiet.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from playground.scene.replay import Recorder, Replay, ReplayError
from playground.view.app import App
from playground.view.camera import Camera
from playground.view.clock import Accumulator
from playground.view.keyboard import CONTROLS, Keyboard
from playground.view.session import Session, Show

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
