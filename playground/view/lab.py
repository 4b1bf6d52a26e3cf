"""The lab panel: a clickable bench beside the picture, drawn with pygame_gui (L shows it) — a
level browser, a checkbox per overlay, pause / step / restart buttons, sliders that follow the
mouse for the hover spring, the 1€ filter and the step, counters of bodies, contacts, joints and
sleeping bodies, and each stage's cost per step as a graph over the last seconds.

The panel never touches the app: :meth:`LabPanel.action` turns one of its events into an
:class:`Action` value, which the app carries out between two steps.
"""

from __future__ import annotations

import dataclasses
from collections import deque
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pygame
import pygame_gui

from playground.view.draw import COLOURS
from playground.view.hud import MARGIN, scope_height
from playground.view.overlay import Overlay
from playground.view.tuning import SLIDERS, Knobs
from playground.world.schedule import Stage
from playground.world.world import World

__all__ = ["Action", "Counts", "LabPanel", "counts"]

PANEL_PX = (300, 600)  # px: the panel's size at most (it stops above the scope strip)
ROW_PX = 24  # px: one row of the panel
SLIDER_STEPS = 1000  # a slider's track is this many steps from its low to its high end
GRAPH_PX = 70  # px: height of the cost graph
GRAPH_FRAMES = 240  # frames of history in the cost graph
KEY_PX = 18  # px: the graph's key (the stages' names) below it
STAGE_COLOURS = (
    (255, 160, 40),
    (40, 220, 220),
    (110, 210, 120),
    (255, 60, 200),
    (90, 150, 255),
    (255, 230, 60),
    (190, 120, 255),
    (225, 228, 235),
    (255, 120, 220),
)


@dataclass(frozen=True, slots=True)
class Action:
    """What the user asked for with the panel: ``kind`` is ``level`` (``value``: its name),
    ``pause``, ``step``, ``restart``, ``overlay`` (``value``: the new :class:`Overlay`) or
    ``knobs`` (``value``: the new :class:`Knobs`)."""

    kind: str
    value: object = None


@dataclass(frozen=True, slots=True)
class Counts:
    """What the world holds now: bodies (dynamic and kinematic), touching pairs, joints, and
    sleeping bodies."""

    bodies: int
    contacts: int
    joints: int
    sleeping: int


def counts(world: World) -> Counts:
    """Count the world's bodies, contacts (pairs of shapes touching), joints and sleepers."""
    bodies = list(world.space.bodies)
    pairs: set[tuple[int, int]] = set()
    for body in bodies:

        def visit(arb: Any) -> None:
            a, b = arb.shapes
            pairs.add((min(id(a), id(b)), max(id(a), id(b))))

        body.each_arbiter(visit)
    return Counts(
        bodies=len(bodies),
        contacts=len(pairs),
        joints=len(world.space.constraints),
        sleeping=sum(1 for b in bodies if b.is_sleeping),
    )


