"""The paper-reproduction job: every figure and the report are written, and the claims table
is computed (breaking the code behind a claim turns its row to FAIL)."""

import os

import pytest

import selfalign as sa
from selfalign import claims, figures, reproduce


def test_reproduce_writes_every_figure_and_the_report(tmp_path):
    table = reproduce.run(str(tmp_path), quiet=True)
    for fn in figures.ALL:
        number = fn.__name__[3:]
        for ext in ("png", "svg", "csv"):
            path = tmp_path / f"fig{int(number):02d}.{ext}"
            assert path.exists() and path.stat().st_size > 0, path
    for name in ("report.md", "index.html"):
        text = (tmp_path / name).read_text(encoding="utf-8")
        for c in table:
            assert c.name in text
    assert not list(tmp_path.glob("*.tmp"))
    # Every claim of the paper holds.
    statuses = {c.name: c.status for c in table}
    assert all(s == "PASS" for s in statuses.values()), statuses


def test_breaking_the_floquet_code_turns_its_claim_to_fail(monkeypatch):
    assert claims.slip_slip_lambda2().status == "PASS"
    real = sa.floquet_multipliers

    class Broken:  # a Floquet analysis whose saltation multiplier is off by 1e-6
        def __init__(self, profile):
            self._r = real(profile)

        def __getattr__(self, name):
            return getattr(self._r, name)

        @property
        def saltation(self):
            return sa.make_monodromy(self._r.saltation.matrix + [[0, 0], [0, 1e-6]])

    monkeypatch.setattr(claims.sa, "floquet_multipliers", lambda p, *a: Broken(p))
    assert claims.slip_slip_lambda2().status == "FAIL"


def test_breaking_the_stick_map_turns_its_claim_to_fail(monkeypatch):
    class ShiftedMap(sa.StickPositionMap):
        def fixed_point(self):
            return super().fixed_point() + 1e-9

    monkeypatch.setattr(claims.sa, "StickPositionMap", ShiftedMap)
    assert claims.fixed_point_is_stick_min().status == "FAIL"
