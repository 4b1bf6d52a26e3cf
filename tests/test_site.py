"""The documentation site as a reader sees it: built with MkDocs in strict mode, opened in headless
Chromium; and its generated pages (level format, command line, API) cover what they document.

The browser tests need the ``docs`` extra and Debian's ``chromium``; without them they skip,
except where ``PLAYGROUND_SITE`` names a built site (``.ci/run`` does), where they must run.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from numpy.typing import NDArray

import playground
from playground.cli.parser import COMMANDS, parser

ROOT = Path(__file__).resolve().parent.parent
CHROMIUM = Path("/usr/bin/chromium")
SHOT_SIZE = (1280, 2400)
"""Window size of a screenshot, px: tall enough to hold chapter 2's first figure."""
FIGURE_COLOURS = 2
"""How many of the figure's most common plot colours are looked for in the screenshot."""
COLOUR_TOLERANCE = 12
"""Per channel, 0–255: a pixel this near a colour is that colour resampled by the browser."""
FIGURE_SHARE = 0.25
"""Of a colour's pixels in the figure, the share the screenshot must hold: the page shows the
figure at half its width or more, so a quarter of its area or more."""
CHROMA = 60
"""max(r, g, b) − min(r, g, b) above which a colour is a plot's colour, not a grey of the page."""
KEYWORD_GREEN = (0, 128, 0)
"""The notebook theme's colour of Python keywords (``import``, ``def``): on screen only if the
notebook's code cells were rendered with its styles."""
KEYWORD_PIXELS = 100
"""Pixels of that colour the screenshot must hold: a few keywords' worth (one is ~30 px), none on
a Markdown page, whose code the site's theme colours otherwise)."""

spec = importlib.util.spec_from_file_location("site_pages", ROOT / "docs" / "site_pages.py")
assert spec is not None and spec.loader is not None
site_pages = importlib.util.module_from_spec(spec)
spec.loader.exec_module(site_pages)


def test_the_level_format_page_has_a_table_for_every_kind_of_table() -> None:
    """Law: every definition of the schema and every top-level key is on the page, with units."""
    schema = json.loads((ROOT / "levels" / "level.schema.json").read_text(encoding="utf-8"))
    page = site_pages.level_format_page(schema)
    for name in schema["$defs"]:
        assert f"\n## {name}\n" in page, name
    for key in schema["properties"]:
        assert f"| `{key}` |" in page, key
    assert "| `dt` | number | s |" in page


def test_the_command_line_page_has_every_command_and_option() -> None:
    """Law: each command of the parser has a section holding its own ``--help`` text."""
    page = site_pages.command_line_page(parser())
    for name, _help, _configure in COMMANDS:
        assert f"\n## playground {name}\n" in page, name
    assert "--seconds" in page and "--screenshot" in page


def test_the_api_pages_document_every_public_name_once() -> None:
    """Law: every name of ``playground.__all__`` is rendered on exactly one API page."""
    pages = site_pages.api_pages()
    directives = [
        line for text in pages.values() for line in text.splitlines() if line.startswith(":::")
    ]
    assert sorted(directives) == sorted(f"::: playground.{n}" for n in playground.__all__)
    nav = site_pages.api_nav()
    assert sorted(nav) == sorted(pages) and nav[0] == "api/index.md"
    assert nav.index("api/world.md") < nav.index("api/controller.md")  # API_GROUPS order


@pytest.fixture(scope="module")
def site() -> Path:
    """The built site: ``$PLAYGROUND_SITE``, or built here when MkDocs is installed."""
    given = os.environ.get("PLAYGROUND_SITE")
    if given:
        return Path(given).resolve()  # a relative path has no file:// URI for the browser
    if importlib.util.find_spec("mkdocs") is None:
        pytest.skip("the docs extra is not installed")
    out = Path(tempfile.mkdtemp(prefix="site-"))
    subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "--site-dir", str(out)],
        cwd=ROOT,
        check=True,
        env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
    )
    return out


