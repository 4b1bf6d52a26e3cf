"""Laws of the probe on stairs (playground/controller/stairs.py): a corner reads as the face past
it, a walking body finds the tread ahead within the step's reach (and nothing else: not a slope,
not a riser under its clearance, not one beyond its reach, not behind it), a grounded body finds
the tread below past its probe, and a controller walks a flight up and down at its speed,
grounded throughout, at any mass and step."""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import Controller, ControllerConfig, Intent, State, World, WorldConfig
from playground._engine.sweep import Sweep
from playground.controller import stairs

CONFIG = ControllerConfig()
"""The default player: ride height 0.95 m, capsule 1.8 m × 0.25 m, probe radius 0.1 m."""
RIDE = CONFIG.ride_height
"""m."""
RHO = CONFIG.probe_radius
"""m."""
TOL_FLOAT = 1e-12
"""m or unit: round-off on geometry of a few metres."""
TOL_RIDE = 1e-6
"""m: the height over the floor 1 s after the last riser down: the critically damped hover has
settled the drop (9.5e-10 m the worst of every flight at every variant, measured)."""
TOL_SPEED_REL = 1e-3
"""Relative, the speed up and down a flight against max_speed: the drive holds it to round-off
on flat treads (measured: 4.0 m/s to 1e-9 on risers of 0.1 and 0.2 m, treads 0.3 and 0.5 m)."""


def _stairs(world: World, riser: float, tread: float, steps: int, landing: float) -> float:
    """A flight of ``steps`` risers from x = 0 (boxes standing on the floor, friction 1), a
    landing, and the same flight down to the floor; returns where it ends, m."""
    body = world.space.static_body
    shapes: list[pymunk.Shape] = []
    x = 0.0
    tops = [*range(1, steps + 1), *range(steps - 1, 0, -1)]
    for i, n in enumerate(tops):
        width = tread + (landing if i == steps - 1 else 0.0)
        shapes.append(pymunk.Poly(body, [(x, 0.0), (x + width, 0.0), (x + width, n * riser),
                                         (x, n * riser)]))  # fmt: skip
        x += width
    for shape in shapes:
        shape.friction = 1.0
    world.add_static(*shapes)
    return x


def _box(top: float, x0: float = 0.0, x1: float = 2.0, floor: bool = True) -> Sweep:
    """A sweep through a space with a floor at y = 0 (unless not) and a box from x0 to x1
    standing on it up to ``top`` (the sweep holds the space)."""
    space = pymunk.Space()
    if floor:
        space.add(pymunk.Segment(space.static_body, (-10.0, 0.0), (10.0, 0.0), 0.0))
    space.add(pymunk.Poly(space.static_body, [(x0, 0.0), (x1, 0.0), (x1, top), (x0, top)]))
    return Sweep(space, pymunk.ShapeFilter())


def test_the_step_reach_is_the_height_of_the_lower_caps_centre() -> None:
    """reach = ride_height − half_length (0.3 m), clearance = ride_height − height/2 (0.05 m):
    both follow the body's own shape."""
    assert stairs.reach(CONFIG) == pytest.approx(0.3, abs=TOL_FLOAT)
    assert stairs.clearance(CONFIG) == pytest.approx(0.05, abs=TOL_FLOAT)
    tall = ControllerConfig(height=2.0, radius=0.3, ride_height=1.2)
    assert stairs.reach(tall) == pytest.approx(1.2 - 0.7, abs=TOL_FLOAT)


def test_a_corner_reads_as_the_face_past_it() -> None:
    """The probe's circle touching a box's corner off its axis reads the corner's slanted normal
    from the engine; face() gives the normal of the top face past it (up), at the same point.
    (The box alone: among several shapes Chipmunk's index culls a shape whose bounding box the
    sweep's centre line misses, so the probe meets corners mostly with a tilted up.)"""
    sweep = _box(0.2, floor=False)
    px = -0.06  # the axis 6 cm before the box's edge: the circle meets its corner
    found = sweep.nearest(px, RIDE, px, RIDE - CONFIG.probe_length, RHO)
    assert found is not None
    _, hx, hy, _, ny = found
    assert (hx, hy) == pytest.approx((0.0, 0.2), abs=TOL_FLOAT)
    assert math.acos(ny) > stairs.CORNER_TILT  # slanted by the corner's offset
    shape, fx, fy, fnx, fny = stairs.face(found, px, RIDE, 0.0, 1.0, RHO)
    assert shape is found[0] and (fx, fy) == (hx, hy)
    assert (fnx, fny) == pytest.approx((0.0, 1.0), abs=TOL_FLOAT)
    # Past the edge going down: the corner stands for the top being left.
    px = 2.06
    found = sweep.nearest(px, RIDE + 0.2, px, RIDE + 0.2 - CONFIG.probe_length, RHO)
    assert found is not None
    assert stairs.face(found, px, RIDE + 0.2, 0.0, 1.0, RHO)[3:] == pytest.approx((0.0, 1.0))


