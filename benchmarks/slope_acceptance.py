"""Issue 22's slope acceptance, measured on the default ControllerConfig at dt = 1/120 s.

1. A 45° ramp, 12 m long, from a run-up: the mean speed along the slope over the climb (as a
   share of ``max_speed``) and the state changes between its foot and its top.
2. A 60° face (past ``max_slope``): set down on it, the states it goes through, and how far its
   up leans from gravity's direction while SLIDING.
3. Walking into a wall at 4 m/s and at 1 m/s and pressing on: how far its up leans from gravity's
   direction from the first touch on, and its state changes.

    python benchmarks/slope_acceptance.py
"""

from __future__ import annotations

import math

from playground import Controller, Intent, State, World


def lean(player: Controller) -> float:
    """The controller's up from gravity's (straight up here), degrees."""
    return abs(math.degrees(math.atan2(player.up[0], player.up[1])))


def ramp_45() -> None:
    world, slope, length = World(), math.radians(45.0), 12.0
    top = (length * math.cos(slope), length * math.sin(slope))
    world.add_static_segment((-20.0, 0.0), (0.0, 0.0))
    world.add_static_segment((0.0, 0.0), top)
    world.add_static_segment(top, (top[0] + 20.0, top[1]))
    player = Controller(world, "player", position=(-4.0, 0.95))
    player.intent = Intent(move=1.0)
    foot: tuple[float, float] | None = None  # (s, m along the slope) at the foot
    crest: tuple[float, float] | None = None
    changes: list[tuple[float, str, str]] = []
    state = player.state
    while world.time < 8.0:
        world.step()
        x, y = player.body.position
        along = x * math.cos(slope) + y * math.sin(slope)
        if foot is None and x >= 0.0:
            foot = (world.time, along)
        if crest is None and x >= top[0]:
            crest = (world.time, along)
        if player.state is not state:
            changes.append((world.time, state.value, player.state.value))
            state = player.state
    assert foot is not None and crest is not None, "never reached the top"
    speed = (crest[1] - foot[1]) / (crest[0] - foot[0])
    climb = [c for c in changes if foot[0] <= c[0] <= crest[0]]
    share = 100.0 * speed / player.config.max_speed
    print(f"45° ramp: {speed:.3f} m/s along the slope over the climb = {share:.1f} % of max_speed;")
    print(f"  state changes in the climb: {len(climb)} {climb}; in the whole run: {changes}")


def face_60() -> None:
    world, slope = World(), math.radians(60.0)
    c, s = math.cos(slope), math.sin(slope)
    foot = (5.0, 0.0)
    world.add_static_segment((-14.0, 0.0), (18.0, 0.0))
    world.add_static_segment(foot, (foot[0] - 6.0 * c, 6.0 * s))
    on = (foot[0] - 4.5 * c, 4.5 * s)
    player = Controller(world, "player", position=(on[0] + 0.7 * s, on[1] + 0.7 * c))
    changes: list[tuple[float, str, str]] = []
    state, worst, sliding = player.state, 0.0, 0.0
    while world.time < 3.0:
        world.step()
        if player.state is State.SLIDING:
            worst = max(worst, lean(player))
            sliding += world.config.dt
        if player.state is not state:
            changes.append((round(world.time, 3), state.value, player.state.value))
            state = player.state
    print(f"60° face: {len(changes)} state changes {changes}; SLIDING {sliding:.2f} s,")
    print(f"  its up within {worst:.3f}° of gravity's while sliding")


def wall(move: float) -> None:
    world = World()
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    world.add_static_segment((2.0, 0.0), (2.0, 5.0))
    player = Controller(world, "player", position=(-3.0, 0.95))
    world.run(0.5)
    player.intent = Intent(move=move)
    touched: float | None = None
    worst = 0.0
    changes: list[tuple[float, str, str]] = []
    state = player.state
    while world.time < 8.0:
        world.step()
        if touched is None and player.sensed.touching:
            touched = world.time
        if touched is not None:
            worst = max(worst, lean(player))
        if player.state is not state:
            changes.append((round(world.time, 3), state.value, player.state.value))
            state = player.state
    speed = move * player.config.max_speed
    print(f"wall at {speed:.0f} m/s: touched at {touched} s; up within {worst:.4f}° of gravity's")
    print(f"  from then on; state changes {changes}")


if __name__ == "__main__":
    ramp_45()
    face_60()
    wall(1.0)
    wall(0.25)
