"""The repository's own tooling, not installed with the package: the generated pages
(docs/performance.md with the performance goals, docs/accuracy.md with the settings guide) and
the teaching chapters' numbers and figures. Run from a checkout: ``python -m tools --help``.
"""
