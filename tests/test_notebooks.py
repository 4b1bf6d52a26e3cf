"""Laws of the chapters' notebooks (docs/chapters/*-notebook.ipynb): named apart from their
chapters, stored without outputs, each saying how to run it, each with a slider whose effect its
text explains, and each runs top to bottom.

Running them needs the ``notebooks`` extra (a Jupyter kernel, nbclient and ipywidgets); without
it those tests skip, and CI runs them after the main suite (.ci/run). A slider's callback runs
inside a widget's output area, where an exception does not stop the notebook, so the run also
fails on any error recorded in the widgets' state.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

CHAPTERS = Path(__file__).resolve().parent.parent / "docs" / "chapters"
NOTEBOOKS = sorted(CHAPTERS.glob("*.ipynb"))
SUFFIX = "-notebook.ipynb"
"""A chapter's notebook is named ``<chapter>-notebook.ipynb``: the site renders notebooks as
pages (mkdocs-jupyter), and ``04-filtering.ipynb`` would get the URL of ``04-filtering.md``."""
KNOBBED = ("04-", "05-", "06-", "07-")
"""Chapters with knobs, each of which has a notebook (filtering, the floating capsule, playing
with gravity, what accuracy costs)."""

SLIDER = re.compile(r"\b(?:Float|FloatLog|Int)Slider\([^)]*description=\"(\w+)\"")
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"

TIMEOUT_S = 120
"""Seconds a single cell may run before the run fails: the slowest takes a few seconds, and a
stuck kernel must fail CI long before its 15 minutes are gone."""


def cells(path: Path) -> list[dict[str, Any]]:
    """The notebook's cells, as stored."""
    found: list[dict[str, Any]] = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return found


def source(cell: dict[str, Any]) -> str:
    text = cell["source"]
    return text if isinstance(text, str) else "".join(text)


def test_every_chapter_with_knobs_has_a_notebook_beside_it_and_links_it() -> None:
    """A notebook named ``<chapter>-notebook.ipynb`` sits beside each chapter that has knobs;
    the chapter links it, and it links the chapter."""
    for prefix in KNOBBED:
        (chapter,) = CHAPTERS.glob(f"{prefix}*.md")
        notebook = chapter.with_name(chapter.stem + SUFFIX)
        assert notebook.is_file(), f"no {notebook.name} beside {chapter.name}"
        assert f"]({notebook.name})" in chapter.read_text(encoding="utf-8"), chapter.name
        text = "".join(source(c) for c in cells(notebook) if c["cell_type"] == "markdown")
        assert f"]({chapter.name})" in text, notebook.name


def test_no_notebook_shares_a_page_url() -> None:
    """Every notebook is named ``*-notebook.ipynb`` (the site renders only those), and none has
    the name of a Markdown page but for its suffix (the two would get one URL)."""
    assert NOTEBOOKS
    pages = {p.stem for p in CHAPTERS.glob("*.md")}
    for path in NOTEBOOKS:
        assert path.name.endswith(SUFFIX), f"{path.name}: name it <chapter>{SUFFIX}"
        assert path.stem not in pages, f"{path.name}: the URL of {path.stem}.md"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_says_how_to_run_it_before_its_first_code(path: Path) -> None:
    """The site shows a notebook without running it: before its first code cell, its text says
    that the sliders need a kernel, and the commands that start one on this very notebook."""
    text = ""
    for cell in cells(path):
        if cell["cell_type"] == "code":
            break
        text += source(cell)
    assert "kernel" in text and "without outputs" in text, path.name
    assert "pip install -e '.[notebooks]' jupyterlab" in text, path.name
    assert f"jupyter lab docs/chapters/{path.name}" in text, path.name


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_stored_without_outputs(path: Path) -> None:
    """Outputs are stripped in the repository: no outputs, no execution counts, no widget state."""
    for i, cell in enumerate(cells(path)):
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [], f"{path.name}: cell {i} has outputs"
            assert cell["execution_count"] is None, f"{path.name}: cell {i} has a count"
    meta = json.loads(path.read_text(encoding="utf-8"))["metadata"]
    assert "widgets" not in meta, f"{path.name}: widget state stored"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_each_slider_is_explained_in_the_text(path: Path) -> None:
    """The notebook has at least one slider, and the text names each slider (in bold, as
    **`name`**) in a markdown cell before the code that makes it, where it says what it does."""
    sliders = []
    text_so_far = ""
    for cell in cells(path):
        if cell["cell_type"] == "markdown":
            text_so_far += source(cell)
            continue
        for name in SLIDER.findall(source(cell)):
            sliders.append(name)
            assert f"**`{name}`**" in text_so_far, f"{path.name}: slider {name!r} not explained"
    assert sliders, f"{path.name}: no slider"


def widget_errors(notebook: Any) -> list[str]:
    """Errors raised inside sliders' callbacks, as the run recorded them in the widgets' state."""
    state = notebook.metadata.get("widgets", {}).get(WIDGET_STATE, {}).get("state", {})
    return [
        f"{out['ename']}: {out['evalue']}"
        for model in state.values()
        if model.get("model_name") == "OutputModel"
        for out in model.get("state", {}).get("outputs", [])
        if out.get("output_type") == "error"
    ]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs_top_to_bottom(path: Path, tmp_path: Path) -> None:
    """Every cell runs, in order, in a fresh kernel started in the chapters' folder, and no
    slider's callback raises."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    manager = pytest.importorskip("jupyter_client.manager")
    pytest.importorskip("ipywidgets")
    pytest.importorskip("ipykernel")
    notebook = nbformat.read(path, as_version=4)
    # Unix sockets, not TCP: a kernel on TCP ports picked free a moment earlier can lose them to
    # another process on a busy machine and die or hang (seen 3 times in 10 runs under load).
    kernel = manager.KernelManager(
        kernel_name="python3", transport="ipc", ip=str(tmp_path / "kernel")
    )
    client = nbclient.NotebookClient(
        notebook,
        km=kernel,
        timeout=TIMEOUT_S,
        resources={"metadata": {"path": str(CHAPTERS)}},
    )
    client.execute()
    assert widget_errors(notebook) == []
