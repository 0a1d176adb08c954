"""Slider-crank linkage (problems/slider_crank.py): loop closure against multipliers.

Reference values are derived by hand in the module docstring, independently of dualmech:
``x_B = r cos(phi) + s``, ``s = sqrt(L^2 - r^2 sin^2 phi)``, its derivatives ``J1``, ``J2``
(differentiated by hand and checked here against central differences), the equation of motion
``(m1 r^2 + m2 J1^2) phi'' + m2 J1 J2 phi'^2 + m1 g r cos(phi) = 0`` and the forces from the
free-body diagrams: ``F = m2 x_B''/e_I`` (rod), ``N = m2 g - F e_J`` (guide), and the crank
force from m1's balance along ``i_A``: ``F_C = -m1 r phi'^2 + F (e . i_A) + m1 g sin(phi)``.
Tolerances are the linear solve's rounding bound ``64 eps cond(A) max(1, |x|)``.
"""
import numpy as np
import pytest

from dualmech.compare import compare
from dualmech.numeric import NumericModel
from dualmech.numeric.formulations import formulations
from dualmech.problems.slider_crank import SliderCrank

_EPS = np.finfo(float).eps
problem = SliderCrank()
M1, M2, R, L, G = 1.0, 2.0, 0.5, 1.2, 9.81   # the declared defaults


def hand(phi, phid):
    """``(phi'', F, N, F_C)`` by the module docstring's hand formulas."""
    s = np.sqrt(L**2 - R**2 * np.sin(phi)**2)
    J1 = -R * np.sin(phi) - R**2 * np.sin(phi) * np.cos(phi) / s
    J2 = -R * np.cos(phi) - R**2 * np.cos(2 * phi) / s \
        - R**4 * np.sin(phi)**2 * np.cos(phi)**2 / s**3
    phidd = -(M2 * J1 * J2 * phid**2 + M1 * G * R * np.cos(phi)) / (M1 * R**2 + M2 * J1**2)
    xdd = J1 * phidd + J2 * phid**2
    e = np.array([s, -R * np.sin(phi)]) / L
    F = M2 * xdd / e[0]
    N = M2 * G - F * e[1]
    iA = np.array([np.cos(phi), np.sin(phi)])
    F_C = -M1 * R * phid**2 + F * (e @ iA) + M1 * G * np.sin(phi)
    return phidd, F, N, F_C


def _bound(A, x):
    return 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.abs(x).max()))


def test_declaration_validates_and_both_forms_agree_exactly():
    problem.validate()
    c = compare(problem)
    assert c.equivalent, str(c)
    assert problem.dimension_issues() == []


def test_hand_derivatives_of_the_loop_closure():
    # J1, J2 against central differences of x_B (error ~ h^2 |x_B'''| + eps |x_B|/h)
    xB = lambda p: R * np.cos(p) + np.sqrt(L**2 - R**2 * np.sin(p)**2)  # noqa: E731
    for p in (0.3, 1.1, 2.5):
        h = 1e-4
        s = np.sqrt(L**2 - R**2 * np.sin(p)**2)
        J1 = -R * np.sin(p) - R**2 * np.sin(p) * np.cos(p) / s
        J2 = -R * np.cos(p) - R**2 * np.cos(2 * p) / s - R**4 * np.sin(p)**2 * np.cos(p)**2 / s**3
        assert abs((xB(p + h) - xB(p - h)) / (2 * h) - J1) <= 1e-7
        assert abs((xB(p + h) - 2 * xB(p) + xB(p - h)) / h**2 - J2) <= 1e-6


def test_at_rest_on_the_guide_the_pin_falls_freely_and_the_guide_carries_the_slider():
    # phi = 0 at rest: J1 = 0, so phi'' = -g/r, no rod or crank force, N = m2 g (by hand)
    assert hand(0.0, 0.0) == pytest.approx((-G / R, 0.0, M2 * G, 0.0), abs=1e-12)
    nm = NumericModel(problem.model("newton_euler"), problem.defaults())
    x = nm.solve(0.0, [0.0], [0.0])
    names = [u.name for u in problem.model("newton_euler").unknowns]
    got = dict(zip(names, x[1:]))
    assert x[0] == pytest.approx(-G / R, rel=1e-13)
    assert got["N"] == pytest.approx(M2 * G, rel=1e-13)
    assert abs(got["F"]) <= 1e-12 and abs(got["F_C"]) <= 1e-12


@pytest.mark.parametrize("phi, phid", [(np.pi / 3, 2.0), (-2.0, -5.0), (2.8, 0.7)])
def test_both_forms_give_the_hand_acceleration_and_joint_forces(phi, phid):
    phidd, F, N, F_C = hand(phi, phid)
    ne = problem.model("newton_euler")
    nm = NumericModel(ne, problem.defaults())
    A, _ = nm.system(0.0, [phi], [phid])
    x = nm.solve(0.0, [phi], [phid])
    got = dict(zip([u.name for u in ne.unknowns], x[1:]))
    ref = np.array([phidd, F, N, F_C])
    tol = _bound(A, ref)
    assert abs(x[0] - phidd) <= tol
    assert abs(got["F"] - F) <= tol and abs(got["N"] - N) <= tol and abs(got["F_C"] - F_C) <= tol
    # maximal coordinates at the same state on the manifold: the multipliers are F and N
    mult = problem.model("multiplier")
    s = np.sqrt(L**2 - R**2 * np.sin(phi)**2)
    xB, J1 = R * np.cos(phi) + s, -R * np.sin(phi) - R**2 * np.sin(phi) * np.cos(phi) / s
    mm = NumericModel(mult, problem.defaults())
    q, qd = [phi, xB, 0.0], [phid, J1 * phid, 0.0]
    A2, _ = mm.system(0.0, q, qd)
    x2 = mm.solve(0.0, q, qd)
    got2 = dict(zip([u.name for u in mult.unknowns], x2[3:]))
    tol2 = _bound(A2, x2)
    assert abs(x2[0] - phidd) <= tol2
    assert abs(got2["F"] - F) <= tol2 and abs(got2["N"] - N) <= tol2


@pytest.fixture(scope="module")
def forms():
    fs, skipped = formulations(problem, y0=[1.0, 3.0], models=["lagrange", "multiplier"],
                               stabilisations=("projection", "ggl"))
    assert skipped == {}
    return {f.name: f for f in fs}


def test_dae_forms_stay_on_the_loop_and_carry_the_hand_forces(forms):
    te = np.linspace(0.0, 2.0, 41)
    for name, method in (("multiplier (DAE, projection)", "DOP853"),
                         ("multiplier (DAE, GGL index 2)", "IDA")):
        f = forms[name]
        run = f.run(method, (0.0, 2.0), te, rtol=1e-8)
        assert run.success, run.message
        g, gd = f.drift(run.y)
        if "projection" in name:   # Gauss-Newton to 1e-13 of the configuration's size
            assert np.abs(g).max() <= 1e-12 and np.abs(gd).max() <= 1e-12
        else:                      # IDA holds g = 0 to its tolerance at its steps
            assert np.abs(g).max() <= 1e-6
        # the reactions along the run are the hand forces at the run's own states
        R_ = f.reactions(te, run.y)
        for i in range(0, te.size, 10):
            _, F, N, _ = hand(run.y[0, i], run.y[3, i])
            assert R_["F"][i] == pytest.approx(F, rel=1e-6, abs=1e-9)
            assert R_["N"][i] == pytest.approx(N, rel=1e-6, abs=1e-9)
