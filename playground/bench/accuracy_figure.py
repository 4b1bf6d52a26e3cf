"""The accuracy figure: error against cost for every configuration of the sweep with its Pareto
front marked, and beside it each scene's error against dt and against solver iterations.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from playground.bench.accuracy import DTS, ITERATIONS, Result
from playground.bench.plots import log_axes, pyplot, save
from playground.bench.scenes import SCENES, Knobs
from playground.bench.sweep_rows import ONE_PERCENT, Config, configurations, pareto, pick

__all__ = ["accuracy_figure"]


def accuracy_figure(rows: Sequence[Result], path: Path) -> list[Config]:
    """Draw error against cost with the Pareto front marked (and, beside it, error against dt
    and iterations) into ``path`` (PNG). Returns the configurations on the front.

    Needs matplotlib (``pip install 'pymunk-playground[bench]'``).
    """
    plt = pyplot()
    configs = configurations(rows)
    front = pareto([(c.cost_ms, c.error) for c in configs])
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    ax = axes[0]
    colours = {"reverse": "tab:blue", "contact": "tab:orange", "finite-difference": "tab:green"}
    for est, colour in colours.items():
        pts = [c for c in configs if c.estimator == est]
        ax.scatter(
            [c.cost_ms for c in pts], [c.error for c in pts], s=12, alpha=0.6, c=colour, label=est
        )
    ax.plot(
        [configs[i].cost_ms for i in front],
        [configs[i].error for i in front],
        "k-o",
        ms=4,
        lw=1.5,
        label="Pareto front",
    )
    log_axes(
        ax,
        "cost, ms of computing per simulated second",
        "mean relative error over the force scenes",
        "Accuracy against cost",
    )
    ax.legend(fontsize=8)
    for ax, label, knob_list, values in (
        (axes[1], "dt, s", [Knobs(dt=dt) for dt in DTS], DTS),
        (axes[2], "solver iterations", [Knobs(iterations=i) for i in ITERATIONS], ITERATIONS),
    ):
        for scene in SCENES:
            xs, ys = [], []
            for v, k in zip(values, knob_list, strict=True):
                r = pick(rows, k).get(scene)
                if r is not None and r.error > 0:
                    xs.append(v)
                    ys.append(r.error)
            if xs:
                ax.plot(xs, ys, "-o", ms=3, label=scene)
        ax.axhline(ONE_PERCENT, color="grey", ls="--", lw=0.8)
        log_axes(
            ax,
            label,
            "relative error (reverse, no filter)",
            f"Error against {label.split(',')[0]}",
        )
        # Label the swept values themselves (1/30 … 1/480 s; 1 … 40): log ticks collide here.
        ax.set_xticks(list(values), [f"1/{round(1 / v)}" if v < 1 else f"{v:g}" for v in values])
        ax.minorticks_off()
        ax.legend(fontsize=7)
    save(fig, path)
    return [configs[i] for i in front]
