"""Config files as text: JSON and TOML rendering of (key, value) items, and recipes of big files
(Python expressions of their bytes)."""

import json
import math
import re

from .vocabulary import KIND


class Raw:
    """A literal written as is into a config file."""

    def __init__(self, text):
        self.text = text


def json_value(v):
    if isinstance(v, Raw):
        return v.text
    if isinstance(v, bool) or v is None:
        return json.dumps(v)
    if isinstance(v, float) and not math.isfinite(v):
        return "1e999" if v > 0 else ("-1e999" if v < 0 else "NaN")
    if isinstance(v, (int, float, str)):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(json_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(json.dumps(k) + ": " + json_value(x) for k, x in v.items()) + "}"
    raise TypeError(v)


def toml_value(v):
    if isinstance(v, Raw):
        return v.text
    if isinstance(v, bool):
        return "true" if v else "false"
    if v is None:
        return '""'
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(v)


def typed(flag, text):
    """A flag's text as the config value a user would write."""
    kind = KIND.get(flag)
    try:
        if kind == "list":
            return [float(x) for x in text.split(",")] if text else []
        if kind in ("num", "int"):
            f = float(text)
            return int(f) if f.is_integer() and abs(f) < 2**53 and "." not in text and "e" not in text.lower() else f
    except (ValueError, OverflowError):
        return text
    return text


def toml_key(k):
    if isinstance(k, Raw):
        return k.text
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k)


def render_config(fmt, items):
    if fmt == "json":
        return "{" + ", ".join(json.dumps(k) + ": " + json_value(v) for k, v in items) + "}\n"
    return "".join(f"{toml_key(k)} = {toml_value(v)}\n" for k, v in items)


# Recipes of big files: Python expressions without single quotes (the reproducer wraps them in
# shell single quotes).
def deep_expr(fmt, depth):
    if fmt == "json":
        return f'b"{{\\"width\\": " + b"[" * {depth} + b"1" + b"]" * {depth} + b"}}"'
    return f'b"width = " + b"[" * {depth} + b"1" + b"]" * {depth} + b"\\n"'


def huge_string_expr(fmt, n=300000):
    if fmt == "json":
        return f'b"{{\\"units\\": \\"" + b"x" * {n} + b"\\"}}"'
    return f'b"units = \\"" + b"x" * {n} + b"\\"\\n"'


MANY_ROWS_EXPR = ('b"t,ydd\\n" + b"".join(b"%r,%r\\n" % (i / 2000, (1.0 if i < 1000 else -1.0))'
                  ' for i in range(2000)) + b"1.0,0\\n"')
