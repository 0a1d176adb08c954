"""Parallelogram four-bar (problems/four_bar.py): loop closure against multipliers.

Reference values are derived by hand in the module docstring, independently of dualmech, from
the free-body diagrams of the two pin masses: the equation of motion
``(m1 + m2) r phi'' = -(m1 + m2) g cos(phi) + k r cos(phi) sin(phi)``, the coupler force
``F3 = m1 k r cos(phi)/(m1 + m2)`` and the crank forces
``F1 = m1 (g sin(phi) - r phi'^2) + F3 cos(phi)``,
``F2 = m2 (g sin(phi) - r phi'^2) - F3 cos(phi) + k r cos^2(phi)``.
Tolerances are the linear solve's rounding bound ``64 eps cond(A) max(1, |x|)`` where a model
is evaluated, and the DAE runs' own error measures where a run is.
"""
import numpy as np
import pytest

from dualmech.numeric import NumericModel
from dualmech.numeric.formulations import formulations
from dualmech.problems.four_bar import FourBar

_EPS = np.finfo(float).eps
problem = FourBar()
M1, M2, R, D_, K, G = 1.0, 2.0, 0.5, 1.5, 40.0, 9.81   # the declared defaults


def hand(phi, phid):
    """``(phi'', F1, F2, F3)`` by the module docstring's hand formulas."""
    c, s = np.cos(phi), np.sin(phi)
    phidd = (-(M1 + M2) * G * c + K * R * c * s) / ((M1 + M2) * R)
    F3 = M1 * K * R * c / (M1 + M2)
    F1 = M1 * (G * s - R * phid**2) + F3 * c
    F2 = M2 * (G * s - R * phid**2) - F3 * c + K * R * c**2
    return np.array([phidd, F1, F2, F3])


def _bound(A, x):
    return 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.abs(x).max()))


def test_hand_forces_balance_each_mass():
    # the hand formulas put back into m2's two balances (independent of dualmech)
    phi, phid = -1.2, 1.7
    phidd, F1, F2, F3 = hand(phi, phid)
    iA = np.array([np.cos(phi), np.sin(phi)])
    jA = np.array([-np.sin(phi), np.cos(phi)])
    a = R * (phidd * jA - phid**2 * iA)
    for m, force in ((M1, F1 * iA - F3 * np.array([1, 0]) - M1 * G * np.array([0, 1])),
                     (M2, F2 * iA + F3 * np.array([1, 0]) - M2 * G * np.array([0, 1])
                      - K * R * np.cos(phi) * np.array([1, 0]))):
        assert np.allclose(m * a, force, rtol=0, atol=64 * _EPS * 100)


def test_hanging_at_rest_with_vertical_cranks_nothing_but_gravity_acts():
    # phi = -pi/2, at rest: the spring is unstretched, the coupler idle, each crank carries its
    # mass: F1 = -m1 g, F2 = -m2 g (tension), phi'' = 0
    ref = np.array([0.0, -M1 * G, -M2 * G, 0.0])
    assert np.allclose(hand(-np.pi / 2, 0.0), ref, rtol=0, atol=1e-14)
    ne = problem.model("newton_euler")
    nm = NumericModel(ne, problem.defaults())
    x = nm.solve(0.0, [-np.pi / 2], [0.0])
    order = [u.name for u in ne.unknowns]
    got = np.array([x[0]] + [x[1 + order.index(n)] for n in ("F1", "F2", "F3")])
    assert np.allclose(got, ref, rtol=0, atol=_bound(nm.system(0.0, [-np.pi / 2], [0.0])[0],
                                                      ref))


@pytest.mark.parametrize("phi, phid", [(-1.2, 1.7), (-0.4, -6.0), (-2.8, 0.3)])
def test_both_forms_give_the_hand_acceleration_and_bar_forces(phi, phid):
    ref = hand(phi, phid)
    ne = problem.model("newton_euler")
    nm = NumericModel(ne, problem.defaults())
    A, _ = nm.system(0.0, [phi], [phid])
    x = nm.solve(0.0, [phi], [phid])
    order = [u.name for u in ne.unknowns]
    got = np.array([x[0]] + [x[1 + order.index(n)] for n in ("F1", "F2", "F3")])
    assert np.abs(got - ref).max() <= _bound(A, ref)
    # maximal coordinates at the same state: the multipliers are the same bar forces
    mult = problem.model("multiplier")
    c, s = np.cos(phi), np.sin(phi)
    q = [R * c, R * s, D_ + R * c, R * s]
    qd = [-R * s * phid, R * c * phid, -R * s * phid, R * c * phid]
    mm = NumericModel(mult, problem.defaults())
    A2, _ = mm.system(0.0, q, qd)
    x2 = mm.solve(0.0, q, qd)
    order2 = [u.name for u in mult.unknowns]
    got2 = np.array([x2[4 + order2.index(n)] for n in ("F1", "F2", "F3")])
    tol2 = _bound(A2, x2)
    assert np.abs(got2 - ref[1:]).max() <= tol2
    # and the pins' accelerations are the crank's: a = r (phi'' j_A - phi'^2 i_A)
    aA = R * (ref[0] * np.array([-s, c]) - phid**2 * np.array([c, s]))
    assert np.abs(x2[:2] - aA).max() <= tol2 and np.abs(x2[2:4] - aA).max() <= tol2


@pytest.fixture(scope="module")
def forms():
    fs, skipped = formulations(problem, y0=[-1.0, 0.0], models=["lagrange", "multiplier"],
                               stabilisations=("projection", "index3", "ggl"))
    assert skipped == {}
    return {f.name: f for f in fs}


@pytest.mark.parametrize("name, method", [("multiplier (DAE, projection)", "DOP853"),
                                          ("multiplier (DAE, GGL index 2)", "IDA"),
                                          ("multiplier (DAE, index 3)", "IDA")])
def test_dae_forms_stay_on_the_loop_and_carry_the_hand_forces(forms, name, method):
    te = np.linspace(0.0, 2.0, 41)
    f = forms[name]
    run = f.run(method, (0.0, 2.0), te, rtol=1e-8)
    assert run.success, run.message
    g, gd = f.drift(run.y)
    if "projection" in name:   # Gauss-Newton to 1e-13 of the configuration's size
        assert np.abs(g).max() <= 1e-12 and np.abs(gd).max() <= 1e-12
    else:   # IDA holds g = 0 at its steps; a sample comes from its interpolant, off by about
        # the positions' error weight rtol * scale (|grad g| = 1): 10 of those at most
        assert np.abs(g).max() <= 10 * 1e-8 * f.scales[:4].max()
    # the bar forces along the run are the hand forces at the run's own crank angle: the
    # index-1 system at a state off the loop by |g| moves them by O(|g|) times the forces'
    # gradients (k r, m g: below 1e3 here)
    R_ = f.reactions(te, run.y)
    phi = np.arctan2(run.y[1], run.y[0])
    phid = (run.y[0] * run.y[5] - run.y[1] * run.y[4]) / (run.y[0]**2 + run.y[1]**2)
    drift = max(np.abs(g).max(), np.abs(gd).max(), 1e-15)
    for i in range(0, te.size, 10):
        ref = hand(phi[i], phid[i])
        for j, n in enumerate(("F1", "F2", "F3")):
            assert abs(R_[n][i] - ref[1 + j]) <= 1e3 * drift + 1e-10
