"""The live tuning panel: sliders for the player's hover spring, the 1€ filter of perceived gravity
and the physics step, drawn with pygame-ce.

The panel only edits a :class:`Knobs` value; the app applies it to the world between two steps,
so a change acts from the next step on. The hover's stability limit, 2π·f·dt < 2ζ + 2√(ζ² + 1)
(:func:`playground.controller.hover_limit`), is drawn on the frequency slider and written beside
it, and the frequency is never let past it: at most ``SAFE_FRACTION`` of the limit, also when a
larger dt or a smaller damping ratio lowers the limit.

>>> knobs = Knobs(hover_frequency=30.0, hover_damping=0.0, min_cutoff=2.0, beta=0.05,
...               dt=1 / 30, substeps=1)
>>> round(knobs.hover_ceiling, 3), round(knobs.stable().hover_frequency, 3)
(9.549, 9.358)
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import pygame

from playground.controller.spring import hover_limit
from playground.gravity import Uniform
from playground.vec import Vec
from playground.view.draw import COLOURS, shade_panel
from playground.world.world import World

__all__ = ["SAFE_FRACTION", "SLIDERS", "Knobs", "Slider", "TuningPanel"]

SAFE_FRACTION = 0.98  # the hover frequency stays below this share of its stability limit
TRACK_PX = 160  # px: length of a slider's track
ROW_PX = 22  # px: height of one slider row
LABEL_PX = 150  # px: the label column
VALUE_PX = 130  # px: the value column
PAD = 6  # px: inner margin


@dataclass(frozen=True, slots=True)
class Knobs:
    """The tunable values.

    Attributes:
        hover_frequency: the player's hover spring, Hz (None fields: no player to tune).
        hover_damping: its damping ratio ζ.
        min_cutoff: the 1€ filter's cutoff at rest, Hz.
        beta: the 1€ filter's speed coefficient.
        dt: the physics step, s.
        substeps: ``space.step`` calls per step.
        gravity: the magnitude of a uniform gravity field, m/s² (None: the field is not
            uniform; its direction is kept, straight down where it was zero).
    """

    hover_frequency: float | None
    hover_damping: float | None
    min_cutoff: float
    beta: float
    dt: float
    substeps: int
    gravity: float | None = None

    @property
    def hover_ceiling(self) -> float:
        """The hover frequency (Hz) at the stability limit for this ζ and dt (inf: no hover)."""
        if self.hover_damping is None:
            return math.inf
        return hover_limit(self.hover_damping) / (2.0 * math.pi * self.dt)

    @classmethod
    def of(cls, world: World, ctrl: Any) -> Knobs:
        """The values as ``world`` and the player's controller ``ctrl`` (None: no player) have
        them now."""
        cfg = world.config
        hover = getattr(ctrl, "config", None)
        field = world.gravity
        return cls(
            hover_frequency=getattr(hover, "hover_frequency", None),
            hover_damping=getattr(hover, "hover_damping", None),
            min_cutoff=cfg.perception.min_cutoff,
            beta=cfg.perception.beta,
            dt=cfg.dt,
            substeps=cfg.substeps,
            gravity=math.hypot(*field.g) if isinstance(field, Uniform) else None,
        )

    def apply(self, world: World, ctrl: Any) -> None:
        """Put these values into ``world`` and ``ctrl`` between two steps (they act from the next
        step on): dt and substeps into the world's config, the 1€ parameters into perceived
        gravity, the hover into the player's controller, a uniform field's magnitude into the
        world's gravity. Only what differs is set."""
        cfg = world.config
        if (self.dt, self.substeps) != (cfg.dt, cfg.substeps):
            world.config = dataclasses.replace(cfg, dt=self.dt, substeps=self.substeps)
        p = cfg.perception
        if (self.min_cutoff, self.beta) != (p.min_cutoff, p.beta):
            world.set_perception(dataclasses.replace(p, min_cutoff=self.min_cutoff, beta=self.beta))
        if self.hover_frequency is not None and self.hover_damping is not None:
            ctrl.tune_hover(self.hover_frequency, self.hover_damping)
        field = world.gravity
        if self.gravity is not None and isinstance(field, Uniform):
            g = math.hypot(*field.g)
            if self.gravity != g:
                ux, uy = (field.g[0] / g, field.g[1] / g) if g > 0.0 else (0.0, -1.0)
                world.gravity = (ux * self.gravity, uy * self.gravity)

    def stable(self) -> Knobs:
        """These knobs with the hover frequency lowered below its limit if it was past it."""
        f = self.hover_frequency
        top = SAFE_FRACTION * self.hover_ceiling
        if f is None or f <= top:
            return self
        return dataclasses.replace(self, hover_frequency=top)


