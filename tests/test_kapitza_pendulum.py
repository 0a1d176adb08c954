"""Kapitza's pendulum (problems/kapitza_pendulum.py), Floquet multipliers and Mathieu's chart.

References: the tension by hand (module docstring of the problem); Landau & Lifshitz,
Mechanics, section 30 problem 1 (the inverted position is stable for a^2 Omega^2 > 2 g l);
the characteristic values of Mathieu's equation from NIST DLMF 28.6.1-28.6.4 (power series,
= Abramowitz & Stegun 20.2.25) and, independently, scipy.special.mathieu_a / mathieu_b (Zhang
& Jin's routines).
"""
import numpy as np
import pytest
import sympy as sp
from scipy.special import mathieu_a, mathieu_b

from dualmech.numeric.studies.atlas import atlas
from dualmech.numeric.studies.floquet import NotDriven, floquet, forcing_period, monodromy
from dualmech.numeric.formulations import formulations
from dualmech.numeric.studies.mathieu import boundary, series, trace
from dualmech.problems import get
from dualmech.problems.kapitza_pendulum import hand_tension, mathieu_parameters

problem = get("kapitza_pendulum")
DEFAULTS = {p.symbol.name: p.default for p in problem.parameters}


def test_the_tension_is_the_hand_one(compared):
    assert sp.simplify(compared("kapitza_pendulum").reactions["T"] - hand_tension()) == 0


def test_the_period_is_read_off_the_drive():
    values = {p.symbol: p.default for p in problem.parameters}
    assert forcing_period(problem.model("lagrange"), values) == pytest.approx(
        2 * np.pi / DEFAULTS["Omega"], rel=1e-15)
    with pytest.raises(NotDriven, match="autonomous"):
        forcing_period(get("simple_pendulum").model("lagrange"), {})


def _orbit(fl, theta):
    (o,) = [o for o in fl.orbits if abs(o.state[0] - theta) < 1e-9]
    return o


def test_frozen_linearisation_no_longer_calls_the_shaken_pendulum_unstable():
    # the bug: a Jacobian at t = 0 gave "every equilibrium found is unstable"
    a = atlas(problem, sections=("linearisation", "floquet"), progress=False)
    assert "driven" in a.skipped["linearisation"] and "floquet" in a.skipped["linearisation"]
    upright = _orbit(a.results["floquet"], np.pi)
    assert upright.stable and upright.equilibrium


def test_inverted_position_turns_stable_where_mathieus_a0_says_and_near_kapitzas_bound():
    g, l, amp = DEFAULTS["g"], DEFAULTS["l"], DEFAULTS["a"]
    q = 2 * amp / l
    # exact boundary: -4 g / (l Omega^2) = a_0(q) (scipy's characteristic value)
    omega_c = np.sqrt(-4 * g / (l * mathieu_a(0, q)))
    # Landau & Lifshitz: a^2 Omega^2 = 2 g l, the leading order in q; a_0 = -q^2/2 (1 - 7 q^2
    # / 64 + O(q^4)) puts the exact boundary 7 q^2/128 higher, to O(q^4) = 1e-4 here
    omega_k = np.sqrt(2 * g * l) / amp
    assert omega_c / omega_k - 1 == pytest.approx(7 * q**2 / 128, abs=q**4)
    for factor, stable in ((1.02, True), (0.98, False)):
        fl = floquet(problem, {"Omega": factor * omega_c})
        assert _orbit(fl, np.pi).stable is stable, str(fl)
        assert _orbit(fl, 0.0).stable   # hanging down stays stable throughout


def test_monodromy_of_the_generated_code_has_mathieus_trace():
    # the problem's own right-hand side over one period of the drive against Mathieu's
    # equation integrated independently (RK4, with its Richardson error estimate); the
    # variational run's error is estimated by its change from a hundredfold looser run
    f = formulations(problem, models=["lagrange"])[0][0]
    period = 2 * np.pi / DEFAULTS["Omega"]
    for theta, inverted in ((np.pi, True), (0.0, False)):
        Phi, _ = monodromy(f.rhs, np.array([theta, 0.0]), 0.0, period, rtol=1e-11)
        loose, _ = monodromy(f.rhs, np.array([theta, 0.0]), 0.0, period, rtol=1e-9)
        e = np.abs(Phi - loose).max()
        # Liouville: no damping, the period map keeps areas
        assert np.linalg.det(Phi) == pytest.approx(1.0, abs=2 * e * np.abs(Phi).max())
        alpha, q = mathieu_parameters(DEFAULTS, inverted)
        tr, err = trace(alpha, q, 400, error=True)
        assert np.trace(Phi) == pytest.approx(float(tr), abs=2 * e + float(err))


@pytest.mark.parametrize("name", ["a0", "b1", "a1"])
@pytest.mark.parametrize("q", [0.1])
def test_transition_curves_at_small_q_match_the_dlmf_series(name, q):
    found = boundary(name, q)
    value, last = series(name, q)
    # the series converge fast here: the truncation error is below the last term kept
    assert found == pytest.approx(value, abs=last + 1e-12)


@pytest.mark.parametrize("name, m, reference", [("a0", 0, mathieu_a), ("b1", 1, mathieu_b),
                                                ("a1", 1, mathieu_a), ("b2", 2, mathieu_b)])
@pytest.mark.parametrize("q", [1.5])
def test_transition_curves_at_larger_q_match_scipys_characteristic_values(name, m, reference, q):
    found = boundary(name, q)
    # the trace's own error (Richardson, times 16 for the coarser run the root used) over the
    # trace's slope across the curve
    _, err = trace(found, q, 1600, error=True)
    slope = (trace(found + 1e-6, q, 1600) - trace(found - 1e-6, q, 1600)) / 2e-6
    assert found == pytest.approx(reference(m, q), abs=4 * 16 * float(err) / abs(slope)
                                  + 1e-13)


def test_atlas_draws_the_floquet_chart(tmp_path):
    a = atlas(problem, sections=("floquet",), progress=False)
    paths = a.write(tmp_path)
    assert (tmp_path / "kapitza_pendulum_atlas_floquet.png") in paths
    text = (tmp_path / "kapitza_pendulum_atlas.txt").read_text()
    assert "Mathieu's equation, alpha = -0.00310613, q = -0.1" in text
