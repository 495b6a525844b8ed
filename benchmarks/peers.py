"""Peer packages that solve the same linkages, measured when installed
(``pip install -e ".[bench]"``; the tests never need them).

What they can compute, and so what they are compared on:

``pylinkage`` (numba-compiled when numba is installed)
    joint positions, velocities and accelerations of a fourbar whose crank
    turns by a fixed angle per step, from a given start, with a crank
    angular velocity and acceleration (``set_input_velocity``): no jerk, no
    gear train or inverted slider-crank as such, and its slider-crank does
    not move the slider in the fast path (:data:`SLIDER_NOTE`). Angular
    outputs are read off its joint vectors (theta3 = arg(B - A), omega3 =
    (B - A) x (V_B - V_A) / b^2, alpha3 = (B - A) x (A_B - A_A) / b^2).
``mechanism``
    any vector-loop linkage: position, velocity and acceleration, each
    solved by ``scipy.optimize.fsolve`` at every position (default tolerance
    1.49e-8), one position at a time: no jerk.

``kimech``
    bodies with local points, joints and a driven joint, solved in body
    coordinates (x, y, angle per link) with scipy, position to acceleration,
    with its own continuation and diagnostics: no jerk. Measured on the
    fourbars.

pylinkage and mechanism never report a singular position: they return
numbers at toggles.
"""

import math

import numpy as np

PEERS = ("pylinkage", "mechanism", "kimech")


SLIDER_NOTE = (
    "pylinkage 1.3.0's slider-crank: step_fast_with_kinematics leaves the slider "
    "where it was assembled, and step_with_derivatives gives its velocity and "
    "acceleration as None; it also has no choice of branch (the slider sits on the "
    "-x side of the crank pin)"
)
RANGE_NOTE = (
    "pylinkage turns its crank by a fixed step before each output, so its first "
    "position would come from one step outside a non-Grashof range; from one step "
    "inside, its first solution lands on the other assembly"
)


def installed():
    """Installed peers: dict name -> version."""
    from importlib.metadata import PackageNotFoundError, version

    out = {}
    for name in PEERS:
        try:
            __import__(name)
            out[name] = version(name)
        except (ImportError, PackageNotFoundError):
            continue
    return out


def _cross(u, v):
    return u.real * v.imag - u.imag * v.real


def _angular(R, V, A):
    """theta, omega, alpha of a link from the vector R across it and the
    relative velocity V and acceleration A of its ends (complex arrays)."""
    L2 = np.abs(R) ** 2
    return np.angle(R), _cross(R, V) / L2, _cross(R, A) / L2


def _even_steps(theta2):
    d = np.diff(theta2)
    if theta2.size > 1 and not np.allclose(d, d[0], rtol=1e-9, atol=1e-12):
        raise ValueError("pylinkage turns its crank by a fixed step: give evenly spaced angles")
    return float(d[0]) if theta2.size > 1 else 0.01


# --- pylinkage ------------------------------------------------------------------
def _pylinkage(NotApplicable):
    def prepare(case, theta2):
        from pylinkage.mechanism import DriverLink, fourbar

        from .cases import MOTION

        if case.mechanism != "fourbar":
            raise NotApplicable(
                SLIDER_NOTE
                if case.mechanism == "slidercrank"
                else "pylinkage has no such mechanism"
            )
        if not case.full_turn:
            raise NotApplicable(RANGE_NOTE)
        p = case.params
        step = _even_steps(theta2)
        N = theta2.size
        # branch 1 puts B above the line A -> O4 at the start: the open circuit
        mech = fourbar(
            crank=p["a"],
            coupler=p["b"],
            rocker=p["c"],
            ground=p["d"],
            omega=step,
            initial_angle=float(theta2[0]) - step,
            branch=1 if case.circuit == "open" else 0,
        )
        crank = next(link for link in mech.links if isinstance(link, DriverLink))
        mech.set_input_velocity(crank, MOTION["omega2"], MOTION["alpha2"])
        mech.compile()
        snapshot = list(mech.get_joint_positions())

        def run():
            mech.set_joint_positions(snapshot)  # every run starts from the same place
            return mech.step_fast_with_kinematics(iterations=N)

        def extract(result):
            pos, vel, acc = (r[..., 0] + 1j * r[..., 1] for r in result)
            idx = _joint_roles(pos[0], theta2[0], p)
            A, B, O4 = idx["A"], idx["B"], idx["O4"]
            t3, w3, a3 = _angular(
                pos[:, B] - pos[:, A], vel[:, B] - vel[:, A], acc[:, B] - acc[:, A]
            )
            t4, w4, a4 = _angular(pos[:, B] - pos[:, O4], vel[:, B], acc[:, B])
            return {
                "theta3": t3,
                "omega3": w3,
                "alpha3": a3,
                "theta4": t4,
                "omega4": w4,
                "alpha4": a4,
            }

        return run, extract

    return prepare


def _joint_roles(z, theta2, p):
    """Which joint column is O2, A, O4, B, told by where they are at the start."""
    A = p["a"] * complex(math.cos(theta2), math.sin(theta2))
    idx = {}
    free = list(range(z.size))
    for role, where in {"O2": 0j, "A": A, "O4": complex(p["d"], 0.0)}.items():
        k = min(free, key=lambda i: abs(z[i] - where))
        idx[role] = k
        free.remove(k)
    idx["B"] = free[0]
    return idx


