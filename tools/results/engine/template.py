"""The template language of the Markdown templates, the scene templates and the experiment files.

    {{ expression }}             the value (engine/expressions.py); numbers in as few digits as they need
    {{ expression :.4f }}        formatted with a Python format spec (after the last top-level ':')
    {% for x in expression %}    repeated for each element ({% for a, b in pairs %} unpacks)
    {% endfor %}
    {% if expression %} {% elif expression %} {% else %} {% endif %}
    {% set name = expression %}  binds a name until the end of the enclosing block
    {# a comment #}

A line that holds nothing but a {% %} or {# #} tag disappears with its line break, so loops over
table rows leave no blank lines. Single braces are text: `podee{area=lens}` needs no escaping.
"""

import re

from .errors import InputError
from .expressions import ExpressionError, evaluate
from .numbers import plain_number

_TAG = re.compile(r"\{\{|\{%|\{#")
_CLOSE = {"{{": "}}", "{%": "%}", "{#": "#}"}


def render(text, scope, source):
    """`text` rendered with the names of `scope`; `source` names it in errors ("templates/aa.md")."""
    return "".join(_render(_parse(_tokens(text, source), source), dict(scope), source))


def render_value(value, source, line):
    """A value as text when no format spec is given."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return plain_number(value)
    if isinstance(value, str):
        return value
    raise InputError(f"{source}:{line}: a {type(value).__name__} is not text; allowed: a number or a string "
                     "(loop over a list with {% for %})")


# --- tokens -----------------------------------------------------------------------------------------

def _closing(text, start, close):
    """The index of `close` after `start`, skipping the quoted strings of expressions (a comment's
    apostrophes are text); -1 if there is none."""
    if close == "#}":
        return text.find(close, start)
    i, quote = start, None
    while i < len(text):
        c = text[i]
        if quote:
            if c == "\\":
                i += 1
            elif c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif text.startswith(close, i):
            return i
        i += 1
    return -1


def _tokens(text, source):
    """(kind, content, line) with kind 'text', 'expr', 'block' or 'comment'."""
    tokens, at = [], 0
    while True:
        m = _TAG.search(text, at)
        if not m:
            tokens.append(("text", text[at:], text.count("\n", 0, at) + 1))
            return tokens
        line = text.count("\n", 0, m.start()) + 1
        end = _closing(text, m.end(), _CLOSE[m.group()])
        if end < 0:
            raise InputError(f"{source}:{line}: '{m.group()}' without its '{_CLOSE[m.group()]}'")
        start, after = m.start(), end + 2
        kind = {"{{": "expr", "{%": "block", "{#": "comment"}[m.group()]
        if kind != "expr":
            # A tag alone on its line takes the line with it.
            line_start = text.rfind("\n", 0, start) + 1
            line_end = text.find("\n", after)
            line_end = len(text) if line_end < 0 else line_end
            if not text[line_start:start].strip() and not text[after:line_end].strip():
                start, after = line_start, min(line_end + 1, len(text))
        tokens.append(("text", text[at:start], text.count("\n", 0, at) + 1))
        tokens.append((kind, text[m.end():end].strip(), line))
        at = after


# --- the tree ---------------------------------------------------------------------------------------

def _parse(tokens, source):
    root = []
    stack = [("root", root, None)]  # (tag, body being filled, node)
    for kind, content, line in tokens:
        body = stack[-1][1]
        if kind == "text":
            body.append(("text", content))
        elif kind == "expr":
            expression, spec = _split_spec(content)
            body.append(("expr", expression, spec, line))
        elif kind == "block":
            word, _, rest = content.partition(" ")
            rest = rest.strip()
            if word == "for":
                m = re.fullmatch(r"([A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*)\s+in\s+(.+)", rest, re.S)
                if not m:
                    raise InputError(f"{source}:{line}: '{{% {content} %}}'; allowed: {{% for NAME in EXPRESSION %}}")
                node = ["for", [n.strip() for n in m.group(1).split(",")], m.group(2), [], line]
                body.append(node)
                stack.append(("for", node[3], node))
            elif word == "if":
                node = ["if", [(rest, [], line)], None]
                body.append(node)
                stack.append(("if", node[1][0][1], node))
            elif word in ("elif", "else"):
                if stack[-1][0] != "if" or stack[-1][2][2] is not None:
                    raise InputError(f"{source}:{line}: '{{% {word} %}}' outside an {{% if %}}")
                node = stack.pop()[2]
                if word == "elif":
                    node[1].append((rest, [], line))
                    stack.append(("if", node[1][-1][1], node))
                else:
                    node[2] = []
                    stack.append(("if", node[2], node))
            elif word in ("endfor", "endif"):
                if stack[-1][0] != word[3:]:
                    raise InputError(f"{source}:{line}: '{{% {word} %}}' without its '{{% {word[3:]} %}}'")
                stack.pop()
            elif word == "set":
                m = re.fullmatch(r"([A-Za-z_]\w*)\s*=\s*(.+)", rest, re.S)
                if not m:
                    raise InputError(f"{source}:{line}: '{{% {content} %}}'; allowed: {{% set NAME = EXPRESSION %}}")
                body.append(("set", m.group(1), m.group(2), line))
            else:
                raise InputError(f"{source}:{line}: unknown tag '{{% {content} %}}'; allowed: for, endfor, if, elif, "
                                 "else, endif, set")
    if len(stack) > 1:
        raise InputError(f"{source}: a '{{% {stack[-1][0]} %}}' without its '{{% end{stack[-1][0]} %}}'")
    return root


def _split_spec(content):
    """'expression :spec' at the last ':' outside brackets and quotes."""
    depth, quote, split = 0, None, -1
    for i, c in enumerate(content):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == ":" and depth == 0:
            split = i
    if split < 0:
        return content, None
    return content[:split], content[split + 1:].strip()


def _value(expression, scope, source, line):
    try:
        return evaluate(expression, scope)
    except ExpressionError as e:
        raise InputError(f"{source}:{line}: {e}") from None


def _render(nodes, scope, source):
    for node in nodes:
        kind = node[0]
        if kind == "text":
            yield node[1]
        elif kind == "expr":
            _, expression, spec, line = node
            value = _value(expression, scope, source, line)
            if spec is None:
                yield render_value(value, source, line)
            else:
                try:
                    yield format(value, spec)
                except (ValueError, TypeError) as e:
                    raise InputError(f"{source}:{line}: format '{spec}' of {value!r}: {e}") from None
        elif kind == "set":
            scope[node[1]] = _value(node[2], scope, source, node[3])
        elif kind == "for":
            _, names, expression, body, line = node
            for element in _value(expression, scope, source, line):
                inner = dict(scope)
                if len(names) == 1:
                    inner[names[0]] = element
                else:
                    if len(element) != len(names):
                        raise InputError(f"{source}:{line}: {element!r} does not unpack into {', '.join(names)}")
                    inner.update(zip(names, element))
                yield from _render(body, inner, source)
        elif kind == "if":
            for condition, body, line in node[1]:
                if _value(condition, scope, source, line):
                    yield from _render(body, dict(scope), source)
                    break
            else:
                if node[2] is not None:
                    yield from _render(node[2], dict(scope), source)
