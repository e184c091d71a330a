"""Python mirrors C++ (issue 21 item 7): every class of the extension is a type of the C++
library under the same name (no Python-only names, no second name for one type), and every
function is a C++ function of the same name, except the few listed here with the reason.
The second method is the library's headers themselves, read as text."""

import inspect
import pathlib
import re

import selfalign._selfalign as ext

HEADERS = pathlib.Path(__file__).resolve().parents[2] / "include" / "selfalign"
# Python functions without a C++ function of that name, and why.
PYTHON_ONLY_FUNCTIONS = {
    # the exact solver's arcs as NumPy columns: C++ passes an arc observer to advance_exact
    "exact_arcs",
}


def _source():
    return "\n".join(p.read_text() for p in HEADERS.rglob("*.hpp"))


def test_every_class_is_a_cpp_type_of_the_same_name():
    src = _source()
    types = set(re.findall(r"\b(?:struct|class|enum class|using)\s+(\w+)", src))
    for name, obj in vars(ext).items():
        if name.startswith("_") or not inspect.isclass(obj):
            continue
        assert obj.__name__ == name, f"{name} is a second name of {obj.__name__}"
        assert name in types, f"{name} is not a type of the C++ library"


def test_every_function_is_a_cpp_function_of_the_same_name():
    src = _source()
    for name, obj in vars(ext).items():
        if name.startswith("_") or inspect.isclass(obj) or not callable(obj):
            continue
        if name in PYTHON_ONLY_FUNCTIONS:
            continue
        assert re.search(r"\b" + re.escape(name) + r"\s*\(", src), \
            f"{name} is not a function of the C++ library"
