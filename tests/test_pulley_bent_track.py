"""Two masses and a pulley on a bent track (problems/pulley_bent_track.py): tensions, tracks."""
import numpy as np
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.pulley_bent_track import (M1, M2, PulleyBentTrack, c, drive, g, hand_reactions, k,
                                        m, scene, theta0, x)

_EPS = np.finfo(float).eps
problem = PulleyBentTrack()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def test_string_moves_with_both_masses_and_the_pulley_rim():
    # M1 and M2 move x'; the rim points where the string leaves turn with speed x' along it
    s = scene()
    O, S = s.O, s.S
    w = s.P.ang_vel_in(O)
    assert sp.simplify(s.p1.vel(O).dot(O.x) - D(x)) == 0
    assert sp.simplify(s.p2.vel(O).dot(S.x) - D(x)) == 0
    rim1 = w.cross(s.A1.pos_from(s.centre))          # towards the pulley along +I
    rim2 = w.cross(s.A2.pos_from(s.centre))          # down the incline along e
    assert sp.simplify(rim1.dot(O.x) - D(x)) == 0
    assert sp.simplify(rim2.dot(S.x) - D(x)) == 0


def test_equation_of_motion_is_the_hand_derived_one():
    # (M1 + M2 + m/2) x'' = -k x - c x' + M2 g sin(theta0) + F(t) cos(theta0)
    (acc,) = problem.model("lagrange").accelerations_solved().values()
    hand = (-k * x - c * D(x) + M2 * g * sp.sin(theta0) + drive * sp.cos(theta0)) \
        / (M1 + M2 + m / 2)
    assert sp.simplify(acc - hand) == 0


@settings(max_examples=40)
@given(points(problem))
def test_tensions_and_track_forces_are_the_hand_derived_ones(point):
    # T1 = M1 x'' + c x' + k x, T2 = T1 + m x''/2, N1 = M1 g,
    # N2 = M2 g cos(theta0) - F(t) sin(theta0)                      (module docstring)
    eqs = problem.model("newton_euler")
    A, b = NumericModel(eqs, point.params).system(point.time, point.q, point.qd)
    sol = np.linalg.solve(A, b)
    got = dict(zip([u.name for u in eqs.unknowns], sol[1:]))
    subs = dict(point.params)
    subs.update({D(x, 2): sol[0], D(x): point.qd[0], x: point.q[0], t: point.time})
    tol = 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.max(np.abs(b))))
    for name, expr in hand_reactions().items():
        hand = float(expr.subs(subs))
        assert abs(got[name] - hand) <= tol * max(1.0, abs(hand)), name
