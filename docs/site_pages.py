"""The documentation site's generated pages: the level format from the JSON Schema, the command
line from the argparse parser, the API reference from ``playground.__all__``, and the README.

MkDocs loads this file as a hook (``hooks:`` in mkdocs.yml); the page makers are plain functions
of the project's own objects, so a test can call them without MkDocs installed.
"""

from __future__ import annotations

import argparse
import ast
import json
import logging
import os
import posixpath
import re
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

try:
    from griffe import Extension as _GriffeExtension
except ImportError:  # the docs extra is not installed: the page makers still work
    _GriffeExtension = object

ROOT = Path(__file__).resolve().parent.parent

API_GROUPS: dict[str, str] = {
    "world": "The world",
    "fixed_step": "The fixed step in a game loop",
    "controller": "The controller",
    "gameplay": "Gameplay events",
    "intents": "Intents",
    "forces": "Forces",
    "gravity": "Gravity",
    "movers": "Movers",
    "perception": "Perception",
    "filters": "Filters",
}
"""The API reference's pages, in order: the subpackage or module under ``playground`` that defines
an object (its ``__module__``'s second part) → the page's title."""

LEADS = (
    "World",
    "Controller",
    "Gameplay",
    "ForceSolver",
    "GravityField",
    "Mover",
    "PerceivedGravity",
)
"""The object each API page opens with, where it has one; the rest follow alphabetically."""

_ROLE = re.compile(r":(?:[a-z]+:)+`~?([^`]+)`")


def plain(text: str) -> str:
    """Sphinx roles as code, the way the docstrings are meant to read.

    >>> plain("the :class:`~playground.World` and :mod:`playground.gravity`")
    'the `playground.World` and `playground.gravity`'
    """
    return _ROLE.sub(r"`\1`", text)


def fenced(text: str) -> str:
    """Doctest blocks (a ``>>>`` line to the next blank line) fenced as code, roles as code: what
    a docstring means, in Markdown.

    >>> fenced("Sums:\\n>>> 1 + 1\\n2\\n\\nsee :func:`sum`.").splitlines()
    ['Sums:', '```pycon', '>>> 1 + 1', '2', '```', '', 'see `sum`.']
    """
    out: list[str] = []
    indent: str | None = None
    for line in plain(text).split("\n"):
        if indent is None and line.lstrip().startswith(">>>"):
            indent = line[: len(line) - len(line.lstrip())]
            out.append(indent + "```pycon")
        elif indent is not None and not line.strip():
            out.append(indent + "```")
            indent = None
        out.append(line)
    if indent is not None:
        out.append(indent + "```")
    return "\n".join(out)


def param_doc(value: str) -> str | None:
    """A declared parameter's doc and unit, from its declaration's source
    (``param(default, doc=..., unit=...)``, :mod:`playground.params`), or None for anything else.

    >>> param_doc("param(70.0, doc='Mass when built.', unit='kg', ge=MIN_MASS)")
    'Mass when built. Unit: kg.'
    >>> param_doc("param(False, doc='Wants to jump.')"), param_doc("0.5")
    ('Wants to jump.', None)
    """
    try:
        call = ast.parse(value, mode="eval").body
    except SyntaxError:
        return None
    if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Name)):
        return None
    if call.func.id != "param":
        return None
    words = {
        k.arg: k.value.value
        for k in call.keywords
        if isinstance(k.value, ast.Constant) and isinstance(k.value.value, str)
    }
    if "doc" not in words:
        return None
    return f"{words['doc']} Unit: {words['unit']}." if words.get("unit") else words["doc"]


class DocstringMarkdown(_GriffeExtension):  # type: ignore[misc, valid-type]
    """Griffe extension (mkdocs.yml loads it): every docstring through :func:`fenced`; a field
    declared with ``param`` and no docstring of its own gets its declared doc and unit."""

    def on_instance(self, *, obj: Any, **kwargs: Any) -> None:
        if obj.docstring is None and getattr(obj, "kind", None) is not None:
            doc = param_doc(str(getattr(obj, "value", "")))
            if doc is not None and obj.kind.value == "attribute":
                from griffe import Docstring

                obj.docstring = Docstring(doc, parent=obj)
        if obj.docstring is not None:
            obj.docstring.value = fenced(obj.docstring.value)


