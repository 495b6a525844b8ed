"""The clock: median of repeats after a warm-up, and what machine it ran on.

Times come from :func:`time.perf_counter`. A call that takes less than
``min_time`` is run several times per repeat (``number``) and the repeat's
time divided by that count, so short calls are not swamped by the clock's
resolution. The benchmark asserts nothing about time; it reports.
"""

import os
import platform
import statistics
import sys
import time

#: a call slower than this [s] is repeated at most SLOW_REPEATS times
SLOW_CALL = 0.5
SLOW_REPEATS = 3


def measure(fn, repeats=7, min_time=0.02, max_number=10000):
    """Median wall time of one call of ``fn`` [s].

    Parameters
    ----------
    fn : callable
        Called with no arguments. Called once first as a warm-up (caches,
        JIT compilation, lazy imports), and that call's result returned.
    repeats : int
        Number of timed repeats whose median is reported (at most
        ``SLOW_REPEATS`` for a call slower than ``SLOW_CALL``).
    min_time : float
        Minimum duration of one repeat [s]; short calls are looped.

    Returns
    -------
    dict
        ``median`` [s per call], ``min``, ``max``, ``repeats``, ``number``
        (calls per repeat), and ``result`` (the warm-up call's return value).
    """
    t0 = time.perf_counter()
    result = fn()
    first = time.perf_counter() - t0
    number = 1
    if first > SLOW_CALL:
        repeats = min(repeats, SLOW_REPEATS)
    if first < min_time:  # a second, warm, estimate decides the loop count
        t0 = time.perf_counter()
        fn()
        once = max(time.perf_counter() - t0, 1e-7)
        number = int(min(max_number, max(1, min_time / once)))
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return {
        "median": statistics.median(times),
        "min": min(times),
        "max": max(times),
        "repeats": repeats,
        "number": number,
        "result": result,
    }


def measure_interleaved(fns, repeats=9, min_time=0.02, max_number=10000):
    """Median times of several callables timed in turn within each repeat.

    On a machine whose load changes (other jobs on a shared 2-core box),
    interleaving gives each callable the same conditions, so their ratios
    stay meaningful even when the absolute times move. Returns a list of
    dicts like :func:`measure` (without ``result``), plus ``ratios``: the
    median over repeats of each callable's time over the first's.
    """
    numbers = []
    for fn in fns:
        fn()  # warm-up
        t0 = time.perf_counter()
        fn()
        once = max(time.perf_counter() - t0, 1e-7)
        numbers.append(int(min(max_number, max(1, min_time / once))))
    times = [[] for _ in fns]
    for _ in range(repeats):
        for k, fn in enumerate(fns):
            n = numbers[k]
            t0 = time.perf_counter()
            for _ in range(n):
                fn()
            times[k].append((time.perf_counter() - t0) / n)
    out = []
    for k in range(len(fns)):
        ratios = [a / b for a, b in zip(times[k], times[0])]
        out.append(
            {
                "median": statistics.median(times[k]),
                "min": min(times[k]),
                "max": max(times[k]),
                "repeats": repeats,
                "number": numbers[k],
                "ratio": statistics.median(ratios),
            }
        )
    return out


def machine():
    """What the numbers were measured on: CPU, cores, Python and package versions."""
    import matplotlib
    import numpy
    import pint

    info = {
        "python": sys.version.split()[0],
        "implementation": platform.python_implementation(),
        "platform": platform.platform(),
        "machine": platform.machine(),
        "cpu": _cpu_name(),
        "cores": os.cpu_count(),
        "numpy": numpy.__version__,
        "pint": pint.__version__,
        "matplotlib": matplotlib.__version__,
    }
    try:
        import mpmath

        info["mpmath"] = mpmath.__version__
    except ImportError:  # pragma: no cover
        pass
    for name in ("pylinkage", "mechanism", "kimech", "numba", "scipy"):
        info[name] = _version(name)
    try:
        from threadpoolctl import threadpool_info

        info["blas"] = [
            {k: p.get(k) for k in ("internal_api", "version", "num_threads", "architecture")}
            for p in threadpool_info()
        ]
    except Exception:  # noqa: BLE001 - threadpoolctl is optional: the report is whole without it
        pass
    info["OPENBLAS_CORETYPE"] = os.environ.get("OPENBLAS_CORETYPE")
    try:
        info["load_average"] = list(os.getloadavg())
    except OSError:  # pragma: no cover
        pass
    return info


def _version(name):
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(name)
    except PackageNotFoundError:
        return None


def _cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or None
