"""Shared test configuration: a non-interactive matplotlib backend, hypothesis
profiles, a check that pytest-xdist keeps each ``xdist_group`` in one worker, and the
strategies for random well-conditioned linkages."""

import math
import os

import pytest
from hypothesis import HealthCheck, assume, settings
from hypothesis import strategies as st

os.environ.setdefault("MPLBACKEND", "Agg")  # before anything imports matplotlib

# as the accelab command does: jsonschema's IRI grammar compiled only if a schema asks
from accelab.lazy_iri import defer_iri_grammar

defer_iri_grammar()

# The same examples in every run (derandomized): `make test` and CI pass or fail on the code,
# not on the draw. `make explore` (ACCELAB_HYPOTHESIS=explore) draws at random, EXPLORE times
# as many: run it after changing a kernel, a reference or a strategy, and keep what it finds as
# an @example (it found the round-off cases named in tests/test_kernels_accuracy.py).
EXPLORE = 50
settings.register_profile(
    "default",
    deadline=None,
    max_examples=60,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile(
    "explore",
    deadline=None,
    max_examples=60 * EXPLORE,
    suppress_health_check=[HealthCheck.too_slow],
)
PROFILE = os.environ.get("ACCELAB_HYPOTHESIS", "default")
settings.load_profile(PROFILE)


def examples(n):
    """``n`` examples for a test that sets its own number: EXPLORE times as many under
    ``make explore``."""
    return n * EXPLORE if PROFILE == "explore" else n


#: the modules that take longest in one worker of ``make test`` [s], measured (-n 3 on 2 cores,
#: the machine busy): handed out longest first, the course group (the notebooks executed, then
#: the site built from them and read) before all, so that no long one starts last
LONGEST = {
    "test_course": 160,  # with test_docs: one group
    "test_browser_assignment": 90,
    "test_browser_hub": 85,
    "test_benchmarks": 8,  # pairs with the course group: xdist gives each worker two at first
    "test_polygon_browser": 75,
    "test_exercises_grade": 59,
    "test_grading_faults": 48,
    "test_browser_course": 41,
    "test_exercises_exchange": 36,
    "test_wheel": 21,
    "test_contributing": 17,
}


def pytest_collection_modifyitems(session, config, items):
    """The longest modules first (:data:`LONGEST`, in that order), then the others that
    hold a slow test, then the rest, each module's tests in their own order. pyproject's
    addopts keep that order (``--no-loadscope-reorder``): with ``--dist loadgroup`` a group,
    or a test outside any group, is a unit of work handed out in it, so the long units
    start at once and the many quick ones fill every worker up to the end."""
    slow = {item.module.__name__ for item in items if item.get_closest_marker("slow")}
    rank = {name: k for k, name in enumerate(LONGEST)}

    def order(item):
        name = item.module.__name__
        if name == "test_docs":  # in the course group, after test_course
            name = "test_course"
        return (rank.get(name, len(rank)), name not in slow)

    items.sort(key=order)  # stable


def pytest_runtest_setup(item):
    """With ``-n N --dist loadgroup`` (make test), the tests of an ``xdist_group`` share
    what one process builds and must run in one worker. pytest-xdist tells the groups
    apart by a suffix it adds to each test's id, which pytest 9.2 drops without a word
    (pytest-xdist issue 1386): the tests then run apart and break each other. Fail them
    then, saying why, rather than run them so."""
    config = item.config
    if (
        hasattr(config, "workerinput")
        and config.getvalue("loadgroup")
        and item.get_closest_marker("xdist_group")
        and "@" not in item.nodeid
    ):
        pytest.fail(
            f"pytest-xdist's --dist loadgroup does not keep the tests of an xdist_group in one "
            f"worker with pytest {pytest.__version__} (pytest-xdist issue 1386): install the "
            "pytest that pyproject's test extra allows (pip install -e '.[test]'), or run "
            "without -n",
            pytrace=False,
        )


# --------------------------------------------------------------------------
# Strategies for random well-conditioned linkages (kernel arguments, SI floats).
# Each builds the geometry from an assembled position, so every draw closes
# its loop with the transmission angle (or its analogue) far from a toggle:
# the sine of it stays above about 0.08.

lengths = st.floats(0.05, 2.0)
angles = st.floats(-math.pi, math.pi)
#: the angle at A between A->O4 and A->B: away from 0 and pi (a toggle)
open_angles = st.floats(0.35, math.pi - 0.35)


@st.composite
def input_motion(draw):
    """theta2, omega2 (nonzero), alpha2, jerk2 (nonzero) and the ground angle theta1."""
    sign = draw(st.sampled_from([-1.0, 1.0]))
    return {
        "theta1": draw(angles),
        "theta2": draw(angles),
        "omega2": sign * draw(st.floats(0.5, 60.0)),
        "alpha2": draw(st.floats(-800.0, 800.0)),
        "jerk2": draw(st.sampled_from([-1.0, 1.0])) * draw(st.floats(1.0, 2e4)),
    }


def _third_side(first, second, psi, b):
    """|B - second| where B = first + b e^{j(arg(second - first) + psi)}."""
    u = (second - first) / abs(second - first)
    return abs(first + b * u * complex(math.cos(psi), math.sin(psi)) - second)


@st.composite
def fourbars(draw):
    """Kernel arguments of a well-conditioned fourbar: a, b, c, d, motion."""
    m = draw(input_motion())
    a, d = draw(lengths), draw(lengths)
    t2 = m["theta2"] - m["theta1"]
    A = a * complex(math.cos(t2), math.sin(t2))
    s = abs(d - A)
    assume(s > 0.1 * (a + d))
    b = s * draw(st.floats(0.3, 3.0))
    c = _third_side(A, complex(d, 0.0), draw(open_angles), b)
    return dict(a=a, b=b, c=c, d=d, **m)


@st.composite
def fivebars(draw):
    """Kernel arguments of a well-conditioned geared fivebar."""
    m = draw(input_motion())
    a, d, f = draw(lengths), draw(lengths), draw(lengths)
    lam = draw(st.sampled_from([-3.0, -2.0, -1.0, -0.5, 0.5, 1.5, 2.0]))
    phi = draw(angles)
    t2 = m["theta2"] - m["theta1"]
    A = a * complex(math.cos(t2), math.sin(t2))
    t5 = lam * t2 + phi
    C = f + d * complex(math.cos(t5), math.sin(t5))
    s = abs(C - A)
    assume(s > 0.1 * (a + d + f))
    b = s * draw(st.floats(0.3, 3.0))
    c = _third_side(A, C, draw(open_angles), b)
    return dict(a=a, b=b, c=c, d=d, f=f, lam=lam, phi=phi, **m)


@st.composite
def slidercranks(draw):
    """Kernel arguments of a well-conditioned offset slider-crank: the rod
    makes at least 25 deg with the perpendicular to the slide."""
    m = draw(input_motion())
    a = draw(lengths)
    b = a * draw(st.floats(0.3, 5.0))
    t2 = m["theta2"] - m["theta1"]
    sin3 = draw(st.floats(-0.9, 0.9))
    c = a * math.sin(t2) - b * sin3  # offset that puts the rod at sin3
    return dict(a=a, b=b, c=c, **m)


@st.composite
def invertedslidercranks(draw):
    """Kernel arguments of a well-conditioned inverted slider-crank (c may be 0)."""
    m = draw(input_motion())
    a, d = draw(lengths), draw(lengths)
    t2 = m["theta2"] - m["theta1"]
    s = abs(a * complex(math.cos(t2), math.sin(t2)) - d)
    assume(s > 0.1 * (a + d))
    c = draw(st.one_of(st.just(0.0), st.floats(0.05, 2.0).map(lambda k: k * s)))
    # |c sin gamma| <= 0.9 s keeps the slide line well inside A's reach
    top = min(1.0, 0.9 * s / c) if c > 0 else 1.0
    sin_g = draw(st.floats(-top, top))
    gamma = math.asin(sin_g)
    if draw(st.booleans()):
        gamma = math.copysign(math.pi, gamma) - gamma
    return dict(a=a, c=c, d=d, gamma=gamma, **m)


@st.composite
def points_on_links(draw, links):
    """Extra points: (name, link, distance [m], angle from the link's line [rad])."""
    return [(f"Q{k}", k, draw(st.floats(0.01, 2.0)), draw(angles)) for k in links]
