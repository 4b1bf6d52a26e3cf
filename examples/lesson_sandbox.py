"""A sandbox for a lesson on perceived gravity: what does a jumping player feel?

Standing, the floor holds the player up with its weight, m·g; in the air it feels nothing at all
(free fall), and on landing it feels a spike. The plot scrolls the felt force (|support|, N)
against the m·g line. Change the constants below and run it again: a heavier player, a stiffer
hover, a higher jump. Run it with ``python examples/lesson_sandbox.py`` (Space jumps, Esc quits).
"""

from __future__ import annotations

from collections.abc import Callable

import pygame

from playground import Controller, ControllerConfig, Intent, World

PLAYER = ControllerConfig(mass=70.0, hover_frequency=5.0, jump_speed=4.0)  # kg, Hz, m/s
SIZE = (800, 400)  # px
SECONDS_SHOWN = 4.0  # s of history on the plot
NEWTONS_PER_PIXEL = 8.0  # N: the plot's scale


def felt(world: World) -> float:
    """What the player feels, N: the magnitude of its support force this step."""
    fx, fy = world.forces("player").support
    return float((fx * fx + fy * fy) ** 0.5)


def main(frames: int | None = None, intents: Callable[[int], Intent] | None = None) -> list[float]:
    """Play; ``frames`` and ``intents`` (frame → Intent) run it scripted at 60 frames a second.
    Returns the felt force (N) after every frame."""
    pygame.init()
    screen = pygame.display.set_mode(SIZE)
    clock, font = pygame.time.Clock(), pygame.font.SysFont(None, 22)
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    player = Controller(world, "player", position=(0.0, 1.0), config=PLAYER)
    weight = PLAYER.mass * 9.81  # N
    history: list[float] = []
    while frames is None or len(history) < frames:
        if any(e.type == pygame.QUIT for e in pygame.event.get()):
            break
        keys = pygame.key.get_pressed()
        if keys[pygame.K_ESCAPE]:
            break
        player.intent = intents(len(history)) if intents else Intent(jump=keys[pygame.K_SPACE])
        for _ in range(2):  # two steps of 1/120 s a frame of 1/60 s
            world.step()
        history.append(felt(world))

        screen.fill((250, 250, 245))
        base = SIZE[1] - 40
        line = base - weight / NEWTONS_PER_PIXEL
        pygame.draw.line(screen, (60, 90, 200), (0, line), (SIZE[0], line))
        shown = history[-int(SECONDS_SHOWN * 60) :]
        points = [
            (i * SIZE[0] / (SECONDS_SHOWN * 60), max(base - f / NEWTONS_PER_PIXEL, 0.0))
            for i, f in enumerate(shown)
        ]
        if len(points) > 1:
            pygame.draw.lines(screen, (200, 40, 60), False, points, 2)
        text = f"felt {history[-1]:6.0f} N   m·g {weight:.0f} N   {player.state.value}"
        screen.blit(font.render(text, True, (20, 20, 20)), (10, 10))
        pygame.display.flip()
        if frames is None:
            clock.tick(60)
    pygame.quit()
    return history


if __name__ == "__main__":
    main()