def _chromium(page: Path, *args: str) -> subprocess.CompletedProcess[bytes]:
    if not CHROMIUM.exists():
        if os.environ.get("PLAYGROUND_SITE"):
            pytest.fail(f"{CHROMIUM} is missing: the site's browser test cannot run")
        pytest.skip("Debian's chromium is not installed")
    with tempfile.TemporaryDirectory() as profile:
        return subprocess.run(
            [
                str(CHROMIUM),
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-quic",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--hide-scrollbars",
                f"--user-data-dir={profile}",
                f"--window-size={SHOT_SIZE[0]},{SHOT_SIZE[1]}",
                *args,
                page.as_uri(),
            ],
            capture_output=True,
            check=True,
            timeout=120,
        )


def _render(page: Path, shot: Path) -> str:
    """The page's DOM after Chromium ran it, and its screenshot written to ``shot``."""
    _chromium(page, f"--screenshot={shot}")
    return _chromium(page, "--dump-dom").stdout.decode("utf-8")


def _pixels(picture: Any) -> NDArray[np.int64]:
    return np.asarray(picture.convert("RGB"), dtype=np.int64).reshape(-1, 3)


def _near(pixels: NDArray[np.int64], colour: NDArray[np.int64]) -> int:
    return int((np.abs(pixels - colour).max(axis=1) <= COLOUR_TOLERANCE).sum())


def test_the_home_page_renders(site: Path, tmp_path: Path) -> None:
    dom = _render(site / "index.html", tmp_path / "home.png")
    assert "How a force-driven character works" in dom
    assert 'href="own-game.html"' in dom and 'href="api/index.html"' in dom
    assert (tmp_path / "home.png").stat().st_size > 10_000


def test_a_chapter_renders_with_its_figure(site: Path, tmp_path: Path) -> None:
    """The figure is on screen: its own strongest colours are among the screenshot's pixels."""
    image = pytest.importorskip("PIL.Image")
    chapter = site / "chapters" / "02-reverse-integration.html"
    dom = _render(chapter, tmp_path / "chapter.png")
    assert "Reverse force integration" in dom
    assert 'src="../img/chapters/02-reverse-integration.png"' in dom
    figure = _pixels(image.open(ROOT / "docs" / "img" / "chapters" / "02-reverse-integration.png"))
    shot = _pixels(image.open(tmp_path / "chapter.png"))
    colours, counts = np.unique(figure, axis=0, return_counts=True)
    plot = (colours.max(axis=1) - colours.min(axis=1)) > CHROMA
    order = np.argsort(-counts[plot])[:FIGURE_COLOURS]
    for colour in colours[plot][order]:
        in_figure, on_page = _near(figure, colour), _near(shot, colour)
        assert on_page >= FIGURE_SHARE * in_figure, (tuple(colour), on_page, in_figure)


def test_the_world_api_page_renders(site: Path, tmp_path: Path) -> None:
    dom = _render(site / "api" / "world.html", tmp_path / "world.png")
    assert 'id="playground.World"' in dom
    for method in ("step", "run", "track", "forces"):
        assert f'id="playground.World.{method}"' in dom, method
    assert "A pymunk space in SI units" in dom  # its docstring


def test_a_notebook_renders_with_its_cells_and_says_it_needs_a_kernel(
    site: Path, tmp_path: Path
) -> None:
    """A chapter's notebook is a page: every cell of it (by its id) is in the page, the code
    highlighted on screen, its link to the chapter made the site's, and the note that the
    sliders need a kernel is there; the chapter links the notebook's page."""
    image = pytest.importorskip("PIL.Image")
    name = "04-filtering-notebook"
    notebook = json.loads((ROOT / "docs" / "chapters" / f"{name}.ipynb").read_text("utf-8"))
    dom = _render(site / "chapters" / f"{name}.html", tmp_path / "notebook.png")
    assert "Filtering a spiky force — turn the knobs" in dom
    for cell in notebook["cells"]:
        assert f'id="cell-id={cell["id"]}"' in dom, cell["id"]
    assert "FloatLogSlider" in dom and "running Jupyter kernel" in dom
    assert 'href="04-filtering.html"' in dom and 'href="04-filtering.md"' not in dom
    shot = _pixels(image.open(tmp_path / "notebook.png"))
    assert _near(shot, np.array(KEYWORD_GREEN)) > KEYWORD_PIXELS
    chapter = (site / "chapters" / "04-filtering.html").read_text(encoding="utf-8")
    assert f'href="{name}.html"' in chapter
