"""The registries of mechanisms and of exercise families, and what CONTRIBUTING.md's
walk-throughs ask for: each test here fails when a step is forgotten, and says which file
to touch.

* a mechanism: its kernel declares its outputs (solver/kernels/NAME.py), its class is
  registered (solver/registry.py) and exported (solver/mechanisms/__init__.py,
  solver/__init__.py), it solves its registered example at every order with derivatives
  that agree with finite differences of its positions, and docs/conventions.md documents it;
* an exercise family: its module is registered (exercises/families/__init__.py) and has
  what the registry reads, and the notebooks that teach it exist;
* a notebook: the README lists it.
"""

import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import numpy as np
import pytest

import accelab.course
import accelab.solver
from accelab.exercises import families
from accelab.exercises.families import REGISTRY as FAMILY_REGISTRY
from accelab.solver import kernels, mechanisms
from accelab.solver.batch import solve_case
from accelab.solver.cases import read_case
from accelab.solver.kernels.common import Motion
from accelab.solver.mechanisms import Mechanism
from accelab.solver.mechanisms.base import order_of
from accelab.solver.registry import BATCH_MECHANISMS, REGISTRY, construction, mechanism_class

ROOT = Path(__file__).resolve().parents[1]
NAMES = list(REGISTRY)
#: modules of exercises/families that are not families: what families share
FAMILY_HELPERS = ("common", "polygon")


def source_of(cls):
    """The repository file defining ``cls`` (accelab.solver.kernels.x -> solver/kernels/x.py)."""
    return "/".join(cls.__module__.split(".")[1:]) + ".py"


def submodules(package):
    return [
        importlib.import_module(f"{package.__name__}.{m.name}")
        for m in pkgutil.iter_modules(package.__path__)
    ]


# ---------------------------------------------------------------- mechanisms
def test_every_mechanism_class_is_registered():
    classes = {
        obj
        for module in submodules(mechanisms)
        for obj in vars(module).values()
        if inspect.isclass(obj) and issubclass(obj, Mechanism) and obj is not Mechanism
    }
    for cls in classes:
        assert cls.name, (
            f"{cls.__name__} has no name: set name = '...' in its class, the key of its "
            "entry in REGISTRY (solver/registry.py)"
        )
        assert cls.name in REGISTRY, (
            f"{cls.__name__} (name {cls.name!r}) is not registered: add its entry to "
            "REGISTRY in solver/registry.py"
        )
        assert mechanism_class(cls.name) is cls, f"REGISTRY[{cls.name!r}] names another class"


@pytest.mark.parametrize("name", NAMES)
def test_a_registered_mechanism_is_complete(name):
    entry = REGISTRY[name]
    cls = mechanism_class(name)
    assert issubclass(cls, Mechanism) and cls.name == name, f"{cls.__name__}.name must be {name!r}"
    assert cls.declaration() is entry.parameters
    exported = getattr(accelab.solver, cls.__name__, None)
    assert exported is cls and cls.__name__ in accelab.solver.__all__, (
        f"export {cls.__name__} in solver/mechanisms/__init__.py and solver/__init__.py"
    )
    if name in BATCH_MECHANISMS:
        assert accelab.solver.MECHANISMS[name] is cls
    if entry.construction is not None:
        assert callable(construction(name)), f"{entry.construction} is not a function"
    names = {p.name for p in entry.parameters.geometry + entry.parameters.point}
    assert set(entry.links.values()) <= names, "links are labelled with parameter names"
    assert entry.example, "give the entry an example position (the tests solve it)"


def test_every_kernel_declares_its_outputs():
    found = {}
    for module in submodules(kernels):
        if module.__name__.rsplit(".", 1)[1] in ("common", "points"):
            continue
        records = [
            obj
            for obj in vars(module).values()
            if inspect.isclass(obj) and issubclass(obj, Motion) and obj is not Motion
        ]
        assert records, (
            f"{module.__name__} declares no outputs: add an @outputs class of Motion with "
            "OUTPUTS (solver/kernels/common.py)"
        )
        for record in records:
            assert record.OUTPUTS and "__slots__" in vars(record), (
                f"{record.__name__}: decorate it with @outputs and give OUTPUTS"
            )
            found[record.__name__] = record
    assert len(found) >= 6


