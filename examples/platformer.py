"""pymunk's platformer example (``pymunk/examples/platformer.py``) with playground's capsule as
the player: the same level, drawing and input loop; the player is a force-driven capsule that
walks, jumps, rides the moving platform and jumps up through the yellow one-way platform.

Run it with ``python examples/platformer.py`` (Left/Right move, Up jumps, Esc or Q quits).
The level is pymunk's, in pixels, turned into metres at PPM pixels a metre.
"""

from __future__ import annotations

import itertools
import os.path
from collections.abc import Callable

import pygame
import pymunk
import pymunk.pygame_util

from playground import Controller, ControllerConfig, FixedStep, Intent, State, Waypoints, World

width, height = 690, 400
fps = 60
PPM = 22.0  # pixels a metre: the capsule (1.8 m) is 40 px tall, as pymunk's player
PLATFORM_SPEED = 2.0  # m/s, pymunk's 1 px a frame at 60 fps
# pymunk's jump clears the platforms 50 px (2.3 m) apart; the capsule's default 4 m/s does not.
PLAYER = ControllerConfig(jump_speed=7.5)  # m/s; the 45° ramp is floor by default (50°)
ASSETS = os.path.join(os.path.dirname(pymunk.__file__), "examples")


def metres(*points: tuple[float, float]) -> list[tuple[float, float]]:
    return [(x / PPM, y / PPM) for x, y in points]


def segment(body: pymunk.Body, a: tuple[float, float], b: tuple[float, float], r: float):
    s = pymunk.Segment(body, *metres(a, b), r / PPM)
    s.friction = 1.0
    return s


def build(start: tuple[float, float] = (100, 100)) -> tuple[World, Controller]:
    """pymunk's level in a playground world, and the player at ``start`` (px)."""
    world = World()
    space, static_body = world.space, world.space.static_body
    walls = [(10, 50), (680, 50), (680, 370), (10, 370), (10, 50)]
    rounded = [(500, 50), (520, 60), (540, 80), (550, 100), (550, 150)]
    shapes = [segment(static_body, a, b, 3) for a, b in itertools.pairwise(walls)]
    shapes += [segment(static_body, a, b, 3) for a, b in itertools.pairwise(rounded)]
    platforms = [
        ((170, 50), (270, 150)),  # the 45° ramp
        ((400, 150), (450, 150)),
        ((400, 200), (450, 200)),
        ((220, 200), (300, 200)),
        ((50, 250), (200, 250)),
        ((10, 370), (50, 250)),
    ]
    shapes += [segment(static_body, a, b, 3) for a, b in platforms]
    space.add(*shapes)

    # The moving platform: a kinematic body that the world drives by velocity along its path.
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    platform.position = metres((650, 100))[0]
    s = segment(platform, (-25, 0), (25, 0), 5)
    s.color = pygame.Color("blue")
    world.add("platform", platform, s)
    corners = tuple(metres((650, 100), (600, 200), (650, 300)))
    path = Waypoints(corners, speed=PLATFORM_SPEED, mode="loop")
    world.add_mover("platform", path)

    player = Controller(world, "player", position=metres(start)[0], config=PLAYER)

    # The one-way platform: contacts with the player begin only while it falls.
    passthrough = segment(static_body, (270, 100), (320, 100), 5)
    passthrough.color = pygame.Color("yellow")
    passthrough.collision_type = 2
    player.shape.collision_type = 1
    space.add(passthrough)

    def passthrough_handler(arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        arbiter.process_collision = arbiter.bodies[0].velocity.y < 0

    space.on_collision(1, 2, begin=passthrough_handler)
    return world, player


def keyboard_intent() -> Intent:
    keys = pygame.key.get_pressed()
    move = float(keys[pygame.K_RIGHT]) - float(keys[pygame.K_LEFT])
    return Intent(move=move, jump=bool(keys[pygame.K_UP]))


def main(
    frames: int | None = None,
    intents: Callable[[int], Intent] | None = None,
    start: tuple[float, float] = (100, 100),
) -> list[tuple[float, float, State]]:
    """Play; ``frames`` and ``intents`` (frame → Intent) run it scripted, ``frames`` of 1/fps s,
    with the player at ``start`` (px). Returns its position (px) and state after every frame."""
    pygame.init()
    screen = pygame.display.set_mode((width, height))
    clock = pygame.time.Clock()
    font = pygame.font.SysFont("Arial", 16)
    img = pygame.image.load(os.path.join(ASSETS, "xmasgirl1.png"))

    world, player = build(start)
    stepper = FixedStep(world, max_steps_per_frame=8)
    pymunk.pygame_util.positive_y_is_up = True
    draw_options = pymunk.pygame_util.DrawOptions(screen)
    draw_options.transform = pymunk.Transform.scaling(PPM)
    direction, frame_number, trace = 1, 0, []

    running = True
    while running and (frames is None or frame_number < frames):
        for event in pygame.event.get():
            if event.type == pygame.QUIT or (
                event.type == pygame.KEYDOWN and event.key in (pygame.K_ESCAPE, pygame.K_q)
            ):
                running = False
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_p:
                pygame.image.save(screen, "platformer.png")
        player.intent = intents(frame_number) if intents else keyboard_intent()
        if player.intent.move:
            direction = 1 if player.intent.move > 0 else -1

        ### Clear screen, helper lines, the world, the player's sprite
        screen.fill(pygame.Color("black"))
        for y in [50, 100, 150, 200, 250, 300]:
            pygame.draw.line(screen, pygame.Color("green"), (10, height - y), (680, height - y))
        world.space.debug_draw(draw_options)
        grounded = player.state is State.GROUNDED
        direction_offset = 48 + (1 * direction + 1) // 2 * 48
        if grounded and abs(player.intent.move) > 0:
            animation_offset = 32 * (frame_number // 8 % 4)
        else:
            animation_offset = 32 * (0 if grounded else 1)
        feet = player.body.position * PPM + (-16, 48 - 0.5 * PLAYER.height * PPM)
        p = pymunk.pygame_util.to_pygame(feet, screen)
        screen.blit(img, p, (animation_offset, direction_offset, 32, 48))
        screen.blit(
            font.render(f"fps: {clock.get_fps():.0f}  {player.state.value}", True, "white"), (0, 0)
        )
        screen.blit(
            font.render("Move with Left/Right, jump with Up", True, "darkgrey"), (5, height - 35)
        )
        pygame.display.flip()
        frame_number += 1

        ### Update physics: whole steps of the world's dt for the frame's time
        seconds = 1.0 / fps if frames is not None else clock.tick(fps) / 1000.0
        stepper.advance(seconds)
        trace.append((player.body.position.x * PPM, player.body.position.y * PPM, player.state))
    pygame.quit()
    return trace


if __name__ == "__main__":
    main()
