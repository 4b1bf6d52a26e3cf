"""The mouse's hand: a soft spring that drags a dynamic body toward the cursor.

The mouse joint is a *force*, not a pymunk constraint. A ``PivotJoint`` to a kinematic mouse body
(pymunk's examples) would be solved inside the engine, and pymunk reports a constraint's impulse as
a magnitude only (``Constraint.impulse``): its direction could neither be drawn nor told apart from
the body's other joints. Instead the pull is the model of Box2D v3's mouse joint — a spring and
damper of a set frequency and damping ratio on the grabbed point, capped at a maximum force — put
into the world's ledger as an APPLIED force at that point. The force solver then subtracts it
exactly (reverse integration stays exact), it is not part of the support force (the body does not
feel it through its feet, so perceived gravity is untouched), and the arrow drawn is the very force
that was applied.

A grabbed body would otherwise swing about the grabbed point for ever (a pendulum the point
spring cannot damp): like Box2D's mouse joint, the pull also damps the body's spin, with a torque
−I·γ·ω.

The spring is the hover's (:func:`playground.controller.hover_spring`): evaluated where pymunk's
integrator will use it, so it is stable while ω·dt stays below 2 (undamped) and more with damping.
Off the centre of mass the grabbed point is lighter, ``1/m_eff = 1/m + |r|²/I`` across r, and the
spring there is faster by √(m/m_eff): ω is lowered so that even that stays below ``step_limit``.

>>> import pymunk
>>> body = pymunk.Body(2.0, float("inf"))
>>> spring = MouseSpring(frequency=1.0, damping_ratio=0.0, max_weights=100.0)
>>> pull = spring.pull(body, (0.0, 0.0), (1.0, 0.0), dt=0.01)
>>> round(pull.force[0], 6), pull.force[1], pull.point, pull.torque  # k·x = m·(2π·1 Hz)²·1 m
(78.956835, 0.0, (0.0, 0.0), 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import pymunk

from playground.controller.spring import hover_spring
from playground.forces.ledger import Category
from playground.gravity import STANDARD_GRAVITY
from playground.vec import Vec

if TYPE_CHECKING:
    from playground.world.world import World

__all__ = ["Grab", "MouseSpring", "Pull"]


@dataclass(frozen=True, slots=True)
class Grab:
    """What the mouse holds: a body by name, the grabbed point on it (body frame, m) and where
    the cursor is (world frame, m)."""

    body: str
    anchor: Vec
    target: Vec


@dataclass(frozen=True, slots=True)
class Pull:
    """One step's pull: the force (N, world) at a world point (m), and the spin-damping torque
    (N·m, counter-clockwise)."""

    force: Vec
    point: Vec
    torque: float


@dataclass(frozen=True, slots=True)
class MouseSpring:
    """The soft mouse joint.

    Attributes:
        frequency: natural frequency of the spring on the grabbed point, Hz.
        damping_ratio: 1 is critical (no overshoot).
        max_weights: the force cap, in weights of the grabbed body (m·g₀, g₀ the standard
            gravity): enough to lift and throw it, not enough to tear it through a wall in one
            step.
        spin_damping: γ, the rate at which the grabbed body's spin decays, 1/s.
        step_limit: the largest ω·dt at the grabbed point (ω is lowered at large dt).
        spin_limit: the largest γ·dt (the spin damping is explicit: stable below 2).
    """

    frequency: float = 5.0
    damping_ratio: float = 1.0
    max_weights: float = 20.0
    spin_damping: float = 3.0
    step_limit: float = 0.5
    spin_limit: float = 0.5

    def pull(self, body: pymunk.Body, anchor: Vec, target: Vec, dt: float) -> Pull:
        """The pull on ``body`` for a step of ``dt`` s, drawing its point ``anchor`` (body frame,
        m) toward ``target`` (world, m)."""
        p = body.local_to_world(anchor)
        c = body.local_to_world(body.center_of_gravity)
        rx, ry = p.x - c.x, p.y - c.y
        w = body.angular_velocity
        # Velocity of the grabbed point: v + ω × r.
        vx, vy = body.velocity.x - w * ry, body.velocity.y + w * rx
        m = body.mass
        omega = self.omega(body, anchor, dt)
        k = m * omega * omega
        c_damp = 2.0 * self.damping_ratio * m * omega
        fx = hover_spring(k, c_damp, m, target[0] - p.x, vx, dt)
        fy = hover_spring(k, c_damp, m, target[1] - p.y, vy, dt)
        cap = self.max_weights * body.mass * STANDARD_GRAVITY
        n = math.hypot(fx, fy)
        if n > cap:
            fx, fy = fx * cap / n, fy * cap / n
        torque = 0.0
        if not math.isinf(body.moment):
            # m·|r|²/I is how much heavier the spin is about the grabbed point than about the
            # centre: the explicit damping's rate is capped by that factor too.
            about = 1.0 + m * (rx * rx + ry * ry) / body.moment
            rate = min(self.spin_damping, self.spin_limit / (dt * about))
            torque = -rate * about * body.moment * w
        return Pull((fx, fy), (p.x, p.y), torque)

    def apply(self, world: World, grab: Grab | None) -> Pull | None:
        """This step's pull on what ``grab`` holds, put into ``world``'s ledger as APPLIED force
        (at the grabbed point) and torque; None when nothing dynamic is held (a CONTROL hook)."""
        if grab is None or grab.body not in world.names:
            return None
        body = world.body(grab.body)
        if body.body_type != pymunk.Body.DYNAMIC:
            return None
        pull = self.pull(body, grab.anchor, grab.target, world.config.dt)
        world.apply_force(body, pull.force, point=pull.point, category=Category.APPLIED)
        if pull.torque != 0.0:
            world.apply_torque(body, pull.torque, category=Category.APPLIED)
        return pull

    def omega(self, body: pymunk.Body, anchor: Vec, dt: float) -> float:
        """The spring's angular frequency (rad/s) on ``body`` grabbed at ``anchor`` (body frame,
        m) at step ``dt`` (s): 2π·frequency, lowered so that ω·dt·√(m/m_eff) ≤ step_limit. A body
        held still sags g·(1 + 2ζ·ω·dt)/ω² below the cursor (the spring's implicit damping
        divides its static stiffness by 1 + 2ζ·ω·dt).

        >>> body = pymunk.Body(1.0, float("inf"))
        >>> round(MouseSpring(frequency=5.0).omega(body, (0.0, 0.0), dt=0.1), 6)
        5.0
        """
        r = body.local_to_world(anchor) - body.local_to_world(body.center_of_gravity)
        inv_i = 0.0 if math.isinf(body.moment) else 1.0 / body.moment
        lighter = math.sqrt(1.0 + body.mass * r.dot(r) * inv_i)  # √(m / m_eff)
        return min(2.0 * math.pi * self.frequency, self.step_limit / (dt * lighter))
