"""Simulation and reactions along trajectories (dualmech.numeric)."""
import numpy as np
import pytest
import sympy as sp

from dualmech.numeric import NumericModel, SingularityError, simulate

from _pendulum import Pendulum, l, m


def test_pendulum_conserves_energy_and_tension_matches_formula():
    p = Pendulum()
    traj = simulate(p, t_span=(0, 3), y0=[1.1, 0.0], rtol=1e-11, atol=1e-12)
    th, thd = traj.q[0], traj.qd[0]
    M, L, G = 1.0, 1.0, 9.81
    energy = 0.5 * M * L**2 * thd**2 - M * G * L * np.cos(th)
    assert np.ptp(energy) < 1e-8 * abs(energy[0])
    # hand: S = m g cos(theta) + m l theta'^2
    assert np.allclose(traj.reactions["S"], M * G * np.cos(th) + M * L * thd**2, rtol=1e-10)


def test_small_oscillation_period_matches_linear_theory():
    p = Pendulum()
    traj = simulate(p, t_span=(0, 2 * np.pi * np.sqrt(1 / 9.81)), y0=[1e-4, 0.0], samples=2,
                    rtol=1e-12, atol=1e-16)
    # after one linear period the pendulum is back where it started (to O(theta0^3))
    assert traj.q[0, -1] == pytest.approx(1e-4, rel=1e-6)


def test_missing_parameter_is_named():
    with pytest.raises(ValueError, match="lacks values for \\['g'\\]"):
        NumericModel(Pendulum().model("lagrange"), {m: 1, l: 1})


def test_wrong_initial_state_shape():
    with pytest.raises(ValueError, match="`y0` must hold 2 numbers"):
        simulate(Pendulum(), y0=[1, 2, 3])


def test_singular_mass_matrix_is_detected():
    from dualmech import EquationSet, coordinate, t
    th = coordinate("theta")
    eqs = EquationSet("car", (th,), (sp.cos(th) * th.diff(t, 2) + sp.sin(th),))
    nm = NumericModel(eqs, {})
    with pytest.raises(SingularityError, match="singular at t=0, theta=1.5708"):
        nm.solve(0.0, [np.pi / 2], [0.0])


def test_reactions_at_one_state_match_the_hand_formula():
    from dualmech.numeric import reactions_at
    # S = m g cos(theta) + m l theta'^2 with the defaults m = l = 1, g = 9.81
    out = reactions_at(Pendulum(), [0.7], [1.3], params={m: 2.0})
    assert out["S"] == pytest.approx(2.0 * 9.81 * np.cos(0.7) + 2.0 * 1.3**2, rel=1e-12)


# -- input errors name the argument, what was given and what is allowed --------------------
@pytest.mark.parametrize("params, message", [
    ({"L": 2}, r"unknown parameter 'L'; did you mean 'l'\? Problem `pendulum` has parameters "
               r"g, l, m"),
    ({sp.Symbol("lenght"): 2}, r"unknown parameter 'lenght'"),
    ({"l": 50}, r"l = 50 is outside the admissible range \[0\.2, 3\]"),
    ({l: -1.0}, r"l = -1\.0 is outside the admissible range"),
    ({"g": "ten"}, r"g = 'ten' is not a number"),
    ({"g": float("inf")}, r"g = inf must be finite"),
], ids=["misspelt-name", "unknown-symbol", "above-range", "below-range", "text-value", "inf"])
def test_bad_parameters_are_refused(params, message):
    with pytest.raises(ValueError, match=message):
        simulate(Pendulum(), t_span=(0, 0.1), params=params)
    from dualmech.numeric import reactions_at
    with pytest.raises(ValueError, match=message):
        reactions_at(Pendulum(), [0.1], [0.0], params=params)


@pytest.mark.parametrize("t_span, message", [
    ((0, 0), r"`t_span` is empty"),
    ((1.5, 1.5), r"`t_span` is empty"),
    ((0, np.inf), r"`t_span` must be finite"),
    ((np.nan, 1), r"`t_span` must be finite"),
    ((1,), r"`t_span` must be two numbers"),
    ("0 5", r"`t_span` must be two numbers"),
], ids=["zero", "equal", "infinite", "nan", "one-number", "text"])
def test_bad_time_spans_are_refused(t_span, message):
    with pytest.raises(ValueError, match=message):
        simulate(Pendulum(), t_span=t_span)


def test_bad_samples_and_initial_state_are_refused():
    with pytest.raises(ValueError, match=r"`samples` must be an integer >= 2, got 1"):
        simulate(Pendulum(), t_span=(0, 1), samples=1)
    with pytest.raises(ValueError, match=r"`y0` must be finite"):
        simulate(Pendulum(), t_span=(0, 1), y0=[np.nan, 0.0])


def test_backward_span_and_right_hand_side_of_a_problem():
    from dualmech.numeric import right_hand_side
    p = Pendulum()
    traj = simulate(p, t_span=(1.0, 0.0), y0=[0.4, 0.0], samples=3)
    assert traj.t[0] == 1.0 and traj.t[-1] == 0.0
    rhs = right_hand_side(p, {"l": 2.0})
    # hand: theta'' = -g/l sin(theta)
    assert rhs(0.0, np.array([0.4, 0.3]))[1] == pytest.approx(-9.81 / 2.0 * np.sin(0.4),
                                                              rel=1e-15)
    Y = np.array([[0.4, -0.2], [0.3, 0.0]])
    assert np.allclose(rhs(0.0, Y)[1], -9.81 / 2.0 * np.sin(Y[0]), rtol=1e-15)


def test_range_check_can_be_lifted_on_purpose():
    from dualmech.numeric import reactions_at
    # hand: S = m g cos(theta) + m l theta'^2 with l = 50 (outside the declared [0.2, 3])
    out = reactions_at(Pendulum(), [0.7], [1.3], params={"l": 50}, check_ranges=False)
    assert out["S"] == pytest.approx(9.81 * np.cos(0.7) + 50 * 1.3**2, rel=1e-12)
