"""The results program (tools/results.py): experiments as TOML, prose as Markdown templates.

docs/results-program.md describes the files it reads and how to add an experiment or a section.
"""
