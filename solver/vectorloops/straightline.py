"""One position's Newton-Raphson system as straight-line Python, per linkage.

The sequential part of a sweep (the coarse chain, walks, a single position)
solves one small system at a time, where numpy's per-call overhead would
exceed the arithmetic, and a generic Python loop over the vectors and a
generic Gaussian elimination spend most of their time on loop bookkeeping.
:func:`compile_kernel` writes, once per linkage, a Python function with every
vector's cosine and sine, every nonzero entry of [J | -F | -dF/dtheta2], the
Gaussian elimination with partial pivoting and the back substitution written
out for that linkage's size (the way :mod:`dataclasses` writes ``__init__``),
and compiles it with ``exec``. It is about three times faster than the loops.

The entries are those of :class:`~.newton.LoopSystem` (rows: real and
imaginary part of each loop; columns: the unknowns, then -F, then
-dF/dtheta2), from its per-vector tables (``_py_vectors``):

    dz_v/dq_u      = k_v j L_v e^{j theta_v}   (v's angle follows unknown u)
    dz_v/dq_u      = e^{j theta_v}             (u is v's length)
    dz_v/dtheta2   = k_v j L_v e^{j theta_v}   (v driven by the input)
"""

import math

#: the generated function's source is kept on it, for reading and debugging
SOURCE_ATTRIBUTE = "source"


def _num(x):
    return repr(float(x))


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
    terms = {}
    for v, (b, k, o, li, Lf, fterms, aterms, lterms, dterms) in enumerate(vectors):
        if b == nu + 1:                       # a fixed angle
            body += [f"    c{v} = {_num(math.cos(o))}", f"    s{v} = {_num(math.sin(o))}"]
        else:
            base = "theta2" if b == nu else f"q{b}"
            angle = base if k == 1.0 else f"{_num(k)} * {base}"
            if o != 0.0:
                angle += f" + {_num(o)}"
            body += [f"    t = {angle}", f"    c{v} = cos(t)", f"    s{v} = sin(t)"]
        if li >= 0:
            body += [f"    lc{v} = q{li} * c{v}", f"    ls{v} = q{li} * s{v}"]
        elif b == nu + 1:                     # a fixed vector: constants
            body += [f"    lc{v} = {_num(Lf * math.cos(o))}", f"    ls{v} = {_num(Lf * math.sin(o))}"]
        else:
            body += [f"    lc{v} = {_num(Lf)} * c{v}", f"    ls{v} = {_num(Lf)} * s{v}"]
        for r, sg in fterms:
            terms.setdefault((r, f), []).append(_term(-sg, f"lc{v}"))
            terms.setdefault((r + 1, f), []).append(_term(-sg, f"ls{v}"))
        for r, u, cf in aterms:
            terms.setdefault((r, u), []).append(_term(-cf, f"ls{v}"))
            terms.setdefault((r + 1, u), []).append(_term(cf, f"lc{v}"))
        for r, u, sg in lterms:
            terms.setdefault((r, u), []).append(_term(sg, f"c{v}"))
            terms.setdefault((r + 1, u), []).append(_term(sg, f"s{v}"))
        for r, cf in dterms:
            terms.setdefault((r, d), []).append(_term(cf, f"ls{v}"))
            terms.setdefault((r + 1, d), []).append(_term(-cf, f"lc{v}"))

    def a(r, c):
        return f"a{r}_{c}"

    for r in range(n):
        for c in range(width):
            parts = terms.get((r, c))
            expr = "".join(parts).strip() if parts else "0.0"
            if expr.startswith("+ "):
                expr = expr[2:]
            elif expr.startswith("- "):
                expr = "-" + expr[2:]
            body.append(f"    {a(r, c)} = {expr}")
    body.append(f"    res = hypot({', '.join(a(r, f) for r in range(n))})")
    body.append("    norms = " + " * ".join(f"hypot({', '.join(a(r, c) for r in range(n))})"
                                            for c in range(nu)))
    body.append("    det = 1.0")
    for k in range(nu):
        cols = range(k, width)
        row_k = ", ".join(a(k, c) for c in cols)
        for r in range(k + 1, n):             # partial pivoting: the largest |a_rk| to row k
            row_r = ", ".join(a(r, c) for c in cols)
            body += [f"    if abs({a(r, k)}) > abs({a(k, k)}):",
                     f"        {row_k}, {row_r} = {row_r}, {row_k}",
                     "        det = -det"]
        body += [f"    if {a(k, k)} == 0.0:", "        return res, 0.0, None, None",
                 f"    det *= {a(k, k)}", f"    i{k} = 1.0 / {a(k, k)}"]
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


def compile_kernel(vectors, nu):
    """The compiled ``kernel`` of :func:`kernel_source` (its source kept in
    its ``source`` attribute)."""
    source = kernel_source(vectors, nu)
    namespace = {"cos": math.cos, "sin": math.sin, "hypot": math.hypot}
    exec(compile(source, "<vector-loop kernel>", "exec"), namespace)
    kernel = namespace["kernel"]
    setattr(kernel, SOURCE_ATTRIBUTE, source)
    return kernel
