"""Grading speed: the instructor's wait for ``accelab grade``, sandbox included.

Builds the demo assignment (rotation, fourbar, tolerance) for a roster of N
students, submits N notebooks (a mix of right, wrong and crashing answers), and
times one ``accelab grade`` run with feedback and CSV, then where the time goes:
the sandboxed runs (and, per submission, the sandbox's start against the
cells), judging with nbgrader's autograde, feedback, the CSV.

    python -m accelab.benchmarks.grading --students 20 --jobs 2 --out build/bench

Goal (issue 11): 20 submissions graded, with feedback and CSV, in at most 20 s
on a 2-core machine.
"""

import argparse
import json
import os
import platform
import shutil
import statistics
import tempfile
import time

GOAL_SECONDS = 20.0


def build_course(folder, students):
    from accelab.exercises.assign import assign
    from accelab.exercises.notebook import read_spec
    from accelab.exercises.simulate import key_code, submit

    roster = [f"s{k:02d}" for k in range(students)]
    assign(folder, "A", roster=roster, course_id="bench", release=True, say=lambda *a: None)
    spec = read_spec(folder, "A")

    def wrong(a, q):
        return None if a.kind == "choice" else f"{a.name} = Q_({-q.magnitude!r}, {a.unit!r})"

    def crash(a, q):
        return "raise RuntimeError('broke')" if a.name.endswith("A_A_x") else None

    for k, student in enumerate(roster):
        transform = (None, wrong, crash)[k % 3]
        submit(folder, "A", student, key_code(spec, student, transform))
    return roster


def sandbox_start_seconds(repeats=5):
    """Seconds to start a sandboxed kernel and hand it a statement (median)."""
    from accelab.exercises.grader.sandbox import sandbox
    from accelab.exercises.grader.supervisor import Limits, run_plan

    statement = {"student": "x", "problems": []}
    times = []
    for _ in range(repeats):
        t0 = time.monotonic()
        run_plan([_noop()], statement, sandbox(), Limits())
        times.append(time.monotonic() - t0)
    return statistics.median(times)


def _noop():
    from accelab.exercises.grader.plan import Step

    return Step(0, "code", "pass")


def measure(students=20, jobs=2, keep=None):
    from accelab.exercises.grader.grade import grade

    folder = keep or tempfile.mkdtemp(prefix="accelab-bench-grading-")
    course = os.path.join(folder, "course")
    try:
        t0 = time.monotonic()
        build_course(course, students)
        setup = time.monotonic() - t0
        load = os.getloadavg()[0]
        subs, _, rows, seconds, timings = grade(course, "A", jobs=jobs, show_progress=False)
        runs = [s.seconds for s in subs if s.prepared]
        start = sandbox_start_seconds()
        return {
            "students": students,
            "jobs": jobs,
            "seconds": seconds,
            "per_submission": seconds / students,
            "goal_seconds": GOAL_SECONDS,
            "met": seconds <= GOAL_SECONDS,
            "stages": timings,
            "sandbox_run_median": statistics.median(runs) if runs else None,
            "sandbox_start_median": start,
            "graded": sum(s.graded for s in subs),
            "full_marks": sum(1 for r in rows if r["total"] == r["max"]),
            "setup_seconds": setup,
            "load_average": load,
            "cpus": os.cpu_count(),
            "machine": platform.processor() or platform.machine(),
            "python": platform.python_version(),
        }
    finally:
        if keep is None:
            shutil.rmtree(folder, ignore_errors=True)


def report(result):
    lines = [
        f"{result['students']} submissions graded with {result['jobs']} jobs, feedback and "
        f"CSV: {result['seconds']:.1f} s ({result['per_submission']:.2f} s per submission; "
        f"goal <= {result['goal_seconds']:g} s: {'met' if result['met'] else 'missed'}; "
        f"load average {result['load_average']:.1f} on {result['cpus']} cores)"
    ]
    for stage, seconds in result["stages"].items():
        lines.append(f"  {stage:<45} {seconds:6.1f} s")
    lines.append(
        f"  one sandboxed run (median, wall, in parallel) {result['sandbox_run_median']:.2f} s,"
        f" of which starting the sandbox and its kernel {result['sandbox_start_median']:.2f} s"
    )
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--students", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default="build/bench", help="folder for grading.json")
    args = parser.parse_args(argv)
    result = measure(args.students, args.jobs)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "grading.json"), "w") as fh:
        json.dump(result, fh, indent=1)
    print(report(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