def _split(name):
    """The registered example as (geometry, solve's keyword arguments), as given (text)."""
    entry = REGISTRY[name]
    geometry = {p.name for p in entry.parameters.geometry}
    example = dict(entry.example)
    return {k: v for k, v in example.items() if k in geometry}, {
        k: v for k, v in example.items() if k not in geometry
    }


@pytest.mark.parametrize("name", NAMES)
def test_a_registered_mechanism_solves_its_example_at_every_order(name):
    geometry, rest = _split(name)
    mech = mechanism_class(name)(**geometry)
    for order in (0, 1, 2, 3):
        kw = (
            dict(rest, order=order) if "order" in inspect.signature(mech.solve).parameters else rest
        )
        r = mech.solve(**kw)
        assert r.valid, f"{name}: the registered example must be a valid position"
        record = r._motion
        empty = [
            n for n in type(record).OUTPUTS if order_of(n) <= order and getattr(record, n) is None
        ]
        assert not empty, (
            f"{name}'s kernel declares {empty} but does not fill them at order {order}: set "
            f"them in solve() of {source_of(type(record))}"
        )
        for output in r.outputs():
            assert np.all(np.isfinite(r.si(output))), (name, order, output)
            assert r[output] is not None  # a Quantity: its kind follows from its name (kind_of)
    if name in BATCH_MECHANISMS:
        answer = solve_case({"mechanism": name, **REGISTRY[name].example})
        assert answer["ok"], answer


def points_reported(result):
    """The points whose vectors a result reports (R_X, and V_X, A_X, J_X with it)."""
    return [o[2:] for o in result.outputs() if o.startswith("R_")]


@pytest.mark.parametrize("name", NAMES)
def test_every_point_reports_its_vectors(name):
    """Each point the class places (``_points``) is reported: R, V, A and J of it are in
    the result's outputs (the class's ``_point_outputs``)."""
    geometry, rest = _split(name)
    mech = mechanism_class(name)(**geometry)
    r = mech.solve(**rest)
    missing = [f"{v}_{x}" for x in mech._points for v in "RVAJ" if f"{v}_{x}" not in r.outputs()]
    assert not missing, (
        f"{name}: the results do not report {', '.join(missing)}: add them to _point_outputs "
        f"in {source_of(type(mech))}"
    )


def _finite_differences(values, h):
    """d/dtheta2, d2, d3 at the middle of 7 values spaced h (central differences)."""
    f = np.asarray(values)
    d1 = (f[4] - f[2]) / (2 * h)
    d2 = (f[4] - 2 * f[3] + f[2]) / h**2
    d3 = (f[5] - 2 * f[4] + 2 * f[2] - f[1]) / (2 * h**3)
    return d1, d2, d3


@pytest.mark.parametrize("name", BATCH_MECHANISMS)
def test_derivatives_agree_with_finite_differences_of_positions(name):
    """A new kernel's velocities, accelerations and jerks are the time derivatives of its
    positions: at a steady crank speed, d/dt = omega2 d/dtheta2 (outputs of the kernel,
    and the points' vectors R_X -> V_X -> A_X -> J_X)."""
    case = read_case({"mechanism": name, **REGISTRY[name].example})
    mech = mechanism_class(name).from_si(case.geometry())
    t0, w = case.params["theta2"], case.params["omega2"]
    h = 1e-3
    sweep = t0 + h * np.arange(-3, 4)
    motion = {"theta2": sweep, "omega2": w, "alpha2": 0.0, "jerk2": 0.0}
    r = mech.solve_si(motion, circuit=case.circuit, **case.point())
    assert np.all(r.valid)
    chains = []
    record = type(r._motion)
    for out in record.OUTPUTS:  # theta3 -> omega3 -> alpha3 -> jerk3, d -> d_dot -> ...
        if out.startswith("theta"):
            chains.append([out] + [q + out[5:] for q in ("omega", "alpha", "jerk")])
        elif not out.endswith("dot") and out + "_dot" in record.OUTPUTS:
            chains.append([out] + [out + s for s in ("_dot", "_ddot", "_dddot")])
    chains += [[f"{v}_{x}" for v in "RVAJ"] for x in points_reported(r)]
    if "R" in r.outputs():  # a single point's vectors
        chains.append(list("RVAJ"))
    assert chains
    for chain in chains:
        position = r.si(chain[0])
        if chain[0].startswith("theta"):
            position = np.unwrap(position)
        for n, (want, name_n) in enumerate(zip(_finite_differences(position, h), chain[1:]), 1):
            got = np.broadcast_to(r.si(name_n), sweep.shape)[3]  # (omega5 may be one value)
            expected = w**n * want
            # central differences with h = 1e-3 agree to about 4e-6 (fourbar ... fivebar), and
            # to their own round-off, about eps max|position| (omega2 / h)^n, near a zero
            roundoff = 100 * np.finfo(float).eps * np.max(np.abs(position)) * (w / h) ** n
            assert abs(got - expected) <= 1e-4 * max(abs(expected), abs(got)) + roundoff, (
                f"{name}: {name_n} = {got} but {w:g}^{n} d^{n}({chain[0]})/dtheta2^{n} = "
                f"{expected} (finite differences)"
            )


