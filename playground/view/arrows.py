"""Force arrows that read at any zoom: their scale, their layout and the peak held between frames.

Scale: a body's weight ``m·g₀`` (g₀ the standard gravity, a fixed reference, so a body whose
gravity is nullified still has a scale) is drawn ``WEIGHT_BODY`` times the body's own size on
screen, kept between ``MIN_WEIGHT_PX`` and ``MAX_WEIGHT_PX``: zooming in makes arrows longer with
the body, a 5 t whale and a 10 kg crate both get readable arrows. With ``x = |F| / (m·g₀)`` an
arrow is ``W·x`` long up to one weight and ``W·(1 + ln x)`` beyond, capped at ``MAX_WEIGHTS·W``:
a tenfold spike is 3.3 weights long instead of leaving the window.

>>> round(arrow_length(98.1, 10.0, 60.0), 6), round(arrow_length(5000 * 9.81, 5000.0, 60.0), 6)
(60.0, 60.0)
>>> round(arrow_length(10 * 98.1, 10.0, 60.0), 1)
198.2
>>> weight_pixels(1.8, 10.0), round(weight_pixels(1.8, 60.0), 6), weight_pixels(1.8, 1000.0)
(36.0, 86.4, 140.0)

Layout: arrows that would lie on top of one another (parallel within ``PARALLEL_RAD``, closer than
their widths, overlapping along their length) are moved sideways until none hides another.

Peak hold: physics runs at its own rate, so between two drawn frames several steps pass; a
one-step impulse (a bounce) would be seen only if it fell on the drawn step. :class:`PeakHold`
keeps, per body, the largest support of the steps since the last drawn frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import pymunk

from playground.gravity import STANDARD_GRAVITY
from playground.vec import Vec
from playground.world.world import World

__all__ = [
    "BUNDLE_PX",
    "G0",
    "PeakHold",
    "ScreenArrow",
    "arrow_length",
    "body_size",
    "spread",
    "weight_pixels",
]

G0 = STANDARD_GRAVITY  # m/s²: the reference weight per kilogram for arrow scaling
WEIGHT_BODY = 0.8  # one weight is this many times the body's size on screen …
MIN_WEIGHT_PX = 36.0  # px: … but never shorter (a far-away body's arrows still read) …
MAX_WEIGHT_PX = 140.0  # px: … nor longer (a close-up whale's arrows stay in the window)
MAX_WEIGHTS = 3.5  # an arrow is at most this many weights long (e^2.5 ≈ 12 weights of force)
MIN_ARROW_PX = 2.0  # px: shorter arrows are not drawn
PARALLEL_RAD = math.radians(12.0)  # arrows this close to parallel can hide each other
GAP_PX = 2.0  # px: clear space kept between arrows moved apart
MAX_SHIFTS = 8  # sideways moves tried per arrow before it is left where it is
BUNDLE_PX = 48.0  # px: a body smaller than this on screen gets one bundle of arrows, off its body


def weight_pixels(size_m: float, zoom: float) -> float:
    """On-screen length (px) of one weight for a body ``size_m`` (m) across at ``zoom`` (px/m)."""
    return min(max(WEIGHT_BODY * size_m * zoom, MIN_WEIGHT_PX), MAX_WEIGHT_PX)


def arrow_length(force: float, mass: float, weight_px: float) -> float:
    """On-screen length (px) of a force of magnitude ``force`` (N) on a body of ``mass`` (kg)
    whose weight is ``weight_px`` px long."""
    if not (mass > 0.0 and math.isfinite(mass) and math.isfinite(force)):
        return 0.0
    x = abs(force) / (mass * G0)
    length = weight_px * x if x <= 1.0 else weight_px * (1.0 + math.log(x))
    return min(length, MAX_WEIGHTS * weight_px)


def body_size(body: pymunk.Body) -> float:
    """Twice the farthest reach of the body's shapes from its centre of gravity, m (independent
    of its angle)."""
    c = body.center_of_gravity
    reach = 0.0
    for s in body.shapes:
        if isinstance(s, pymunk.Circle):
            reach = max(reach, (s.offset - c).length + s.radius)
        elif isinstance(s, pymunk.Segment):
            reach = max(reach, (s.a - c).length + s.radius, (s.b - c).length + s.radius)
        elif isinstance(s, pymunk.Poly):
            reach = max(reach, *((v - c).length + s.radius for v in s.get_vertices()))
    return 2.0 * reach


@dataclass(frozen=True, slots=True)
class ScreenArrow:
    """An arrow on screen: start and direction·length (px), colour key, width (px), and what it
    stands for: the force's magnitude (N; NaN: not a force) and the body it acts on ("": none),
    for its label."""

    start: Vec
    d: Vec
    kind: str
    width: int = 2
    newtons: float = math.nan
    body: str = ""


def _overlaps(a: ScreenArrow, b: ScreenArrow) -> bool:
    la, lb = math.hypot(*a.d), math.hypot(*b.d)
    if la < MIN_ARROW_PX or lb < MIN_ARROW_PX:
        return False
    ux, uy = a.d[0] / la, a.d[1] / la
    cross = abs(ux * b.d[1] - uy * b.d[0]) / lb
    if cross > math.sin(PARALLEL_RAD):
        return False
    # Perpendicular distance of b's start from a's line, and overlap along a's direction.
    rx, ry = b.start[0] - a.start[0], b.start[1] - a.start[1]
    if abs(ux * ry - uy * rx) >= (a.width + b.width) / 2.0 + GAP_PX:
        return False
    s0 = ux * rx + uy * ry
    s1 = s0 + ux * b.d[0] + uy * b.d[1]
    return max(s0, s1) > 0.0 and min(s0, s1) < la


def spread(arrows: Sequence[ScreenArrow]) -> list[ScreenArrow]:
    """The arrows in the same order, each moved sideways (alternately left and right, by the
    widths involved) off any earlier arrow it would lie on.

    >>> up = ScreenArrow((0.0, 0.0), (0.0, -50.0), "support", 2)
    >>> [a.start for a in spread([up, up, up])]
    [(0.0, 0.0), (4.0, 0.0), (-4.0, 0.0)]
    """
    placed: list[ScreenArrow] = []
    for a in arrows:
        n = math.hypot(*a.d)
        moved = a
        if n >= MIN_ARROW_PX:
            px, py = -a.d[1] / n, a.d[0] / n
            k = 0
            while k < MAX_SHIFTS and any(_overlaps(p, moved) for p in placed):
                k += 1
                step = max(a.width, max((p.width for p in placed), default=2)) + GAP_PX
                side = (k + 1) // 2 * (1.0 if k % 2 else -1.0) * step
                moved = replace(a, start=(a.start[0] + px * side, a.start[1] + py * side))
        placed.append(moved)
    return placed


class PeakHold:
    """The largest support force (N) of each tracked body over the steps since the last drawn
    frame: call :meth:`sample` after every physics step and :meth:`peaks` when drawing.

    A paused view keeps showing the last frame's peaks; the first step after a drawn frame starts
    a new window.
    """

    def __init__(self) -> None:
        self._peak: dict[str, Vec] = {}
        self._drawn = False

    def sample(self, world: World) -> None:
        """Fold this step's support of every tracked body into the held peaks."""
        if self._drawn:
            self._peak.clear()
            self._drawn = False
        for body in world.tracked_bodies:
            name = world.name_of(body)
            if name is None:
                continue
            f = world.forces(name).support
            held = self._peak.get(name)
            if held is None or math.hypot(*f) > math.hypot(*held):
                self._peak[name] = f

    def peaks(self) -> dict[str, Vec]:
        """The held peaks by body name (the window closes: the next sample starts a new one)."""
        self._drawn = True
        return dict(self._peak)
