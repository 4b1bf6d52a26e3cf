"""The oscilloscope strip: one body's |support force|, raw and filtered, over the last seconds of
simulated time, against its weight m·g and a time axis.

Its scale is robust: the top is a high percentile of the window (``SCALE_QUANTILE``), with
headroom, kept between ``MIN_TOP_WEIGHTS`` and ``MAX_TOP_WEIGHTS`` weights, so a one-step impact
spike (a bounce, a load-time kick) is drawn clipped at the top with its value written beside it
instead of flattening everything else; the m·g line never sinks below 1/``MAX_TOP_WEIGHTS`` of
the height.

>>> scope = Scope(seconds=1.0, dt=0.25)
>>> for k in range(6):
...     scope.push(float(k), float(k) / 2)
>>> scope.raw.tolist(), scope.filtered.tolist()
([2.0, 3.0, 4.0, 5.0], [1.0, 1.5, 2.0, 2.5])
>>> scope_top(np.full(100, 700.0), 700.0), scope_top(np.array([700.0] * 99 + [7000.0]), 700.0)
(1400.0, 1400.0)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import pygame
from numpy.typing import NDArray

from playground.view.draw import COLOURS
from playground.world.world import World

__all__ = ["Scope", "ScopeLayout", "draw_scope", "scope_on", "scope_top"]

SCALE_QUANTILE = 0.97  # the top follows this quantile of the window: 3 % of it may clip
HEADROOM = 1.25  # … times this
MIN_TOP_WEIGHTS = 2.0  # the top is at least two weights (m·g at mid-height at rest) …
MAX_TOP_WEIGHTS = 4.5  # … and at most 4.5 (the m·g line stays above 22 % of the height)
LINE_MG = (200, 200, 200)
DASH_PX = 6  # px: dashes of the m·g line


class Scope:
    """A ring buffer of |support| raw and filtered (N), one sample per physics step.

    ``seconds`` of history at step ``dt`` (s); :attr:`raw` and :attr:`filtered` are oldest first.
    ``name`` is the body it follows and ``weight`` its m·g (N), drawn as a reference line.
    """

    def __init__(
        self, seconds: float = 4.0, dt: float = 1.0 / 120.0, name: str = "", weight: float = 0.0
    ) -> None:
        if not (seconds > 0.0 and dt > 0.0):
            raise ValueError(f"seconds, dt: expected numbers > 0, got {seconds!r}, {dt!r}")
        self.seconds = seconds
        self.dt = dt
        self.name = name
        self.weight = weight
        self.capacity = max(round(seconds / dt), 2)
        self._raw = np.zeros(self.capacity)
        self._filtered = np.zeros(self.capacity)
        self._count = 0
        self._read_at = -1  # the world's step last read (-1: none)

    def read(self, world: World) -> None:
        """Push the body's |support| raw and its perceived weight m·|g_perceived| (N) from
        ``world``, once per physics step (a second read in the same step adds nothing)."""
        p = self.name or None
        if p is None or world.steps == self._read_at:
            return
        try:
            reading = world.forces(p)
            pg = world.perceived_gravity(p)
        except KeyError:
            return
        m = world.body(p).mass
        self.push(math.hypot(*reading.support), m * math.hypot(*pg))
        self._read_at = world.steps

    def push(self, raw: float, filtered: float) -> None:
        """Add one step's |support| raw and filtered, N."""
        i = self._count % self.capacity
        self._raw[i] = raw
        self._filtered[i] = filtered
        self._count += 1

    def clear(self) -> None:
        self._count = 0

    def _ordered(self, a: NDArray[np.float64]) -> NDArray[np.float64]:
        if self._count <= self.capacity:
            return a[: self._count].copy()
        i = self._count % self.capacity
        return np.concatenate([a[i:], a[:i]])

    @property
    def raw(self) -> NDArray[np.float64]:
        return self._ordered(self._raw)

    @property
    def filtered(self) -> NDArray[np.float64]:
        return self._ordered(self._filtered)


@functools.lru_cache(maxsize=8)
def _dashes(width: int) -> pygame.Surface:
    """The m·g line's dashes, ``width`` px long, 1 px high (made once per width)."""
    strip = pygame.Surface((width, 1))
    strip.set_colorkey((0, 0, 0))
    for x in range(0, width, DASH_PX * 2):
        pygame.draw.line(strip, LINE_MG, (x, 0), (min(x + DASH_PX, width), 0), 1)
    return strip


def scope_on(world: World, name: str | None, seconds: float, dt: float) -> Scope:
    """A scope of ``seconds`` at step ``dt`` on the body ``name`` with its weight m·g as the
    reference line (N; none where it feels no gravity: there is no weight to compare with), or
    on nobody if ``name`` is not in ``world``."""
    if name is None or name not in world.names:
        return Scope(seconds=seconds, dt=dt)
    g = math.hypot(*world.gravity_at(name))
    return Scope(seconds=seconds, dt=dt, name=name, weight=world.body(name).mass * g)


