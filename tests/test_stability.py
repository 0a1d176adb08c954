"""Linearisation about steady motions (dualmech.model.stability, dualmech.numeric.stability).

Reference values are derived by hand, independently of the toolkit: the pendulum's small
oscillation ``omega^2 = g / l``; the rolling disk's lean eigenvalues
``lambda^2 = 4 (g r - 3 v^2) / (5 r^2)`` and critical speed ``sqrt(g r / 3)`` (derivation in
the docstring of ``problems/rolling_disk.py``).
"""
import math

import numpy as np
import pytest
import sympy as sp

from dualmech import ModelError, rate
from dualmech.model.stability import linearize_about
from dualmech.numeric.stability import stability
from dualmech.problems import get
from dualmech.problems import pendulum_particle as pp
from dualmech.problems import rolling_disk as rd


def _eig(matrix) -> np.ndarray:
    return np.linalg.eigvals(np.array(matrix.evalf(30), dtype=float))


def _nonzero(eig, scale=1.0) -> np.ndarray:
    return np.sort_complex(eig[np.abs(eig) > 1e-9 * scale])


@pytest.fixture(scope="module")
def pendulum():
    return get("pendulum_particle")


@pytest.fixture(scope="module")
def disk():
    return get("rolling_disk")


def test_multiplier_model_linearises_like_the_minimal_one(pendulum):
    """The Cartesian model (rod force as multiplier, holonomic constraint) reduced to its
    tangent space gives the hanging pendulum's ``+-i sqrt(g/l)``, as the Lagrangian in theta."""
    numbers = {pp.g: 9, pp.l: 2}
    cart = linearize_about(pendulum.model("cartesian"), {pp.y: pp.l}, numbers)
    minimal = linearize_about(pendulum.model("lagrange"), {}, numbers)
    assert cart.constraints[0][1] == "holonomic"
    assert cart.states == ("x", "x'") and cart.dependent == ("y", "y'")
    assert minimal.states == ("theta", "theta'")
    want = np.array([-1j, 1j]) * math.sqrt(9 / 2)
    for lin in (cart, minimal):
        assert np.allclose(np.sort_complex(_eig(lin.at())), want, atol=1e-13)
    assert cart.symbolic == minimal.symbolic == sp.Matrix([[0, 1], [sp.Rational(-9, 2), 0]])


def test_multiplier_model_linearised_symbolically_in_a_parameter(pendulum):
    cart = linearize_about(pendulum.model("cartesian"), {pp.y: pp.l}, {pp.g: 9}, parameter=pp.l)
    assert sp.simplify(cart.symbolic - sp.Matrix([[0, 1], [-9 / pp.l, 0]])) == sp.zeros(2, 2)


def test_study_compares_every_derivation(pendulum):
    study = stability(pendulum, params={"g": 9, "l": 2})
    d = study.derivations
    assert d["agree"] is True and {"lagrange", "cartesian", "newton_euler"} <= set(d["models"])
    assert "newton_euler_inertial" in d["not_linearised"]   # not square: stated, not hidden
    assert np.allclose(np.sort(np.abs(study.eigenvalues[0])), [math.sqrt(4.5)] * 2)


@pytest.mark.parametrize("model", ["lagrange", "newton_euler"])
@pytest.mark.parametrize("speed", [0.5, 0.8, 1.3, 1.9])
def test_rolling_disk_lean_eigenvalues_match_the_hand_derivation(disk, model, speed):
    """Steady motion with rates (spin ``v/r``, ``x' = v``): the nonzero eigenvalues are
    ``+-sqrt(4 (g r - 3 v^2) / (5 r^2))``, from the contact-force model and the multiplier
    model alike; three more are zero (heading, speed, the conserved heading momentum)."""
    numbers = {rd.m: 2, rd.r: sp.Rational(3, 10), rd.g: 10}
    lin = linearize_about(disk.model(model), disk.steady_motion.about, numbers, parameter=rd.v)
    assert lin.dropped == ("phi", "x", "y") and set(lin.dependent) == {"x'", "y'"}
    assert [kind for _, kind in lin.constraints] == ["velocity", "velocity"]
    eig = _eig(lin.at(speed))
    lam2 = complex(rd.lean_eigenvalue_squared().subs({rd.g: 10, rd.r: 0.3, rd.v: speed}))
    want = np.sort_complex(np.array([-1, 1]) * np.sqrt(lam2))
    assert np.allclose(_nonzero(eig, 10), want, rtol=1e-12, atol=1e-12)
    assert np.sum(np.abs(eig) < 1e-12) == 3


def test_rolling_disk_models_give_the_same_state_matrix(disk):
    numbers = {rd.m: 1, rd.r: sp.Rational(1, 4), rd.g: sp.Rational(981, 100)}
    a, b = (linearize_about(disk.model(n), disk.steady_motion.about, numbers, parameter=rd.v)
            for n in ("lagrange", "newton_euler"))
    assert a.states == b.states and a.symbolic == b.symbolic


