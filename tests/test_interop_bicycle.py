"""sympy's own Whipple bicycle through the sympy bridge, checked against ours.

sympy's model is the one of its test suite (``sympy/physics/mechanics/tests/test_kane3.py``,
sympy 1.14.0, copied into ``tests/_sympy_bicycle.py``): Kane's method, four coordinates (yaw
``q1``, roll ``q2``, pitch ``q4``, steer ``q5``; the rear contact's position and the wheel
angles left out), six speeds (``u3``, ``u6`` the wheels' spin rates), the pitch dependent through
the front contact's height, three dependent speeds through the front contact's velocity.
Ours is ``problems/whipple_bicycle.py`` (eight coordinates).  Same axes (x forward, y left, z
up); sympy's steer turns about the steer axis pointing down, ours about it pointing up, so
``q5 = -delta``; ``u3 = thetaR'``, ``u6 = thetaF'`` (see the helper's docstring).

Independent references: the two models were written separately (sympy's by Moore from
Autolev, ours by hand); the state matrix sympy's test precomputes (``Res``, 15 digits) is its
linearisation, compared entry by entry with ours.
"""
from __future__ import annotations

import inspect
import random

import mpmath
import pytest
import sympy as sp

from dualmech.model.equations import ModelError
from dualmech.problems import get
from dualmech.verify.interop import from_mechanics

from _sympy_bicycle import SYMPY_TEST_A, SYMPY_TEST_VALUES, benchmark_values, sympy_bicycle

BICYCLE = "whipple_bicycle"


@pytest.fixture(scope="module")
def ours():
    problem = get(BICYCLE)
    return problem, inspect.getmodule(type(problem))


@pytest.fixture(scope="module")
def bridged(ours):
    problem, W = ours
    km, _ = sympy_bicycle()
    return from_mechanics(km, problem, name="sympy_kane",
                          coordinates={"q1": W.psi, "q2": W.phi, "q4": W.theta,
                                       "q5": -W.delta},
                          ignorable={"u3": W.thetaR, "u6": W.thetaF},
                          symbols=benchmark_values(W))


def test_the_exact_geometry_is_the_tests_own_to_its_digits(ours):
    """benchmark_values rewrites the test's formulas (exact tilt, acos expanded): the lengths
    must be the test's 15-digit floats to their precision."""
    _, W = ours
    exact = benchmark_values(W)
    lengths = ["WFrad", "WRrad", "htangle", "forkoffset", "forklength", "framelength",
               "forkcg1", "forkcg3", "framecg1", "framecg3"]
    for name in lengths:
        assert abs(float(sp.N(exact[name] - SYMPY_TEST_VALUES[name], 30))) < 2e-15, name
    # the inertias and masses: our defaults are the test's numbers (products with sign flip)
    defaults = get(BICYCLE).defaults()
    for name, value in exact.items():
        if name not in lengths:
            assert float(value.xreplace(defaults)) == pytest.approx(
                float(SYMPY_TEST_VALUES[name]), abs=1e-15), name


@pytest.mark.slow
def test_sympys_bicycle_is_accepted_with_its_constraints_at_their_level(bridged, ours):
    _, W = ours
    assert set(bridged.coordinates) == {W.psi, W.phi, W.theta, W.delta, W.thetaR, W.thetaF}
    assert bridged.is_square and len(bridged.equations) == 6
    levels = {c.name: (c.level, c.label) for c in bridged.constraints}
    # the front contact's height takes the row of the velocity constraint its rate replaces
    # (sympy's third, the contact's vertical velocity, paired with u6): the verdict draws its
    # points on the height and the two rolling conditions
    assert levels == {"u1": ("velocity", "constraint u1 (acceleration level)"),
                      "u4": ("velocity", "constraint u4 (acceleration level)"),
                      "configuration q4": ("position", "constraint u6 (acceleration level)")}
    assert set(bridged.labels[3:]) == {c.label for c in bridged.constraints}
    # the configuration constraint is the front contact's height, ours up to sign and
    # normalisation: both vanish at the same pitch (upright: zero)
    g = next(c.expression for c in bridged.constraints if c.level == "position")
    upright = {q: 0 for q in bridged.coordinates}
    assert abs(sp.N(g.xreplace(upright), 40)) < 1e-35
    assert abs(sp.N(g.xreplace({**upright, W.theta: sp.Rational(1, 100)}), 40)) > 1e-3


def _real(x) -> mpmath.mpf:
    """A number symengine evaluated (a complex one with no imaginary part, from a square root
    of sympy's contact-point normalisation, taken as real)."""
    x = x.n(220)
    if not x.is_real:
        assert abs(mpmath.mpf(str(x.imaginary_part()))) < mpmath.mpf(10) ** -50, x
        x = x.real_part()
    return mpmath.mpf(str(x))


