"""The benchmark's charts, drawn from its JSON (so they can be redrawn alone).

* ``bench-speed-accuracy`` -- Chart 1: time per position against worst
  relative error over the fourbar's cycle, one point per method and setting,
  the Pareto front drawn;
* ``bench-stability`` -- Chart 2: error against distance to a toggle, per
  method, with where each refuses; and Newton-Raphson's outcomes as its
  starting guess worsens;
* ``bench-scaling`` -- time per position against the number of positions
  and against the number of loops.

Colours are the Okabe-Ito palette (distinguishable with the common colour
vision deficiencies), and every family also has its own marker shape.
"""

import math

import numpy as np

#: family -> (colour, marker)
STYLE = {
    "kernels": ("#0072B2", "o"),
    "kernels-o2": ("#0072B2", "o"),
    "units": ("#56B4E9", "s"),
    "scalar": ("#009E73", "D"),
    "loops": ("#E69F00", "^"),
    "fd": ("#CC79A7", "v"),
    "graphical": ("#D55E00", "P"),
    "peer-pylinkage": ("#000000", "X"),
    "pylinkage": ("#000000", "X"),
    "peer-mechanism": ("#7F7F7F", "*"),
    "mechanism": ("#7F7F7F", "*"),
    "peer-kimech": ("#882255", "h"),
    "kimech": ("#882255", "h"),
}
GOAL_ERROR = 1e-13


def _style(key):
    family = key.split("-")[0] if key.startswith(("loops", "fd")) else key
    return STYLE.get(family, ("#444444", "o"))


def _save(fig, outdir, stem, formats):
    import os

    paths = []
    for ext in formats:
        path = os.path.join(outdir, f"{stem}.{ext}")
        fig.savefig(
            path,
            dpi=130 if ext == "png" else None,
            metadata={"Date": None} if ext == "svg" else None,
        )
        paths.append(path)
    return paths


