"""The shipped levels and their JSON Schema: data, installed as ``playground.levels``.

This folder is mapped into the package when it is built (see ``pyproject.toml``);
:func:`playground.level.shipped` reads it with ``importlib.resources``.
"""
