"""The robustness matrix (issue 22), in the slow tier: every level in ``levels/`` at each of the
27 variants of :mod:`playground.scene.robustness` (player mass ×0.5, ×1, ×2 × dt 1/60, 1/120,
1/240 s × substeps 1, 2, 4; a level without a player has no mass axis).

A variant passes every check, or the level declares it unsupported in ``[[variants.unsupported]]``
with its physical reason (then it is skipped, and the skip says which checks failed and why);
a declared variant that passes fails here (the declaration is stale), and so does one where a
check its declarations do not name fails. ``python benchmarks/matrix.py`` prints the table.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from playground.level import load
from playground.scene.robustness import VARIANTS, Variant, run

LEVELS = sorted((Path(__file__).parents[1] / "levels").glob("*.toml"))


def _cases() -> Iterator[object]:
    for path in LEVELS:
        level = load(path)
        for variant in VARIANTS:
            if variant.settings(level) is not None:
                yield pytest.param(path, variant, id=f"{path.stem}-{variant.id}")


@pytest.mark.slow
@pytest.mark.parametrize(("path", "variant"), list(_cases()))
def test_the_level_holds_or_declares_why_not(path: Path, variant: Variant) -> None:
    outcome = run(path, path.stem, variant)
    why = "; ".join(str(d) for d in outcome.declared)
    failed = "\n  ".join(outcome.details or (outcome.error or "",))
    if outcome.verdict == "declared":
        pytest.skip(f"declared unsupported ({why}); failed: {', '.join(outcome.failed)}")
    assert outcome.verdict != "stale", (
        f"{path.name} declares {variant.label} unsupported ({why}), but every check passes: "
        "the declaration is stale (narrow or remove it)"
    )
    assert outcome.verdict == "pass", f"{path.name} at {variant.label}:\n  {failed}"
