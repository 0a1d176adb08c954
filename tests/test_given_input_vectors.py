"""Given inputs as force vectors and moments (Problem.inputs), in both forms, the verdict,
a simulation and ``show``.  The teacher's file: tests/corpus/teacher_problems/
driven_cart_pendulum.py -- a cart (mass M, position x) pushed by F(t) on a smooth rail, a
uniform rod (mass m, length L, angle theta from the downward vertical) hinged at the cart,
a motor torque tau(t) O.z on the rod and a wind force Fx(t) O.x + Fy(t) O.y at its tip.

Derived by hand (independently of both models).  Mass centre G = (x + (L/2) s, -(L/2) c)
with s = sin theta, c = cos theta; tip = (x + L s, -L c); I_G = m L^2 / 12.

    T = (M + m) x'^2 / 2 + (m L / 2) c x' theta' + (m L^2 / 6) theta'^2,   V = -m g (L/2) c
    virtual work: F dx + tau dtheta + Fx d(x + L s) + Fy d(-L c), so
    Q_x = F + Fx,   Q_theta = tau + L (Fx c + Fy s)

    (M + m) x'' + (m L/2)(c theta'' - s theta'^2)          = F + Fx
    (m L/2) c x'' + (m L^2/3) theta'' + m g (L/2) s          = tau + L (Fx c + Fy s)

The rail's push N from the whole system's vertical balance:
    N - (M + m) g + Fy = m a_Gy = (m L/2)(s theta'' + c theta'^2).
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import compare, problems
from dualmech.cli.main import main
from dualmech.numeric import NumericModel
from dualmech.numeric.inputs import input_functions
from dualmech.numeric.simulation import problem_parameters

FILE = Path(__file__).resolve().parent / "corpus" / "teacher_problems" / \
    "driven_cart_pendulum.py"
M, m, L, g = 2.0, 0.5, 0.8, 9.81       # the file's defaults
STATE = dict(x=0.1, theta=0.4, xd=0.2, thd=1.3)
LOADS = dict(F=1.0, tau=0.5, F_x=0.3, F_y=-0.2)


def hand_accelerations(theta, thd, F, tau, F_x, F_y):
    s, c = np.sin(theta), np.cos(theta)
    A = np.array([[M + m, m * L / 2 * c], [m * L / 2 * c, m * L**2 / 3]])
    b = np.array([F + F_x + m * L / 2 * s * thd**2,
                  tau + L * (F_x * c + F_y * s) - m * g * L / 2 * s])
    return np.linalg.solve(A, b)


def hand_N(theta, thd, thdd, F_y):
    s, c = np.sin(theta), np.cos(theta)
    return (M + m) * g - F_y + m * L / 2 * (s * thdd + c * thd**2)


@pytest.fixture(scope="module")
def problem():
    return problems.load(str(FILE))


def _module(p):
    import sys
    return sys.modules[type(p).__module__]


def test_both_forms_agree_for_every_value_of_the_inputs(problem):
    assert compare(problem).equivalent


@pytest.mark.parametrize("mistake", ["wind moment without Fy", "motor torque reversed"])
def test_a_wrong_moment_of_an_input_is_a_disagreement(problem, mistake):
    mod = _module(problem)

    class Wrong(type(problem)):
        def lagrange(self):
            lg = mod.Lagrangian(coordinates=[mod.x, mod.theta])
            lg.kinetic_of(mod.cart, mod.O)
            lg.kinetic_of(mod.rod, mod.O)
            lg.gravity(-mod.g * mod.O.y, [mod.rod], mod.O)
            lg.force_at("push", mod.F * mod.O.x, mod.P, mod.O)
            sign = -1 if mistake == "motor torque reversed" else 1
            lg.torque_on("motor", sign * mod.tau * mod.O.z, mod.B, mod.O)
            wind = mod.Fx * mod.O.x if mistake == "wind moment without Fy" else mod.wind
            lg.force_at("wind", wind, mod.tip, mod.O)
            return lg.equations()
    assert not compare(Wrong()).equivalent


@pytest.mark.parametrize("model", ["newton_euler", "lagrange"])
def test_each_form_gives_the_hand_accelerations(problem, model):
    values = problem_parameters(problem, None)
    eqs = problem.in_reference_coordinates(problem.model(model))
    fns = input_functions(problem, {k: (lambda v: lambda t: v)(v) for k, v in LOADS.items()})
    got = NumericModel(eqs, values, backend="python", inputs=fns).solve(
        0.0, [STATE["x"], STATE["theta"]], [STATE["xd"], STATE["thd"]])[:2]
    want = hand_accelerations(STATE["theta"], STATE["thd"], **LOADS)
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_show_at_a_state_gives_the_hand_rail_force(capsys, problem):
    at = "x=0.1, theta=0.4, x'=0.2, theta'=1.3, F=1, tau=0.5, F_x=0.3, F_y=-0.2"
    status = main(["show", str(FILE), "--json", "--at", at])
    out, err = capsys.readouterr()
    assert status == 0, err
    values = json.loads(out)["values_at_state"]["values"]
    thdd = hand_accelerations(STATE["theta"], STATE["thd"], **LOADS)[1]
    N = hand_N(STATE["theta"], STATE["thd"], thdd, LOADS["F_y"])
    assert values["N"]["direct"] == pytest.approx(N, rel=1e-12)
    assert values["N"]["referee"] == pytest.approx(N, rel=1e-12)


def test_simulation_follows_the_hand_equations_with_the_declared_histories(problem):
    """The file declares F = 2 sin 3t, tau = 1/2, Fx = 3t/10, Fy = -1/5; scipy's DOP853 on
    the hand equations is the reference, the run is CVODE on the generated C."""
    from scipy.integrate import solve_ivp
    from dualmech.cli.simulate import summary

    def hand(t, y):
        a = hand_accelerations(y[1], y[3], 2 * np.sin(3 * t), 0.5, 0.3 * t, -0.2)
        return [y[2], y[3], a[0], a[1]]
    ref = solve_ivp(hand, (0, 2), [0, 0.3, 0, 0], method="DOP853", rtol=1e-12, atol=1e-12)
    run = summary(problem, duration=2.0, rtol=1e-10, atol=1e-12)
    assert run["method"] == "CVODE-Adams" and run["inputs_in_python"] is None
    assert run["inputs"] == {"F": "default: 2*sin(3*t)", "tau": "default: 1/2",
                             "F_x": "default: 3*t/10", "F_y": "default: -1/5"}
    # CVODE's global error at rtol 1e-10 over 2 s: ~1e-9 measured; dropping Fy from the
    # equations moves theta' at t = 2 by 0.15, dropping tau by 0.22 (measured on the hand
    # equations), so 1e-7 tells a missing input term from the integration error
    assert np.abs(np.array(run["final_state"]) - ref.y[:, -1]).max() < 1e-7


def test_show_takes_the_declared_defaults_for_inputs_not_named(capsys):
    """At t = 0 the defaults are F = 0, tau = 1/2, Fx = 0, Fy = -1/5 (named: F_y only)."""
    status = main(["show", str(FILE), "--json", "--at", "x=0.1, theta=0.4, theta'=1.3, "
                   "F_y=0.7"])
    out, err = capsys.readouterr()
    assert status == 0, err
    got = json.loads(out)["values_at_state"]
    assert got["state"]["tau"] == 0.5 and got["state"]["F_y"] == 0.7
    thdd = hand_accelerations(0.4, 1.3, 0.0, 0.5, 0.0, 0.7)[1]
    assert got["values"]["N"]["direct"] == pytest.approx(hand_N(0.4, 1.3, thdd, 0.7),
                                                         rel=1e-12)