def _anchor(name: str) -> str:
    return name.lower().replace("_", "-")


def _type(spec: Mapping[str, Any]) -> str:
    """One schema node's type, written briefly: references link to their table."""
    if "$ref" in spec:
        name = str(spec["$ref"]).rsplit("/", 1)[-1]
        return f"[{name}](#{_anchor(name)})"
    for key in ("oneOf", "anyOf"):
        if key in spec:
            kinds = [_type(s) for s in spec[key] if s.get("type") != "null"]
            return " or ".join(kinds) + (" or none" if len(kinds) < len(spec[key]) else "")
    if "enum" in spec:
        return " \\| ".join(f"`{json.dumps(v)}`" for v in spec["enum"])
    if "const" in spec:
        return f"`{json.dumps(spec['const'])}`"
    kind = spec.get("type", "any")
    if kind == "array":
        if "prefixItems" in spec:
            return "[" + ", ".join(_type(s) for s in spec["prefixItems"]) + "]"
        return "list of " + _type(spec.get("items", {}))
    if kind == "object" and "additionalProperties" in spec:
        extra = spec["additionalProperties"]
        if isinstance(extra, Mapping):
            return "table of " + _type(extra)
    return str(kind)


def _bounds(spec: Mapping[str, Any]) -> str:
    parts = []
    for key, sign in (
        ("minimum", "≥"),
        ("ge", "≥"),
        ("exclusiveMinimum", ">"),
        ("maximum", "≤"),
        ("le", "≤"),
        ("exclusiveMaximum", "<"),
    ):
        if key in spec:
            parts.append(f"{sign} {spec[key]:g}")
    return ", ".join(parts)


def _cell(text: str) -> str:
    return plain(text).replace("\n", " ").replace("|", "\\|")


def _table(node: Mapping[str, Any]) -> Iterator[str]:
    props: Mapping[str, Any] = node.get("properties", {})
    required = set(node.get("required", ()))
    yield "| key | type | unit | default | bounds | meaning |"
    yield "|---|---|---|---|---|---|"
    for key, spec in props.items():
        if key in required:
            default = "required"
        elif "default" in spec:
            default = f"`{json.dumps(spec['default'])}`"
        else:
            default = "—"
        yield (
            f"| `{key}` | {_type(spec)} | {spec.get('unit', '')} | {default} | {_bounds(spec)} "
            f"| {_cell(spec.get('description', ''))} |"
        )


def level_format_page(schema: Mapping[str, Any]) -> str:
    """The level format reference: the top-level keys, then one table per table kind.

    >>> page = level_format_page({"title": "Level", "properties": {"seconds": {"type": "number",
    ...     "unit": "s", "default": 3.0, "minimum": 0}}, "$defs": {}})
    >>> "| `seconds` | number | s | `3.0` | ≥ 0 |" in page
    True
    """
    lines = [
        "# Level format",
        "",
        "A level is one TOML file. This page is generated from the level JSON Schema",
        "(`playground schema`, committed as `levels/level.schema.json`); each key's unit,",
        "default and bounds come from the core's own declarations. `playground check FILE`",
        "applies the same rules plus the ones a schema cannot say (names that must exist,",
        "ordered windows), then builds the scene as `playground run` does: a joint needs a",
        "dynamic body; every event, scripted `nullify` and check names a body that exists at",
        "its time (the timeline walked in run order); a spawned prop gets every check a prop",
        "gets; derived values (the field after a flip, a jump's impulse, an actor's reach)",
        "stay within the limits. What `check` accepts, `run` runs; each refusal names the",
        "file and the key.",
        "",
        "## The file",
        "",
        plain(str(schema.get("description", ""))),
        "",
        *_table(schema),
    ]
    for name, node in schema.get("$defs", {}).items():
        lines += ["", f"## {name}", "", plain(str(node.get("description", "")))]
        if "properties" in node:
            lines += ["", *_table(node)]
        else:
            lines += ["", f"Type: {_type(node)}."]
    return "\n".join(lines) + "\n"


