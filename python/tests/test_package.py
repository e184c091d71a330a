"""The package as installed: its public API, stubs, docstrings and types."""

import ast
import enum
import inspect
import pathlib
import pickle
import re

import numpy as np

import selfalign as sa
from selfalign import _selfalign

PACKAGE_DIR = pathlib.Path(sa.__file__).parent


def public_names(module):
    return {n for n in dir(module) if not n.startswith("_")}


def test_init_reexports_the_whole_extension_api():
    assert public_names(_selfalign) == set(sa.__all__)
    for name in sa.__all__:
        obj = getattr(sa, name)
        # The studies that take executor= are Python wrappers of the extension's functions.
        assert getattr(obj, "__wrapped__", obj) is getattr(_selfalign, name), name


def test_stub_declares_every_public_name():
    tree = ast.parse((PACKAGE_DIR / "_selfalign.pyi").read_text())
    declared = set()
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            declared.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            declared.add(node.target.id)
    assert public_names(_selfalign) <= declared


def test_stub_classes_declare_every_public_member():
    tree = ast.parse((PACKAGE_DIR / "_selfalign.pyi").read_text())
    stub_members = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    names.add(item.name)
                elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                    names.add(item.target.id)
                elif isinstance(item, ast.Assign):
                    names.update(t.id for t in item.targets if isinstance(t, ast.Name))
            stub_members[node.name] = names
    for name, cls in vars(_selfalign).items():
        if not isinstance(cls, type) or issubclass(cls, BaseException | enum.Enum):
            continue
        own = {m for m in vars(cls) if not m.startswith("_")}
        missing = own - stub_members[cls.__name__]  # an alias checks its class
        assert not missing, f"{name}: {sorted(missing)} not in the stub"


def test_py_typed_marker_is_installed():
    assert (PACKAGE_DIR / "py.typed").is_file()


def test_everything_public_has_a_docstring():
    undocumented = []
    for name in sa.__all__:
        obj = getattr(sa, name)
        if not (callable(obj) or isinstance(obj, type)):
            continue
        if not (obj.__doc__ or "").strip():
            undocumented.append(name)
        if isinstance(obj, type) and not issubclass(obj, (BaseException, enum.Enum)):
            for member, value in vars(obj).items():
                if member.startswith("_"):
                    continue
                if hasattr(obj, "__members__") and member in ("name", "value"):
                    continue  # pybind11's own enum properties
                if isinstance(value, property) or inspect.isroutine(value) or callable(value):
                    if not (getattr(value, "__doc__", None) or "").strip():
                        undocumented.append(f"{name}.{member}")
    assert not undocumented


def test_int_valued_enums_are_int_enums():
    for cls in (sa.StickSlipCase, sa.ArcKind, sa.ArcEnd):
        assert issubclass(cls, enum.IntEnum)
        assert cls.__module__ == "selfalign"
    assert sa.StickSlipCase.slip_slip == 4
    assert sa.StickSlipCase(1) is sa.StickSlipCase.stick_slip_forward
    assert [int(c) for c in sa.StickSlipCase] == [0, 1, 2, 3, 4, 5]
    assert pickle.loads(pickle.dumps(sa.StickSlipCase.slip_slip)) is sa.StickSlipCase.slip_slip
    # Values taken from the int32 case arrays of the sweeps convert back.
    assert sa.StickSlipCase(np.int32(3)) is sa.StickSlipCase.general_stick_slip
    assert sa.describe(np.int32(4)) == sa.describe(sa.StickSlipCase.slip_slip)


def test_string_enums_accept_their_cli_spelling():
    assert sa.SimulationOptions(method="time-stepping").method == sa.Method.time_stepping
    assert sa.Method("exact") == sa.Method.exact
    assert sa.Interpolation("linear") == sa.Interpolation.linear


def test_package_docstring_example_runs():
    import doctest

    failures, tried = doctest.testmod(sa, verbose=False)
    assert tried > 0 and failures == 0


def test_option_reprs_evaluate_back_to_equal_options():
    namespace = vars(sa)
    examples = [
        sa.SimulationOptions(method="time-stepping", duration=3.5, step=2e-4, record=False),
        sa.SteadyStateOptions(max_periods=50, velocity_tol=1e-10),
        sa.ConvergenceOptions(v1=0.25, duration=4.0),
        sa.TimeSteppingOptions(step=1e-3, theta=1.0),
        sa.FloquetOptions(fd_step=1e-6, steady=sa.SteadyStateOptions(max_periods=10)),
        sa.StoppingOptions(max_periods=20, fractions=[0.5, 0.9]),
        sa.PositioningOptions(entries=7, stopping=sa.StoppingOptions(max_periods=30)),
        sa.ThreePhaseParameters(1.0, 0.084, 3.0, 0.9),
        sa.ObjectState(0.5, -0.1, 0.2),
    ]
    for obj in examples:
        again = eval(repr(obj), namespace)
        assert type(again) is type(obj)
        assert repr(again) == repr(obj)


def _stub_function_signatures():
    """name -> set of parameter-name tuples (one per overload) declared in the stub; '*'
    marks the start of keyword-only parameters."""
    tree = ast.parse((PACKAGE_DIR / "_selfalign.pyi").read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            a = node.args
            names = tuple(x.arg for x in a.posonlyargs + a.args)
            if a.kwonlyargs:
                names += ("*",) + tuple(x.arg for x in a.kwonlyargs)
            out.setdefault(node.name, set()).add(names)
    return out


def _built_signatures(name):
    """The parameter names of every overload of a function of the built module, read off the
    signature lines pybind11 writes at the top of its docstring (or, for the functions the
    package wraps in Python, the wrapper's own signature)."""
    fn = getattr(_selfalign, name)
    out = set()
    for line in (fn.__doc__ or "").splitlines():
        m = re.match(r"^(?:\d+\. )?" + re.escape(name) + r"\((.*)\) ->", line)
        if not m:
            continue
        params, depth, current = [], 0, ""
        for ch in m.group(1):
            depth += ch in "([{"
            depth -= ch in ")]}"
            if ch == "," and depth == 0:
                params.append(current.strip())
                current = ""
            else:
                current += ch
        if current.strip():
            params.append(current.strip())
        out.add(tuple(p.split(":")[0].split("=")[0].strip() for p in params))
    return out


def test_stub_signatures_match_the_built_module():
    """Issue 21: the stub is checked signature by signature against the built module (the
    parameter names, their order, keyword-only markers and every overload), not only by name."""
    stub = _stub_function_signatures()
    checked = 0
    for name in sorted(public_names(_selfalign)):
        fn = getattr(_selfalign, name)
        if isinstance(fn, type) or not callable(fn):
            continue
        built = _built_signatures(name)
        assert built, f"{name}: no signature in its docstring"
        wrapper = getattr(sa, name)
        if hasattr(wrapper, "__wrapped__"):
            # A Python wrapper (executor=, chunk_size=) passes **kwargs on to the extension:
            # the stub is the extension's signature with the wrapper's own keywords added.
            # Overloads (positioning_surfaces) take their positional rest as *args there.
            own = [p.name for p in inspect.signature(wrapper, follow_wrapped=False)
                   .parameters.values() if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)]
            for declared in stub[name]:
                assert set(own) <= set(declared), f"{name}: {own} not all in the stub"
            assert {tuple(n for n in d if n not in own) for d in stub[name]} == \
                {tuple(n for n in e if n not in own) for e in built}, \
                f"{name}: {stub[name]} vs {built}"
        else:
            assert built == stub.get(name), f"{name}: built {built} != stub {stub.get(name)}"
        checked += 1
    assert checked > 50
