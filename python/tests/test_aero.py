"""``pg.aero``: scattered points solved as the polars of their conditions — each point equal,
bit for bit, to the same α of ``pg.polar`` over that condition's α values — in the broadcast
shape and order of the inputs, with every per-point field of a polar; bad inputs stop before
any solve with the CLI's messages."""

from __future__ import annotations

import numpy as np
import polargen as pg
import pytest

from conftest import same


def test_each_point_is_the_polar_of_its_condition_in_input_order():
    alphas = [6.0, -2.0, 0.0, 3.0, 1.0, 2.0, 4.0, 5.0, -1.0, 3.0]
    r = pg.aero("naca0012", alpha=alphas, re=1e6)
    pol = pg.polar("naca0012", re=1e6, alpha=sorted(set(alphas)))
    row = {a: i for i, a in enumerate(pol.alpha)}
    at = [row[a] for a in alphas]
    assert r.shape == (len(alphas),)
    assert set(pol.columns()) <= set(r), "every per-point field of a polar"
    for name, column in pol.columns().items():
        assert same(r[name], np.asarray(column)[at]) if column.dtype.kind == "f" \
            else list(r[name]) == list(np.asarray(column)[at]), name
    assert same(r.re, np.full(len(alphas), 1e6)) and same(r.mach, np.zeros(len(alphas)))


def test_inputs_broadcast_and_conditions_are_polars():
    alpha = np.array([0.0, 2.0, 4.0])
    re = np.array([[5e5], [2e6]])
    r = pg.aero("naca2412", alpha=alpha, re=re, mach=0.2, xtr=(0.1, 1.0))
    assert r.cl.shape == (2, 3) and r.alpha.shape == (2, 3)
    for i, reynolds in enumerate(re[:, 0]):
        pol = pg.polar("naca2412", re=reynolds, mach=0.2, alpha=alpha, xtr=(0.1, 1.0))
        assert same(r.cl[i], pol.cl) and same(r.cd[i], pol.cd), reynolds
        assert list(r.converged[i]) == list(pol.converged)
    # a trip array: each value its own condition
    t = pg.aero("naca2412", alpha=2.0, re=1e6, xtr=[1.0, 0.05])
    assert t.xtr_top[1] == pytest.approx(0.05, abs=1e-5) and t.xtr_top[0] > 0.1
    assert t.cd[1] > t.cd[0]
    frame = r.to_pandas()
    assert len(frame) == 6 and {"alpha", "re", "mach", "cl", "cd", "converged"} <= set(frame)


def test_progress_reports_the_points_to_solve():
    """A repeated point is solved once: 2 points to solve for 3 asked."""
    seen = []
    pg.aero("naca0012", alpha=[0.0, 0.0, 2.0], re=[1e6, 1e6, 2e6],
            progress=lambda done, total: seen.append((done, total)))
    assert seen and seen[-1] == (2, 2), seen


@pytest.mark.parametrize("call, error, text", [
    (lambda: pg.aero("naca0012", alpha=[0, 1, 2], re=[1e6, 2e6]), ValueError,
     "do not broadcast together: alpha (3,), re (2,)"),
    (lambda: pg.aero("naca0012", alpha=0.0, re=-1.0), ValueError, "re -1:"),
    (lambda: pg.aero("naca0012", alpha=0.0, re=1e6, mach=1.2), ValueError, "mach 1.2"),
    (lambda: pg.aero("naca0012", alpha=[0.0, np.nan], re=1e6), ValueError, "alpha"),
    (lambda: pg.aero("naca0012", alpha=0.0, re=1e6, xtr=[0.5, 1.5]), ValueError, "xtr 1.5"),
    (lambda: pg.aero("naca0012", alpha="0:4:1", re=1e6), TypeError, "alpha: expected numbers"),
])
def test_bad_inputs_raise_before_solving(call, error, text):
    with pytest.raises(error) as caught:
        call()
    assert text in str(caught.value), str(caught.value)