def scope_top(values: NDArray[np.float64], weight: float) -> float:
    """The force (N) at the top of the scope for the ``values`` in view and a ``weight`` m·g (N)."""
    finite = values[np.isfinite(values)]
    q = float(np.quantile(finite, SCALE_QUANTILE)) if finite.size else 0.0
    if weight > 0.0 and math.isfinite(weight):
        return min(max(HEADROOM * q, MIN_TOP_WEIGHTS * weight), MAX_TOP_WEIGHTS * weight)
    return HEADROOM * q if q > 0.0 else 1.0


@dataclass(frozen=True, slots=True)
class ScopeLayout:
    """Where :func:`draw_scope` put things (px): the plot, the title line above it, the clipped
    spike's value (None: no spike clipped), and the force at the plot's top, N."""

    plot: pygame.Rect
    title: pygame.Rect
    spike: pygame.Rect | None
    top: float


def draw_scope(
    surf: pygame.Surface, font: pygame.font.Font, scope: Scope, rect: pygame.Rect
) -> ScopeLayout:
    """Draw the scope into ``rect`` (its panel already drawn); returns where things went.

    The title has its own line above the plot, so nothing drawn in the plot (a clipped spike's
    value sits at the plot's top) can cover it."""
    raw, filt = scope.raw, scope.filtered
    line = font.get_linesize()
    plot = pygame.Rect(rect.x + 46, rect.y + line + 4, rect.width - 52, rect.height - line - 22)
    top = scope_top(np.concatenate([raw, filt]), scope.weight)

    def y_of(v: float) -> float:
        return plot.bottom - min(max(v / top, 0.0), 1.0) * plot.height

    # Time axis: a tick a second, labelled back from now.
    n = scope.capacity
    per_px = (plot.width - 1) / (n - 1)
    for s in range(math.floor(scope.seconds) + 1):
        x = plot.right - s / scope.dt * per_px
        if x < plot.x:
            break
        pygame.draw.line(surf, COLOURS["grid"], (x, plot.y), (x, plot.bottom))
        label = font.render("now" if s == 0 else f"−{s} s", True, COLOURS["dim"])
        left = min(x - label.get_width() // 2, plot.right - label.get_width())
        surf.blit(label, (left, plot.bottom + 2))
    pygame.draw.line(surf, COLOURS["dim"], (plot.x, plot.bottom), (plot.right, plot.bottom))
    surf.blit(font.render(f"{top:.0f} N", True, COLOURS["dim"]), (rect.x + 4, plot.y))
    surf.blit(font.render("0", True, COLOURS["dim"]), (rect.x + 4, plot.bottom - 8))
    title = f"{scope.name}: |support| raw (thin) / filtered (thick), N"
    text = font.render(title, True, COLOURS["dim"])
    title_rect = surf.blit(text, (plot.x, rect.y + 2))
    if raw.size < 2:
        return ScopeLayout(plot, title_rect, None, top)
    xs = plot.right - (raw.size - 1 - np.arange(raw.size)) * per_px
    for data, colour, width in (
        (raw, COLOURS["support"], 1),
        (filt, COLOURS["support_filtered"], 2),
    ):
        pts = np.column_stack([xs, plot.bottom - np.clip(data / top, 0.0, 1.0) * plot.height])
        pygame.draw.lines(surf, colour, False, pts.tolist(), width)
    if scope.weight > 0.0:
        # Dashed and on top: at rest the traces run along it and show through its gaps.
        y = round(y_of(scope.weight))
        surf.blit(_dashes(plot.width), (plot.x, y))
        surf.blit(font.render("m·g", True, LINE_MG), (rect.x + 4, y - 8))
    # The largest clipped spike, with its value, where it happened.
    over = np.nonzero(raw > top)[0]
    spike: pygame.Rect | None = None
    if over.size:
        i = int(over[np.argmax(raw[over])])
        x = float(xs[i])
        value = font.render(f"{raw[i]:.0f} N", True, COLOURS["support"])
        pygame.draw.polygon(
            surf, COLOURS["support"], [(x, plot.y), (x - 4, plot.y + 6), (x + 4, plot.y + 6)]
        )
        left = min(max(x - value.get_width() / 2, plot.x), plot.right - value.get_width())
        # On its own dark box: the value reads over the traces.
        spike = value.get_rect(topleft=(round(left), plot.y + 7)).inflate(4, 0)
        surf.fill(COLOURS["background"], spike)
        surf.blit(value, (left, plot.y + 7))
    return ScopeLayout(plot, title_rect, spike, top)
