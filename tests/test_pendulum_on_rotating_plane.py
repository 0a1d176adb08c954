"""Pendulum on a rotating plane (problems/pendulum_on_rotating_plane.py): the normal force."""
import random

import pytest
import sympy as sp

from dualmech import t
from dualmech.verify.check import compare
from dualmech.model.dimensions import audit
from dualmech.model.equations import to_plain
from dualmech.exact.form import ExactForm
from dualmech.problems.pendulum_on_rotating_plane import (N, Omega, PendulumOnRotatingPlane, alpha, beta0,
                                                 c, g, hand_rod_force, l, m, plane_angle, theta)

problem = PendulumOnRotatingPlane()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
S = sp.Symbol("S", real=True)


def _identically_zero(expr) -> bool:
    """Exact rational-point test (dualmech.exact.form) at 4 random points."""
    plain = to_plain(expr, (theta,))
    form = ExactForm.build([plain], sorted(plain.free_symbols, key=str))
    assert form.method == "exact"
    rng = random.Random(11)
    return all(form.evaluate(form.sample(rng)) == [0] for _ in range(4))


@pytest.fixture(scope="module")
def comparison():
    return compare(problem)


def test_declaration_validates():
    problem.validate()
    assert problem.model_names == ["newton_euler", "lagrange", "multiplier", "contact_velocity"]
    assert problem.dimension_issues() == []
    # beta is prescribed: theta is the only free coordinate of every model once mapped
    for m_ in problem.models().values():
        assert problem.in_reference_coordinates(m_).coordinates == (theta,)


def test_normal_force_of_the_free_body_diagram_and_both_multipliers_agree(comparison):
    (pair,) = [p for p in comparison.pairs if p.kind == "reactions" and "N" in p.reactions]
    assert pair.equivalent and pair.method == "exact"
    names = " ".join(f"{p.reference} {p.candidate}" for p in comparison.pairs
                     if p.kind == "reactions")
    assert all(n in names for n in ("newton_euler", "multiplier", "contact_velocity"))


def test_rod_force_is_derived_twice_and_agrees(comparison):
    # the multiplier model frees the rod's length too: S by a second derivation
    (pair,) = [p for p in comparison.pairs if p.kind == "reactions" and "S" in p.reactions]
    assert pair.equivalent and pair.method == "exact" and pair.candidate == "multiplier"
    assert comparison.not_cross_checked == []


def test_rod_and_normal_force_satisfy_the_free_body_equations_by_hand():
    # hand (module docstring): N = m g cos(beta) + m (beta'' lever + 2 beta' l sin th th')
    bt = plane_angle()
    lever = c - l * sp.cos(theta)
    N_hand = m * g * sp.cos(bt) + m * (bt.diff(t, 2) * lever
                                       + 2 * bt.diff(t) * l * sp.sin(theta) * D(theta))
    known = dict(problem.model("lagrange").accelerations_solved())
    known.update({N: N_hand, S: hand_rod_force()})
    for label, eq in zip(problem.model("newton_euler").labels,
                         problem.model("newton_euler").equations):
        assert _identically_zero(eq.xreplace(known)), label


def test_plane_at_rest_is_an_incline_pendulum():
    # Omega = alpha = 0: l th'' + g sin(beta0) sin(th) = 0, so omega^2 = g sin(beta0)/l
    still = problem.model("lagrange").substitute({Omega: 0, alpha: 0})
    (w,) = still.natural_frequencies()
    assert sp.simplify(w**2 - g * sp.sin(beta0) / l) == 0
    N_rest = problem.model("newton_euler").substitute({Omega: 0, alpha: 0}).reactions_solved()[N]
    assert sp.simplify(N_rest - m * g * sp.cos(beta0)) == 0


EXPECTED = {
    "(a) r_rel, v_rel, w": "correct",
    "(a) V_xyz": "correct",
    "(a) X and Z in x, y, z": "correct",
    "(a) v": "wrong",                    # theta'' printed where theta' belongs
    "(b) T": "correct",
    "(c) V, L": "correct",
    "(d) constraint v_z": "correct",
    "(d) theta: dL/dtheta', d/dt, dL/dtheta": "correct",
    "(d) theta equation": "correct",
    "(d) equation of motion": "correct",
    "(d) beta: dL/dbeta', d/dt, dL/dbeta": "correct",
    "(d) beta equation with lambda_B": "correct",
    "(d) normal force lambda_B": "correct",
}


def test_published_verdicts(comparison):
    assert comparison.equivalent, str(comparison)
    assert {v.label: v.verdict for v in comparison.published} == EXPECTED
    # the slip shows in the dimensions: theta'' beside beta' (c - l cos(theta))
    v = next(p for p in problem.published() if p.label == "(a) v")
    issues = audit(v.printed[0] - v.reference[0], problem.dimensions())
    assert issues and "theta''" in str(issues[0])
