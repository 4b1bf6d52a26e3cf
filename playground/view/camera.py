"""The camera: the one transform between world metres and screen pixels.

World y points up, screen y points down. The camera looks at a centre (m), magnifies by a zoom
(pixels per metre) and may roll so that a chosen "up" (the player's perceived up) points to the
top of the screen. Following and rolling are smoothed over *render* time; they never touch physics.

>>> cam = Camera(size=(800, 600), pixels_per_metre=50.0)
>>> cam.to_screen((0.0, 0.0))
(400.0, 300.0)
>>> cam.to_screen((1.0, 2.0))
(450.0, 200.0)
>>> cam.to_world(cam.to_screen((1.25, -3.5)))
(1.25, -3.5)
"""

from __future__ import annotations

import math

from playground.vec import Vec

__all__ = ["Camera"]

MIN_ZOOM = 2.0  # px/m: a 1 km level still fits a window
MAX_ZOOM = 1000.0  # px/m: a 1 mm detail is still a pixel

CENTRE_LIMIT = 1.0e9
"""m: the farthest the camera looks. A body flying off drags the camera at most this far, where a
float still resolves 1e-7 m: near 1e16 m adding the grid's 1 m spacing changes nothing, and the
grid loop would never end."""


class Camera:
    """World (m, y up) ↔ screen (px, y down), with follow, zoom and roll.

    Attributes:
        size: the screen size, px.
        centre: the world point at the middle of the screen, m.
        zoom: pixels per metre.
        roll: the camera's roll, rad (counter-clockwise); 0 keeps world y up on screen.
        follow_time: time constant of following a target, s of render time (0: lock on).
        roll_time: time constant of rolling toward a target up, s of render time.
    """

    def __init__(
        self,
        *,
        size: tuple[int, int],
        pixels_per_metre: float = 40.0,
        centre: Vec = (0.0, 0.0),
        follow_time: float = 0.15,
        roll_time: float = 0.3,
    ) -> None:
        if size[0] <= 0 or size[1] <= 0:
            raise ValueError(f"size: expected a positive (width, height) in px, got {size!r}")
        if not (math.isfinite(pixels_per_metre) and pixels_per_metre > 0.0):
            raise ValueError(f"pixels_per_metre: expected a number > 0, got {pixels_per_metre!r}")
        self.size = (int(size[0]), int(size[1]))
        self.zoom = min(max(float(pixels_per_metre), MIN_ZOOM), MAX_ZOOM)
        self._centre: Vec = (0.0, 0.0)
        self.centre = (float(centre[0]), float(centre[1]))
        self.roll = 0.0
        self.follow_time = follow_time
        self.roll_time = roll_time
        self._cos = 1.0
        self._sin = 0.0

    @property
    def centre(self) -> Vec:
        """The world point at the middle of the screen, m, within ±:data:`CENTRE_LIMIT`; a
        non-finite centre is ignored (the camera stays where it was).

        >>> cam = Camera(size=(10, 10))
        >>> cam.centre = (1e300, float("nan"))
        >>> cam.centre
        (1000000000.0, 0.0)
        """
        return self._centre

    @centre.setter
    def centre(self, value: Vec) -> None:
        x, y = (float(v) for v in value)
        old = self._centre
        self._centre = (
            min(max(x, -CENTRE_LIMIT), CENTRE_LIMIT) if math.isfinite(x) else old[0],
            min(max(y, -CENTRE_LIMIT), CENTRE_LIMIT) if math.isfinite(y) else old[1],
        )

    # -- the transform ---------------------------------------------------------------------------

    def to_screen(self, p: Vec) -> Vec:
        """World point (m) to screen point (px)."""
        dx = (p[0] - self.centre[0]) * self.zoom
        dy = (p[1] - self.centre[1]) * self.zoom
        # Rotate by −roll: the camera turned by +roll makes the world turn the other way.
        rx = self._cos * dx + self._sin * dy
        ry = -self._sin * dx + self._cos * dy
        return (self.size[0] / 2.0 + rx, self.size[1] / 2.0 - ry)

    def to_world(self, s: Vec) -> Vec:
        """Screen point (px) to world point (m)."""
        rx = s[0] - self.size[0] / 2.0
        ry = self.size[1] / 2.0 - s[1]
        dx = self._cos * rx - self._sin * ry
        dy = self._sin * rx + self._cos * ry
        return (self.centre[0] + dx / self.zoom, self.centre[1] + dy / self.zoom)

    def vector(self, v: Vec) -> Vec:
        """A world vector (any unit) to its screen direction and length in px per unit.

        >>> Camera(size=(10, 10), pixels_per_metre=10.0).vector((1.0, 1.0))
        (10.0, -10.0)
        """
        rx = self._cos * v[0] + self._sin * v[1]
        ry = -self._sin * v[0] + self._cos * v[1]
        return (rx * self.zoom, -ry * self.zoom)

    def pixels(self, metres: float) -> float:
        """A length in m to px."""
        return metres * self.zoom

    # -- motion (render time) --------------------------------------------------------------------

    def set_roll(self, roll: float) -> None:
        """Set the roll (rad) at once."""
        self.roll = math.remainder(roll, 2.0 * math.pi)
        self._cos = math.cos(self.roll)
        self._sin = math.sin(self.roll)

    def zoom_by(self, factor: float) -> None:
        """Multiply the zoom by ``factor`` (clamped to a sane range)."""
        self.zoom = min(max(self.zoom * factor, MIN_ZOOM), MAX_ZOOM)

    def follow(self, target: Vec, elapsed: float) -> None:
        """Move the centre toward ``target`` (m) over ``elapsed`` s of render time.

        >>> cam = Camera(size=(10, 10), follow_time=0.0)
        >>> cam.follow((3.0, 4.0), 0.016)
        >>> cam.centre
        (3.0, 4.0)
        """
        a = _blend(elapsed, self.follow_time)
        cx, cy = self.centre
        self.centre = (cx + a * (target[0] - cx), cy + a * (target[1] - cy))

    def keep_in_view(self, target: Vec, margin: float) -> None:
        """Move the centre just enough that ``target`` (m) lies at least ``margin`` (a share of
        the window, 0 … 0.5) inside the window's edges: a fast body is never left behind.

        >>> cam = Camera(size=(100, 100), pixels_per_metre=10.0)
        >>> cam.keep_in_view((20.0, 0.0), 0.1)
        >>> cam.to_screen((20.0, 0.0))
        (90.0, 50.0)
        """
        sx, sy = self.to_screen(target)
        w, h = self.size
        lo_x, hi_x = margin * w, (1.0 - margin) * w
        lo_y, hi_y = margin * h, (1.0 - margin) * h
        ex = sx - min(max(sx, lo_x), hi_x)
        ey = sy - min(max(sy, lo_y), hi_y)
        if (ex, ey) == (0.0, 0.0) or not (math.isfinite(ex) and math.isfinite(ey)):
            return
        moved = self.to_world((w / 2.0 + ex, h / 2.0 + ey))
        self.centre = moved

    def roll_toward(self, up: Vec | None, elapsed: float) -> None:
        """Turn so that the world vector ``up`` points to the top of the screen (None: level).

        >>> cam = Camera(size=(10, 10), roll_time=0.0)
        >>> cam.roll_toward((-1.0, 0.0), 0.016)
        >>> round(cam.roll, 6), [round(c / cam.zoom, 6) + 0.0 for c in cam.vector((-1.0, 0.0))]
        (1.570796, [0.0, -1.0])
        """
        if up is None or not (math.isfinite(up[0]) and math.isfinite(up[1])) or up == (0.0, 0.0):
            goal = 0.0
        else:
            goal = math.atan2(up[1], up[0]) - math.pi / 2.0
        error = math.remainder(goal - self.roll, 2.0 * math.pi)
        self.set_roll(self.roll + _blend(elapsed, self.roll_time) * error)


def _blend(elapsed: float, time_constant: float) -> float:
    """Fraction of the way to go after ``elapsed`` s of a first-order lag of ``time_constant``."""
    if time_constant <= 0.0:
        return 1.0
    return 1.0 - math.exp(-max(elapsed, 0.0) / time_constant)