def _solve_rows(eqs, point, values) -> dict:
    """``eqs`` (rows in sympy form, as the bridge gives them) solved for its accelerations at
    ``point`` (plain state symbols, symengine) and parameter ``values``, at 220 bits."""
    import symengine as se
    from dualmech.model.equations import state_symbols
    subs = {k: se.RealMPFR(str(v), 220) for k, v in point.items()}
    subs.update({se.Symbol(s.name): se.RealMPFR(str(v), 220) for s, v in values.items()})
    acc = [se.Symbol(state_symbols(q).qdd.name) for q in eqs.coordinates]
    M = mpmath.matrix(len(eqs.equations), len(acc))
    r = mpmath.matrix(len(eqs.equations), 1)
    for i, row in enumerate(eqs.equations):
        row = se.sympify(eqs.to_plain(row)).subs(subs)
        for j, a in enumerate(acc):
            M[i, j] = _real(row.diff(a))
        r[i] = -_real(row.subs({a: 0 for a in acc}))
    return dict(zip([f"{q.func.__name__}''" for q in eqs.coordinates], mpmath.lu_solve(M, r)))


@pytest.mark.slow
def test_sympys_nonlinear_bicycle_has_our_accelerations_on_the_constraints(bridged, ours):
    """At random states on the constraints (pitch from the front contact, dependent rates
    from the rolling conditions; 60 digits) the six accelerations sympy's model determines are
    ours, to 40 digits; a wrong term would show in the first few."""
    from test_whipple_bicycle import _manifold_state, _solve
    problem, W = ours
    rng = random.Random(11)
    for _ in range(2):
        point = _manifold_state(W, rng)
        values = {s: v * (1 + rng.uniform(-0.2, 0.2)) for s, v in problem.defaults().items()}
        lag = _solve(problem.model("lagrange"), point, values)
        theirs = _solve_rows(bridged, point, values)
        assert set(theirs) == {"psi''", "phi''", "theta''", "delta''", "thetaR''", "thetaF''"}
        scale = max(abs(lag[k]) for k in theirs)
        worst = max(abs(lag[k] - theirs[k]) for k in theirs)
        print(f"sympy's bicycle vs ours: {mpmath.nstr(worst / scale, 3)} relative")
        assert worst < mpmath.mpf(10) ** -40 * scale, (worst, scale)
    # the same comparison sees a slip: the frame's product of inertia not sign-flipped
    km, _ = sympy_bicycle()
    slipped = from_mechanics(km, problem, name="slipped",
                             coordinates={"q1": W.psi, "q2": W.phi, "q4": W.theta,
                                          "q5": -W.delta},
                             ignorable={"u3": W.thetaR, "u6": W.thetaF},
                             symbols={**benchmark_values(W), "Iframe31": W.IBxz})
    bad = _solve_rows(slipped, point, values)
    assert max(abs(lag[k] - bad[k]) for k in bad) > mpmath.mpf(10) ** -4 * scale


@pytest.mark.slow
@pytest.mark.parametrize("speed", [0, 1, 3, 5])
def test_our_state_matrix_is_sympys_entry_by_entry(ours, speed):
    """Our linearisation about upright straight running, read in sympy's state (roll, steer,
    their rates; steer of the opposite sign), is the matrix sympy's test precomputes, every
    entry to its eps (1e-12): the lower rows are -M^-1 (g K0 + v^2 K2) and -M^-1 v C1 of the
    benchmark, so M^-1 K0, M^-1 K2 and M^-1 C1 are checked, not only the eigenvalues.

    Our reduced state keeps its own independent speeds (a rate absent from it, such as the
    steer rate, is the linear function of the state its coordinate's row gives); the yaw and
    the forward speed must not enter the rows kept."""
    import numpy as np
    from dualmech.verify.stability_claims import _Spectra
    problem, _ = ours
    lin = _Spectra(problem).lin
    A = np.array(lin.at(speed).evalf(30).tolist(), dtype=float)
    states = list(lin.states)
    idle = [states.index(s) for s in ("psi", "x'")]
    kept = [i for i in range(len(states)) if i not in idle]
    assert np.max(np.abs(A[np.ix_(kept, idle)])) < 1e-30
    rows = []                                   # sympy's state as a function of ours
    for name in ("phi", "delta", "phi'", "delta'"):
        if name in states:
            rows.append(np.eye(len(states))[states.index(name)])
        else:                                   # a rate: its coordinate's row of A
            rows.append(A[states.index(name[:-1])])
    S = np.array(rows)[:, kept]
    assert abs(np.linalg.det(S)) > 1e-3
    A_s = S @ A[np.ix_(kept, kept)] @ np.linalg.inv(S)
    sign = np.diag([1.0, -1.0, 1.0, -1.0])                   # q5 = -delta
    theirs = sign @ np.array(SYMPY_TEST_A(speed)) @ sign
    assert np.max(np.abs(A_s - theirs)) < 1e-12, A_s - theirs