def _subcommands(top: argparse.ArgumentParser) -> Iterator[tuple[str, argparse.ArgumentParser]]:
    for action in top._actions:  # argparse keeps its subparsers only here
        if isinstance(action, argparse._SubParsersAction):
            yield from action.choices.items()


def command_line_page(top: argparse.ArgumentParser) -> str:
    """The command line reference: the parser's own help for the command and each subcommand.

    >>> p = argparse.ArgumentParser(prog="tool")
    >>> sub = p.add_subparsers()
    >>> _ = sub.add_parser("go", help="go somewhere").add_argument("--far", help="how far, m")
    >>> page = command_line_page(p)
    >>> "## tool go" in page and "how far, m" in page
    True
    """
    old = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = "100"  # argparse wraps at the terminal's width: fix it for the page
    try:
        lines = [
            "# Command line",
            "",
            f"Generated from the `{top.prog}` command's own parser; `{top.prog} COMMAND --help`",
            "prints the same text.",
            "",
            "```text",
            top.format_help().rstrip(),
            "```",
        ]
        for name, sub in _subcommands(top):
            lines += ["", f"## {top.prog} {name}", "", "```text", sub.format_help().rstrip(), "```"]
    finally:
        if old is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = old
    return "\n".join(lines) + "\n"


def api_groups(names: list[str], modules: Mapping[str, str]) -> dict[str, list[str]]:
    """The public names by API page (see :data:`API_GROUPS`); a name whose module has no page of
    its own goes on the world's.

    >>> api_groups(["Stage", "Uniform", "World"], {"Stage": "playground.world.schedule",
    ...     "Uniform": "playground.gravity.fields", "World": "playground.world.world"})
    {'world': ['World', 'Stage'], 'gravity': ['Uniform']}
    """
    groups: dict[str, list[str]] = {key: [] for key in API_GROUPS}
    for name in names:
        part = modules[name].split(".")[1]
        groups[part if part in API_GROUPS else "world"].append(name)
    return {
        key: sorted(value, key=lambda name: (name not in LEADS, name))
        for key, value in groups.items()
        if value
    }


def _home(name: str, obj: object) -> str:
    """The module defining a public name: its ``__module__``, or for a value without one of
    ours (a type alias such as a union), the module whose ``__all__`` declares it."""
    import sys

    module = str(getattr(obj, "__module__", ""))
    if module.startswith("playground."):
        return module
    return next(
        key
        for key, mod in sorted(sys.modules.items())
        if key.startswith("playground.") and name in getattr(mod, "__all__", ())
    )


def api_pages() -> dict[str, str]:
    """Every API page (path → markdown): one per group of ``playground.__all__``, and an index."""
    import playground

    names = sorted(playground.__all__)
    modules = {name: _home(name, getattr(playground, name)) for name in names}
    groups = api_groups(names, modules)
    pages = {}
    index = [
        "# API reference",
        "",
        "Everything `import playground` offers (`playground.__all__`), from its docstrings.",
        "",
    ]
    for key, members in groups.items():
        title = API_GROUPS[key]
        index.append(f"- [{title}]({key}.md): " + ", ".join(f"`{m}`" for m in members))
        body = [f"# {title}", ""]
        for member in members:
            body += [f"::: playground.{member}", ""]
        pages[f"api/{key}.md"] = "\n".join(body)
    pages["api/index.md"] = "\n".join(index) + "\n"
    return pages


_README_LINK = re.compile(r"\]\(docs/")


def readme_page(text: str) -> str:
    """The README as a page of the site: its links into ``docs/`` made relative to the site.

    >>> readme_page("see [it](docs/index.md)")
    'see [it](index.md)'
    """
    return _README_LINK.sub("](", text)


def generated_pages() -> dict[str, str]:
    """Every generated page of the site: path under the site → markdown."""
    from playground.cli.parser import parser

    schema = json.loads((ROOT / "levels" / "level.schema.json").read_text(encoding="utf-8"))
    pages = {
        "reference/levels.md": level_format_page(schema),
        "reference/command-line.md": command_line_page(parser()),
        "readme.md": readme_page((ROOT / "README.md").read_text(encoding="utf-8")),
    }
    pages.update(api_pages())
    return pages


