#!/usr/bin/env python3
"""Regenerates docs/results.md, docs/images/, the README's speed table and the HTML reports from
measurements on this machine; every number in them comes from the run.
    tools/results.py                    every section (about 1.5 hours on 2 cores cold)
    tools/results.py SECTION...         those sections, spliced into docs/results.md between their markers
    tools/results.py --list [SECTION]   the command lines, without running them
The experiments are tools/results/experiments/*.toml, the prose tools/results/templates/*.md:
docs/results-program.md. Python 3.11's standard library only."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "results"))

from engine.cli import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