def test_a_face_and_a_rounded_shape_keep_the_probes_normal() -> None:
    """On a face the hit is returned as it is (the same tuple); on a segment with rounded ends
    its end cap is a real curved surface and keeps the engine's normal."""
    sweep = _box(0.2)
    found = sweep.nearest(1.0, 1.5, 1.0, 0.0, RHO)
    assert found is not None and stairs.face(found, 1.0, 1.5, 0.0, 1.0, RHO) is found
    round_space = pymunk.Space()
    round_space.add(pymunk.Segment(round_space.static_body, (-2.0, 0.0), (0.0, 0.0), 0.05))
    cap = Sweep(round_space, pymunk.ShapeFilter()).nearest(0.08, 1.0, 0.08, -1.0, RHO)
    assert cap is not None and cap[4] < math.cos(stairs.CORNER_TILT)
    assert stairs.face(cap, 0.08, 1.0, 0.0, 1.0, RHO) is cap


@pytest.mark.parametrize("riser", [0.1, 0.2, 0.29])
def test_walking_toward_a_riser_within_reach_finds_the_tread_ahead(riser: float) -> None:
    """At ride height over the floor, 0.5 m before a riser, walking at 4 m/s toward it, the
    body looks radius + probe_radius + speed·lead_time = 0.25 + 0.1 + 0.4 m ahead and finds the
    tread: a hit on its
    top, normal up; walking away or standing (move 0) it finds nothing."""
    sweep = _box(riser, 0.5, 3.0)
    floor = sweep.nearest(0.0, RIDE, 0.0, RIDE - CONFIG.probe_length, RHO)
    assert floor is not None
    tread = stairs.step_up(sweep, floor, 0.0, RIDE, 4.0, 0.0, 0.0, 1.0, 1.0, CONFIG)
    assert tread is not None
    assert tread[2] == pytest.approx(riser, abs=TOL_FLOAT)
    assert tread[3:] == pytest.approx((0.0, 1.0), abs=TOL_FLOAT)
    assert stairs.step_up(sweep, floor, 0.0, RIDE, -4.0, 0.0, 0.0, 1.0, -1.0, CONFIG) is None
    assert stairs.step_up(sweep, floor, 0.0, RIDE, 0.0, 0.0, 0.0, 1.0, 0.0, CONFIG) is None


@pytest.mark.parametrize(
    ("riser", "why"),
    [(0.04, "under the clearance"), (0.31, "beyond the reach"), (0.9, "a wall")],
)
def test_no_step_under_the_clearance_or_beyond_the_reach(riser: float, why: str) -> None:
    """A riser under the clearance (0.05 m) passes under the capsule and is left to the probe
    under the body; one beyond the reach (0.3 m) or a wall is no step."""
    sweep = _box(riser, 0.5, 3.0)
    floor = sweep.nearest(0.0, RIDE, 0.0, RIDE - CONFIG.probe_length, RHO)
    assert floor is not None
    assert stairs.step_up(sweep, floor, 0.0, RIDE, 4.0, 0.0, 0.0, 1.0, 1.0, CONFIG) is None, why


def test_a_slope_ahead_is_no_step() -> None:
    """A 20° ramp starting ahead is a change of slope, not a tread parallel to the floor."""
    space = pymunk.Space()
    space.add(pymunk.Segment(space.static_body, (-10.0, 0.0), (0.5, 0.0), 0.0))
    slope = math.tan(math.radians(20.0))
    space.add(pymunk.Segment(space.static_body, (0.5, 0.0), (3.0, 2.5 * slope), 0.0))
    sweep = Sweep(space, pymunk.ShapeFilter())
    floor = sweep.nearest(0.0, RIDE, 0.0, RIDE - CONFIG.probe_length, RHO)
    assert floor is not None
    assert stairs.step_up(sweep, floor, 0.0, RIDE, 4.0, 0.0, 0.0, 1.0, 1.0, CONFIG) is None


def test_a_tread_below_the_probe_within_reach_is_found() -> None:
    """probe_length + reach below the centre (1.7 m): a tread 1.6 m below is found, 1.8 m not."""
    sweep = _box(0.2, -5.0, 5.0)
    found = stairs.below(sweep, 0.0, 1.8, (0.0, -1.0), (0.0, 1.0), CONFIG)
    assert found is not None and found[2] == pytest.approx(0.2, abs=TOL_FLOAT)
    assert stairs.below(sweep, 0.0, 2.0, (0.0, -1.0), (0.0, 1.0), CONFIG) is None


