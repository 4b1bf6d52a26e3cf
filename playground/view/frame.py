"""The picture of one frame of the app: the grid, the world and its overlays, the mouse, the HUD
with its notes and the scope, the overlay panel, the legend and the compass down the right edge,
the tuning panel and the help. Every panel's rect goes into the HUD's ``rects`` (they must all fit
the window, and pixel checks leave them out). Drawing only reads the world.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pygame

from playground.view.draw import COLOURS, draw_grid
from playground.view.hud import HudInfo
from playground.view.keyboard import CONTROLS
from playground.view.overlay import draw_panel
from playground.view.pointer import draw_mouse, focus_notes
from playground.view.session import roles_of

if TYPE_CHECKING:
    from playground.view.app import App

__all__ = ["draw_frame"]


def draw_frame(app: App) -> pygame.Surface:
    """Draw ``app``'s current frame onto its surface and return the surface."""
    surf = app.surface
    surf.fill(COLOURS["background"])
    draw_grid(surf, app.camera)
    _world(app, surf)
    _hud(app, surf)
    _panels(app, surf)
    return surf


def _world(app: App, surf: pygame.Surface) -> None:
    """The world, its overlays, the selection marker and the mouse spring."""
    session = app.session
    show = session.show
    app.painter.draw(
        surf,
        app.camera,
        app.world,
        show.controllers,
        roles_of(show),
        focus=app.selected
        if app.selected is not None
        else (show.follow if show.follow in show.controllers else show.player),
        nullify_target=session.nearest_enemy(),
    )
    if draw_mouse(surf, app.camera, app.world, app.selected, session.grab, session.pull):
        app.painter.drawn.add("mouse")


def _notes(app: App) -> list[str]:
    """The HUD's notes: the help key, a flipped gravity, the selected body, who is playing."""
    session = app.session
    notes = ["H: controls"]
    if session.keyboard.flipped:
        notes.append("own gravity flipped (G restores)")
    notes.extend(focus_notes(app.world, app.selected, session.grab, session.pull))
    if session.playback is not None:
        notes.append("replaying")
    elif session.script is not None and not session.keyboard.touched:
        notes.append("scripted demo: press a key to take over")
    return notes


def _hud(app: App, surf: pygame.Surface) -> None:
    """The HUD at the top left and the scope along the bottom."""
    state = getattr(getattr(app.session.player, "state", None), "value", None)
    app.hud.draw(
        surf,
        HudInfo(
            title=app.session.show.title,
            sim_time=app.world.time,
            physics_hz=app.physics_hz,
            render_hz=app.render_hz,
            speed=app.speed,
            paused=app.paused,
            state=str(state) if state is not None else None,
            stage_costs={} if app.compact else app.costs.means,
            notes=[] if app.compact else _notes(app),
        ),
        app.scope if app.scope.name else None,
    )


def _panels(app: App, surf: pygame.Surface) -> None:
    """Down the right edge the overlay panel, the legend and the compass; the tuning panel
    under the HUD; the help over everything."""
    right = app.size[0] - 8
    if app.compact:
        panel = pygame.Rect(right, 8, 0, 0)
    else:
        panel = draw_panel(surf, app.small, app.overlay, (right, 8))
    font = app.tiny if app.compact else app.small
    legend = app.painter.draw_legend(surf, font, (right, panel.bottom + 4))
    app.hud.rects += [panel, legend]
    compass = app.painter.draw_compass(
        surf, app.small, app.camera, (right - 60, legend.bottom + 60)
    )
    if compass is not None:
        app.hud.rects.append(compass)
    if app.tuning.visible:
        below = max((r.bottom for r in app.hud.rects[:2]), default=0)
        app.hud.rects.append(app.tuning.draw(surf, (8, below + 4)))
    if app.show_help:
        app.hud.draw_help(surf, CONTROLS, app.session.show.description)
