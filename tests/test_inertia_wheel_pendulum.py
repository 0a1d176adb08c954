"""Inertia-wheel pendulum (problems/inertia_wheel_pendulum.py): reactions, errata, linearisation."""
import random

import sympy as sp

from dualmech import t
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


def test_motor_torque_reacts_on_the_rod():
    # hand: J q1'' = -tau - M g sin(q1),  I2 (q1'' + q2'') = tau
    acc = problem.model("lagrange").accelerations_solved()
    assert sp.simplify(acc[DD(q1)] + (tau + M * g * sp.sin(q1)) / J) == 0
    assert sp.simplify(acc[DD(q1)] + acc[DD(q2)] - tau / I2) == 0


def test_pivot_and_bearing_forces_are_the_hand_derived_ones():
    # the hand reactions and the Lagrange accelerations satisfy every free-body equation
    # exactly; the direct system is regular, so they are its reactions
    acc = problem.model("lagrange").accelerations_solved()
    known = dict(acc)
    known.update({sp.Symbol(k, real=True): v for k, v in hand_reactions(acc[DD(q1)]).items()})
    for label, eq in zip(problem.model("newton_euler").labels,
                         problem.model("newton_euler").equations):
        assert _identically_zero(eq.xreplace(known)), label


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

