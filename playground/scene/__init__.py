"""A scene: a level built into a running world, and what runs on it.

:func:`build` (:mod:`~playground.scene.scene`) turns a validated level into a :class:`Scene`,
refusing what no single key can show (:mod:`~playground.scene.feasibility`). On a scene run its
checks (:mod:`~playground.scene.checks`), its recordings (:mod:`~playground.scene.recording`) and
its replays (:mod:`~playground.scene.replay`). The layer between the level format and the core.
"""

from playground.scene.scene import Scene, build

__all__ = ["Scene", "build"]