#: docs/conventions.md's tables with a row per batch mechanism
TABLES = ("The mechanisms and their vector loops", "Outputs")


def documented_rows(heading):
    """{mechanism: the rest of its row} of the table in docs/conventions.md's section
    ``heading``, in the table's order."""
    text = (ROOT / "docs" / "conventions.md").read_text()
    section = text.split(f"\n## {heading}\n", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `(\w+)`[^|]*\|(.*)$", section, flags=re.MULTILINE)
    return dict(rows)


def test_batch_mechanisms_are_documented():
    for table in TABLES:
        rows = documented_rows(table)
        for name in BATCH_MECHANISMS:
            assert name in rows, f"docs/conventions.md: give {name} a row in '{table}'"
        order = [n for n in rows if n in BATCH_MECHANISMS]
        assert order == list(BATCH_MECHANISMS), (
            f"docs/conventions.md, '{table}': the rows go in the order of REGISTRY "
            f"(solver/registry.py: {', '.join(BATCH_MECHANISMS)}); they are {', '.join(order)}: "
            "move the row, or the entry"
        )


@pytest.mark.parametrize("name", BATCH_MECHANISMS)
def test_the_documented_outputs_are_reported(name):
    """Every name docs/conventions.md's 'Outputs' row gives is in the batch answer to the
    registered example (which places a coupler point where the mechanism takes one)."""
    row = documented_rows("Outputs")[name]
    documented = {w for code in re.findall(r"`([^`]+)`", row) for w in code.split()}
    answer = solve_case({"mechanism": name, **REGISTRY[name].example})
    assert answer["ok"], answer
    missing = sorted(documented - set(answer))
    assert not missing, (
        f"docs/conventions.md, 'Outputs': {name}'s row names {', '.join(missing)}, which "
        f"it does not report (it reports {', '.join(k for k in answer if k != 'ok')})"
    )


def test_the_readme_lists_every_mechanism_class():
    readme = (ROOT / "README.md").read_text()
    for name in NAMES:
        cls = mechanism_class(name).__name__
        assert f"`{cls}`" in readme, (
            f"README.md, 'Using the solver': add `{cls}` to the list of mechanism classes"
        )


# ---------------------------------------------------------------- exercise families
def test_every_family_module_is_registered():
    modules = {f.module for f in FAMILY_REGISTRY.values()}
    for info in pkgutil.iter_modules(families.__path__):
        if info.name in FAMILY_HELPERS:
            continue
        assert info.name in modules, (
            f"exercises/families/{info.name}.py is not registered: add its Family entry to "
            "REGISTRY in exercises/families/__init__.py"
        )


@pytest.mark.parametrize("name", list(FAMILY_REGISTRY))
def test_a_registered_family_is_complete(name):
    family = FAMILY_REGISTRY[name]
    module = family.load()
    assert getattr(module, "FAMILY", None) == name, f"{module.__name__}.FAMILY must be {name!r}"
    for attr in ("TITLE", "DEFAULTS", "generate_problem"):
        assert hasattr(module, attr), f"{module.__name__} needs {attr}"
    assert family.chapter and family.asks, "say what of the chapter it practises and asks"
    stems = {p.stem for p in accelab.course.notebooks()}
    assert family.notebooks and set(family.notebooks) <= stems, (
        f"{name}: the notebooks that teach it must be course notebooks ({family.notebooks})"
    )
    assert families.FAMILIES[name] is module.generate_problem


# ---------------------------------------------------------------- notebooks
def test_the_readme_lists_every_notebook():
    readme = (ROOT / "README.md").read_text()
    for source in accelab.course.notebooks():
        assert f"](course/{source.name})" in readme, (
            f"README.md, 'The course': add a line for {source.name}"
        )
