"""A crate's contact force read with the force solver alone, on a plain pymunk space: no World,
no controller, the game's own space and loop. A 10 kg crate drops onto a floor; once it rests,
the floor holds it up with its weight, 98.1 N, and it feels g.

Run it with ``python examples/crate.py`` (Space drops it again, Esc quits).
"""

from __future__ import annotations

import pygame
import pymunk

from playground import ForceSensor

PPM = 60.0  # pixels a metre
SIZE = (640, 400)  # px
MASS = 10.0  # kg


def build() -> tuple[pymunk.Body, ForceSensor]:
    """A space with a floor and a 10 kg, 1 m crate 2 m up, and a sensor tracking the crate."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)  # m/s²
    floor = pymunk.Segment(space.static_body, (-4.0, 0.0), (4.0, 0.0), 0.05)
    floor.friction = 0.8
    crate = pymunk.Body(MASS, pymunk.moment_for_box(MASS, (1.0, 1.0)))
    crate.position = (0.0, 2.5)
    box = pymunk.Poly.create_box(crate, (1.0, 1.0))
    box.friction = 0.8
    space.add(floor, crate, box)
    sensor = ForceSensor(space)
    sensor.track(crate)
    return crate, sensor  # the space is sensor.space


def to_screen(x: float, y: float) -> tuple[float, float]:
    return SIZE[0] / 2 + x * PPM, SIZE[1] - 60 - y * PPM


def main(frames: int | None = None) -> list[tuple[float, float]]:
    """Play; ``frames`` runs that many frames of 1/60 s headless. Returns the crate's support
    force (N) after every frame."""
    pygame.init()
    screen = pygame.display.set_mode(SIZE)
    clock, font = pygame.time.Clock(), pygame.font.SysFont(None, 24)
    crate, sensor = build()
    trace: list[tuple[float, float]] = []
    while frames is None or len(trace) < frames:
        for event in pygame.event.get():
            if event.type == pygame.QUIT or (
                event.type == pygame.KEYDOWN and event.key == pygame.K_ESCAPE
            ):
                return trace
            if event.type == pygame.KEYDOWN and event.key == pygame.K_SPACE:
                crate.position, crate.velocity = (0.0, 2.5), (0.0, 0.0)
        sensor.step(1 / 60, substeps=2)  # steps the space, reading the crate around it
        support = sensor.readings(crate).support  # N: what the floor does to it
        trace.append(support)

        screen.fill((245, 245, 240))
        pygame.draw.line(screen, (60, 60, 60), to_screen(-4, 0), to_screen(4, 0), 3)
        corners = [to_screen(*crate.local_to_world(v)) for v in box_corners(crate)]
        pygame.draw.polygon(screen, (180, 120, 60), corners)
        x, y = crate.position
        tip = (x + support[0] / 100, y + support[1] / 100)  # 1 m of arrow per 100 N
        pygame.draw.line(screen, (40, 160, 60), to_screen(x, y), to_screen(*tip), 4)
        text = f"support {support[1]:6.1f} N   (m·g = {MASS * 9.81:.1f} N)"
        screen.blit(font.render(text, True, (20, 20, 20)), (10, 10))
        pygame.display.flip()
        if frames is None:
            clock.tick(60)
    pygame.quit()
    return trace


def box_corners(body: pymunk.Body) -> list[tuple[float, float]]:
    """The crate's corners in its own frame, m."""
    (shape,) = body.shapes
    assert isinstance(shape, pymunk.Poly)
    return [(v.x, v.y) for v in shape.get_vertices()]


if __name__ == "__main__":
    main()