def test_sweep_finds_the_critical_speed(disk):
    """Critical speed ``sqrt(g r / 3)`` (hand derivation), off the sweep's grid."""
    study = stability(disk, params={"g": 9.81, "r": 0.25}, sweep=(0.3, 1.7, 29))
    want = math.sqrt(9.81 * 0.25 / 3)
    assert min(abs(v - want) for v in study.values) > 1e-3   # not a grid point
    (crit,) = study.critical
    assert abs(crit.value - want) < 1e-6
    assert crit.kind == "a real pair meets at zero and becomes imaginary"
    assert (crit.stable_below, crit.stable_above) == (False, True)
    assert study.trivial_zeros == 3
    assert study.derivations["agree"] is True
    assert study.stable == [v > want for v in study.values]


def test_not_a_steady_motion_is_refused(disk):
    leaning = dict(disk.steady_motion.about)
    leaning[rd.theta] = sp.Rational(1, 10)
    with pytest.raises(ModelError, match="not a steady motion"):
        linearize_about(disk.model("lagrange"), leaning, disk.defaults(), parameter=rd.v)


def test_a_moving_coordinate_the_equations_depend_on_is_refused(pendulum):
    """theta'' = 0 at theta = 0 for any theta', but theta' != 0 carries the pendulum away."""
    with pytest.raises(ModelError, match="theta move"):
        linearize_about(pendulum.model("lagrange"), {rate(pp.theta): 1}, pendulum.defaults())


def test_a_state_breaking_the_rolling_constraint_is_refused(disk):
    with pytest.raises(ModelError, match="breaks the constraint"):
        linearize_about(disk.model("newton_euler"), {rate(rd.phi): rd.v / rd.r},
                        disk.defaults(), parameter=rd.v)


def test_independent_speeds_named_by_the_user(disk):
    lin = linearize_about(disk.model("lagrange"), disk.steady_motion.about, disk.defaults(),
                          parameter=rd.v, independent=["psi", "theta", "psi'", "theta'", "x'"])
    assert set(lin.dependent) == {"phi'", "y'"}
    eig = _eig(lin.at(0.5))
    want = np.sqrt(complex(rd.lean_eigenvalue_squared().subs({rd.g: 10, rd.r: 0.3, rd.v: 0.5})))
    assert np.allclose(np.sort(np.abs(_nonzero(eig, 10))), [abs(want)] * 2, rtol=1e-12)
    with pytest.raises(ModelError, match="cannot be solved"):
        linearize_about(disk.model("lagrange"), disk.steady_motion.about, disk.defaults(),
                        parameter=rd.v, independent=["psi", "theta", "phi'", "x'", "y'"])


def test_damping_sweep_finds_the_hopf_crossing_and_critical_damping():
    """``m x'' + b x' + k x = 0`` (by hand: ``lambda = (-b +- sqrt(b^2 - 4 m k)) / (2 m)``): the
    complex pair crosses the imaginary axis at ``b = 0`` and becomes real at ``b = 2 sqrt(m k)``
    (= 20 for m = 2, k = 50); the grid holds neither value."""
    study = stability(get("spring_mass_damper"), {}, "b", (-7, 27, 18), params={"F0": 0})
    hopf, real = study.critical
    assert hopf.kind == "real part crosses zero (a complex pair)" and abs(hopf.value) < 1e-9
    assert (hopf.stable_below, hopf.stable_above) == (False, True)
    assert real.kind == "a pair becomes real" and abs(real.value - 20) < 1e-6
    assert (real.stable_below, real.stable_above) == (True, True)
    for b, eig in zip(study.values, study.eigenvalues):
        want = np.roots([2, b, 50])
        assert np.allclose(np.sort_complex(eig), np.sort_complex(want), atol=1e-12)


def test_steady_motion_declaration_is_checked(disk):
    from dualmech import ProblemError, SteadyMotion
    with pytest.raises(ValueError, match="needs `parameter`"):
        SteadyMotion({}, "", (0, 1, 5))
    with pytest.raises(ValueError, match="count must be a whole number >= 2"):
        SteadyMotion({}, "v", (0, 1, 1))

    class Typo(type(disk)):
        steady_motion = SteadyMotion({rate(rd.h): 1}, "v", (0, 1, 3))
    with pytest.raises(ProblemError, match="not a coordinate of the reference model"):
        Typo().validate()


def test_big_reduced_states_use_numbers_and_find_the_same_critical_speed(disk, monkeypatch):
    from dualmech.numeric import stability as numeric_stability
    monkeypatch.setattr(numeric_stability, "EXACT_SIZE", 1)
    study = stability(disk, params={"g": 9.81, "r": 0.25}, sweep=(0.3, 1.7, 29))
    (crit,) = study.critical
    assert abs(crit.value - math.sqrt(9.81 * 0.25 / 3)) < 1e-6 and study.trivial_zeros == 3


def test_time_in_form_only_is_cancelled_and_a_real_drive_is_refused():
    """The bead's multiplier model holds ``sin(w t)^2 + cos(w t)^2`` (its rotating frame):
    linearised, it is the other models' ``theta'' = (w^2 - g/R) theta`` at the bottom; the
    Kapitza pendulum's pivot drive is refused (no steady motion), not linearised at a time."""
    hoop = stability(get("bead_on_hoop"))
    assert hoop.derivations["agree"] is True and "multiplier" in hoop.derivations["models"]
    assert np.allclose(np.sort(hoop.eigenvalues[0].real),
                       [-math.sqrt(36 - 9.81 / 0.5), math.sqrt(36 - 9.81 / 0.5)])
    with pytest.raises(ModelError, match="depends on time explicitly"):
        stability(get("kapitza_pendulum"))
