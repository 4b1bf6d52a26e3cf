"""Laws of the figures package (:mod:`tools.figures`): one module per teaching chapter
declares that chapter's numbers and its figure."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from tools.figures import CHAPTERS, FIGURES, NUMBERS

ROOT = Path(__file__).resolve().parents[3]
DOCS = ROOT / "docs"
CHAPTER = re.compile(r"docs/chapters/((\d\d)-[\w-]+\.md)")
MODULE = re.compile(r"tools\.figures\.ch(\d\d)_\w+")


def test_each_chapter_has_one_module_whose_docstring_names_it() -> None:
    """Every chapter file is served by exactly one module, in reading order, which names it."""
    served = []
    for module in CHAPTERS:
        (found,) = {m.group(1, 2) for m in CHAPTER.finditer(module.__doc__ or "")}
        name, number = found
        assert (DOCS / "chapters" / name).is_file(), (module.__name__, name)
        assert MODULE.fullmatch(module.__name__).group(1) == number, (module.__name__, name)
        served.append(name)
    assert served == sorted(p.name for p in (DOCS / "chapters").glob("*.md"))


def test_every_number_and_figure_is_declared_by_its_chapters_module() -> None:
    """``chN_…`` numbers and the ``NN-…`` figure come from chapter N's module, each chapter has
    exactly one figure and quotes at least one number."""
    for name, fn in NUMBERS.items():
        chapter = int(MODULE.fullmatch(fn.__module__).group(1))
        assert name.startswith(f"ch{chapter}_"), (name, fn.__module__)
    for name, draw in FIGURES.items():
        assert name.startswith(MODULE.fullmatch(draw.__module__).group(1) + "-"), name
    for module in CHAPTERS:
        mine = [n for n, fn in NUMBERS.items() if fn.__module__ == module.__name__]
        drawn = [n for n, fn in FIGURES.items() if fn.__module__ == module.__name__]
        assert mine and len(drawn) == 1, (module.__name__, mine, drawn)


def test_the_numbers_need_no_matplotlib() -> None:
    """Computing a number imports neither matplotlib nor pygame."""
    code = (
        "import sys, tools.figures as f; f.NUMBERS['ch8_hitch_steps'](); "
        "print(sorted(m for m in ('matplotlib', 'pygame') if m in sys.modules))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT
    )
    assert out.stdout.strip() == "[]", out
