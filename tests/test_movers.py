"""Laws of kinematic movers: each step ends exactly on the path, reached by velocity alone."""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Circle, Elevator, Mover, Sine, Spin, Waypoints, World, WorldConfig
from playground.movers import Path

TOL_POSE = 1e-12
"""m and rad: a kinematic body moves by v·h per substep; v was computed to land on the pose, so
only rounding (of ~1e-15 relative on poses of a few metres) separates them."""

PATHS: dict[str, Path] = {
    "loop": Waypoints(((0.0, 0.0), (3.0, 0.0), (3.0, 2.0)), speed=2.0, mode="loop"),
    "pingpong-eased": Waypoints(((0.0, 0.0), (2.0, 1.0)), speed=1.5, ease=True, mode="pingpong"),
    "once": Waypoints(((1.0, 1.0), (2.0, 1.0)), speed=1.0, mode="once", angle=0.4),
    "sine": Sine(center=(0.0, 1.0), amplitude=(2.0, 0.5), frequency=0.7, phase=0.3),
    "circle": Circle(center=(1.0, 2.0), radius=3.0, period=2.5, turn_with_path=True),
    "spin": Spin(position=(0.5, 0.5), rate=-2.0, angle=0.1),
    "elevator": Elevator(start=(0.0, -1.0), acceleration=2.5, start_time=0.3, duration=1.0),
}


@pytest.mark.parametrize("substeps", [1, 3])
@pytest.mark.parametrize("path", PATHS.values(), ids=PATHS.keys())
def test_mover_lands_on_its_path_every_step(path: Path, substeps: int) -> None:
    """Law: after every step the body is at path.pose(t) (position and angle), and it got there by
    moving with the velocity it was given (p_after − p_before = v·dt): never teleported."""
    world = World(WorldConfig(substeps=substeps))
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("mover", body, pymunk.Poly.create_box(body, (1.0, 0.2)))
    world.add_mover("mover", path)
    dt = world.config.dt
    for _ in range(round(3.0 / dt)):
        before, angle_before = body.position, body.angle
        world.step()
        (x, y), angle = path.pose(world.time)
        assert abs(body.position.x - x) <= TOL_POSE and abs(body.position.y - y) <= TOL_POSE
        assert abs(body.angle - angle) <= TOL_POSE
        moved = body.position - before
        assert abs(moved.x - body.velocity.x * dt) <= TOL_POSE
        assert abs(moved.y - body.velocity.y * dt) <= TOL_POSE
        assert abs(body.angle - angle_before - body.angular_velocity * dt) <= TOL_POSE


def test_waypoint_modes() -> None:
    """Law: loop returns to the first point after one circuit; ping-pong reaches the last point
    halfway and is back at the start after a round trip; once stops at the last point."""
    pts = ((0.0, 0.0), (3.0, 0.0), (3.0, 4.0))
    loop = Waypoints(pts, speed=2.0, mode="loop")
    circuit = (3.0 + 4.0 + 5.0) / 2.0
    assert loop.pose(circuit)[0] == pytest.approx((0.0, 0.0), abs=1e-12)
    assert loop.pose(circuit + 1.5)[0] == pytest.approx(loop.pose(1.5)[0], abs=1e-12)
    ping = Waypoints(pts, speed=1.0, mode="pingpong")
    assert ping.pose(7.0)[0] == pytest.approx((3.0, 4.0), abs=1e-12)
    assert ping.pose(14.0)[0] == pytest.approx((0.0, 0.0), abs=1e-12)
    once = Waypoints(pts, speed=1.0, mode="once")
    assert once.pose(100.0)[0] == (3.0, 4.0)
    assert once.pose(-5.0)[0] == (0.0, 0.0)


def test_eased_waypoints_stop_at_corners() -> None:
    """Law: an eased leg starts and ends at rest (displacement ~ t² near a corner) and is at its
    midpoint halfway through."""
    path = Waypoints(((0.0, 0.0), (2.0, 0.0)), speed=1.0, ease=True, mode="pingpong")
    eps = 1e-3
    assert path.pose(eps)[0][0] < 10 * eps * eps
    assert 2.0 - path.pose(2.0 - eps)[0][0] < 10 * eps * eps
    assert path.pose(1.0)[0][0] == pytest.approx(1.0, abs=1e-12)


def test_elevator_acceleration() -> None:
    """Law: the elevator's second difference of position is a·dt² while accelerating, and zero
    (constant speed) after ``duration``."""
    a, dt = 2.5, 0.01
    lift = Elevator(start=(0.0, 0.0), acceleration=a, start_time=0.5, duration=1.0)
    for t in (0.7, 1.2):
        y0, y1, y2 = (lift.pose(t + k * dt)[0][1] for k in range(3))
        assert y2 - 2 * y1 + y0 == pytest.approx(a * dt * dt, rel=1e-9)
    y0, y1, y2 = (lift.pose(2.0 + k * dt)[0][1] for k in range(3))
    assert abs(y2 - 2 * y1 + y0) <= 1e-12
    assert lift.pose(0.2)[0] == (0.0, 0.0)


def test_mover_drives_only_kinematic_bodies() -> None:
    """Law: a mover refuses a dynamic body (it would fight the solver), naming the problem."""
    with pytest.raises(ValueError, match="KINEMATIC"):
        Mover(pymunk.Body(1.0, 1.0), Spin())


def test_path_validation() -> None:
    """Law: bad path parameters raise ValueError naming the parameter."""
    with pytest.raises(ValueError, match="points"):
        Waypoints(((0.0, 0.0),))
    with pytest.raises(ValueError, match="speed"):
        Waypoints(((0.0, 0.0), (1.0, 0.0)), speed=0.0)
    with pytest.raises(ValueError, match="period"):
        Circle(period=0.0)
    with pytest.raises(ValueError, match="frequency"):
        Sine(frequency=math.nan)
