"""Trolley with a pendulum (problems/trolley_pendulum.py): generalised forces, two coordinate options."""
import pytest
import sympy as sp

from dualmech import Frame, Point, rot_z, t
from dualmech.problems.trolley_pendulum import (F, P, TrolleyPendulum, X, a, energies, g,
                                       hand_generalised_forces, hand_tension, m, theta, x)

problem = TrolleyPendulum()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("trolley_pendulum")


def _virtual_work(coords, trolley_x):
    """``Q_j = F i . d v_pivot / d q'_j + P i . d v_bob / d q'_j`` from frames and points."""
    O = Frame.ground("O")
    arm = O.child("arm", rot_z(theta))
    pivot = Point.origin(O).locate("pivot", trolley_x * O.x)
    bob = pivot.locate("bob", -a * arm.y)
    loads = ((F * O.x, pivot), (P * O.x, bob))
    return [sp.simplify(sum(f.dot(p.vel(O).diff(D(q), O)) for f, p in loads)) for q in coords]


@pytest.mark.parametrize("option, coords, trolley_x, model", [
    ("x", (x, theta), x, "lagrange"),
    ("X", (X, theta), X - a * sp.sin(theta), "bob_coordinates"),
], ids=["trolley-position", "bob-position"])
def test_generalised_forces_are_the_virtual_work_of_F_and_P(option, coords, trolley_x, model):
    # the source's recipe: the work of a change delta q_j alone is Q_j delta q_j
    hand = hand_generalised_forces(option)
    assert [sp.simplify(v - h) for v, h in zip(_virtual_work(coords, trolley_x), hand)] == [0, 0]
    # and the models carry exactly these (they enter Lagrange's equation as -Q)
    parts = problem.model(model).contributions
    Q = [sp.expand(-(p.get("F on trolley", 0) + p.get("P on bob", 0))) for p in parts]
    assert [sp.simplify(q - h) for q, h in zip(Q, hand)] == [0, 0]


def test_theta_force_depends_on_which_other_coordinate_is_held():
    # at fixed x a change of theta moves the bob (P works); at fixed X it moves the trolley
    assert hand_generalised_forces("x")[1] == P * a * sp.cos(theta)
    assert hand_generalised_forces("X")[1] == -F * a * sp.cos(theta)


def test_rate_of_the_x_momentum_is_the_x_generalised_force():
    # section 3.1 applied: dT/dx' = (M + m) x' + m a theta' cos theta; x is cyclic, so its
    # rate is Q_x = F + P (conserved when F = P = 0)
    T, _ = energies()
    p_x = T.diff(D(x))
    acc = problem.model("lagrange").accelerations_solved()
    rate = p_x.diff(t).xreplace(acc)
    assert sp.simplify(rate - (F + P)) == 0


def test_rod_pull_from_both_derivations_is_the_hand_one(comparison):
    assert comparison.reaction_derivations == {"T": ["newton_euler", "multiplier"]}
    acc = problem.model("lagrange").accelerations_solved()
    assert sp.simplify(comparison.reactions["T"] - hand_tension().xreplace(acc)) == 0
    # at rest, hanging, no forces: the bob's weight
    still = comparison.reactions["T"].subs({D(theta): 0, theta: 0, F: 0, P: 0})
    assert sp.simplify(still - m * g) == 0


def test_comparator_names_the_momentum_where_a_force_belongs(comparison):
    verdicts = {v.label: v for v in comparison.published}
    # the wrong term is named: -dL/dx' = -(M + m) x' - m a theta' cos theta, a momentum
    detail = verdicts["Lagrange's equation, d/dt dL/dq' - dL/dq' = Q"].detail
    assert "dimensionally inconsistent" in detail and "M L T^-1" in detail
