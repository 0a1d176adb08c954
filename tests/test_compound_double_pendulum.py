"""Compound double pendulum (problems/compound_double_pendulum.py): hinge force, errata."""
import sympy as sp

from dualmech import t
from dualmech.problems.compound_double_pendulum import (CompoundDoublePendulum, I0, a, b, g, m,
                                               printed_reduced, scene, theta1, theta2)

problem = CompoundDoublePendulum()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731


def test_angular_momentum_of_the_body_about_the_pivot_it_is_not_pinned_to():
    # hand: h_O . k = I0 th2' + m (r_OG x v_G) . k
    #              = I0 th2' + m (a^2 th1' + b^2 th2' + a b (th1' + th2') cos(th1 - th2));
    # the pivot O is not a point of the body, so I_O w (+ m r_OG x v_O, v_O = 0) would be wrong
    sc = scene()
    h = sc.body.angular_momentum(sc.o, sc.O).dot(sc.O.z)
    w1, w2 = D(theta1), D(theta2)
    hand = I0 * w2 + m * (a**2 * w1 + b**2 * w2 + a * b * (w1 + w2) * sp.cos(theta1 - theta2))
    assert sp.simplify(h - hand) == 0


def test_light_link_carries_the_hinge_force_along_itself():
    # link, moments about O: (r_A x (-R)) . k = -a (R_x cos th1 + R_y sin th1) = 0
    ne = problem.model("newton_euler")
    R_x, R_y = ne.unknowns
    (eq,) = [e for lab, e in zip(ne.labels, ne.equations) if "(link)" in lab]
    assert sp.simplify(eq + a * (R_x * sp.cos(theta1) + R_y * sp.sin(theta1))) == 0


def _hinge_force_at(state):
    """``(R_x, R_y)`` of the direct form at a state, solved exactly."""
    ne = problem.model("newton_euler")
    rates = {DD(theta1): sp.Symbol("al1"), DD(theta2): sp.Symbol("al2")}
    for q, (angle, rate) in state.items():
        rates[D(q)] = rate
    eqs = [e.xreplace(rates).xreplace({q: s[0] for q, s in state.items()})
           for e in ne.equations]
    sol = sp.solve(eqs, [*ne.unknowns, sp.Symbol("al1"), sp.Symbol("al2")], dict=True)[0]
    return tuple(sp.simplify(sol[u]) for u in ne.unknowns)


def test_hinge_force_with_both_links_hanging_and_turning():
    # hand: at th1 = th2 = 0 the accelerations vanish (the sin terms do), so
    # a_G = (a w1^2 + b w2^2) j and R = (0, m (g + a w1^2 + b w2^2))
    w1, w2 = sp.symbols("w1 w2", real=True)
    R_x, R_y = _hinge_force_at({theta1: (0, w1), theta2: (0, w2)})
    assert R_x == 0
    assert sp.simplify(R_y - m * (g + a * w1**2 + b * w2**2)) == 0


def test_theta1_divided_through_keeps_an_a_in_the_gravity_term():
    # Lagrange theta1 / (m a) is a th1'' + b th2'' cos + b th2'^2 sin + g sin th1
    lag = problem.model("lagrange").equations[0] / (m * a)
    e1, _ = printed_reduced()
    assert sp.simplify(e1 - lag - g * (a - 1) * sp.sin(theta1)) == 0


def test_theta2_finally_needs_I0_2mb2_and_then_only_its_gravity_term_is_wrong():
    lag = problem.model("lagrange").equations[1]
    _, e2 = printed_reduced()
    # with I0 + m b^2 = 3 m b^2 the printed inertia and velocity terms are Lagrange / (m b) ...
    assert sp.simplify(e2 - lag.subs(I0, 2 * m * b**2) / (m * b)
                       - g * (b - 1) * sp.sin(theta2)) == 0
    # ... and the only wrong term is g b sin(th2), for g sin(th2)
    corrected = e2 - g * b * sp.sin(theta2) + g * sp.sin(theta2)
    assert sp.simplify(corrected - lag.subs(I0, 2 * m * b**2) / (m * b)) == 0
    # read as I0 = 3 m b^2 instead, the theta2'' coefficient would be 4 b, not 3 b
    assert sp.simplify(lag.subs(I0, 3 * m * b**2).diff(DD(theta2)) / (m * b)) == 4 * b
