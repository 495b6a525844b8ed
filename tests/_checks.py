"""How the tests compare an answer with the reference (accelab.benchmarks.reference).

:func:`errors` is the error measure of the kernels' accuracy tests;
:func:`compare_to_branches` the rule of the project's reference check
(shared/tools/check_reference.py), for the worked cases in tests/data/.
"""

import math

from mpmath import mp, mpc, mpf

DPS = 50


def order_of(name):
    """Derivative order of an output: -1 angle, 0 position/length, 1..3."""
    if name.startswith("theta"):
        return -1
    for prefix, n in (
        ("omega", 1),
        ("alpha", 2),
        ("jerk", 3),
        ("V_", 1),
        ("A_", 2),
        ("J_", 3),
        ("R_", 0),
    ):
        if name.startswith(prefix):
            return n
    for suffix, n in (("_dddot", 3), ("_ddot", 2), ("_dot", 1)):
        if name.endswith(suffix):
            return n
    return 0


def angle_error(x, y):
    """|x - y| modulo 2 pi [rad]."""
    return abs(math.remainder(float(x) - float(y), 2 * math.pi))


def _group(name):
    """(derivative order, 'angular' or 'linear') of an output."""
    return order_of(name), (
        "angular" if name[:5] in ("omega", "alpha") or name.startswith("jerk") else "linear"
    )


def scales(ref):
    """The largest magnitude of each (order, kind) group of outputs in ``ref``.
    Angular groups also count the products that enter them: omega_k^2 for
    order 2, |omega_k|^3 and |omega_k alpha_k| for order 3."""
    out = {}

    def grow(key, value):
        out[key] = max(out.get(key, 0.0), float(abs(value)))

    for k, v in ref.items():
        if k.startswith("theta"):
            continue
        grow(_group(k), v)
        if k.startswith("omega"):
            grow((2, "angular"), v * v)
            grow((3, "angular"), v**3)
            alpha = ref.get("alpha" + k[5:])
            if alpha is not None:
                grow((3, "angular"), v * alpha)
    return out


def errors(got, ref, floor=1e-3):
    """Error of each output in ``got`` relative to ``ref``.

    Angles: the absolute difference modulo 2 pi [rad]. Other outputs: |got -
    ref| / max(|ref|, floor * scale), where scale is the largest magnitude of
    the outputs of the same derivative order and kind (angular or linear;
    see :func:`scales`), so an output that passes through zero is judged
    against the size of its neighbours. Vectors compare by the length of the
    difference.
    """
    sizes = scales(ref)
    out = {}
    for k, v in got.items():
        if k not in ref:
            continue
        if k.startswith("theta"):
            out[k] = angle_error(v, ref[k])
            continue
        with mp.workdps(DPS):
            vector = isinstance(ref[k], (mpc, complex)) or isinstance(v, complex)
            got_mp = mpc(complex(v)) if vector else mpf(float(v))
            diff = float(abs(got_mp - (mpc(ref[k]) if vector else ref[k])))
        out[k] = diff / max(float(abs(ref[k])), floor * sizes.get(_group(k), 0.0), 1e-30)
    return out


#: outputs the reference check requires, and those that pick the branch
REQUIRED = {
    "fourbar": [
        "theta3",
        "theta4",
        "omega3",
        "omega4",
        "alpha3",
        "alpha4",
        "jerk3",
        "jerk4",
        "A_A",
        "A_B",
    ],
    "slidercrank": ["theta3", "omega3", "alpha3", "d", "d_dot", "d_ddot", "A_A", "A_B"],
    "invertedslidercrank": [
        "theta3",
        "theta4",
        "omega3",
        "omega4",
        "alpha3",
        "alpha4",
        "b",
        "b_dot",
        "b_ddot",
        "A_A",
        "A_B",
        "A_coriolis",
    ],
    "fivebar": ["theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4", "A_A", "A_B", "A_C"],
    "rotation": ["A", "A_t", "A_n"],
}
BRANCH_KEYS = {
    "fourbar": ["theta3", "theta4"],
    "slidercrank": ["theta3", "d"],
    "invertedslidercrank": ["theta4", "b"],
    "fivebar": ["theta3", "theta4"],
    "rotation": [],
}


def _magnitude(v):
    return math.hypot(*v) if isinstance(v, list) else abs(v)


def _close(name, got, want, scale, rtol):
    if order_of(name) == -1:
        return isinstance(got, (int, float)) and angle_error(got, want) <= max(rtol, 1e-10) * 10
    tol = rtol * max(_magnitude(want), 1e-3 * scale)
    if isinstance(want, list):
        return (
            isinstance(got, list)
            and len(got) == 2
            and math.hypot(got[0] - want[0], got[1] - want[1]) <= tol
        )
    return isinstance(got, (int, float)) and abs(got - want) <= tol


def compare_to_branches(mech, result, branches, rtol, circuit=None):
    """'' when a batch result (SI, vectors as [x, y]) matches one of the
    expected branches to ``rtol``, else the reason. The rules of the
    project's reference check (shared/tools/check_reference.py): the branch
    is the one whose positions match to 1e-6; angles compare modulo 2 pi to
    10 rtol; other outputs to rtol relative, but never tighter than rtol
    times 1e-3 of the largest output of their derivative order."""
    if not result.get("ok"):
        return f"reported {result.get('error')}: {result.get('message')}"
    missing = [k for k in REQUIRED[mech] if k not in result]
    if missing:
        return f"missing outputs {missing}"
    found = [
        b
        for b in branches
        if all(_close(k, result.get(k), b[k], 1, 1e-6) for k in BRANCH_KEYS[mech])
    ]
    if not found:
        return "positions match no branch"
    branch = found[0]
    if circuit and branch.get("circuit") and branch["circuit"] != circuit:
        return f"asked for {circuit}, got the {branch['circuit']} branch"
    scales = {}
    for k, v in branch.items():
        if isinstance(v, (int, float, list)) and not isinstance(v, bool):
            scales[order_of(k)] = max(scales.get(order_of(k), 0), _magnitude(v))
    bad = [
        k
        for k, v in branch.items()
        if k in result
        and not isinstance(v, str)
        and not _close(k, result[k], v, scales.get(order_of(k), 1), rtol)
    ]
    return f"{bad} off, e.g. {bad[0]}: got {result[bad[0]]}, want {branch[bad[0]]}" if bad else ""
