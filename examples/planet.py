"""A walk around a small planet: radial gravity, and a camera that turns with the player's
perceived up, so the ground is always below it on screen.

Run it with ``python examples/planet.py`` (Left/Right walk, Up jumps, Esc quits).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import pygame
import pymunk

from playground import Controller, Intent, Radial, World

RADIUS = 10.0  # m, the planet's
PPM = 24.0  # pixels a metre
SIZE = (800, 500)  # px


def build() -> tuple[World, Controller]:
    """A 10 m planet with 9.81 m/s² at its surface, and a player standing on its top."""
    world = World(gravity=Radial(center=(0.0, 0.0), surface_gravity=9.81, radius=RADIUS))
    ground = pymunk.Circle(world.space.static_body, RADIUS)
    ground.friction = 1.0
    world.add_static(ground)
    return world, Controller(world, "player", position=(0.0, RADIUS + 0.95))


def to_screen(x: float, y: float, camera: tuple[float, float, float]) -> tuple[float, float]:
    """A point (m) on screen (px), for a camera at (cx, cy) m turned by ``turn`` rad."""
    cx, cy, turn = camera
    dx, dy = x - cx, y - cy
    rx = dx * math.cos(turn) - dy * math.sin(turn)
    ry = dx * math.sin(turn) + dy * math.cos(turn)
    return SIZE[0] / 2 + rx * PPM, SIZE[1] * 0.6 - ry * PPM


def main(
    frames: int | None = None, intents: Callable[[int], Intent] | None = None
) -> list[tuple[float, float]]:
    """Play; ``frames`` and ``intents`` (frame → Intent) run it scripted at 60 frames a second.
    Returns the player's position (m) after every frame."""
    pygame.init()
    screen = pygame.display.set_mode(SIZE)
    clock = pygame.time.Clock()
    world, player = build()
    trace: list[tuple[float, float]] = []
    while frames is None or len(trace) < frames:
        if any(e.type == pygame.QUIT for e in pygame.event.get()):
            break
        keys = pygame.key.get_pressed()
        if keys[pygame.K_ESCAPE]:
            break
        move = float(keys[pygame.K_RIGHT]) - float(keys[pygame.K_LEFT])
        player.intent = intents(len(trace)) if intents else Intent(move, bool(keys[pygame.K_UP]))
        for _ in range(2):  # two steps of 1/120 s a frame of 1/60 s
            world.step()

        # The camera: centred on the player, turned so its perceived up points up the screen.
        ux, uy = world.perceived_up("player")
        cx, cy = player.body.position
        camera = (cx, cy, math.atan2(ux, uy))

        screen.fill((20, 22, 30))
        pygame.draw.circle(screen, (70, 110, 70), to_screen(0.0, 0.0, camera), RADIUS * PPM)
        for k in range(24):  # markers on the ground, to see the walk
            a = k * math.pi / 12
            pygame.draw.circle(
                screen,
                (200, 200, 120),
                to_screen(RADIUS * math.cos(a), RADIUS * math.sin(a), camera),
                3,
            )
        half = player.config.height / 2 - player.config.radius
        ax, ay = player.axis
        ends = [to_screen(cx + s * half * ax, cy + s * half * ay, camera) for s in (-1.0, 1.0)]
        pygame.draw.line(screen, (230, 180, 60), *ends, int(2 * player.config.radius * PPM))
        pygame.display.flip()
        trace.append((cx, cy))
        if frames is None:
            clock.tick(60)
    pygame.quit()
    return trace


if __name__ == "__main__":
    main()
