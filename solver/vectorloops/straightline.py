"""One position's Newton-Raphson system as straight-line Python, per linkage.

The sequential part of a sweep (the coarse chain, walks, a single position)
solves one small system at a time, where numpy's per-call overhead would
exceed the arithmetic, and a generic Python loop over the vectors and a
generic Gaussian elimination spend most of their time on loop bookkeeping.
:func:`compile_kernel` writes, once per linkage, a Python function with every
vector's cosine and sine, every nonzero entry of [J | -F | -dF/dtheta2], the
Gaussian elimination with partial pivoting and the back substitution written
out for that linkage's size (the way :mod:`dataclasses` writes ``__init__``),
and compiles it with ``exec``. It is about three times faster than the loops
(:func:`plain_step`: the same operations written as loops over the same
tables, which the tests check it against bit for bit).

The entries are those of :class:`~.newton.LoopSystem` (rows: real and
imaginary part of each loop; columns: the unknowns, then -F, then
-dF/dtheta2), from its per-vector tables (``LoopSystem.step_tables``):

    dz_v/dq_u      = k_v j L_v e^{j theta_v}   (v's angle follows unknown u)
    dz_v/dq_u      = e^{j theta_v}             (u is v's length)
    dz_v/dtheta2   = k_v j L_v e^{j theta_v}   (v driven by the input)
"""

import math
from typing import Any

#: the generated function's source is kept on it, for reading and debugging
SOURCE_ATTRIBUTE = "source"


def _num(x):
    return repr(float(x))


def _entries(vectors, nu):
    """What one Newton step computes, as data shared by the generated code
    (:func:`kernel_source`) and the plain evaluation (:func:`plain_step`).

    Returns ``(setup, terms)``: ``setup`` lists, per vector, ``(v, angle,
    length)`` with ``angle`` either ``("fixed", cos, sin)`` or ``("turns",
    base, ratio, offset)`` (base: an unknown's index, or ``nu`` for theta2)
    and ``length`` either ``("unknown", index)``, ``("constant", lc, ls)`` or
    ``("fixed", L)``; ``terms`` maps each entry (row, column) of [J | -F |
    -dF/dtheta2] to its terms ``(coefficient, name)`` in order, name one of
    ``c{v}``, ``s{v}``, ``lc{v}``, ``ls{v}``.
    """
    f, d = nu, nu + 1
    setup: list[Any] = []
    terms: dict[tuple[int, int], list[tuple[float, str]]] = {}
    for v, (b, k, o, li, Lf, fterms, aterms, lterms, dterms) in enumerate(vectors):
        angle: tuple[Any, ...]
        length: tuple[Any, ...]
        if b == nu + 1:  # a fixed angle
            angle = ("fixed", math.cos(o), math.sin(o))
        else:
            angle = ("turns", b, k, o)
        if li >= 0:
            length = ("unknown", li)
        elif b == nu + 1:  # a fixed vector: constants
            length = ("constant", Lf * math.cos(o), Lf * math.sin(o))
        else:
            length = ("fixed", Lf)
        setup.append((v, angle, length))
        for r, sg in fterms:
            terms.setdefault((r, f), []).append((-sg, f"lc{v}"))
            terms.setdefault((r + 1, f), []).append((-sg, f"ls{v}"))
        for r, u, cf in aterms:
            terms.setdefault((r, u), []).append((-cf, f"ls{v}"))
            terms.setdefault((r + 1, u), []).append((cf, f"lc{v}"))
        for r, u, sg in lterms:
            terms.setdefault((r, u), []).append((sg, f"c{v}"))
            terms.setdefault((r + 1, u), []).append((sg, f"s{v}"))
        for r, cf in dterms:
            terms.setdefault((r, d), []).append((cf, f"ls{v}"))
            terms.setdefault((r + 1, d), []).append((-cf, f"lc{v}"))
    return setup, terms


def _term(coef, name):
    """``+ coef * name`` as source, with unit coefficients written plainly."""
    if coef == 1.0:
        return f" + {name}"
    if coef == -1.0:
        return f" - {name}"
    return f" + {_num(coef)} * {name}"


