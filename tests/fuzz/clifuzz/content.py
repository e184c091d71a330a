"""Checks of an output's content: JSON with no NaN / Infinity and null only where documented
(contract.NULLABLE), CSV numbers finite except where documented (contract.ALLOWED_NONFINITE_CSV)."""

import json
import math

from .contract import (ALLOWED_NONFINITE_CSV, F_OVERFLOW_VBAR, GRID_COLUMNS, NULLABLE,
                       TEXT_CSV_COLUMNS)


NOTES = []  # documented but noteworthy outcomes (failed sweep cells), printed in the summary


class NonFinite(Exception):
    pass


def _reject_constant(token):
    raise NonFinite(token)


def _float(token):
    v = float(token)
    if not math.isfinite(v):
        raise NonFinite(token)
    return v


def check_json(sub, where, text):
    try:
        doc = json.loads(text, parse_constant=_reject_constant, parse_float=_float)
    except NonFinite as e:
        return [("nonfinite-json", f"{where}: {e}")]
    except ValueError as e:
        return [("json-invalid", f"{where}: {str(e)[:100]}; starts {text[:60]!r}")]
    nulls = []
    collect_nulls(doc, "", nulls)
    allowed = NULLABLE.get(sub, set())
    bad = [k for k in nulls if k not in allowed]
    f = []
    if bad:
        f.append(("null-undocumented", f"{where}: null at {', '.join(sorted(set(bad))[:5])}"))
    if sub == "steady" and isinstance(doc, dict) and doc.get("case") not in (0, None):
        physical_nulls = [k for k in ("v_bar", "x_dot_0s", "phase", "displacement", "converged",
                                      "periods", "method") if k in nulls]
        if doc.get("profile") == "three-phase":
            physical_nulls += [k for k in ("t1", "t2", "t3", "y_ini", "y_dot_ini", "a2", "a3")
                               if k in nulls]
            # case_a_priori: the Fig. 8 rules, null under a law other than the paper's
            # (docs/cli.md "steady": --mu-static, --mu-backward) or with a jerk limit.
            law = doc.get("law") or {}
            paper_law = (law.get("static") == 1 and law.get("kinetic_forward") == 1
                         and law.get("kinetic_backward") == 1 and law.get("viscous") is None
                         and law.get("stribeck_velocity") is None)
            if paper_law and doc.get("jerk") is None and "case_a_priori" in nulls:
                physical_nulls.append("case_a_priori")
        if "f" in nulls and doc.get("v_bar") not in (0, 0.0):
            physical_nulls.append("f")
        if physical_nulls:
            f.append(("null-undocumented",
                      f"{where}: case {doc.get('case')} with null {', '.join(physical_nulls)} "
                      "(docs/cli.md: null only for case 0 / f infinite)"))
    if sub == "floquet" and isinstance(doc, dict):
        # docs/cli.md "floquet": matrix and multipliers "null where available is false"
        for m in ("analytic", "saltation", "finite_difference"):
            part = doc.get(m)
            if isinstance(part, dict) and part.get("available") is True:
                inner = []
                collect_nulls({k: part.get(k) for k in ("matrix", "multipliers")}, m, inner)
                if inner:
                    f.append(("null-undocumented", f"{where}: {m} available with null in {inner[0]}"))
    if sub == "simulate" and isinstance(doc, dict) and "stick_fraction" in nulls \
            and doc.get("trajectory_file") is not None:
        f.append(("null-undocumented", f"{where}: stick_fraction null although a trajectory is written"))
    if sub == "accumulation" and isinstance(doc, dict) and "accumulates_for_every_entry" in nulls \
            and doc.get("accumulation_condition_reason") is None:
        f.append(("null-undocumented", f"{where}: accumulates_for_every_entry null without a reason"))
    if sub == "optimize" and isinstance(doc, dict):
        # An infeasible result has no profile, hence no f or v_bar: null there is the
        # "expected outcome as a value" of docs/cli.md ("an infeasible result names its binding
        # limit"); a feasible result must carry both.
        for r in doc.get("results") or []:
            if isinstance(r, dict):
                nulls_here = [k for k in ("f", "v_bar") if k in r and r[k] is None]
                if nulls_here and r.get("feasible") is not False:
                    f.append(("null-undocumented", f"{where}: feasible result with null {nulls_here}"))
    if sub == "accuracy" and isinstance(doc, dict) and doc.get("reaches") is True:
        bad = [k for k in ("case", "case_name", "v_bar", "x_dot_0s", "f", "x_mu") if k in nulls]
        if bad:
            f.append(("null-undocumented", f"{where}: reaches with null {', '.join(bad)}"))
    return f


def collect_nulls(node, path, out):
    if node is None:
        out.append(path)
    elif isinstance(node, dict):
        for k, v in node.items():
            collect_nulls(v, f"{path}.{k}" if path else k, out)
    elif isinstance(node, list):
        for v in node:
            collect_nulls(v, path, out)


def check_csv(sub, where, text):
    lines = [ln for ln in text.split("\n") if ln != ""]
    if not lines:
        return [("csv-malformed", f"{where}: empty")]
    header = lines[0]
    cols = header.split(",")
    rules = ALLOWED_NONFINITE_CSV.get(sub, {})
    f = []
    for n, line in enumerate(lines[1:], start=2):
        cells = line.split(",")
        if len(cells) != len(cols):
            f.append(("csv-malformed", f"{where} line {n}: {len(cells)} cells for {len(cols)} columns"))
            break
        row = dict(zip(cols, cells))
        for col, cell in row.items():
            if col in TEXT_CSV_COLUMNS:
                continue
            try:
                v = float(cell)
            except ValueError:
                f.append(("csv-malformed", f"{where} line {n}: {col} = {cell[:30]!r}"))
                return f
            if math.isfinite(v):
                continue
            if row.get("status") == "failed" and col not in GRID_COLUMNS:
                if NOTES is not None:
                    NOTES.append(f"{sub}: a cell with status failed ({where} line {n})")
                continue
            if not nonfinite_allowed(rules.get(col), cell, row):
                f.append(("nonfinite-csv", f"{where} line {n}: {col} = {cell} ({header[:60]})"))
                return f
    return f


def _num(row, col):
    try:
        return float(row.get(col, "nan"))
    except ValueError:
        return math.nan


def nonfinite_allowed(rule, cell, row):
    isnan = cell.lower() in ("nan", "-nan")
    if rule is None:
        return False
    if rule == "any":
        return True
    if rule == "nan-if-case0":
        return isnan and _num(row, "case") == 0
    if rule == "nan-if-case0-inf-if-vbar0":
        return (isnan and _num(row, "case") == 0) or (cell == "inf" and abs(_num(row, "v_bar")) < F_OVERFLOW_VBAR)
    if rule == "nan-if-nonphysical":
        return isnan and _num(row, "physical") == 0
    if rule == "nan-if-nonphysical-inf-if-vbar0":
        return (isnan and _num(row, "physical") == 0) or (cell == "inf" and abs(_num(row, "v_bar")) < F_OVERFLOW_VBAR)
    if rule == "nan-if-case0-or-inf":
        return (isnan and _num(row, "case") == 0) or cell == "inf"
    if rule == "nan-if-not-stopped":
        return isnan and row.get("stop") == "not-stopped"
    return False
