"""The safe evaluator of answer expressions.

An answer's ``expr`` is a Python expression over the batch outputs of the cases it
depends on, e.g. ``"abs(B.A - A.A)"``: ``LABEL.KEY`` is output KEY of case LABEL
(vectors ``[x, y]`` become complex numbers ``x + 1j*y``), with only ``abs``,
``angle`` (radians), ``real``, ``imag``, ``+ - * /``, unary minus and numbers.
Both the answer key and the grader evaluate through :func:`evaluate`, so the
published expression and the graded value can never disagree.
"""

import ast
import cmath

FUNCTIONS = {
    "abs": abs,
    "angle": lambda z: cmath.phase(complex(z)),
    "real": lambda z: complex(z).real,
    "imag": lambda z: complex(z).imag,
}
BINARY = {
    ast.Add: lambda x, y: x + y,
    ast.Sub: lambda x, y: x - y,
    ast.Mult: lambda x, y: x * y,
    ast.Div: lambda x, y: x / y,
}
UNARY = {ast.USub: lambda x: -x, ast.UAdd: lambda x: +x}


class ExprError(ValueError):
    """An expression uses something outside the allowed grammar, or a name that
    the case outputs do not have."""


def parse(text):
    """Parse and check an expression; returns the ast. Raises ExprError."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise ExprError(f"cannot parse expr {text!r}: {exc.msg}") from None
    _check(tree.body, text)
    return tree


def _check(node, text):
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise ExprError(f"only numbers are allowed as constants in {text!r}")
    elif isinstance(node, ast.BinOp):
        if type(node.op) not in BINARY:
            raise ExprError(
                f"operator {type(node.op).__name__} is not allowed in {text!r}; use + - * /"
            )
        _check(node.left, text)
        _check(node.right, text)
    elif isinstance(node, ast.UnaryOp):
        if type(node.op) not in UNARY:
            raise ExprError(f"unary {type(node.op).__name__} is not allowed in {text!r}")
        _check(node.operand, text)
    elif isinstance(node, ast.Call):
        if (
            not isinstance(node.func, ast.Name)
            or node.func.id not in FUNCTIONS
            or len(node.args) != 1
            or node.keywords
        ):
            raise ExprError(f"only abs(x), angle(x), real(x), imag(x) may be called in {text!r}")
        _check(node.args[0], text)
    elif isinstance(node, ast.Attribute):
        if not isinstance(node.value, ast.Name):
            raise ExprError(f"names must look like LABEL.KEY in {text!r}")
    else:
        raise ExprError(
            f"{type(node).__name__} is not allowed in {text!r}; only LABEL.KEY, "
            "numbers, + - * / and abs, angle, real, imag"
        )


def _value(output, label, key, text):
    if key not in output:
        raise ExprError(f"case {label!r} has no output {key!r} (needed by {text!r})")
    value = output[key]
    if isinstance(value, (list, tuple)):
        if len(value) != 2:
            raise ExprError(f"output {label}.{key} is not a scalar or an [x, y] vector")
        return complex(value[0], value[1])
    return float(value)


def evaluate(text, outputs):
    """Evaluate ``text`` over ``outputs`` (a map label -> batch result dict, SI).

    Returns a float, or a complex number when the expression is a vector.
    Raises ExprError for a bad expression or a missing label or key.
    """
    tree = parse(text)

    def ev(node):
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, ast.BinOp):
            return BINARY[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp):
            return UNARY[type(node.op)](ev(node.operand))
        if isinstance(node, ast.Call):
            return FUNCTIONS[node.func.id](ev(node.args[0]))
        label = node.value.id
        if label not in outputs:
            raise ExprError(f"expr {text!r} names case {label!r}, which the answer does not list")
        return _value(outputs[label], label, node.attr, text)

    return ev(tree.body)


def labels(text):
    """The case labels an expression refers to."""
    return sorted({n.value.id for n in ast.walk(parse(text)) if isinstance(n, ast.Attribute)})
