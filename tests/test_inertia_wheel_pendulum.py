"""Inertia-wheel pendulum (problems/inertia_wheel_pendulum.py): reactions, errata, linearisation."""
import random

import pytest
import sympy as sp

from dualmech import t
from dualmech.verify.check import compare
from dualmech.model.dimensions import audit
from dualmech.model.equations import to_plain
from dualmech.exact.form import ExactForm
from dualmech.problems.inertia_wheel_pendulum import (I1, I2, InertiaWheelPendulum, g, hand_reactions, l1,
                                             l_c1, m1, m2, q1, q2, tau)

problem = InertiaWheelPendulum()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
J = I1 + m1 * l_c1**2 + m2 * l1**2
M = m1 * l_c1 + m2 * l1


def _identically_zero(expr) -> bool:
    """Exact rational-point test (dualmech.exact.form): zero at 4 random points, else False."""
    plain = to_plain(expr, (q1, q2))
    form = ExactForm.build([plain], sorted(plain.free_symbols, key=str))
    assert form.method == "exact"
    rng = random.Random(5)
    return all(form.evaluate(form.sample(rng)) == [0] for _ in range(4))


@pytest.fixture(scope="module")
def comparison():
    return compare(problem)


def test_declaration_validates():
    problem.validate()
    assert problem.model_names == ["newton_euler", "lagrange", "multiplier"]
    assert problem.dimension_issues() == []


def test_motor_torque_reacts_on_the_rod():
    # hand: J q1'' = -tau - M g sin(q1),  I2 (q1'' + q2'') = tau
    acc = problem.model("lagrange").accelerations_solved()
    assert sp.simplify(acc[DD(q1)] + (tau + M * g * sp.sin(q1)) / J) == 0
    assert sp.simplify(acc[DD(q1)] + acc[DD(q2)] - tau / I2) == 0


def test_pivot_and_bearing_forces_are_the_hand_derived_ones(comparison):
    # the hand reactions and the Lagrange accelerations satisfy every free-body equation
    # exactly; the direct system is regular, so they are its reactions
    acc = problem.model("lagrange").accelerations_solved()
    known = dict(acc)
    known.update({sp.Symbol(k, real=True): v for k, v in hand_reactions(acc[DD(q1)]).items()})
    for label, eq in zip(problem.model("newton_euler").labels,
                         problem.model("newton_euler").equations):
        assert _identically_zero(eq.xreplace(known)), label
    (pair,) = [p for p in comparison.pairs if p.kind == "reactions"]
    assert pair.equivalent and set(pair.reactions) == {"R_x", "R_y", "F_x", "F_y"}


def test_a_free_wheel_adds_nothing_to_the_pendulums_frequency():
    # with tau = 0 the library's linearisation about q = 0 gives omega^2 = M g / J for the
    # swing and 0 for the free spin: I2 drops out (hand: I2 (q1' + q2') is conserved)
    free = problem.model("lagrange").substitute({tau: 0})
    omegas = free.natural_frequencies()
    assert sorted(sp.simplify(w**2 - M * g / J) == 0 for w in omegas) == [False, True]
    assert any(w == 0 for w in omegas)


def _printed(label):
    return next(p for p in problem.published() if p.label == label).printed


def test_printed_q1_equation_misses_the_square_on_l_c1():
    (eq,) = _printed("(d) q1 equation")
    issues = audit(eq, problem.dimensions())
    assert [i.term for i in issues] == ["l_c1*m1*q1''"]   # in the notation people read
    fixed = eq - m1 * l_c1 * DD(q1) + m1 * l_c1**2 * DD(q1)
    assert sp.simplify(fixed.xreplace(problem.model("lagrange").accelerations_solved())) == 0


EXPECTED = {
    "(a) generalised forces": "correct",
    "(b) angular velocities": "correct",
    "(b) positions and velocities": "correct",
    "(c) T1, T2": "correct",
    "(c) U1, U2": "correct",
    "(d) dL/dq1'": "wrong",                 # l_c1 not squared; q1'' for q1'
    "(d) dL/dq1": "correct",
    "(d) q1 equation": "wrong",             # m1 l_c1 q1'' must be m1 l_c1^2 q1''
    "(d II) dL/dq2', dL/dq2": "wrong",      # I2 (q1'' + q2'') for I2 (q1' + q2')
    "(d II) q2 equation": "correct",
    "(d) equations of motion": "wrong",     # the set holds the wrong q1 equation
}


def test_published_verdicts(comparison):
    assert comparison.equivalent, str(comparison)
    assert {v.label: v.verdict for v in comparison.published} == EXPECTED
