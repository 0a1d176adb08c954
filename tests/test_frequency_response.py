"""Frequency-response model (problems/frequency_response.py): steady state, identified values."""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.problems.frequency_response import FrequencyResponse, F0, amplitude, c, k, m, omega, x

problem = FrequencyResponse()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731
# the source's identified values (exact): k = 3 N/m, m = 3/16 kg, c = 9/16 kg/s, F0 = 9 N
IDENTIFIED = {k: 3, m: sp.Rational(3, 16), c: sp.Rational(9, 16), F0: 9}


@pytest.mark.parametrize("model", ["newton_euler", "lagrange"])
def test_hand_derived_steady_state_solves_each_model(model):
    # x_p = Re(X e^{i omega t}), X = F0/(k - m omega^2 + i c omega)  (module docstring)
    delta = (k - m * omega**2)**2 + (c * omega)**2
    xp = F0 * ((k - m * omega**2) * sp.cos(omega * t) + c * omega * sp.sin(omega * t)) / delta
    (eq,) = problem.model(model).equations
    on = eq.subs({D(x, 2): D(xp, 2), D(x): D(xp)}).subs(x, xp)
    assert sp.simplify(on) == 0
    # and its amplitude is the one the library computes from the model's matrices
    # (squared: x_p(0)^2 + (x_p'(0)/omega)^2 = |X|^2)
    amp2 = xp.subs(t, 0)**2 + (D(xp) / omega).subs(t, 0)**2
    assert sp.simplify(amp2 - amplitude(problem.model(model), omega)**2) == 0


def test_identified_values_reproduce_the_two_readings_the_source_uses():
    # X(0) = 3 m, omega_n = 4 rad/s, X(4 rad/s) = 4 m -- exactly, from the model's matrices
    lag = problem.model("lagrange")
    assert amplitude(lag, 0).subs(IDENTIFIED) == 3
    assert amplitude(lag, 4).subs(IDENTIFIED) == 4
    (w_n,) = lag.substitute({F0: 0}).natural_frequencies()
    assert w_n.subs(IDENTIFIED) == 4


def test_with_the_identified_values_the_peak_is_below_omega_n():
    # zeta = 3/8: d|X|^2/d omega = 0 at omega^2 = omega_n^2 (1 - 2 zeta^2) = 23/2, not 16
    w = sp.Symbol("w", positive=True)
    amp2 = (amplitude(problem.model("lagrange"), w)**2).subs(IDENTIFIED)
    (peak,) = sp.solve(sp.diff(amp2, w), w)
    assert peak**2 == sp.Rational(23, 2)
    assert sp.sqrt(amp2.subs(w, peak)) > 4


def test_unforced_response_from_rest_at_one_is_the_damped_cosine():
    # (b): x(0) = 1, x'(0) = 0, F0 = 0; hand: exp(-zeta w_n t)(cos w_d t + zeta w_n/w_d sin w_d t)
    values = {s: float(v) for s, v in IDENTIFIED.items()}
    values[omega] = 4.0
    model = NumericModel(problem.model("lagrange").substitute({F0: 0}), values)
    rhs = lambda time, y: [y[1], model.accelerations(time, y[:1], y[1:])[0]]  # noqa: E731
    times = np.linspace(0.0, 8.0, 81)
    rtol, atol = 1e-11, 1e-13
    sol = solve_ivp(rhs, (0.0, 8.0), [1.0, 0.0], method="DOP853", t_eval=times, rtol=rtol,
                    atol=atol)
    zeta, w_n = 3 / 8, 4.0
    w_d = w_n * np.sqrt(1 - zeta**2)
    hand = np.exp(-zeta * w_n * times) * (np.cos(w_d * times)
                                          + zeta * w_n / w_d * np.sin(w_d * times))
    # global error of a stable linear ODE: at most (number of steps) x the local tolerance
    tol = sol.nfev * (rtol * 1.0 + atol)
    assert sol.success and np.max(np.abs(sol.y[0] - hand)) <= tol
