"""The expressions of templates and experiment files: a small, safe subset of Python.

`{{ rmse('aa/spheres', 'lean') :.4f }}` evaluates `rmse('aa/spheres', 'lean')` here. Allowed:
literals, lists and tuples, names bound by the caller (loop variables, [vars], the helpers of
engine/helpers.py), arithmetic, comparisons, `and`/`or`/`not`, `a if c else b`, subscripts and
slices, `table.key` for a key of a table (a TOML table, a metrics entry), f-strings and calls of
the bound helpers. Nothing else (no Python attributes, no imports, no lambdas): an experiment file
cannot run arbitrary code.
"""

import ast
import operator

_BINARY = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
}
_UNARY = {ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Not: operator.not_}
_COMPARE = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
}


class ExpressionError(Exception):
    """An expression that does not parse, uses what is not allowed, or fails when evaluated."""


def evaluate(text, scope):
    """The value of expression `text` with the names of `scope` (a mapping) bound."""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as e:
        raise ExpressionError(f"'{text.strip()}' is not an expression ({e.msg})") from None
    try:
        return _Evaluator(scope).visit(tree.body)
    except ExpressionError:
        raise
    except Exception as e:  # a helper's own error (a missing run, a missing method) or a type error
        raise ExpressionError(f"'{text.strip()}': {e}") from None


class _Evaluator(ast.NodeVisitor):
    def __init__(self, scope):
        self.scope = scope

    def generic_visit(self, node):
        raise ExpressionError(f"{type(node).__name__} is not allowed in an expression; allowed: literals, names, "
                              "arithmetic, comparisons, and/or/not, if-else, subscripts, f-strings, helper calls")

    def visit_Constant(self, node):
        return node.value

    def visit_Name(self, node):
        if node.id not in self.scope:
            raise ExpressionError(f"name '{node.id}' is not defined; defined: {', '.join(sorted(self.scope))}")
        return self.scope[node.id]

    def visit_List(self, node):
        return [self.visit(e) for e in node.elts]

    def visit_Tuple(self, node):
        return tuple(self.visit(e) for e in node.elts)

    def visit_BinOp(self, node):
        return _BINARY[type(node.op)](self.visit(node.left), self.visit(node.right)) if type(node.op) in _BINARY \
            else self.generic_visit(node.op)

    def visit_UnaryOp(self, node):
        return _UNARY[type(node.op)](self.visit(node.operand)) if type(node.op) in _UNARY \
            else self.generic_visit(node.op)

    def visit_BoolOp(self, node):
        value = self.visit(node.values[0])
        for other in node.values[1:]:
            if isinstance(node.op, ast.And) and not value or isinstance(node.op, ast.Or) and value:
                return value
            value = self.visit(other)
        return value

    def visit_Compare(self, node):
        left = self.visit(node.left)
        for op, right_node in zip(node.ops, node.comparators):
            if type(op) not in _COMPARE:
                self.generic_visit(op)
            right = self.visit(right_node)
            if not _COMPARE[type(op)](left, right):
                return False
            left = right
        return True

    def visit_IfExp(self, node):
        return self.visit(node.body) if self.visit(node.test) else self.visit(node.orelse)

    def visit_Subscript(self, node):
        return self.visit(node.value)[self.visit(node.slice)]

    def visit_Attribute(self, node):
        table = self.visit(node.value)
        if not isinstance(table, dict):
            raise ExpressionError(f"'{ast.unparse(node)}': only a table has keys (.{node.attr})")
        if node.attr not in table:
            raise ExpressionError(f"'{ast.unparse(node)}': no key '{node.attr}'; it has: {', '.join(sorted(table))}")
        return table[node.attr]

    def visit_Slice(self, node):
        part = lambda n: None if n is None else self.visit(n)
        return slice(part(node.lower), part(node.upper), part(node.step))

    def visit_JoinedStr(self, node):
        return "".join(self.visit(v) for v in node.values)

    def visit_FormattedValue(self, node):
        spec = self.visit(node.format_spec) if node.format_spec else ""
        return format(self.visit(node.value), spec)

    def visit_Call(self, node):
        function = self.visit(node.func)
        if not callable(function):
            raise ExpressionError(f"'{ast.unparse(node.func)}' is not a helper")
        args = [self.visit(a) for a in node.args]
        kwargs = {k.arg: self.visit(k.value) for k in node.keywords}
        return function(*args, **kwargs)