@pytest.mark.parametrize("gap", [0.1, 0.3, 0.6, 1.0, 1.5, 2.0, 3.0])
def test_walking_off_a_landing_from_rest(gap: float) -> None:
    """From rest ``gap`` m before the edge of a 6 m landing atop 5 risers of 0.2 m on 0.3 m treads,
    walking off at full input: GROUNDED all the way down, at ride height on the floor at the
    end. (Still accelerating at the edge from 1 m, its up no longer leans back 27° with the
    drive: it is held within max_lean of the field's beyond its own step's lean, and the
    probe reads the treads below.)"""
    world = World(WorldConfig(dt=1 / 120))
    world.add_static_segment((-20.0, 0.0), (40.0, 0.0), radius=0.0)
    end = _stairs(world, 0.2, 0.3, 5, 6.0)
    edge = 0.3 * 5 + 6.0
    player = Controller(world, "player", (edge - gap, 1.0 + RIDE))
    world.run(1.0)
    player.intent = Intent(move=1.0)
    airborne = 0.0
    changes = 0
    while player.body.position.x < end:
        world.step()
        airborne += world.config.dt if player.state is State.AIRBORNE else 0.0
        changes += player.transition is not None
    assert changes == 0
    assert airborne == 0.0
    world.run(1.0)
    assert player.body.position.y == pytest.approx(RIDE, abs=TOL_RIDE)


FLIGHTS = [(0.1, 0.3), (0.1, 0.5), (0.2, 0.3), (0.2, 0.5), (0.25, 0.3), (0.25, 0.5)]
"""(riser, tread), m: the flights walked at full speed up and down."""
VARIANTS = [
    (mass, dt, substeps)
    for mass in (35.0, 70.0, 140.0)
    for dt in (1 / 60, 1 / 120, 1 / 240)
    for substeps in (1, 2, 4)
]
"""The robustness matrix's 27 variants: mass (kg), dt (s), substeps."""
FAST_VARIANTS = [(70.0, 1 / 120, 1), (35.0, 1 / 60, 2), (140.0, 1 / 240, 4)]
"""Three of them for the fast tier: each mass, dt and substep count once."""
STEEP_COARSE = ((0.25, 0.3), 1 / 60)
"""The flight (40°) and the step at which the walk is not claimed: the hover, stepped at
2πf·dt = 0.52, lags; in one substep the cap meets a nosing (the walk slows to 1.8 m/s), in
four the body turns AIRBORNE for 0.1 s going down."""


def _cases(variants: list[tuple[float, float, int]]) -> list[tuple[float, ...]]:
    """Every flight at every variant but :data:`STEEP_COARSE`'s."""
    return [
        (riser, tread, mass, dt, substeps)
        for riser, tread in FLIGHTS
        for mass, dt, substeps in variants
        if ((riser, tread), dt) != STEEP_COARSE
    ]


def _walk(riser: float, tread: float, mass: float, dt: float, substeps: int) -> None:
    """Walking at max_speed over a flight of 5 risers, a 2 m landing and 4 risers down: the
    speed along stays max_speed (the hover lifts the body before its cap meets a riser, and
    the treads are flat), the state stays GROUNDED from start to end (down, the body drops past
    the probe for a moment and the tread below keeps it grounded), and it ends at ride height
    on the floor beyond."""
    world = World(WorldConfig(dt=dt, substeps=substeps))
    world.add_static_segment((-20.0, 0.0), (40.0, 0.0), radius=0.0)
    end = _stairs(world, riser, tread, 5, 2.0)
    player = Controller(world, "player", (-3.0, RIDE), ControllerConfig(mass=mass))
    player.intent = Intent(move=1.0)
    world.run(1.0)  # s: at speed before the first riser at x = 0
    assert player.body.position.x < 0.0
    states = set()
    slowest = math.inf
    while player.body.position.x < end:
        world.step()
        states.add(player.state)
        slowest = min(slowest, player.body.velocity.x)
    assert states == {State.GROUNDED}
    assert slowest == pytest.approx(CONFIG.max_speed, rel=TOL_SPEED_REL)
    world.run(1.0)
    assert player.body.position.y == pytest.approx(RIDE, abs=TOL_RIDE)


@pytest.mark.parametrize(("riser", "tread", "mass", "dt", "substeps"), _cases(FAST_VARIANTS))
def test_a_flight_up_and_down_at_full_speed_grounded_throughout(
    riser: float, tread: float, mass: float, dt: float, substeps: int
) -> None:
    """:func:`_walk` at three variants."""
    _walk(riser, tread, mass, dt, substeps)


@pytest.mark.slow
@pytest.mark.parametrize(("riser", "tread", "mass", "dt", "substeps"), _cases(VARIANTS))
def test_every_flight_at_every_variant(
    riser: float, tread: float, mass: float, dt: float, substeps: int
) -> None:
    """:func:`_walk` at the robustness matrix's 27 variants."""
    _walk(riser, tread, mass, dt, substeps)