def api_nav() -> list[str]:
    """The API section of the site's navigation: the index, then each page in
    :data:`API_GROUPS` order (only the groups that have names, so a moved name never leaves an
    empty page behind)."""
    return sorted(api_pages(), key=lambda path: (path != "api/index.md", _page_rank(path)))


def _page_rank(path: str) -> int:
    key = path.removeprefix("api/").removesuffix(".md")
    return list(API_GROUPS).index(key) if key in API_GROUPS else -1


def _replace_api(nav: Any) -> bool:
    """Put :func:`api_nav` under the nav's ``API`` entry; whether one was found."""
    for item in nav if isinstance(nav, list) else ():
        if isinstance(item, dict):
            for title, sub in item.items():
                if title == "API":
                    item[title] = api_nav()
                    return True
                if _replace_api(sub):
                    return True
    return False


def on_config(config: Any) -> Any:
    """MkDocs hook: the API pages in the navigation, from ``playground.__all__``."""
    if not _replace_api(config["nav"]):
        raise ValueError("mkdocs.yml: the nav has no 'API' entry for the generated API pages")
    return config


def on_files(files: Any, config: Any) -> Any:
    """MkDocs hook: add the generated pages to the site's files."""
    from mkdocs.structure.files import File

    for path, text in generated_pages().items():
        files.append(File.generated(config, path, content=text))
    return files


def on_page_markdown(markdown: str, page: Any, config: Any, files: Any) -> str:
    """MkDocs hook: a link from a chapter to ``../README.md`` (right on GitHub) goes to the
    site's copy of the README."""
    here = posixpath.dirname(page.file.src_uri)
    target = posixpath.relpath("readme.md", here or ".")
    return re.sub(r"\]\((?:\.\./)+README\.md", f"]({target}", markdown)


_MD_HREF = re.compile(r'href="(?![a-z][a-z0-9+.-]*:|/|#)([^"#]+\.md)(#[^"]*)?"')
_log = logging.getLogger("mkdocs.hooks.site_pages")  # under "mkdocs": --strict counts it


def notebook_links(
    html: str, src_uri: str, url: str, pages: Mapping[str, str]
) -> tuple[str, list[str]]:
    """A notebook page's links to the site's pages made the site's URLs, and the links whose
    page does not exist. A notebook links a chapter as Jupyter opens it (``04-filtering.md``);
    MkDocs rewrites and checks such links only in Markdown pages, so a notebook page's are done
    here. ``pages``: each page's source path → its URL, both under the site.

    >>> pages = {"chapters/04-filtering.md": "chapters/04-filtering.html", "index.md": "index.html"}
    >>> html = '<a href="04-filtering.md#lag">4</a><a href="../index.md">1</a><a href="x.md">x</a>'
    >>> html, missing = notebook_links(html, "chapters/nb.ipynb", "chapters/nb.html", pages)
    >>> html
    '<a href="04-filtering.html#lag">4</a><a href="../index.html">1</a><a href="x.md">x</a>'
    >>> missing
    ['x.md']
    """
    here, at = posixpath.dirname(src_uri), posixpath.dirname(url) or "."
    missing: list[str] = []

    def site_url(match: re.Match[str]) -> str:
        target = posixpath.normpath(posixpath.join(here, match[1]))
        if target not in pages:
            missing.append(match[1])
            return match[0]
        return f'href="{posixpath.relpath(pages[target], at)}{match[2] or ""}"'

    return _MD_HREF.sub(site_url, html), missing


def on_page_content(html: str, page: Any, config: Any, files: Any) -> str:
    """MkDocs hook: a notebook page's links to other pages (see :func:`notebook_links`); a link
    to no page is a warning, so ``--strict`` fails on it as on a Markdown page's."""
    if not page.file.src_uri.endswith(".ipynb"):
        return html
    pages = {f.src_uri: f.url for f in files.documentation_pages()}
    html, missing = notebook_links(html, page.file.src_uri, page.file.url, pages)
    for link in missing:
        _log.warning(
            "%s: the notebook links %r, which is no page of the site", page.file.src_uri, link
        )
    return html