@dataclass(frozen=True, slots=True)
class Slider:
    """One slider: a :class:`Knobs` field, its label, range and scale (log or linear, integer)."""

    field: str
    label: str
    low: float
    high: float
    log: bool = False
    integer: bool = False

    def fraction(self, value: float) -> float:
        """Where ``value`` sits on the track, 0 … 1 (clamped)."""
        v = min(max(value, self.low), self.high)
        if self.log:
            return math.log(v / self.low) / math.log(self.high / self.low)
        return (v - self.low) / (self.high - self.low)

    def value(self, fraction: float) -> float:
        """The value at ``fraction`` of the track (clamped; rounded for an integer slider).

        >>> Slider("substeps", "substeps", 1, 8, integer=True).value(0.6)
        5.0
        >>> round(Slider("dt", "dt", 0.001, 0.1, log=True).value(0.5), 6)
        0.01
        """
        f = min(max(fraction, 0.0), 1.0)
        if self.log:
            v = self.low * (self.high / self.low) ** f
        else:
            v = self.low + f * (self.high - self.low)
        return float(round(v)) if self.integer else v


SLIDERS: tuple[Slider, ...] = (
    Slider("hover_frequency", "hover frequency", 0.5, 40.0, log=True),
    Slider("hover_damping", "hover damping ζ", 0.0, 2.0),
    Slider("min_cutoff", "1€ min_cutoff", 0.05, 20.0, log=True),
    Slider("beta", "1€ beta", 0.0, 1.0),
    Slider("dt", "dt", 1.0 / 960.0, 1.0 / 20.0, log=True),
    Slider("substeps", "substeps", 1, 8, integer=True),
    Slider("gravity", "gravity |g|", 0.0, 30.0),
)


def _shown(field: str, value: float) -> str:
    if field == "hover_frequency":
        return f"{value:.2f} Hz"
    if field == "min_cutoff":
        return f"{value:.3g} Hz"
    if field == "dt":
        return f"{value * 1e3:.2f} ms ({1.0 / value:.0f} Hz)"
    if field == "substeps":
        return f"{value:.0f}"
    if field == "gravity":
        return f"{value:.2f} m/s²"
    return f"{value:.3g}"


