"""Bead on a spinning hoop, Example 13 (problems/bead_on_hoop.py)."""
import pytest
import sympy as sp

from dualmech import EquationSet, ModelError, t
from dualmech.verify.check import compare_models
from dualmech.problems.bead_on_hoop import BeadOnHoop, R, g, hand_reactions, m, omega, theta

problem = BeadOnHoop()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
TH0 = sp.acos(g / (R * omega**2))  # the off-axis equilibrium, where R omega^2 > g


def test_hoop_angle_is_prescribed_so_theta_is_the_only_coordinate():
    # rheonomic: the hoop angle psi = omega t is prescribed, theta is the only coordinate
    assert problem.model("lagrange").coordinates == (theta,)
    assert problem.model("lagrange").equations[0].has(omega)


def test_printed_angular_acceleration_is_the_solved_lagrange_equation():
    # th'' = (omega^2 cos th - g/R) sin th: the Lagrange equation over m R^2 (correct)
    (thdd,) = sp.solve(problem.model("lagrange").equations[0], DD(theta))
    printed = (omega**2 * sp.cos(theta) - g / R) * sp.sin(theta)
    assert sp.simplify(thdd - printed) == 0


@pytest.mark.parametrize("model", ["newton_euler", "multiplier"])
def test_hand_derived_reactions_satisfy_each_derivation(model):
    # N = m g cos th + m R (th'^2 + omega^2 sin^2 th), N_b = 2 m R omega th' cos th: put into
    # the direct / multiplier equations, every row must hold on the Lagrangian motion
    eqs = problem.in_reference_coordinates(problem.model(model))
    assert eqs.is_square
    values = {sp.Symbol(n, real=True): e for n, e in hand_reactions().items()}
    rows = [e.subs(values) for e in eqs.equations]
    # a row the hand reactions were read from vanishes identically; the rest must be the motion
    left = [e for e in rows if sp.simplify(e) != 0]
    assert 0 < len(left) < len(rows)
    closed = EquationSet("hand", eqs.coordinates, left)
    result = compare_models(problem.model("lagrange"), closed, explain=False)
    assert result.equivalent and result.method == "exact"


def test_sympy_solve_misses_theta_pi_but_linearize_accepts_it():
    found = problem.model("lagrange").equilibria()
    values = [e[theta] for e in found]
    assert 0 in values and sp.pi not in values and len(values) == 3
    # the two others are +-arccos(g / (R omega^2))
    for val in values:
        if val != 0:
            assert sp.simplify(sp.cos(val) - g / (R * omega**2)) == 0
    M, C, K = problem.model("lagrange").linearize({theta: sp.pi})   # no error: an equilibrium
    assert sp.simplify(K[0, 0] + m * R * (g + R * omega**2)) == 0   # always negative


def test_linearize_refuses_a_state_that_is_no_equilibrium():
    with pytest.raises(ModelError, match="not an equilibrium"):
        problem.model("lagrange").linearize({theta: sp.pi / 3})


def test_stability_of_the_equilibria():
    lag = problem.model("lagrange")
    # bottom: stiffness m R (g - R omega^2), stable below omega^2 = g / R
    _, _, K = lag.linearize({theta: 0})
    assert sp.simplify(K[0, 0] - m * R * (g - R * omega**2)) == 0
    assert K[0, 0].subs(omega, sp.sqrt(g / R) / 2).is_positive
    assert K[0, 0].subs(omega, 2 * sp.sqrt(g / R)).is_negative
    # top: unstable for every omega
    _, _, K = lag.linearize({theta: sp.pi})
    assert K[0, 0].is_negative
    # off-axis (exists for R omega^2 > g): stiffness m R^2 omega^2 sin^2 th0 > 0, stable,
    # and the small oscillations there have the frequency omega sin th0
    M, _, K = lag.linearize({theta: TH0})
    assert sp.simplify(K[0, 0] - m * R**2 * omega**2 * sp.sin(TH0)**2) == 0
    (w,) = [f for f in lag.natural_frequencies({theta: TH0}) if f != 0]
    assert sp.simplify(w**2 - omega**2 * sp.sin(TH0)**2) == 0


def test_in_plane_force_at_the_off_axis_equilibrium_is_m_R_omega_squared():
    # at rest relative to the hoop at cos th0 = g/(R omega^2): N = m R omega^2, whatever g
    N = hand_reactions()["N"].subs(D(theta), 0).subs(theta, TH0)
    assert sp.simplify(N - m * R * omega**2) == 0
    assert hand_reactions()["N_b"].subs(D(theta), 0) == 0


def test_jacobi_integral_is_conserved_on_the_motion():
    # rheonomic, so T + U is not conserved; h = T2 - T0 + U is (T0 = m (R omega sin th)^2 / 2)
    h = (m * (R * D(theta))**2 / 2 - m * (R * omega * sp.sin(theta))**2 / 2
         + m * g * R * (1 - sp.cos(theta)))
    (thdd,) = sp.solve(problem.model("lagrange").equations[0], DD(theta))
    assert sp.simplify(h.diff(t).subs(DD(theta), thdd)) == 0
    energy = h + m * (R * omega * sp.sin(theta))**2
    assert sp.simplify(energy.diff(t).subs(DD(theta), thdd)) != 0