# --- mechanism (fsolve) ---------------------------------------------------------------
def _mechanism(NotApplicable):
    def prepare(case, theta2):
        from .cases import MOTION

        if case.mechanism not in ("fourbar", "slidercrank"):
            raise NotApplicable("measured here on the fourbar and slider-crank only")
        p = case.params
        N = theta2.size
        w = np.full(N, MOTION["omega2"])
        al = np.full(N, MOTION["alpha2"])

        def build():
            from mechanism import Mechanism, Vector, get_joints

            if case.mechanism == "fourbar":
                O2, A, B, O4 = get_joints("O2 A B O4")
                a = Vector((O2, A), r=p["a"])
                b = Vector((A, B), r=p["b"])
                c = Vector((O4, B), r=p["c"])
                d = Vector((O2, O4), r=p["d"], theta=0.0, style="ground")

                def loops(x, i):
                    return a(i) + b(x[0]) - c(x[1]) - d()

                guess = np.array([case.guess["R3"], case.guess["R4"]])
                vectors, out = (a, b, c, d), {"3": b, "4": c}
            else:
                O2, A, B, F = get_joints("O2 A B F")
                a = Vector((O2, A), r=p["a"])
                b = Vector((B, A), r=p["b"])
                c = Vector((F, B), r=p["c"], theta=0.5 * math.pi)
                d = Vector((O2, F), theta=0.0, style="ground")

                def loops(x, i):
                    return a(i) - b(x[0]) - c() - d(x[1])

                guess = np.array([case.guess["R3"], case.guess["R1"]])
                vectors, out = (a, b, c, d), {"3": b, "d": d}
            mech = Mechanism(
                vectors=vectors,
                origin=O2,
                loops=loops,
                pos=theta2,
                vel=w,
                acc=al,
                guess=(guess, np.zeros(2), np.zeros(2)),
            )
            return mech, out

        def run():
            mech, out = build()
            mech.iterate()
            return out

        def extract(out):
            res = {}
            for key, v in out.items():
                if key == "d":
                    res.update(d=v.pos.rs, d_dot=v.vel.r_dots, d_ddot=v.acc.r_ddots)
                else:
                    res.update(
                        {
                            f"theta{key}": np.angle(np.exp(1j * v.pos.thetas)),
                            f"omega{key}": v.vel.omegas,
                            f"alpha{key}": v.acc.alphas,
                        }
                    )
            return {k: np.array(x, dtype=float) for k, x in res.items()}

        return run, extract

    return prepare


# --- kimech -------------------------------------------------------------------------
def _kimech(NotApplicable):
    def prepare(case, theta2):
        import kimech as km

        from .cases import MOTION

        if case.mechanism != "fourbar":
            raise NotApplicable("measured here on the fourbars only")
        p = case.params
        N = theta2.size
        w = np.full(N, MOTION["omega2"])
        al = np.full(N, MOTION["alpha2"])

        def run():
            m = km.Mechanism("fourbar")
            g = m.ground
            g.add_point("O2", (0.0, 0.0))
            g.add_point("O4", (p["d"], 0.0))
            crank, coupler, rocker = (m.add_link(n) for n in ("crank", "coupler", "rocker"))
            crank.add_point("O", (0.0, 0.0))
            crank.add_point("A", (p["a"], 0.0))
            coupler.add_point("A", (0.0, 0.0))
            coupler.add_point("B", (p["b"], 0.0))
            rocker.add_point("O", (0.0, 0.0))
            rocker.add_point("B", (p["c"], 0.0))
            drive = m.revolute(g["O2"], crank["O"])
            m.revolute(crank["A"], coupler["A"])
            m.revolute(coupler["B"], rocker["B"])
            m.revolute(rocker["O"], g["O4"])
            A = p["a"] * complex(math.cos(theta2[0]), math.sin(theta2[0]))
            guess = {
                crank: (0.0, 0.0, float(theta2[0])),
                coupler: (A.real, A.imag, case.kernel_guess(theta2[0])["R3"]),
                rocker: (p["d"], 0.0, case.kernel_guess(theta2[0])["R4"]),
            }
            driver = km.KinematicDriver(drive, position=theta2, velocity=w, acceleration=al)
            return km.solve(m, drivers=driver, initial_guess=guess)

        def extract(sol):
            q, v, a = sol.coordinates, sol.coordinate_velocities, sol.coordinate_accelerations
            return {
                "theta3": np.angle(np.exp(1j * q[:, 5])),
                "omega3": v[:, 5],
                "alpha3": a[:, 5],
                "theta4": np.angle(np.exp(1j * q[:, 8])),
                "omega4": v[:, 8],
                "alpha4": a[:, 8],
            }

        return run, extract

    return prepare


def peer_methods(Method, NotApplicable):
    """Methods for the installed peers (none when none is installed)."""
    have = installed()
    out = []
    if "pylinkage" in have:
        try:
            import numba  # noqa: F401

            jit = "numba"
        except ImportError:
            jit = "pure Python, no numba"
        out.append(
            Method(
                "pylinkage",
                f"pylinkage {have['pylinkage']} ({jit})",
                "peer-pylinkage",
                2,
                _pylinkage(NotApplicable),
                vectorised=False,
            )
        )
    if "mechanism" in have:
        out.append(
            Method(
                "mechanism",
                f"mechanism {have['mechanism']} (fsolve)",
                "peer-mechanism",
                2,
                _mechanism(NotApplicable),
                vectorised=False,
            )
        )
    if "kimech" in have:
        out.append(
            Method(
                "kimech",
                f"kimech {have['kimech']} (scipy, body coordinates)",
                "peer-kimech",
                2,
                _kimech(NotApplicable),
                vectorised=False,
            )
        )
    return out