class TuningPanel:
    """Draws :class:`Knobs` as sliders and turns mouse presses and drags on them into new knobs.

    :attr:`knobs` is what the panel shows; :attr:`changed` is set when the user moved a slider
    (the app applies it and clears it).
    """

    def __init__(self, font: pygame.font.Font) -> None:
        self.font = font
        self.visible = False
        self.knobs: Knobs | None = None
        self.changed = False
        self.rect = pygame.Rect(0, 0, 0, 0)
        self._tracks: dict[str, pygame.Rect] = {}
        self._held: str | None = None

    def show(self, knobs: Knobs) -> None:
        """Show ``knobs`` (a fresh level's values), forgetting any drag in progress."""
        self.knobs = knobs
        self._held = None

    def applied(self, knobs: Knobs) -> None:
        """Show ``knobs``, the world's values once the panel's change was applied; a drag in
        progress goes on (the held slider keeps following the mouse)."""
        self.knobs = knobs
        self.changed = False

    def _rows(self) -> list[Slider]:
        k = self.knobs
        if k is None:
            return []
        return [s for s in SLIDERS if getattr(k, s.field) is not None]

    def draw(self, surf: pygame.Surface, topleft: Vec) -> pygame.Rect:
        """Draw the panel with its top-left corner at ``topleft``; returns its rectangle."""
        rows = self._rows()
        k = self.knobs
        if not self.visible or k is None:
            self.rect = pygame.Rect(0, 0, 0, 0)
            return self.rect
        line = self.font.get_linesize()
        notes = ["tuning (T hides, R restores the level's values); applies from the next step"]
        if k.hover_damping is not None:
            notes.append(
                f"hover stable while f < {k.hover_ceiling:.3g} Hz  (2π·f·dt < "
                f"{hover_limit(k.hover_damping):.3g} at ζ = {k.hover_damping:.2f})"
            )
        width = max(
            LABEL_PX + TRACK_PX + VALUE_PX + 3 * PAD,
            max(self.font.size(n)[0] for n in notes) + 2 * PAD,
        )
        height = len(notes) * line + len(rows) * ROW_PX + 2 * PAD
        rect = pygame.Rect(int(topleft[0]), int(topleft[1]), width, height)
        shade_panel(surf, rect, (0, 0, 0, 200))
        y = rect.y + PAD
        for i, text in enumerate(notes):
            colour = COLOURS["text"] if i == 0 else COLOURS["hover"]
            surf.blit(self.font.render(text, True, colour), (rect.x + PAD, y))
            y += line
        self._tracks = {}
        for slider in rows:
            value = float(getattr(k, slider.field))
            surf.blit(self.font.render(slider.label, True, COLOURS["text"]), (rect.x + PAD, y + 2))
            track = pygame.Rect(rect.x + PAD + LABEL_PX, y + ROW_PX // 2 - 2, TRACK_PX, 4)
            pygame.draw.rect(surf, COLOURS["dim"], track)
            if slider.field == "hover_frequency" and math.isfinite(k.hover_ceiling):
                # The stability limit on the track: everything right of it is refused.
                x = track.x + slider.fraction(k.hover_ceiling) * track.width
                if k.hover_ceiling < slider.high:
                    bad = pygame.Rect(round(x), track.y - 3, track.right - round(x), 10)
                    pygame.draw.rect(surf, COLOURS["grip"], bad)
            knob_x = track.x + slider.fraction(value) * track.width
            pygame.draw.circle(surf, COLOURS["text"], (round(knob_x), track.centery), 6)
            surf.blit(
                self.font.render(_shown(slider.field, value), True, COLOURS["text"]),
                (track.right + 2 * PAD, y + 2),
            )
            self._tracks[slider.field] = track
            y += ROW_PX
        self.rect = rect
        return rect

    def press(self, pos: Vec) -> bool:
        """A mouse press at ``pos`` (px): True if the panel took it (a press on a slider's row
        moves that slider there and holds it for dragging)."""
        if not self.visible or not self.rect.collidepoint(pos):
            return False
        for name, track in self._tracks.items():
            if track.inflate(16, ROW_PX - track.height).collidepoint(pos):
                self._held = name
                self._set(pos)
        return True

    def drag(self, pos: Vec) -> bool:
        """The mouse moved to ``pos`` (px): True if a slider is held (and it followed)."""
        if self._held is None:
            return False
        self._set(pos)
        return True

    def release(self) -> bool:
        """The mouse button went up: True if a slider was held."""
        held = self._held is not None
        self._held = None
        return held

    def _set(self, pos: Vec) -> None:
        name = self._held
        if name is None or self.knobs is None:
            return
        slider = next(s for s in SLIDERS if s.field == name)
        track = self._tracks[name]
        value = slider.value((pos[0] - track.x) / track.width)
        change: dict[str, Any] = {name: int(value) if slider.integer else value}
        new = dataclasses.replace(self.knobs, **change).stable()
        if new != self.knobs:
            self.knobs = new
            self.changed = True
