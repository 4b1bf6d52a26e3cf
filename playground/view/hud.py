"""The heads-up display: title, clocks and rates, stage costs, player state, the oscilloscope
strip (:mod:`playground.view.scope`) and the help overlay, every panel inside the window.
"""

from __future__ import annotations

import textwrap
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import pygame

from playground.view.draw import COLOURS, shade_panel
from playground.view.scope import Scope, ScopeLayout, draw_scope
from playground.world.schedule import Stage, StageTiming

__all__ = ["MARGIN", "Hud", "HudInfo", "StageCosts", "scope_height"]

TEXT = (225, 228, 235)
DIM = (150, 155, 165)
PANEL = (0, 0, 0, 160)
HELP_PANEL = (12, 14, 20, 240)  # nearly opaque: the help must read over a busy scene
MARGIN = 8  # px between panels and the window's edge


def scope_height(window_height: int) -> int:
    """The scope strip's height (px) in a window ``window_height`` px high (it sits ``MARGIN``
    above the bottom edge)."""
    return max(min(120, window_height // 5), 56)


class StageCosts:
    """Mean wall-clock cost per step of each stage over the last ``window`` seconds of wall time."""

    def __init__(self, window: float = 0.5) -> None:
        self.window = window
        self._snapshot: dict[Stage, tuple[float, int]] = {}
        self._age = 0.0
        self.means: dict[Stage, float] = {}

    def update(self, timings: Mapping[Stage, StageTiming], elapsed: float) -> None:
        """Call once per rendered frame with the world's timings and the frame's wall time, s."""
        self._age += elapsed
        if self._snapshot and self._age < self.window:
            return
        means: dict[Stage, float] = {}
        for stage, t in timings.items():
            total0, calls0 = self._snapshot.get(stage, (0.0, 0))
            if t.calls > calls0:
                means[stage] = (t.total - total0) / (t.calls - calls0)
        if means or not self._snapshot:
            self.means = means
        self._snapshot = {s: (t.total, t.calls) for s, t in timings.items()}
        self._age = 0.0


@dataclass(frozen=True, slots=True)
class HudInfo:
    """What the HUD shows this frame (times in s, rates in Hz)."""

    title: str
    sim_time: float
    physics_hz: float
    render_hz: float
    speed: float
    paused: bool
    state: str | None = None
    stage_costs: Mapping[Stage, float] = field(default_factory=dict)
    notes: Sequence[str] = ()


class Hud:
    """Draws :class:`HudInfo`, the scope and the help overlay; every panel stays in the window."""

    def __init__(self, font: pygame.font.Font, small: pygame.font.Font) -> None:
        self.font = font
        self.small = small
        self.rects: list[pygame.Rect] = []
        self.scope_layout: ScopeLayout | None = None
        """Where the scope's parts were drawn last frame (None: no scope)."""

    def _panel(
        self,
        surf: pygame.Surface,
        rect: pygame.Rect,
        colour: tuple[int, int, int, int] = PANEL,
    ) -> None:
        shade_panel(surf, rect, colour)
        self.rects.append(rect)

    def _lines(
        self,
        surf: pygame.Surface,
        lines: Sequence[tuple[str, tuple[int, int, int]]],
        x: int,
        y: int,
    ) -> pygame.Rect:
        font = self.small
        h = font.get_linesize()
        w = max((font.size(t)[0] for t, _ in lines), default=0) + 12
        rect = pygame.Rect(x, y, w, h * len(lines) + 8)
        self._panel(surf, rect)
        for i, (text, colour) in enumerate(lines):
            surf.blit(font.render(text, True, colour), (x + 6, y + 4 + i * h))
        return rect

    def draw(
        self, surf: pygame.Surface, info: HudInfo, scope: Scope | None, left: int = MARGIN
    ) -> None:
        """Draw the status panel (top left, its left edge at ``left`` px) and the scope strip
        (bottom)."""
        self.rects = []
        self.scope_layout = None
        title = self.font.render(info.title, True, TEXT)
        lines: list[tuple[str, tuple[int, int, int]]] = []
        status = "PAUSED" if info.paused else f"×{info.speed:g}"
        lines.append((f"t = {info.sim_time:8.3f} s   {status}", TEXT))
        lines.append((f"physics {info.physics_hz:6.1f} Hz   render {info.render_hz:5.1f} Hz", TEXT))
        if info.state is not None:
            lines.append((f"player: {info.state}", COLOURS["player"]))
        if info.stage_costs:
            total = sum(info.stage_costs.values())
            lines.append((f"cost per step {total * 1e6:7.1f} µs", DIM))
            for stage, cost in info.stage_costs.items():
                lines.append((f"  {stage.name.lower():<8} {cost * 1e6:7.1f} µs", DIM))
        lines.extend((n, DIM) for n in info.notes)
        head = pygame.Rect(left, MARGIN, title.get_width() + 12, title.get_height() + 6)
        self._panel(surf, head)
        surf.blit(title, (left + 6, MARGIN + 3))
        self._lines(surf, lines, left, head.bottom + 2)
        if scope is not None:
            self._scope(surf, scope)

    def _scope(self, surf: pygame.Surface, scope: Scope) -> None:
        sw, sh = surf.get_size()
        height = scope_height(sh)
        rect = pygame.Rect(MARGIN, sh - height - MARGIN, sw - 2 * MARGIN, height)
        self._panel(surf, rect)
        self.scope_layout = draw_scope(surf, self.small, scope, rect)

    def draw_help(
        self, surf: pygame.Surface, lines: Sequence[tuple[str, str]], about: str = ""
    ) -> None:
        """Draw the level's description (``about``, wrapped) and the controls (key, action),
        centred in the window."""
        font = self.small
        h = font.get_linesize()
        kw = max(font.size(k)[0] for k, _ in lines) + 16
        w = kw + max(font.size(a)[0] for _, a in lines) + 24
        sw, sh = surf.get_size()
        width = min(max(w, 480), sw - 2 * MARGIN)
        wrapped = textwrap.wrap(about, width=max((width - 24) // max(font.size("n")[0], 1), 20))
        rows = len(wrapped) + (1 if wrapped else 0) + len(lines)
        rect = pygame.Rect(0, 0, width, min(h * rows + 16, sh - 2 * MARGIN))
        rect.center = (sw // 2, sh // 2)
        self._panel(surf, rect, HELP_PANEL)
        pygame.draw.rect(surf, DIM, rect, 1)
        y = rect.y + 8
        for text in wrapped:
            surf.blit(font.render(text, True, TEXT), (rect.x + 12, y))
            y += h
        if wrapped:
            y += h
        for key, action in lines:
            if y + h > rect.bottom:
                break
            surf.blit(font.render(key, True, COLOURS["player"]), (rect.x + 12, y))
            surf.blit(font.render(action, True, TEXT), (rect.x + 12 + kw, y))
            y += h
