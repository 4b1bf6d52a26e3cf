"""``help(Controller)`` as a game developer reads it: a signature one can read at a glance and a
docstring that shows the per-frame input and the readings to animate from."""

from __future__ import annotations

import inspect
import pydoc

from playground import Controller

MAX_SIGNATURE = 240
"""Characters: the signature, annotations and all, fits about two lines of a terminal. A default
value spelled out (a whole ``ControllerConfig()`` was ~1 000 characters) breaks it."""


def test_the_signature_is_short_and_names_its_arguments() -> None:
    signature = str(inspect.signature(Controller))
    assert len(signature) <= MAX_SIGNATURE, signature
    for name in ("world", "name", "position", "config", "source", "angle", "laws"):
        assert name in signature, name


def test_help_shows_the_per_frame_input_and_the_readings() -> None:
    text = pydoc.render_doc(Controller, renderer=pydoc.plaintext)
    for word in ("intent", "Intent(", "state", "grounded", "up", "tilt", "ground_velocity"):
        assert word in text, word
    assert ">>>" in (Controller.__doc__ or "")
