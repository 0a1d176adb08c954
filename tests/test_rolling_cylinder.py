"""Rolling cylinder with an offset mass (problems/rolling_cylinder.py): contact forces, stability."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.rolling_cylinder import (M, R, RollingCylinder, g, hand_reactions, m, r, scene,
                                       theta)

_EPS = np.finfo(float).eps
problem = RollingCylinder()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def test_rolling_is_built_into_the_kinematics():
    # the body point at the contact Q has zero velocity: v_C + w x (Q - C) = 0
    s = scene()
    w = s.B.ang_vel_in(s.O)
    v_contact = s.C.vel(s.O) + w.cross(s.Q.pos_from(s.C))
    assert v_contact.is_zero()


def test_equilibria_and_their_stability_from_the_library():
    # source (b): theta_eq = n pi, stable for n even, unstable for n odd
    lag = problem.model("lagrange")
    found = sorted(e[theta] for e in lag.equilibria())
    assert found == [0, sp.pi]
    for n in range(-2, 3):
        # about n pi: mass f(n pi) = (3/2) M R^2 + m (R -+ r)^2 > 0, stiffness (-1)^n m g r
        Mn, Cn, Kn = lag.linearize({theta: n * sp.pi})
        assert Cn == sp.zeros(1, 1)
        arm = R - r if n % 2 == 0 else R + r
        assert sp.expand(Mn[0] - sp.Rational(3, 2) * M * R**2 - m * arm**2) == 0, n
        assert Kn[0] == sp.Integer(-1)**n * m * g * r, n


def test_natural_frequency_and_period_are_the_sources():
    # source (c): omega_n^2 = m g r / ((3/2) M R^2 + m (R - r)^2), T_n = 2 pi/omega_n
    lag = problem.model("lagrange")
    (w_n,) = lag.natural_frequencies({theta: 0})
    source = sp.sqrt(m * g * r / (sp.Rational(3, 2) * M * R**2 + m * (R - r)**2))
    assert sp.simplify(w_n**2 - source**2) == 0
    values = problem.defaults()
    omegas, modes = lag.natural_frequencies({theta: 0}, values=values)
    printed = float(source.subs(values))
    # a generalised eigenproblem of size 1: error a few ulps of the result
    assert abs(omegas[0].real - printed) <= 8 * _EPS * printed
    sigma, mu = values[R] / values[r], values[M] / values[m]
    T_printed = 2 * np.pi * np.sqrt(values[r] / values[g]) * np.sqrt(
        (sigma - 1)**2 + 1.5 * mu * sigma**2)
    assert abs(2 * np.pi / omegas[0].real - T_printed) <= 8 * _EPS * T_printed


def test_printed_equation_of_motion_misses_the_centripetal_term():
    # on the motion, f theta'' + m g r sin(theta) = -m r R sin(theta) theta'^2 (not 0)
    acc = problem.model("lagrange").accelerations_solved()[D(theta, 2)]
    f = sp.Rational(3, 2) * M * R**2 + m * (R**2 + r**2 - 2 * r * R * sp.cos(theta))
    printed = f * acc + m * g * r * sp.sin(theta)
    assert sp.simplify(printed + m * r * R * sp.sin(theta) * D(theta)**2) == 0


@settings(max_examples=40)
@given(points(problem))
def test_friction_and_normal_force_are_the_hand_derived_ones(point):
    # F = -(M + m) R theta'' + m r (theta'' cos - theta'^2 sin),
    # N = (M + m) g + m r (theta'' sin + theta'^2 cos)            (module docstring)
    eqs = problem.model("newton_euler")
    A, b = NumericModel(eqs, point.params).system(point.time, point.q, point.qd)
    sol = np.linalg.solve(A, b)
    got = dict(zip([u.name for u in eqs.unknowns], sol[1:]))
    subs = dict(point.params)
    subs.update({D(theta, 2): sol[0], D(theta): point.qd[0], theta: point.q[0]})
    tol = 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.max(np.abs(b))))
    for name, expr in hand_reactions().items():
        hand = float(expr.subs(subs))
        assert abs(got[name] - hand) <= tol * max(1.0, abs(hand)), name


@pytest.mark.slow
def test_at_rest_at_the_stable_equilibrium_the_ground_carries_the_weight():
    sol = problem.model("newton_euler").reactions_solved()
    rest = {D(theta): 0, theta: 0}
    assert {u.name: sp.simplify(v.subs(rest)) for u, v in sol.items()} == \
        {"F": 0, "N": (M + m) * g}


def test_second_form_of_the_lagrangian_has_the_sign_of_the_cross_term_flipped():
    # printed minus derived = 2 R m r theta'^2 cos(theta): + 2 r R cos where - 2 r R cos belongs
    pub = {p.label: p for p in problem.published()}["(a) L, second form"]
    diff = pub.printed[0] - pub.reference[0]
    assert sp.simplify(diff - 2 * R * m * r * D(theta)**2 * sp.cos(theta)) == 0