def kernel_source(vectors, nu):
    """Source of ``kernel(q, theta2) -> (residual, orient, dq, slope)`` for the
    per-vector tables ``vectors`` of a linkage with ``nu`` unknowns (= rows).

    ``residual`` is |F|, ``orient`` det J over the product of J's column
    norms, ``dq`` the Newton step (solution of J dq = -F) and ``slope``
    dq/dtheta2 (solution of J s = -dF/dtheta2), both lists; ``dq`` and
    ``slope`` are None (and ``orient`` 0.0) where a pivot is exactly zero.
    """
    n, f, d = nu, nu, nu + 1
    width = nu + 2
    body = [f"    {', '.join(f'q{u}' for u in range(nu))}{',' if nu == 1 else ''} = q"]
    setup, terms = _entries(vectors, nu)
    for v, angle, length in setup:
        if angle[0] == "fixed":
            body += [f"    c{v} = {_num(angle[1])}", f"    s{v} = {_num(angle[2])}"]
        else:
            _, b, k, o = angle
            base = "theta2" if b == nu else f"q{b}"
            text = base if k == 1.0 else f"{_num(k)} * {base}"
            if o != 0.0:
                text += f" + {_num(o)}"
            body += [f"    t = {text}", f"    c{v} = cos(t)", f"    s{v} = sin(t)"]
        if length[0] == "unknown":
            body += [f"    lc{v} = q{length[1]} * c{v}", f"    ls{v} = q{length[1]} * s{v}"]
        elif length[0] == "constant":
            body += [f"    lc{v} = {_num(length[1])}", f"    ls{v} = {_num(length[2])}"]
        else:
            body += [
                f"    lc{v} = {_num(length[1])} * c{v}",
                f"    ls{v} = {_num(length[1])} * s{v}",
            ]

    def a(r, c):
        return f"a{r}_{c}"

    for r in range(n):
        for c in range(width):
            parts = [_term(coef, name) for coef, name in terms.get((r, c), [])]
            expr = "".join(parts).strip() if parts else "0.0"
            if expr.startswith("+ "):
                expr = expr[2:]
            elif expr.startswith("- "):
                expr = "-" + expr[2:]
            body.append(f"    {a(r, c)} = {expr}")
    body.append(f"    res = hypot({', '.join(a(r, f) for r in range(n))})")
    body.append(
        "    norms = "
        + " * ".join(f"hypot({', '.join(a(r, c) for r in range(n))})" for c in range(nu))
    )
    body.append("    det = 1.0")
    for k in range(nu):
        cols = range(k, width)
        row_k = ", ".join(a(k, c) for c in cols)
        for r in range(k + 1, n):  # partial pivoting: the largest |a_rk| to row k
            row_r = ", ".join(a(r, c) for c in cols)
            body += [
                f"    if abs({a(r, k)}) > abs({a(k, k)}):",
                f"        {row_k}, {row_r} = {row_r}, {row_k}",
                "        det = -det",
            ]
        body += [
            f"    if {a(k, k)} == 0.0:",
            "        return res, 0.0, None, None",
            f"    det *= {a(k, k)}",
            f"    i{k} = 1.0 / {a(k, k)}",
        ]
        for r in range(k + 1, n):
            body.append(f"    m = {a(r, k)} * i{k}")
            for c in range(k + 1, width):
                body.append(f"    {a(r, c)} -= m * {a(k, c)}")
    for k in reversed(range(nu)):
        for out, col in (("x", f), ("y", d)):
            rest = "".join(f" - {a(k, j)} * {out}{j}" for j in range(k + 1, nu))
            body.append(f"    {out}{k} = ({a(k, col)}{rest}) * i{k}")
    xs = ", ".join(f"x{u}" for u in range(nu))
    ys = ", ".join(f"y{u}" for u in range(nu))
    body.append(f"    return res, (det / norms if norms > 0.0 else 0.0), [{xs}], [{ys}]")
    return "def kernel(q, theta2):\n" + "\n".join(body) + "\n"


def plain_step(vectors, nu, q, theta2):
    """What the generated ``kernel(q, theta2)`` returns, computed by loops over
    the same tables: the same operations in the same order, so the same bits
    (the reference the generated code is tested against)."""
    f, d, width = nu, nu + 1, nu + 2
    setup, terms = _entries(vectors, nu)
    x = {}
    for v, angle, length in setup:
        if angle[0] == "fixed":
            c, s = angle[1], angle[2]
        else:
            _, b, k, o = angle
            t = theta2 if b == nu else q[b]
            if k != 1.0:
                t = k * t
            if o != 0.0:
                t = t + o
            c, s = math.cos(t), math.sin(t)
        x[f"c{v}"], x[f"s{v}"] = c, s
        if length[0] == "unknown":
            x[f"lc{v}"], x[f"ls{v}"] = q[length[1]] * c, q[length[1]] * s
        elif length[0] == "constant":
            x[f"lc{v}"], x[f"ls{v}"] = length[1], length[2]
        else:
            x[f"lc{v}"], x[f"ls{v}"] = length[1] * c, length[1] * s
    A = [[0.0] * width for _ in range(nu)]
    for (r, col), parts in terms.items():
        acc = None
        for coef, name in parts:
            value = x[name]
            if acc is None:
                acc = value if coef == 1.0 else (-value if coef == -1.0 else coef * value)
            elif coef == 1.0:
                acc = acc + value
            elif coef == -1.0:
                acc = acc - value
            else:
                acc = acc + coef * value
        A[r][col] = acc
    res = math.hypot(*(A[r][f] for r in range(nu)))
    norms = 1.0
    for col in range(nu):
        norms *= math.hypot(*(A[r][col] for r in range(nu)))
    det = 1.0
    inv = [0.0] * nu
    for k in range(nu):
        for r in range(k + 1, nu):
            if abs(A[r][k]) > abs(A[k][k]):
                A[k][k:], A[r][k:] = A[r][k:], A[k][k:]
                det = -det
        if A[k][k] == 0.0:
            return res, 0.0, None, None
        det *= A[k][k]
        inv[k] = 1.0 / A[k][k]
        for r in range(k + 1, nu):
            m = A[r][k] * inv[k]
            for col in range(k + 1, width):
                A[r][col] -= m * A[k][col]
    xs, ys = [0.0] * nu, [0.0] * nu
    for k in reversed(range(nu)):
        for out, col in ((xs, f), (ys, d)):
            acc = A[k][col]
            for j in range(k + 1, nu):
                acc = acc - A[k][j] * out[j]
            out[k] = acc * inv[k]
    return res, (det / norms if norms > 0.0 else 0.0), xs, ys


def compile_kernel(vectors, nu):
    """The compiled ``kernel`` of :func:`kernel_source` (its source kept in
    its ``source`` attribute)."""
    source = kernel_source(vectors, nu)
    namespace = {"cos": math.cos, "sin": math.sin, "hypot": math.hypot}
    exec(compile(source, "<vector-loop kernel>", "exec"), namespace)
    kernel = namespace["kernel"]
    setattr(kernel, SOURCE_ATTRIBUTE, source)
    return kernel
