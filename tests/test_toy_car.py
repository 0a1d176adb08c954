"""Toy car on a rotating track (problems/toy_car.py): four derivations, reaction, errata."""
import dataclasses

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.verify.check import compare_models, reaction_pairs
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.toy_car import R, ToyCar, coriolis_term, frames, g, m, phi, theta

_EPS = np.finfo(float).eps
problem = ToyCar()


@pytest.fixture
def comparison(compared):
    return compared("toy_car")


def test_frames_follow_the_source_conventions():
    f = frames()
    # K x k_A = sin(phi) I and k_A x k_B = sin(theta) j_A
    assert (f.O.z.cross(f.A.z) - sp.sin(phi) * f.O.x).is_zero()
    assert (f.A.z.cross(f.B.z) - sp.sin(theta) * f.A.y).is_zero()


def test_coriolis_term_is_minus_two_R_phidot_thetadot_sin_theta_j_B():
    # hand: v_rel = d/dt|_A (-R k_B) = -R theta' i_B, w_A = phi' I, I x i_B = sin(theta) j_B
    f = frames()
    expected = -2 * R * phi.diff(t) * theta.diff(t) * sp.sin(theta) * f.B.y
    diff = coriolis_term(f) - expected
    assert all(sp.simplify(c) == 0 for c in diff.express(f.B).components)


def test_mass_matrix_is_singular_only_where_cos_theta_vanishes():
    det = problem.model("lagrange").mass_matrix().det()
    assert sp.simplify(det - m**2 * R**4 * sp.cos(theta)**2) == 0
    assert problem.singular == (sp.cos(theta),)
    lo, hi = problem.coordinate_info(theta).range
    assert -np.pi / 2 < lo < hi < np.pi / 2


def test_small_oscillations_about_the_bottom_have_the_simple_pendulum_frequency():
    # both angles swing the car like a simple pendulum of length R: omega^2 = g / R
    M, C, K = problem.model("lagrange").linearize()
    assert C == sp.zeros(2, 2)
    assert M == m * R**2 * sp.eye(2) and K == m * g * R * sp.eye(2)


@settings(max_examples=60)
@given(points(problem))
def test_recovered_reaction_is_the_printed_answer_10(point):
    # (10): F_r = m (g cos(phi) cos(theta) + R phi'^2 cos^2(theta) + R theta'^2), hand-checked
    nm = NumericModel(problem.model("newton_euler"), point.params)
    A, b = nm.system(point.time, point.q, point.qd)
    F_r = np.linalg.solve(A, b)[2]
    p = {str(k): v for k, v in point.params.items()}
    (th, ph), (thd, phd) = point.q, point.qd
    hand = p["m"] * (p["g"] * np.cos(ph) * np.cos(th) + p["R"] * phd**2 * np.cos(th)**2
                     + p["R"] * thd**2)
    tol = 16 * _EPS * np.linalg.cond(A) * max(1.0, abs(hand), float(np.max(np.abs(b))))
    assert abs(F_r - hand) <= tol


def test_car_at_rest_at_the_bottom_feels_its_weight():
    F = problem.model("newton_euler").reactions_solved()[sp.Symbol("F_r", real=True)]
    rest = {theta.diff(t): 0, phi.diff(t): 0}
    assert sp.simplify(F.subs(rest).subs({theta: 0, phi: 0}) - m * g) == 0


def test_comparators_reaction_is_the_printed_answer_10(comparison):
    # F_r of the free-body diagram, compared with the multiplier of the constraint R - rho = 0
    assert comparison.reaction_derivations == {"F_r": ["newton_euler", "multiplier"]}
    F = comparison.reactions["F_r"]
    printed = m * (g * sp.cos(phi) * sp.cos(theta) + R * phi.diff(t)**2 * sp.cos(theta)**2
                   + R * theta.diff(t)**2)
    assert sp.simplify(F - printed) == 0


@pytest.mark.parametrize("model", ["newton_euler", "angular_momentum"])
@pytest.mark.parametrize("ingredient", ["gravity on car", "inertia of car"])
def test_comparator_catches_a_flipped_ingredient(model, ingredient):
    broken = problem.model(model).flipped(ingredient)
    result = compare_models(problem.model("lagrange"), broken, explain=False)
    assert not result.equivalent and result.method == "exact"


def test_multiplier_of_the_track_constraint_is_the_direct_reaction():
    # rho: m rho'' - m rho (theta'^2 + phi'^2 cos^2) - m g cos(theta) cos(phi) + F_r = 0 at rho = R
    (pair,) = reaction_pairs(problem)
    assert {pair.reference, pair.candidate} == {"newton_euler", "multiplier"}
    assert pair.equivalent and pair.method == "exact"


@pytest.mark.parametrize("broken", ["newton_euler", "multiplier"])
def test_a_break_that_leaves_the_motion_alone_shows_in_the_reaction(broken):
    # the car's motion does not depend on m: doubling m in the free-body diagram only, or
    # writing the constraint as rho - R (flipping F_r), changes F_r and nothing else
    models = dict(problem.models())
    if broken == "newton_euler":
        models[broken] = models[broken].substitute({m: 2 * m})
    else:  # keep the name: it selects the coordinate map rho -> R
        models[broken] = dataclasses.replace(models[broken].flipped("constraint F_r"),
                                             name=broken)
    moved = problem.in_reference_coordinates(models[broken])
    assert compare_models(problem.model("lagrange"), moved, explain=False).equivalent
    (pair,) = reaction_pairs(problem, models)
    assert not pair.equivalent


def test_the_problem_pickles_with_its_models_built():
    # the grader keeps a problem's context on disk: the problem pickles once its models,
    # printed answers and quantities are built, and comes back with the same equations
    import pickle
    a = ToyCar()
    a.models(), a.published(), a.quantities()
    back = pickle.loads(pickle.dumps(a, protocol=5))
    assert set(back.model("lagrange").equations) == set(a.model("lagrange").equations)
