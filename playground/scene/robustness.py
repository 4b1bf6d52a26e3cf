"""The robustness matrix: every level at 27 variants of the player's mass, the step and its
substeps, judged against the variants the level declares it cannot support.

A level is written, tuned and checked at one setting. Its checks state physics (m·g, m·v²/r,
m·v), so they should hold at any player mass and at any step a game would use; where the
physics of the level itself does not (a threshold a heavier player's weight crosses, a contact
a coarser step resolves otherwise), the level says so in a ``[[variants.unsupported]]`` table
(:mod:`playground.level.support`). Each variant is the level run with ``--set`` settings
(:mod:`playground.level.variants`):

- the player's mass at :data:`MASS_FACTORS` × its declared mass (only the player's: enemies,
  crates and the other actors keep theirs); a level without a player has no mass axis;
- ``settings.dt`` at each of :data:`DTS`, s;
- ``settings.substeps`` at each of :data:`SUBSTEPS`.

>>> [v.label for v in VARIANTS[:4]]
['m×0.5 dt 1/60 s1', 'm×0.5 dt 1/60 s2', 'm×0.5 dt 1/60 s4', 'm×0.5 dt 1/120 s1']
>>> len(VARIANTS)
27
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Literal

from playground.level.document import Level
from playground.level.errors import LevelError
from playground.level.loading import load
from playground.level.support import Unsupported, declared
from playground.level.variants import Setting

__all__ = [
    "DTS",
    "MASS_FACTORS",
    "SUBSTEPS",
    "VARIANTS",
    "Outcome",
    "Variant",
    "Verdict",
    "player",
    "run",
]

MASS_FACTORS = (0.5, 1.0, 2.0)
"""The player's mass, × its declared mass (a 35, 70 and 140 kg person for the default 70 kg)."""

DTS = (1 / 60, 1 / 120, 1 / 240)
"""Steps, s: a game's frame at 60 Hz, the playground's default, and half of it."""

SUBSTEPS = (1, 2, 4)
"""Physics substeps per step (``settings.substeps``)."""


@dataclass(frozen=True, slots=True)
class Variant:
    """One cell of the matrix: the player's mass factor, the step (s) and its substeps."""

    mass: float
    dt: float
    substeps: int

    @property
    def label(self) -> str:
        """``m×2 dt 1/240 s4``: short, for tables and test ids."""
        rate = Fraction(self.dt).limit_denominator(10_000)
        step = f"1/{rate.denominator}" if rate.numerator == 1 else f"{self.dt:g}"
        return f"m×{self.mass:g} dt {step} s{self.substeps}"

    @property
    def id(self) -> str:
        """``m2-dt240-s4``: the label in ASCII, for test ids."""
        return f"m{self.mass:g}-dt{round(1 / self.dt)}-s{self.substeps}"

    def settings(self, level: Level) -> tuple[Setting, ...] | None:
        """The ``--set`` settings that make this variant of ``level``; None when it has no
        player and the variant scales the player's mass (there is nothing to scale)."""
        sets = [Setting("settings.dt", self.dt), Setting("settings.substeps", self.substeps)]
        who = player(level)
        if who is None:
            return None if self.mass != 1.0 else tuple(sets)
        mass = next(a.controller.mass for a in level.actors if a.name == who)
        return (Setting(f"actors.{who}.controller.mass", self.mass * mass), *sets)


VARIANTS = tuple(Variant(m, dt, n) for m in MASS_FACTORS for dt in DTS for n in SUBSTEPS)
"""Every variant, by mass, then step, then substeps (27)."""


def player(level: Level) -> str | None:
    """The name of the level's player: the actor whose role is ``player`` (an actor named
    ``player`` with no role is one), or None.

    >>> from playground.level import find, load
    >>> player(load(find("crusher"))), player(load(find("incline")))
    ('player', None)
    """
    for actor in level.actors:
        if actor.role == "player" or (actor.role is None and actor.name == "player"):
            return actor.name
    return None


Verdict = Literal["pass", "declared", "stale", "fail", "none"]
"""What a variant came to: every check passed and no declaration covers it (``pass``); it is
declared unsupported and only checks its declarations name failed (``declared``); it is
declared unsupported but every check passed (``stale``: the declaration hides a pass); a check
failed that no declaration excuses, or the run could not be made (``fail``); there is no such
variant (``none``: no player to scale)."""


@dataclass(frozen=True, slots=True)
class Outcome:
    """One level at one variant.

    Attributes:
        level: the level's name.
        variant: the variant.
        checks: how many checks the level has.
        failed: the names of the checks that failed.
        details: what each of them reported, in the same order.
        declared: the level's declarations that this variant matches.
        error: why the variant could not be run (it did not load, or the run raised).
        seconds: wall-clock time of the run, s.
    """

    level: str
    variant: Variant
    checks: int = 0
    failed: tuple[str, ...] = ()
    details: tuple[str, ...] = ()
    declared: tuple[Unsupported, ...] = ()
    error: str | None = None
    seconds: float = 0.0
    ran: bool = True

    @property
    def excused(self) -> frozenset[str] | None:
        """The checks the matching declarations allow to fail (None: any of them)."""
        if any(d.checks is None for d in self.declared):
            return None
        return frozenset(name for d in self.declared for name in d.checks or ())

    @property
    def unexcused(self) -> tuple[str, ...]:
        """The failed checks no matching declaration names."""
        allowed = self.excused
        return tuple(f for f in self.failed if allowed is not None and f not in allowed)

    @property
    def verdict(self) -> Verdict:
        if not self.ran:
            return "none"
        if not self.declared:
            return "fail" if self.error is not None or self.failed else "pass"
        if self.error is not None:
            return "declared" if self.excused is None else "fail"
        if not self.failed:
            return "stale"
        return "fail" if self.unexcused else "declared"


def run(path: Path, name: str, variant: Variant) -> Outcome:
    """Run the level at ``path`` (called ``name``) as ``variant`` to its end."""
    from playground.scene import build
    from playground.scene.checks import watch

    start = time.perf_counter()
    try:
        sets = variant.settings(load(path))
        if sets is None:
            return Outcome(name, variant, ran=False)
        level = load(path, sets)
    except LevelError as exc:
        return Outcome(name, variant, error=str(exc))
    found = declared(level)
    try:
        scene = build(level)
        checks = watch(scene)
        scene.run(level.settings.seconds)
        results = checks.results()
    except Exception as exc:  # a variant may blow up anywhere: report it as its outcome
        error = f"{type(exc).__name__}: {exc}"
        return Outcome(name, variant, len(level.expect), declared=found, error=error)
    bad = [r for r in results if not r.passed]
    return Outcome(
        name,
        variant,
        len(results),
        tuple(r.name for r in bad),
        tuple(r.detail for r in bad),
        found,
        seconds=time.perf_counter() - start,
    )
