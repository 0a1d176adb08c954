"""Symmetric top (problems/symmetric_top.py): steady precession, conserved momenta, gimbal lock."""
import numpy as np
import pytest
import sympy as sp

from dualmech import t
from dualmech.model.equations import state_symbols
from dualmech.numeric import NumericModel, simulate
from dualmech.problems.symmetric_top import (A, C, M, SymmetricTop, frames, g, h, momenta, phi, psi,
                                    steady_precession_rates, theta)

problem = SymmetricTop()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731
W3 = D(psi) + D(phi) * sp.cos(theta)
_EPS = np.finfo(float).eps


def _zero(expr) -> bool:
    return sp.simplify(sp.expand(expr)) == 0


def _plain(expr, x):
    """``expr`` with ``psi'`` as the plain symbol ``x`` (sympy takes no limits in derivatives)."""
    return expr.subs(D(psi), x)


def test_nutation_frame_rates_and_mass_centre_by_hand():
    f = frames()
    w = f.b.ang_vel_in(f.O).express(f.F2).components
    hand = [-D(phi) * sp.sin(theta), D(theta), W3]
    assert all(_zero(a - b) for a, b in zip(w, hand))
    assert all(_zero(a - b) for a, b in zip(f.G.pos_from(f.o).express(f.F2).components,
                                             [0, 0, h]))


def test_gimbal_lock_upright_is_the_declared_singular_set():
    det = problem.model("lagrange").mass_matrix().det()
    assert _zero(det - A**2 * C * sp.sin(theta)**2)
    assert problem.singular == (sp.sin(theta),)


def test_body_axes_spin_equation_is_eulers_third_with_A_equal_B():
    # C w3' - (A - B) w1 w2 = Q3 with A = B and no moment of the weight about z
    assert _zero(problem.model("body_axes").equations[2] + C * D(W3))


@pytest.mark.parametrize("model", ["lagrange", "newton_euler"])
def test_steady_precession_rates_solve_the_hand_quadratic(model):
    # theta'' = theta' = 0: (C - A) cos(theta) phi'^2 + C psi' phi' - M g h = 0 (module doc)
    rates = steady_precession_rates(problem.model(model))
    assert len(rates) == 2
    for r in rates:
        assert _zero((C - A) * sp.cos(theta) * r**2 + C * D(psi) * r - M * g * h)


@pytest.mark.slow
def test_fast_top_precesses_at_the_sources_rate():
    # source, "high spin rate ... Precession": phi' = M g h / (C psi') as psi' -> oo
    x = sp.Symbol("x", positive=True)
    rates = [_plain(r, x) for r in steady_precession_rates(problem.model("lagrange"))]
    slow = [r for r in rates if sp.limit(r, x, sp.oo) == 0]
    assert len(slow) == 1
    assert _zero(sp.limit(slow[0] / (M * g * h / (C * x)), x, sp.oo) - 1)


def test_weightless_top_gives_the_sources_nutation_line():
    # source, "Nutation": A cos(theta) phi' - C (psi' + phi' cos(theta)) = 0 with gravity neglected
    rates = steady_precession_rates(problem.model("lagrange"), {g: 0})
    moving = [r for r in rates if r != 0]
    assert len(rates) == 2 and len(moving) == 1
    assert _zero(A * sp.cos(theta) * moving[0] - C * (D(psi) + moving[0] * sp.cos(theta)))


def _theta_wander(rate_factor: float) -> float:
    """Largest |theta - theta0| over 1.5 s started on the library's slow steady precession."""
    values = problem.defaults()
    th0, spin = 0.6, 50.0
    slow = min(steady_precession_rates(problem.model("lagrange")),
               key=lambda r: abs(float(r.subs(values).subs({theta: th0, D(psi): spin}))))
    rate = float(slow.subs(values).subs({theta: th0, D(psi): spin}))
    traj = simulate(problem, t_span=(0.0, 1.5), y0=[0.0, th0, 0.0, rate * rate_factor, 0.0,
                                                    spin], rtol=1e-11, atol=1e-13)
    return float(np.max(np.abs(traj.q[1] - th0)))


def test_simulated_top_stays_on_the_library_steady_precession():
    # started on the computed rate, theta must wander less than a start one part in a
    # million off it does: the rate is right to better than 1e-6 of itself
    assert _theta_wander(1.0) < _theta_wander(1.0 + 1e-6)


def test_ignorable_angles_by_the_sources_rule():
    # section 3.1: Q = 0, dV/dq = 0 and dT/dq = 0 for phi and psi, not for theta
    w1 = D(theta) * sp.sin(psi) - D(phi) * sp.sin(theta) * sp.cos(psi)
    w2 = D(theta) * sp.cos(psi) + D(phi) * sp.sin(theta) * sp.sin(psi)
    T = (A * (w1**2 + w2**2) + C * W3**2) / 2
    V = M * g * h * sp.cos(theta)
    for q in (phi, psi):
        assert _zero(T.diff(q)) and V.diff(q) == 0
    assert not _zero(T.diff(theta) - V.diff(theta))
    p_phi, p_psi = momenta()
    assert _zero(T.diff(D(phi)) - p_phi) and _zero(T.diff(D(psi)) - p_psi)


@pytest.mark.parametrize("state", [(0.3, 0.7, -1.1, 0.9, -0.4, 25.0),
                                   (-2.0, 2.3, 0.8, -1.7, 1.3, -8.0)])
def test_momenta_are_conserved_on_the_direct_models_motion(state):
    # d/dt p = (dp/dq) q' + (dp/dq') q'' with q'' from the free-body diagram (not from T)
    *q, = state[:3]
    qd = state[3:]
    nm = NumericModel(problem.model("newton_euler"), problem.defaults())
    A_, b_ = nm.system(0.0, q, qd)
    qdd = np.linalg.solve(A_, b_)
    coords = (phi, theta, psi)
    point = {}
    for c, v, vd, vdd in zip(coords, q, qd, qdd):
        s = state_symbols(c)
        point.update({s.q: v, s.qd: vd, s.qdd: vdd})
    values = {k: v for k, v in problem.defaults().items()}
    for p in momenta():
        rate = problem.model("lagrange").to_plain(D(p))
        terms = [float(term.subs(values).subs(point)) for term in sp.Add.make_args(sp.expand(rate))]
        scale = max(1.0, max(abs(x) for x in terms))
        assert abs(sum(terms)) <= 16 * _EPS * np.linalg.cond(A_) * scale * len(terms)
