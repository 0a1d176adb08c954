"""Rod-and-disk pendulum on a spring-mounted mass (problems/pendulum_on_mass.py)."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.verify.check import compare_models
from dualmech.numeric import NumericModel
from dualmech.testing import Point, assert_same_motion, points
from dualmech.problems.pendulum_on_mass import (M, PendulumOnMass, frames, g, k, m,
                                       pendulum_mass_properties, r, theta, y)

_EPS = np.finfo(float).eps
problem = PendulumOnMass()


@pytest.fixture
def comparison(compared):
    return compared("pendulum_on_mass")


def test_pendulum_inertia_about_the_pivot():
    # rod: 4/3 + 4 across; disk: 1/2 across a diameter, 1 about its normal; parallel axis 2m(5r)^2
    f = frames()
    assert pendulum_mass_properties().center == sp.Matrix([0, -4 * r, 0])
    I_A = f.pendulum.inertia_about(f.a)
    expected = m * r**2 * sp.diag(sp.Rational(335, 6), sp.Rational(1, 2), sp.Rational(169, 3))
    assert (I_A - expected).applyfunc(sp.simplify) == sp.zeros(3, 3)


def test_pivot_follows_the_source_geometry():
    # A r_B = 5r (sin(theta) I - cos(theta) J)
    f = frames()
    r_AB = f.b.pos_from(f.a).express(f.O).components
    assert (r_AB - 5 * r * sp.Matrix([sp.sin(theta), -sp.cos(theta), 0])).applyfunc(
        sp.simplify) == sp.zeros(3, 1)


def test_small_oscillations_about_the_static_equilibrium():
    # y_eq = (M + 3m) g / k; spring: omega^2 = k / (M + 3m); compound pendulum about A:
    # omega^2 = (3m g)(4r) / (169/3 m r^2) = 36 g / (169 r)
    y_eq = (M + 3 * m) * g / k
    Mm, C, K = problem.model("lagrange").linearize({y: y_eq, theta: 0})
    assert C == sp.zeros(2, 2)
    assert Mm == sp.diag(M + 3 * m, sp.Rational(169, 3) * m * r**2)
    assert K == sp.diag(k, 12 * m * g * r)


@pytest.mark.slow
def test_at_rest_in_equilibrium_the_pivot_carries_the_pendulum_weight():
    sol = problem.model("newton_euler").solve()
    rest = {y.diff(t): 0, theta.diff(t): 0}
    at = {y: (M + 3 * m) * g / k, theta: 0}
    F_N, F_Rx, F_Ry = sp.symbols("F_N F_Rx F_Ry", real=True)
    values = {u: sp.simplify(sol[u].subs(rest).subs(at)) for u in (F_N, F_Rx, F_Ry)}
    assert values == {F_N: 0, F_Rx: 0, F_Ry: -3 * m * g}   # on M: the pendulum pulls down


@settings(max_examples=60)
@given(points(problem))
def test_recovered_reactions_match_the_hand_formulas(point):
    # hand, from the free-body diagrams with the Lagrangian accelerations:
    #   F_Ry = M g - k y - M y''             (M, along J)
    #   F_Rx = -12 m r (theta'' cos(theta) - theta'^2 sin(theta))   (pendulum, along I)
    #   F_N = F_Rx                           (M, along I)
    ref = NumericModel(problem.model("lagrange"), point.params)
    A_l, b_l = ref.system(point.time, point.q, point.qd)
    ydd, thdd = np.linalg.solve(A_l, b_l)
    ne = NumericModel(problem.model("newton_euler"), point.params)
    A, b = ne.system(point.time, point.q, point.qd)
    F_N, F_Rx, F_Ry = np.linalg.solve(A, b)[2:]
    p = {str(s): v for s, v in point.params.items()}
    (yy, th), (_, thd) = point.q, point.qd
    hand_Rx = -12 * p["m"] * p["r"] * (thdd * np.cos(th) - thd**2 * np.sin(th))
    hand_Ry = p["M"] * p["g"] - p["k"] * yy - p["M"] * ydd
    scale = max(1.0, float(np.max(np.abs(b))), abs(hand_Rx), abs(hand_Ry),
                p["M"] * abs(ydd), p["k"] * abs(yy))
    tol = 64 * _EPS * (np.linalg.cond(A) + np.linalg.cond(A_l)) * scale
    assert abs(F_Rx - hand_Rx) <= tol
    assert abs(F_N - hand_Rx) <= tol
    assert abs(F_Ry - hand_Ry) <= tol


MOTION_INGREDIENTS = ["spring", "gravity on M", "gravity on pendulum", "inertia of M",
                      "inertia of pendulum"]


@pytest.mark.parametrize("ingredient", MOTION_INGREDIENTS)
def test_a_flipped_force_or_inertia_changes_the_motion(ingredient):
    # numeric, independent of the comparator: flipping any non-reaction term of the direct
    # model must move the accelerations away from the Lagrangian ones at an arbitrary state
    broken = problem.model("newton_euler").flipped(ingredient)

    class Broken(PendulumOnMass):
        def newton_euler(self):
            return broken

    point = Point(problem.defaults(), 0.37, (0.23, -0.61), (0.7, -1.3))
    with pytest.raises(AssertionError, match="newton_euler"):
        assert_same_motion(Broken(), point)


@pytest.mark.parametrize("ingredient", MOTION_INGREDIENTS)
def test_comparator_catches_a_flipped_force_or_inertia(ingredient):
    # regression: with int / int -> float in dualmech/exact/linalg.py the integer reaction matrix
    # made the least squares inexact and the flipped forces passed as equivalent
    broken = problem.model("newton_euler").flipped(ingredient)
    result = compare_models(problem.model("lagrange"), broken, explain=False)
    assert not result.equivalent and result.method == "exact"


def test_shaft_force_is_the_pivots_horizontal_force(comparison):
    # hand: M's balance along I, F_N = F_Rx; the multiplier model frees the shaft (x) and the
    # pivot (p, q), so each of F_N, F_Rx, F_Ry is derived twice
    assert comparison.reaction_derivations == {
        r: ["newton_euler", "multiplier"] for r in ("F_N", "F_Rx", "F_Ry")}
    assert sp.simplify(comparison.reactions["F_N"] - comparison.reactions["F_Rx"]) == 0
