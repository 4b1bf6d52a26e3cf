"""What drawing one frame of the view costs: ``App.render()`` on a level at 1280×720 off screen,
after its physics for the frame, with the lab panel hidden and shown.

    python benchmarks/view_frame.py                      # crusher, 5 repeats of 120 frames
    python benchmarks/view_frame.py --level sandbox --repeats 9

Each repeat restarts the level, runs 60 warm-up frames, then times ``render()`` alone over the
next frames (physics excluded); the output is the median over repeats of each repeat's median
frame, ms, with and without the lab panel (alternating, in one process).
"""

from __future__ import annotations

import argparse
import statistics
import time

import pygame

from playground.view import App
from playground.view.launcher import init_headless, level_names, show_level

SIZE = (1280, 720)
WARM_UP = 60  # frames before timing: the level's start (load-time spikes) is not the steady cost


def one_repeat(level: str, frames: int, lab: bool) -> float:
    """The median render time (s) of ``frames`` frames of ``level`` after the warm-up."""
    app = App(show_level, level, levels=level_names(), size=SIZE)
    if lab:
        app.handle(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_l))
    app.run_frames(WARM_UP)
    times = []
    for _ in range(frames):
        app.frame(1.0 / 60.0)
        t0 = time.perf_counter()
        app.render()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--level", default="crusher")
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    init_headless()
    plain: list[float] = []
    panel: list[float] = []
    for _ in range(args.repeats):
        plain.append(one_repeat(args.level, args.frames, lab=False))
        panel.append(one_repeat(args.level, args.frames, lab=True))
    print(
        f"{args.level} at {SIZE[0]}x{SIZE[1]}: render {statistics.median(plain) * 1e3:.2f} ms "
        f"a frame, with the lab panel {statistics.median(panel) * 1e3:.2f} ms "
        f"(median of {args.repeats} repeats of {args.frames} frames)"
    )


if __name__ == "__main__":
    main()
