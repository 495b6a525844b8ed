"""Markdown tables of a benchmark run (``accelab bench --out DIR --report``),
for the README."""


def _num(x, digits=3):
    if x is None:
        return "–"
    if isinstance(x, str):
        return x
    if x == 0:
        return "0"
    if abs(x) >= 1000 or abs(x) < 0.01:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


def goals_table(data):
    lines = ["| goal | target | measured | met |", "|---|---|---|---|"]
    for g in data["goals"]:
        measured = g["measured"] if isinstance(g["measured"], str) else _num(g["measured"])
        note = f" ({g['note']})" if g.get("note") else ""
        lines.append(
            f"| {g['goal']}{note} | {g['target']} | {measured} | "
            f"{'yes' if g['met'] else '**no**'} |"
        )
    return "\n".join(lines)


def cases_table(
    data,
    methods=(
        "kernels",
        "units",
        "scalar",
        "loops",
        "fd-h1e-03",
        "graphical",
        "pylinkage",
        "mechanism",
        "kimech",
    ),
):
    """Per case: time per position [us] / worst relative error, per method."""
    rows = {(r["case"], r["method"]): r for r in data["results"]}
    present = [m for m in methods if any(k[1] == m for k in rows)]
    labels = {m["key"]: m["label"] for m in data["methods"]}
    head = "| case | " + " | ".join(labels.get(m, m) for m in present) + " |"
    lines = [head, "|---" * (len(present) + 1) + "|"]
    for c in data["cases"]:
        cells = []
        for m in present:
            r = rows.get((c["name"], m))
            if r is None or "skipped" in r or r.get("worst") is None:
                cells.append("–")
            else:
                flag = f", {r['flagged']} refused" if r.get("flagged") else ""
                cells.append(f"{_num(r['us_per_position'])} µs / {_num(r['worst'], 2)}{flag}")
        lines.append(f"| {c['title']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def units_table(data):
    lines = ["| positions | unit-free [µs] | unit-aware [µs] | ratio |", "|---|---|---|---|"]
    for r in data["units"]["rows"]:
        lines.append(
            f"| {r['N']} | {_num(r['unit_free_us'])} | {_num(r['unit_aware_us'])} | "
            f"{r['ratio']:.2f} |"
        )
    return "\n".join(lines)


def loops_table(data):
    lines = ["| linkage | loops | µs per position | mean Newton iterations |", "|---|---|---|---|"]
    for r in data["scaling"]["loops"]:
        lines.append(
            f"| {r['title']} | {r['loops']} | {_num(r['us'])} | {r['mean_iterations']:.2f} |"
        )
    return "\n".join(lines)


def machine_line(data):
    m = data["machine"]
    load = m.get("load_average")
    load = f", load average {load[0]:.1f} at the start" if load else ""
    return (
        f"{m.get('cpu') or m.get('machine')}, {m.get('cores')} cores{load}; Python "
        f"{m['python']}, numpy {m['numpy']}, pint {m['pint']}, mpmath {m.get('mpmath')}; "
        f"peers: pylinkage {m.get('pylinkage')} (numba {m.get('numba')}), mechanism "
        f"{m.get('mechanism')}, kimech {m.get('kimech')} (scipy {m.get('scipy')}); "
        f"{data['mode']} run, "
        f"{data['elapsed_s']:.0f} s, {data['date']}"
    )


def markdown(data):
    return "\n\n".join(
        [
            machine_line(data),
            goals_table(data),
            cases_table(data),
            units_table(data),
            loops_table(data),
        ]
    )