def _pareto(points):
    """Indices of the non-dominated points (faster or more accurate than
    every other), sorted by time."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], math.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def speed_accuracy(data, outdir, formats=("png", "svg"), case="fourbar-open"):
    """Chart 1."""
    import matplotlib.pyplot as plt

    rows = [r for r in data["results"] if r["case"] == case and r.get("worst") is not None]
    meta = next(c for c in data["cases"] if c["name"] == case)
    fig, ax = plt.subplots(figsize=(9.5, 6.2), layout="constrained")
    floor = 1e-16
    pts = []
    fd = []
    notes = []  # (x, y, text, family) of the labelled points
    seen = set()
    for r in rows:
        colour, marker = _style(r["method"])
        x, y = r["us_per_position"], max(r["worst"], floor)
        pts.append((x, y))
        filled = r["order"] >= 3
        family = r["method"].split("-")[0]
        label = r["label"]
        if family == "loops":
            label = "vector loops (general solver), at each tolerance"
        if family == "fd" or label in seen:
            label = None
        seen.add(label)
        ax.scatter(
            [x],
            [y],
            s=90 if marker != "*" else 160,
            marker=marker,
            facecolors=colour if filled else "white",
            edgecolors=colour,
            linewidths=1.8,
            zorder=3,
            label=label,
        )
        if family == "fd":
            fd.append((r["setting"], x, y))
        else:
            notes.append((x, y, _short(r), family))
    for x, y, text, family in _merge(notes):
        dx, dy, ha = _OFFSETS.get(family, (8, 6, "left"))
        ax.annotate(
            text,
            (x, y),
            textcoords="offset points",
            xytext=(dx, dy),
            fontsize=8,
            color="#222222",
            ha=ha,
        )
    if fd:
        fd.sort()
        colour, marker = _style("fd")
        ax.plot([f[1] for f in fd], [f[2] for f in fd], color=colour, lw=1, alpha=0.6, zorder=2)
        ax.scatter(
            [],
            [],
            marker=marker,
            s=90,
            facecolors=colour,
            edgecolors=colour,
            label="finite differences of the closed-form position",
        )
        for h, x, y in fd:
            ax.annotate(
                f"h = {h:.0e}",
                (x, y),
                textcoords="offset points",
                xytext=(8, -3),
                fontsize=8,
                color=colour,
            )
    front = _pareto(pts)
    if len(front) > 1:
        fx, fy = [pts[i][0] for i in front], [pts[i][1] for i in front]
        ax.step(
            fx + [fx[-1] * 30],
            fy + [fy[-1]],
            where="post",
            color="#444444",
            lw=1.2,
            ls="--",
            zorder=1,
            label="Pareto front (nothing is both faster and more accurate)",
        )
    ax.axhline(GOAL_ERROR, color="#009E73", lw=1, ls=":", zorder=0)
    ax.text(
        0.99,
        GOAL_ERROR * 1.4,
        "accuracy goal 1e-13",
        fontsize=8,
        color="#009E73",
        ha="right",
        transform=ax.get_yaxis_transform(),
    )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(
        f"time per position [µs]  (median of {data['config']['repeats']} repeats, "
        f"{meta['positions']} positions in one call)"
    )
    ax.set_ylabel("worst relative error over the cycle, any output [–]")
    ax.set_title(
        f"Speed against accuracy: {meta['title']}, {meta['positions']} positions, position to jerk",
        fontsize=11,
    )
    ax.grid(True, which="major", color="#dddddd", lw=0.6)
    ax.scatter(
        [],
        [],
        marker="o",
        s=60,
        facecolors="white",
        edgecolors="#444444",
        label="hollow marker: to acceleration only (no jerk)",
    )
    ax.legend(fontsize=8, loc="upper right", framealpha=0.95)
    ymin = min(p[1] for p in pts)
    ymax = max(p[1] for p in pts)
    ax.set_ylim(ymin / 10, ymax * 30)
    paths = _save(fig, outdir, "bench-speed-accuracy", formats)
    plt.close(fig)
    return paths


def _merge(notes, close=0.12):
    """Join the labels of points closer than ``close`` decades in both axes."""
    groups = []
    for x, y, text, family in notes:
        for g in groups:
            if (
                abs(math.log10(g[0] / x)) < close
                and abs(math.log10(g[1] / y)) < close
                and g[3] == family
            ):
                g[2].append(text)
                break
        else:
            groups.append((x, y, [text], family))
    out = []
    for x, y, texts, family in groups:
        if family == "loops" and len(texts) > 1:
            tols = [t.replace("tol ", "") for t in texts]
            text = "tol " + ", ".join(tols)
        else:
            text = ", ".join(texts)
        out.append((x, y, text, family))
    return out


#: where each family's label sits relative to its point (points, points, alignment)
_OFFSETS = {
    "kernels": (6, -15, "left"),
    "units": (6, 9, "left"),
    "scalar": (6, 9, "left"),
    "graphical": (-6, -14, "right"),
    "loops": (6, 9, "left"),
    "pylinkage": (0, 11, "center"),
    "mechanism": (8, 6, "left"),
    "kimech": (8, -12, "left"),
}


def _short(r):
    key = r["method"]
    if key == "loops":
        return "tol default" + (f" {r['setting']:.0e}" if r.get("setting") else "")
    if key.startswith("loops"):
        return f"tol {r['setting']:.0e}"
    return {
        "kernels": "closed forms (unit-free)",
        "units": "unit-aware API",
        "scalar": "scalar loop",
        "graphical": "graphical",
    }.get(key, key)


def stability(data, outdir, formats=("png", "svg")):
    """Chart 2."""
    import matplotlib.pyplot as plt

    st = data["stability"]
    fig, (ax, bx) = plt.subplots(
        1, 2, figsize=(14, 6.2), layout="constrained", gridspec_kw={"width_ratios": [1.35, 1]}
    )
    d = np.asarray(st["delta"])
    names = list(st["methods"])
    row_y = {k: 10.0 * 6.0**i for i, k in enumerate(names)}  # one row per method
    for key in names:
        m = st["methods"][key]
        colour, marker = _style(key)
        err = np.array([np.nan if e is None else max(e, 1e-17) for e in m["errors"]])
        ax.plot(
            d,
            err,
            marker=marker,
            color=colour,
            ms=6,
            lw=1.3,
            label=m["label"],
            markerfacecolor=colour if key not in ("mechanism", "kimech") else "white",
        )
        ref = np.asarray(m["refused"], dtype=bool)
        if ref.any():
            ax.scatter(
                d[ref],
                np.full(ref.sum(), row_y[key]),
                marker=marker,
                s=22,
                color=colour,
                facecolors=colour if key not in ("mechanism", "kimech") else "white",
            )
    top = row_y[names[-1]] * 4 if names else 100.0
    ax.axhspan(4.0, top, color="#eeeeee", zorder=0)
    ax.text(
        d.max() * 1.5,
        row_y[names[0]] if names else 10.0,
        "refused here (NaN or an error: singular,\nnot assemblable), one row per method ",
        ha="right",
        va="center",
        fontsize=8,
        color="#444444",
    )
    ax.axhline(GOAL_ERROR, color="#009E73", lw=1, ls=":")
    ax.text(1e-6, GOAL_ERROR * 1.5, "accuracy goal 1e-13", ha="center", fontsize=8, color="#009E73")
    thr = st.get("thresholds", {})
    if thr.get("kernels"):
        ax.axvline(thr["kernels"], color="#0072B2", lw=1.2, ls="--")
        ax.text(
            thr["kernels"] / 1.4,
            3e-11,
            thr.get("kernels_text", ""),
            fontsize=8,
            color="#0072B2",
            va="center",
            ha="right",
        )
    if thr.get("condition"):
        ax.axvline(thr["condition"], color="#0072B2", lw=1, ls=":")
        ax.text(
            thr["condition"] * 1.4,
            3e-15,
            thr.get("condition_text", ""),
            fontsize=8,
            color="#0072B2",
            ha="left",
            va="bottom",
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(1e-16, top)
    ax.set_xlabel("distance of theta2 from the toggle position [rad]")
    ax.set_ylabel("relative error, worst output (to jerk) [–]")
    ax.set_title(f"(a) Near a toggle: {st['title']}", fontsize=11)
    ax.grid(True, color="#dddddd", lw=0.6)
    ax.legend(fontsize=8, loc="lower left")
    # (b) Newton-Raphson against its starting guess
    nw = data["newton"]
    off = np.asarray(nw["offsets"])
    colours = ["#0072B2", "#D55E00", "#009E73"]
    styles = {
        "same": ("-", "o", "intended assembly"),
        "other": ("--", "^", "other assembly (branch jump)"),
        "failed": (":", "x", "no convergence (error raised)"),
        "wrong": ("-.", "s", "returned a non-closure"),
    }
    from matplotlib.lines import Line2D

    point_handles, style_handles = [], []
    for k, p in enumerate(nw["points"]):
        c = colours[k % len(colours)]
        for outcome, (ls, mk, _) in styles.items():
            if outcome == "wrong" and not any(p["wrong"]):
                continue
            bx.plot(
                off, p[outcome], color=c, lw=2 if outcome == "same" else 1.3, ls=ls, marker=mk, ms=4
            )
        point_handles.append(Line2D([], [], color=c, lw=2, label=p["text"]))
    for outcome, (ls, mk, text) in styles.items():
        if outcome != "wrong" or any(any(p["wrong"]) for p in nw["points"]):
            style_handles.append(
                Line2D([], [], color="#444444", ls=ls, marker=mk, ms=4, label=text)
            )
    first = bx.legend(
        handles=point_handles,
        fontsize=8,
        loc="lower left",
        bbox_to_anchor=(0.01, 0.56),
        title="where",
        title_fontsize=8,
    )
    bx.add_artist(first)
    bx.legend(
        handles=style_handles,
        fontsize=8,
        loc="upper left",
        bbox_to_anchor=(0.01, 0.5),
        title="outcome",
        title_fontsize=8,
    )
    bx.set_xscale("log")
    bx.set_ylim(-0.03, 1.03)
    bx.set_xlabel("error of the starting guess of the unknown angles [rad]")
    bx.set_ylabel(f"fraction of {nw['trials']} random guesses [–]")
    bx.set_title("(b) Newton-Raphson (vector loops) as its starting guess worsens", fontsize=11)
    bx.grid(True, color="#dddddd", lw=0.6)
    paths = _save(fig, outdir, "bench-stability", formats)
    plt.close(fig)
    return paths


_SCALING_LABELS = {
    "kernels": "closed forms, unit-free",
    "kernels-o2": "closed forms, unit-free",
    "units": "closed forms, unit-aware",
    "scalar": "closed forms, scalar loop",
    "loops": "vector loops",
    "pylinkage": "pylinkage",
    "mechanism": "mechanism",
    "kimech": "kimech",
}


def scaling(data, outdir, formats=("png", "svg")):
    """Chart 3: cost against the number of positions and of loops."""
    import matplotlib.pyplot as plt

    sc = data["scaling"]
    fig, (ax, bx) = plt.subplots(
        1, 2, figsize=(13, 5.5), layout="constrained", gridspec_kw={"width_ratios": [1.5, 1]}
    )
    for key, m in sc["positions"].items():
        if not m["points"]:
            continue
        colour, marker = _style(key)
        n = [p["N"] for p in m["points"]]
        us = [p["us"] for p in m["points"]]
        ls = "--" if m["order"] < 3 else "-"
        face = colour if m["order"] >= 3 else "white"
        short = _SCALING_LABELS.get(key.split("-tol")[0], m["label"])
        ax.plot(
            n,
            us,
            color=colour,
            marker=marker,
            ls=ls,
            lw=1.5,
            markerfacecolor=face,
            label=short + ("" if m["order"] >= 3 else ", to acceleration"),
        )
    ax.axhline(0.2, color="#009E73", lw=1, ls=":")
    ax.text(
        1.2,
        0.2 * 1.15,
        "goal: 0.2 µs/position at 10^5 (closed forms, to jerk)",
        fontsize=8,
        color="#009E73",
    )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("number of positions solved in one call [–]")
    ax.set_ylabel("time per position [µs] (median)")
    ax.set_title("(a) Fourbar: cost per position against the work", fontsize=11)
    ax.grid(True, color="#dddddd", lw=0.6)
    ax.legend(fontsize=8, loc="upper right", title="to jerk unless said", title_fontsize=8)
    rows = sc["loops"]
    colour, marker = _style("loops")
    xs = [r["loops"] + (0.08 if "slider" in r["case"] else 0) for r in rows]
    bx.plot(
        [x for x, r in zip(xs, rows) if "slider" not in r["case"]],
        [r["us"] for r in rows if "slider" not in r["case"]],
        color=colour,
        marker=marker,
        ms=8,
        lw=1.5,
        label="revolute chain: fourbar, Watt II sixbar, eightbar",
    )
    sl = [(x, r) for x, r in zip(xs, rows) if "slider" in r["case"]]
    if sl:
        bx.scatter(
            [x for x, _ in sl],
            [r["us"] for _, r in sl],
            marker="s",
            s=60,
            facecolors="white",
            edgecolors=colour,
            linewidths=1.8,
            label="sixbar driving a slider",
        )
    for x, r in zip(xs, rows):
        slider = "slider" in r["case"]
        bx.annotate(
            f"{r['us']:.0f} µs",
            (x, r["us"]),
            textcoords="offset points",
            xytext=(9, 2) if slider else (-9, -12),
            ha="left" if slider else "right",
            fontsize=8,
        )
    bx.axhline(50, color="#009E73", lw=1, ls=":")
    bx.text(
        3.45,
        50,
        "goal: 50 µs/position\n(sixbar)",
        fontsize=8,
        color="#009E73",
        ha="right",
        va="bottom",
    )
    bx.set_xticks([1, 2, 3])
    bx.set_xticklabels(["1\n(fourbar)", "2\n(sixbar)", "3\n(eightbar)"])
    bx.set_xlim(0.7, 3.5)
    bx.set_ylim(0, max(max(r["us"] for r in rows), 50) * 1.25)
    bx.set_xlabel("number of loops [–]")
    bx.set_ylabel(f"time per position [µs], {sc['loops_positions']} positions, to jerk")
    bx.set_title("(b) General vector-loop solver against the number of loops", fontsize=11)
    bx.grid(True, color="#dddddd", lw=0.6)
    bx.legend(fontsize=8, loc="upper left")
    paths = _save(fig, outdir, "bench-scaling", formats)
    plt.close(fig)
    return paths


def draw_all(data, outdir, formats=("png", "svg")):
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "accelab"
    import os

    os.makedirs(outdir, exist_ok=True)
    return (
        speed_accuracy(data, outdir, formats)
        + stability(data, outdir, formats)
        + scaling(data, outdir, formats)
    )