class LabPanel:
    """The panel's widgets in a pygame_gui manager for a window of ``size`` px."""

    def __init__(self, size: tuple[int, int], levels: Sequence[str]) -> None:
        self.levels = list(levels)
        self.visible = False
        self.manager = pygame_gui.UIManager(size)
        self.knobs: Knobs | None = None
        self.overlay = Overlay()
        self.history: deque[Mapping[Stage, float]] = deque(maxlen=GRAPH_FRAMES)
        self._size = size
        self._level = self.levels[0] if self.levels else ""
        self._build()

    # -- layout ----------------------------------------------------------------------------------

    def _build(self) -> None:
        self.manager.clear_and_reset()  # type: ignore[no-untyped-call]
        # Above the scope strip, which stays readable.
        room = self._size[1] - scope_height(self._size[1]) - 3 * MARGIN
        w, h = PANEL_PX[0], min(PANEL_PX[1], room)
        self.rect = pygame.Rect(8, 8, w, h)
        # Built shown and hidden after: a checkbox made inside a hidden panel fails (0.6.14).
        self.panel = pygame_gui.elements.UIPanel(self.rect, manager=self.manager)
        inner = w - 16
        y = 4
        options: list[str | tuple[str, str]] = [*(self.levels or [self._level])]
        self.browser = pygame_gui.elements.UIDropDownMenu(
            options,
            self._level if self._level in options else str(options[0]),
            pygame.Rect(4, y, inner, ROW_PX),
            manager=self.manager,
            container=self.panel,
        )
        y += ROW_PX + 4
        third = inner // 3
        self.buttons = {
            kind: pygame_gui.elements.UIButton(
                pygame.Rect(4 + i * third, y, third - 4, ROW_PX),
                text,
                manager=self.manager,
                container=self.panel,
            )
            for i, (kind, text) in enumerate(
                (("pause", "pause"), ("step", "step"), ("restart", "restart"))
            )
        }
        y += ROW_PX + 4
        self.boxes: dict[str, pygame_gui.elements.UICheckBox] = {}
        fields = [f.name for f in dataclasses.fields(Overlay)]
        for i, name in enumerate(fields):
            col, row = i % 2, i // 2
            self.boxes[name] = pygame_gui.elements.UICheckBox(
                pygame.Rect(4 + col * (inner // 2), y + row * (ROW_PX - 4), 18, 18),
                name.replace("_", " "),
                manager=self.manager,
                container=self.panel,
                initial_state=bool(getattr(self.overlay, name)),
            )
        y += ((len(fields) + 1) // 2) * (ROW_PX - 4) + 4
        self.sliders: dict[str, pygame_gui.elements.UIHorizontalSlider] = {}
        self.values: dict[str, pygame_gui.elements.UILabel] = {}
        for s in SLIDERS:
            pygame_gui.elements.UILabel(
                pygame.Rect(4, y, inner // 2, ROW_PX - 4),
                s.label,
                manager=self.manager,
                container=self.panel,
            )
            self.values[s.field] = pygame_gui.elements.UILabel(
                pygame.Rect(4 + inner // 2, y, inner // 2, ROW_PX - 4),
                "",
                manager=self.manager,
                container=self.panel,
            )
            y += ROW_PX - 4
            self.sliders[s.field] = pygame_gui.elements.UIHorizontalSlider(
                pygame.Rect(4, y, inner, ROW_PX - 8),
                0,
                (0, SLIDER_STEPS),
                manager=self.manager,
                container=self.panel,
            )
            y += ROW_PX - 6
        self.counter = pygame_gui.elements.UILabel(
            pygame.Rect(4, y, inner, ROW_PX - 4), "", manager=self.manager, container=self.panel
        )
        y += ROW_PX
        self.graph = pygame.Rect(self.rect.x + 8, self.rect.y + y + 4, inner, GRAPH_PX)
        self.rect.height = min(y + GRAPH_PX + 16 + KEY_PX, h)
        self.panel.set_dimensions(self.rect.size)
        self.show(self.visible)

    def resize(self, size: tuple[int, int]) -> None:
        """Lay the panel out for a window of ``size`` px."""
        if size != self._size:
            self._size = size
            self.manager.set_window_resolution(size)
            self._build()

    # -- state shown -----------------------------------------------------------------------------

    def show(self, visible: bool) -> None:
        self.visible = visible
        if visible:
            self.panel.show()
        else:
            self.panel.hide()

    def level_started(self, level: str, overlay: Overlay, knobs: Knobs) -> None:
        """A level (re)started: show its name, its overlays and its knobs."""
        if level != self._level:
            self._level = level
            self._build()
        self.history.clear()
        self.sync(overlay, knobs)

    def sync(self, overlay: Overlay, knobs: Knobs) -> None:
        """Show ``overlay`` and ``knobs`` (the app's values now); a slider being dragged keeps
        following the mouse."""
        self.overlay = overlay
        self.knobs = knobs
        for name, box in self.boxes.items():
            on = bool(getattr(overlay, name))
            if box.is_checked != on:
                box.set_state(on)
        for s in SLIDERS:
            value = getattr(knobs, s.field)
            slider = self.sliders[s.field]
            if value is None:
                slider.disable()  # type: ignore[no-untyped-call]
                self.values[s.field].set_text("(no player)")
                continue
            if not slider.grabbed_slider:
                slider.set_current_value(round(s.fraction(float(value)) * SLIDER_STEPS))
            self.values[s.field].set_text(_shown(s.field, float(value)))

    # -- events ----------------------------------------------------------------------------------

    def process(self, event: pygame.event.Event) -> bool:
        """Offer ``event`` to the widgets: True if the panel took it (a click on it)."""
        if not self.visible:
            return False
        used = bool(self.manager.process_events(event))
        pos = getattr(event, "pos", None)
        if pos is not None and event.type in (pygame.MOUSEBUTTONDOWN, pygame.MOUSEBUTTONUP):
            used = used or self.rect.collidepoint(pos)
        return used

    def action(self, event: pygame.event.Event) -> Action | None:
        """The :class:`Action` one of the panel's own events asks for (None: not the panel's)."""
        if event.type == pygame_gui.UI_DROP_DOWN_MENU_CHANGED and event.ui_element is self.browser:
            return Action("level", str(event.text))
        if event.type == pygame_gui.UI_BUTTON_PRESSED:
            for kind, button in self.buttons.items():
                if event.ui_element is button:
                    return Action(kind)
        if event.type in (pygame_gui.UI_CHECK_BOX_CHECKED, pygame_gui.UI_CHECK_BOX_UNCHECKED):
            for name, box in self.boxes.items():
                if event.ui_element is box:
                    on = event.type == pygame_gui.UI_CHECK_BOX_CHECKED
                    self.overlay = dataclasses.replace(self.overlay, **{name: on})
                    return Action("overlay", self.overlay)
        if event.type == pygame_gui.UI_HORIZONTAL_SLIDER_MOVED and self.knobs is not None:
            for s in SLIDERS:
                if event.ui_element is self.sliders[s.field]:
                    value = s.value(float(event.value) / SLIDER_STEPS)
                    change: dict[str, Any] = {s.field: int(value) if s.integer else value}
                    self.knobs = dataclasses.replace(self.knobs, **change).stable()
                    return Action("knobs", self.knobs)
        return None

    # -- each frame ------------------------------------------------------------------------------

    def update(self, elapsed: float, world: World, costs: Mapping[Stage, float]) -> None:
        """Advance the widgets by ``elapsed`` s; count the world; keep this frame's costs."""
        if not self.visible:
            return
        self.manager.update(elapsed)
        c = counts(world)
        self.counter.set_text(
            f"bodies {c.bodies}  contacts {c.contacts}  joints {c.joints}  asleep {c.sleeping}"
        )
        self.history.append(dict(costs))

    def draw(self, surf: pygame.Surface, font: pygame.font.Font) -> pygame.Rect | None:
        """Draw the panel and its cost graph; returns the panel's rect (None: hidden)."""
        if not self.visible:
            return None
        self.manager.draw_ui(surf)
        self._graph(surf, font)
        return self.rect

    def _graph(self, surf: pygame.Surface, font: pygame.font.Font) -> None:
        """Each stage's cost per step (µs) over the kept frames, one line per stage."""
        g = self.graph
        if g.bottom + KEY_PX > self.rect.bottom:
            return
        pygame.draw.rect(surf, COLOURS["background"], g)
        pygame.draw.rect(surf, COLOURS["dim"], g, 1)
        n = len(self.history)
        stages = sorted({s for frame in self.history for s in frame}, key=lambda s: s.value)
        table = np.array([[frame.get(s, 0.0) for s in stages] for frame in self.history])
        top = float(table.max()) if table.size else 0.0
        surf.blit(
            font.render(f"cost per step, top {top * 1e6:.0f} µs", True, COLOURS["dim"]),
            (g.x + 4, g.y + 2),
        )
        if top <= 0.0 or n < 2:
            return
        xs = g.x + np.arange(n) * (g.width - 1) / (GRAPH_FRAMES - 1)
        ys = g.bottom - 1 - table / top * (g.height - 16)
        x = g.x + 4
        for k, stage in enumerate(stages):
            colour = STAGE_COLOURS[k % len(STAGE_COLOURS)]
            pts = np.column_stack([xs, ys[:, k]]).tolist()
            pygame.draw.lines(surf, colour, False, pts, 1)
            # The key below the graph: each stage's name in its line's colour.
            name = font.render(stage.name.lower(), True, colour)
            if x + name.get_width() <= g.right:
                surf.blit(name, (x, g.bottom + 2))
                x += name.get_width() + 6


def _shown(field: str, value: float) -> str:
    if field in ("hover_frequency", "min_cutoff"):
        return f"{value:.3g} Hz"
    if field == "dt":
        return f"{value * 1e3:.2f} ms"
    if field == "substeps":
        return f"{value:.0f}"
    if field == "gravity":
        return f"{value:.2f} m/s²"
    return f"{value:.3g}"
