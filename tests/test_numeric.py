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
