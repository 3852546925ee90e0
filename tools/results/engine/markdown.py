"""Markdown the helpers write and where it goes: tables of thumbnails, and splicing a block between
the markers of docs/results.md (<!-- section:NAME --> ... <!-- /section:NAME -->, markers included
in the block) or of another file (<!-- NAME --> ... <!-- /NAME -->, markers kept)."""

from .errors import InputError


def table(header, rows):
    """A Markdown table: a header row, the rule, the rows (lists of cell texts)."""
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join("---" for _ in header) + " |"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def section_block(name, body):
    return f"<!-- section:{name} -->\n{body}<!-- /section:{name} -->\n"


def splice_section(document, name, block, where):
    """`document` with section `name` (markers and all) replaced by `block`."""
    lines = document.splitlines(keepends=True)
    start, end = f"<!-- section:{name} -->\n", f"<!-- /section:{name} -->\n"
    if start not in lines:
        raise InputError(f"{where} has no '{start.strip()}' section to replace; run tools/results.py (every section) "
                         "first")
    i = lines.index(start)
    try:
        j = lines.index(end, i)
    except ValueError:
        raise InputError(f"{where}: '{start.strip()}' without its '{end.strip()}'") from None
    return "".join(lines[:i]) + block + "".join(lines[j + 1:])


def splice_marker(document, marker, body, where):
    """`document` with what lies between <!-- marker --> and <!-- /marker --> replaced by `body`."""
    lines = document.splitlines(keepends=True)
    start, end = f"<!-- {marker} -->", f"<!-- /{marker} -->"
    found = [k for k, line in enumerate(lines) if start in line]
    if not found:
        raise InputError(f"{where} has no '{start}' marker; allowed: a file holding '{start}' ... '{end}'")
    i = found[0]
    j = next((k for k in range(i + 1, len(lines)) if end in lines[k]), None)
    if j is None:
        raise InputError(f"{where}: '{start}' without its '{end}'")
    return "".join(lines[:i + 1]) + body + "".join(lines[j:])
