"""The public API of accelab.solver is typed, and mypy checks it (`make lint`).

Every function, class and method a user calls, by the names the package exports
(each module's ``__all__``) and the kernels' functions (every kernel module, found by
itself), annotates each of its parameters and its return value. A new public function
without annotations fails here, naming it; mypy ([tool.mypy] in pyproject.toml) then
checks that the annotations hold.
"""

import importlib
import inspect

import pytest

#: modules whose ``__all__`` is the public API
MODULES = (
    "accelab.solver",
    "accelab.solver.mechanisms",
    "accelab.solver.results",
    "accelab.solver.units",
    "accelab.solver.errors",
    "accelab.solver.batch",
    "accelab.solver.cases",
    "accelab.solver.registry",
    "accelab.solver.parameters",
    "accelab.solver.vectorloops",
)
#: the kernels' shared helpers a kernel is written with: module -> its public functions
HELPERS = {
    "accelab.solver.kernels.common": ("angles", "slider", "outputs"),
}
#: kernel modules that are not a mechanism's (shared helpers; their API is HELPERS)
NOT_A_MECHANISM = {"common", "points"}


def kernels():
    """Module -> public functions of every unit-free kernel: each module of
    ``accelab.solver.kernels`` (a new mechanism's kernel is found by itself: nothing to
    list here), every function it defines whose name does not start with ``_``; and the
    helpers of :data:`HELPERS`."""
    import pkgutil

    import accelab.solver.kernels as package

    found = dict(HELPERS)
    for info in pkgutil.iter_modules(package.__path__):
        if info.name in NOT_A_MECHANISM:
            continue
        name = f"{package.__name__}.{info.name}"
        module = importlib.import_module(name)
        found[name] = tuple(
            attr
            for attr, value in vars(module).items()
            if inspect.isfunction(value) and value.__module__ == name and not attr.startswith("_")
        )
    return found


KERNELS = kernels()


def ours(obj):
    return (getattr(obj, "__module__", None) or "").startswith("accelab.")


def functions(name, obj):
    """(qualified name, function) of everything callable ``obj`` offers a user."""
    if inspect.isclass(obj):
        if not ours(obj):
            return
        for attr, value in vars(obj).items():
            if attr.startswith("_") and attr != "__init__":
                continue
            if isinstance(value, property):
                yield f"{name}.{attr}", value.fget
            elif isinstance(value, (classmethod, staticmethod)):
                yield f"{name}.{attr}", value.__func__
            elif inspect.isfunction(value):
                yield f"{name}.{attr}", value
        for base in obj.__mro__[1:]:
            if ours(base) and not base.__name__.startswith("_"):
                yield from functions(f"{name}({base.__name__})", base)
    elif inspect.isfunction(obj) and ours(obj):
        yield name, obj


def public_functions():
    seen = {}
    for module_name in MODULES:
        module = importlib.import_module(module_name)
        for attr in module.__all__:
            for name, fn in functions(f"{module_name}.{attr}", getattr(module, attr)):
                seen.setdefault(fn, name)
    for module_name, attrs in KERNELS.items():
        module = importlib.import_module(module_name)
        for attr in attrs:
            for name, fn in functions(f"{module_name}.{attr}", getattr(module, attr)):
                seen.setdefault(fn, name)
    return sorted((name, fn) for fn, name in seen.items())


def unannotated(fn):
    """The parameters (and 'return') of ``fn`` that have no annotation."""
    fn = inspect.unwrap(fn)
    sig = inspect.signature(fn)
    missing = [
        p.name
        for i, p in enumerate(sig.parameters.values())
        if p.annotation is inspect.Parameter.empty and not (i == 0 and p.name in ("self", "cls"))
    ]
    if sig.return_annotation is inspect.Signature.empty:
        missing.append("return")
    return missing


PUBLIC = public_functions()


def test_the_public_api_is_found():
    names = [n for n, _ in PUBLIC]
    for expected in (
        "accelab.solver.FourBar.solve",
        "accelab.solver.mechanisms.Result.si",
        "accelab.solver.units.to_si",
        "accelab.solver.batch.solve_case",
        "accelab.solver.kernels.fourbar.solve",
    ):
        assert any(n == expected or n.startswith(expected + "(") for n in names), expected
    assert len(PUBLIC) > 60


@pytest.mark.parametrize("name, fn", PUBLIC, ids=[n for n, _ in PUBLIC])
def test_public_function_is_annotated(name, fn):
    missing = unannotated(fn)
    assert not missing, f"{name}: annotate {', '.join(missing)} (see CONTRIBUTING.md, Style)"
