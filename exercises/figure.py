"""A schematic figure of a problem's linkage (PNG bytes), drawn from the solver's
positions of the instructor's preview variant: every student's geometry differs,
so the figure is labelled as a schematic and shows symbols, not numbers."""

import io

import numpy as np

from solver.batch import read_case

from .problem import solve_cases


def _xy(out, key):
    x, y = out[key]
    return np.array([x, y])


def draw(problem, dpi=90):
    """PNG bytes of the problem's figure."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.0, 3.6), dpi=dpi)
    spec = problem.figure
    mech = spec["mechanism"]
    outputs = solve_cases({"F": spec["case"]})
    out = outputs["F"]
    O2 = np.zeros(2)

    def link(p, q, label=None, color="C0", lw=3):
        ax.plot([p[0], q[0]], [p[1], q[1]], "-", color=color, lw=lw, solid_capstyle="round")
        if label:
            m = (p + q) / 2
            ax.annotate(label, m, textcoords="offset points", xytext=(6, 6), fontsize=11,
                        color=color)

    def pin(p, label, ground=False):
        ax.plot(*p, "o", ms=7, mfc="white", mec="k", zorder=5)
        if ground:
            ax.plot(*p, marker=(3, 0, 0), ms=16, color="0.4", zorder=1,
                    transform=ax.transData)
        ax.annotate(label, p, textcoords="offset points", xytext=(-14, -14), fontsize=11)

    if mech == "rotation":
        A = _xy(out, "R")
        link(O2, A, "$p$")
        pin(O2, "O", ground=True)
        pin(A, "A")
        if "case_B" in spec:
            B = _xy(solve_cases({"B": spec["case_B"]})["B"], "R")
            t = np.linspace(read_case(spec["case"]).params["theta2"],
                            read_case(spec["case_B"]).params["theta2"], 30)
            r = np.hypot(*A)
            ax.plot(r * np.cos(t), r * np.sin(t), "--", color="0.5")
            link(O2, B, None, color="C1", lw=2)
            pin(B, "B")
        ax.annotate("$\\omega, \\alpha$", O2, textcoords="offset points", xytext=(10, -22))
    else:
        A, B = _xy(out, "R_A"), _xy(out, "R_B")
        link(O2, A, "$a$")
        pin(O2, "$O_2$", ground=True)
        params = read_case(spec["case"]).params
        if mech == "fourbar":
            O4 = np.array([params["d"], 0.0])
            link(A, B, "$b$")
            link(O4, B, "$c$")
            pin(O4, "$O_4$", ground=True)
            link(O2, O4, "$d$", color="0.4", lw=1.5)
            if "R_P" in out:
                P = _xy(out, "R_P")
                ax.fill([A[0], B[0], P[0]], [A[1], B[1], P[1]], color="C0", alpha=0.15)
                link(A, P, "$p$", color="C2", lw=1.5)
                pin(P, "P")
        elif mech == "fivebar":
            C, O5 = _xy(out, "R_C"), np.array([params["f"], 0.0])
            link(A, B, "$b$")
            link(C, B, "$c$")
            link(O5, C, "$d$")
            pin(O5, "$O_5$", ground=True)
            pin(C, "C")
            link(O2, O5, "$f$", color="0.4", lw=1.5)
        elif mech == "slidercrank":
            link(A, B, "$b$")
            w, h = 0.35 * np.hypot(*A), 0.2 * np.hypot(*A)
            ax.add_patch(matplotlib.patches.Rectangle((B[0] - w / 2, B[1] - h / 2), w, h,
                                                      fc="C1", alpha=0.4, ec="k"))
            ax.axhline(B[1] - h / 2, color="0.4", lw=1)
        elif mech == "invertedslidercrank":
            O4 = np.array([params["d"], 0.0])
            u = (A - B) / max(np.hypot(*(A - B)), 1e-12)
            link(O4, B, "$c$", color="C3", lw=2)
            link(B, A + 0.4 * u * np.hypot(*A), "link 4", color="C3", lw=2)
            w = 0.25 * np.hypot(*A)
            corners = np.array([[-1, -0.5], [1, -0.5], [1, 0.5], [-1, 0.5]]) * w
            rot = np.array([[u[0], -u[1]], [u[1], u[0]]])
            blk = corners @ rot.T + A
            ax.fill(blk[:, 0], blk[:, 1], color="C1", alpha=0.4, ec="k")
            pin(O4, "$O_4$", ground=True)
            link(O2, O4, "$d$", color="0.4", lw=1.5)
        pin(A, "A")
        pin(B, "B")
        if mech != "slidercrank":
            ax.annotate("$\\theta_2, \\omega_2, \\alpha_2$", O2, textcoords="offset points",
                        xytext=(8, 14), fontsize=10)
    ax.set_aspect("equal")
    ax.margins(0.15)
    ax.set_title(f"{problem.title} (schematic: your values differ)", fontsize=9)
    ax.set_xticks([])
    ax.set_yticks([])
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()

