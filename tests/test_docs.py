"""Laws of the teaching chapters (docs/chapters): the text and the code never disagree.

Every number a chapter quotes sits in a marker, ``<!-- num:NAME -->3.00<!-- /num -->`` (the value
of ``tools.figures.NUMBERS[NAME]`` rounded to the digits shown) or
``<!-- below:NAME -->1e-12<!-- /below -->`` (an upper bound on it). The snippets themselves run as
doctests (pytest collects ``docs/**/*.md``). The exercises' answers and each chapter's claims are
checked as laws in tests/tools/figures/, a file per chapter module.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tools import figures
from tools.cli import main

DOCS = Path(__file__).resolve().parent.parent / "docs"
CHAPTERS = sorted((DOCS / "chapters").glob("*.md"))
MARKER = re.compile(r"<!-- (num|below):(\w+) -->([^<]*)<!-- /\1 -->")
FIGURE = re.compile(r"!\[[^\]]*\]\(\.\./img/chapters/([^)]+)\)")
GIF = re.compile(r"!\[[^\]]*\]\(\.\./img/gifs/([^)]+)\)")

TOL_REL = 1e-9
"""Relative slack beyond the printed rounding: float noise across machines and BLAS builds."""


def markers() -> list[tuple[str, str, str, str]]:
    """(chapter file, kind, name, text) of every marker in the chapters."""
    found = []
    for path in CHAPTERS:
        for kind, name, text in MARKER.findall(path.read_text(encoding="utf-8")):
            found.append((path.name, kind, name, text.strip()))
    return found


def printed_rounding(text: str) -> float:
    """Half a unit of the last printed digit of ``text`` ("5.0" → 0.05, "882.9" → 0.05)."""
    digits = len(text.split(".")[1]) if "." in text else 0
    return 0.5 * 10.0**-digits


def test_there_are_ten_chapters_and_an_index_linking_them_in_order() -> None:
    """The table of contents lists every chapter, in reading order."""
    assert len(CHAPTERS) == 10
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    positions = [index.find(f"chapters/{p.name}") for p in CHAPTERS]
    assert all(p >= 0 for p in positions), positions
    assert positions == sorted(positions)


@pytest.mark.parametrize(("chapter", "kind", "name", "text"), markers())
def test_quoted_number_is_what_the_code_computes(
    chapter: str, kind: str, name: str, text: str
) -> None:
    """A quoted number is the code's value rounded to the digits shown (or a bound above it)."""
    assert name in figures.NUMBERS, f"{chapter}: unknown number {name!r}"
    value = figures.NUMBERS[name]()
    quoted = float(text)
    if kind == "below":
        assert value < quoted, f"{chapter}: {name} = {value!r} is not below {text}"
    else:
        slack = printed_rounding(text) + TOL_REL * abs(value)
        assert abs(value - quoted) <= slack, f"{chapter}: {name} = {value!r}, text says {text}"


def test_every_number_the_code_makes_is_quoted() -> None:
    """No number is computed for nothing: each one in NUMBERS appears in some chapter."""
    quoted = {name for _, _, name, _ in markers()}
    assert set(figures.NUMBERS) <= quoted, sorted(set(figures.NUMBERS) - quoted)


def test_every_chapter_shows_a_figure_the_code_makes() -> None:
    """Each chapter embeds at least one figure, and every embedded figure is in FIGURES."""
    for path in CHAPTERS:
        shown = FIGURE.findall(path.read_text(encoding="utf-8"))
        assert shown, f"{path.name}: no figure"
        for name in shown:
            assert name in figures.FIGURES, f"{path.name}: {name} is not made by the code"


def test_one_command_regenerates_every_figure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``python -m tools figures --out DIR`` writes one PNG per figure, headless, and shows its
    progress on stderr (figure by figure, to the last)."""
    assert main(["figures", "--out", str(tmp_path)]) == 0
    for name in figures.FIGURES:
        data = (tmp_path / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n", name
    err = capsys.readouterr().err
    total = len(figures.FIGURES)
    assert f"{total}/{total}" in err, err[-300:]
    assert sorted(figures.FIGURES)[-1] in err


SEED_CHAPTERS = ("01-", "02-", "06-")
"""Chapters built on the seed post's sequences: each shows its level moving."""


def test_seed_chapters_show_their_levels_moving() -> None:
    """The seed-sequence chapters embed at least one GIF of a level; every embedded GIF exists,
    is a GIF with more than one frame, and has a caption after it (what to look at)."""
    from PIL import Image

    for path in CHAPTERS:
        text = path.read_text(encoding="utf-8")
        shown = GIF.findall(text)
        if path.name.startswith(SEED_CHAPTERS):
            assert shown, f"{path.name}: no GIF"
        for name in shown:
            gif = DOCS / "img" / "gifs" / name
            assert gif.read_bytes()[:6] == b"GIF89a", name
            with Image.open(gif) as im:
                assert im.n_frames > 1, name
            after = text.split(f"(../img/gifs/{name})", 1)[1].splitlines()[1:]
            # The caption follows the image (or the row of images it belongs to).
            rest = [ln for ln in after if ln.strip() and not ln.startswith("![")]
            assert rest and rest[0].startswith("*"), f"{path.name}: {name} has no caption"
