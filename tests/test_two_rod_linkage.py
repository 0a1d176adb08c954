"""Two-rod linkage on a sprung slider (problems/two_rod_linkage.py): theta and x, F_R, errata."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.verify.check import compare, compare_models
from dualmech.model.equations import to_plain
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.two_rod_linkage import (M, TwoRodLinkage, c, g, k, l, l0, m, scene, theta, x)

_EPS = np.finfo(float).eps
problem = TwoRodLinkage()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def _at_pythagorean_angle(expr, sin_value):
    """``expr`` (in theta) at cos(theta) = 3/5, sin(theta) = sin_value (+-4/5): exact, and
    sqrt(4 l^2 sin^2) evaluates to 8 l/5 whatever the sign of sin(theta)."""
    plain = to_plain(sp.expand_trig(expr), (theta,))
    th = sp.Symbol("theta", real=True)
    return sp.simplify(plain.subs({sp.cos(th): sp.Rational(3, 5), sp.sin(th): sin_value}))


def test_geometry_is_the_sources():
    # O r_A = l (cos, sin), O r_B = 2 l cos(theta) I; x = 2 l cos(theta) - l0 (quiz 2, (a))
    s = scene()
    assert [sp.simplify(v) for v in s.pA.pos_from(s.o).express(s.O).components] == \
        [l * sp.cos(theta), l * sp.sin(theta), 0]
    assert [sp.simplify(v) for v in s.pB.pos_from(s.o).express(s.O).components] == \
        [2 * l * sp.cos(theta), 0, 0]
    assert problem.coordinate_maps()["lagrange_x"] == {x: 2 * l * sp.cos(theta) - l0}


def test_theta_form_mass_matrix_is_regular_and_x_form_blows_up_where_sin_vanishes():
    # theta: m l^2 + 4 M l^2 sin^2 > 0.  x: M + m l^2/D with D = 4 l^2 - (l0 + x)^2, and on
    # the map D = 4 l^2 sin^2(theta): infinite where the rods fold flat (sin(theta) = 0)
    assert sp.expand(problem.model("lagrange").mass_matrix()[0]
                     - (m * l**2 + 4 * M * l**2 * sp.sin(theta)**2)) == 0
    Dx = 4 * l**2 - (l0 + x)**2
    assert sp.simplify(problem.model("lagrange_x").mass_matrix()[0] - (M + m * l**2 / Dx)) == 0
    on_map = Dx.subs(x, 2 * l * sp.cos(theta) - l0)
    assert sp.simplify(on_map - 4 * l**2 * sp.sin(theta)**2) == 0
    assert problem.singular == (sp.sin(theta),)
    lo, hi = problem.coordinate_info(theta).range
    assert 0 < lo < hi < np.pi


def test_x_equation_is_the_hand_derived_one():
    # module docstring: M x'' + m l^2 (x''/D + (l0 + x) x'^2/D^2) + c x' + k x
    #                   = m g (l0 + x)/(2 sqrt(D))
    Dx = 4 * l**2 - (l0 + x)**2
    hand = (M * D(x, 2) + m * l**2 * (D(x, 2) / Dx + (l0 + x) * D(x)**2 / Dx**2) + c * D(x)
            + k * x - m * g * (l0 + x) / (2 * sp.sqrt(Dx)))
    (eq,) = problem.model("lagrange_x").equations
    assert sp.simplify(eq - hand) == 0


@pytest.mark.parametrize("sin_value, same", [(sp.Rational(4, 5), True),
                                             (sp.Rational(-4, 5), False)])
def test_x_form_describes_the_upper_branch_only(sin_value, same):
    # sqrt(D) = 2 l |sin(theta)|: the x form is the theta form where m is above the line, and
    # with sin(theta) < 0 its gravity term has the wrong sign (m would hang below the line)
    ref = problem.model("lagrange").accelerations_solved()[D(theta, 2)]
    mapped = problem.in_reference_coordinates(problem.model("lagrange_x"))
    (eq,) = mapped.equations
    lhs = eq.subs(D(theta, 2), ref)
    assert (_at_pythagorean_angle(lhs, sin_value) == 0) is same


def test_without_the_declared_domain_the_x_form_is_a_different_motion():
    # over every real theta, sqrt(4 l^2 sin^2(theta)) is 2 l |sin(theta)|: the comparator must
    # refuse to call the x form equivalent when it is not told that m stays above the line
    mapped = problem.in_reference_coordinates(problem.model("lagrange_x"))
    result = compare_models(problem.model("lagrange"), mapped, explain=False)
    assert not result.equivalent


def test_printed_x_equation_misses_a_factor_half_and_has_the_wrong_sign_of_x():
    # on the motion the printed left side is the true one plus
    # m g ((l0 + x)/2 - (l0 - x))/sqrt(D); at cos = 3/5, sin = 4/5: x + l0 = 6 l/5, sqrt(D) = 8 l/5
    pub = {p.label: p for p in problem.published()}["(b) x equation"]
    ref = problem.model("lagrange").accelerations_solved()[D(theta, 2)]
    on_x = pub.printed[0]
    x_th = 2 * l * sp.cos(theta) - l0
    printed = on_x.subs({D(x, 2): D(x_th, 2), D(x): D(x_th)}).subs(x, x_th)
    value = _at_pythagorean_angle(printed.subs(D(theta, 2), ref), sp.Rational(4, 5))
    xv = 6 * l / 5 - l0
    hand = m * g * ((l0 + xv) / 2 - (l0 - xv)) / (8 * l / 5)
    assert sp.simplify(value - hand) == 0


@settings(max_examples=40)
@given(points(problem))
def test_bar_force_and_shaft_force_are_the_hand_derived_ones(point):
    # M, I:  F_R cos(theta) = M x'' + c x' + k x   (the source's (B));
    # M, J:  N = M g + F_R sin(theta)
    nm = NumericModel(problem.model("newton_euler"), point.params)
    A, b = nm.system(point.time, point.q, point.qd)
    sol = np.linalg.solve(A, b)
    thdd = sol[0]
    names = [u.name for u in problem.model("newton_euler").unknowns]
    F_R, N = sol[1 + names.index("F_R")], sol[1 + names.index("N")]
    p = {str(s): v for s, v in point.params.items()}
    (th,), (thd,) = point.q, point.qd
    xv = 2 * p["l"] * np.cos(th) - p["l0"]
    xd = -2 * p["l"] * thd * np.sin(th)
    xdd = -2 * p["l"] * (thdd * np.sin(th) + thd**2 * np.cos(th))
    rhs = p["M"] * xdd + p["c"] * xd + p["k"] * xv
    scale = max(1.0, float(np.max(np.abs(b))), abs(F_R))
    tol = 64 * _EPS * np.linalg.cond(A) * scale
    assert abs(F_R * np.cos(th) - rhs) <= tol
    assert abs(N - p["M"] * p["g"] - F_R * np.sin(th)) <= tol


def test_middle_form_of_V_counts_the_spring_from_O_instead_of_from_its_free_length():
    # k |r_B|^2/2 - k (|r_B| - l0)^2/2 = k l0 (2 l cos(theta) - l0/2)
    pub = {p.label: p for p in problem.published()}["(b) V, middle form"]
    diff = pub.printed[0] - pub.reference[0]
    assert sp.simplify(diff - k * l0 * (2 * l * sp.cos(theta) - l0 / 2)) == 0


def test_printed_bar_force_in_theta_is_short_of_the_spring_free_length():
    # printed minus derived = k l0 (I - tan(theta) J): exact, at a rational state with
    # cos = 3/5, sin = 4/5 and the reactions of the direct form solved in rationals
    pub = {p.label: p for p in problem.published()}["(B) F_R in theta"]
    values = {M: 2, m: sp.Rational(1, 2), k: 40, c: sp.Rational(3, 2), l: 1,
              l0: sp.Rational(3, 5), g: sp.Rational(981, 100), D(theta): sp.Rational(7, 3)}
    ne = problem.model("newton_euler")
    A, b = ne.matrix()
    th = sp.Symbol("theta", real=True)
    at = lambda e: sp.expand_trig(e.subs(values).subs(theta, th).rewrite(sp.cos)).subs(  # noqa
        {sp.cos(th): sp.Rational(3, 5), sp.sin(th): sp.Rational(4, 5)})
    sol = A.applyfunc(at).LUsolve(b.applyfunc(at))
    state = dict(zip(ne.accelerations + ne.unknowns, sol))
    for printed, derived, expected in zip(pub.printed, pub.reference,
                                          (k * l0, -k * l0 * sp.Rational(4, 3))):
        assert at((printed - derived).subs(state)) == at(expected)


class _SpuriousRadial(TwoRodLinkage):
    """The direct form with a spurious ``m l theta'^2`` on m along the rod OA (``i_A``): a
    student's centripetal term counted as a force.  It changes only ``F_L``."""

    def newton_euler(self):
        from dualmech import NewtonEuler
        s = scene()
        O = s.O
        ne = NewtonEuler(coordinates=[theta], ground=O)
        ne.gravity(-g * O.y)
        ne.linear_spring("spring", s.slider, k, s.x, O.x)
        ne.linear_damper("dashpot", s.slider, c, s.x.diff(t), O.x)
        ne.reaction("N", s.slider, O.y)
        ne.reaction("F_R", s.slider, s.R.x, against=s.bob)
        ne.reaction("F_L", s.bob, s.A.x)
        ne.force("spurious", s.bob, m * l * D(theta)**2 * s.A.x)
        for body in (s.bob, s.slider):
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        return ne.equations()


@pytest.mark.slow
def test_spurious_radial_term_in_the_direct_form_is_caught_by_the_second_F_L():
    broken = compare(_SpuriousRadial())
    motion = [p for p in broken.pairs if p.kind == "motion"]
    assert all(p.equivalent for p in motion)            # the motion is untouched ...
    assert not broken.equivalent                        # ... but F_L now disagrees
    (pair,) = [p for p in broken.pairs if p.kind == "reactions"]
    assert not pair.equivalent
    assert [mm.equation for mm in pair.mismatches] == ["reaction F_L"] * len(pair.mismatches)
    assert "DIFFERENT" in str(broken) and "all derivations agree" not in str(broken)


@pytest.mark.slow
def test_reaction_only_mismatch_is_explained_with_values_and_the_term():
    broken = compare(_SpuriousRadial())
    (pair,) = [p for p in broken.pairs if p.kind == "reactions"]
    ne = next(mm for mm in pair.mismatches if mm.model == "newton_euler")
    # a real state, both values of F_L, the row that breaks with the multiplier's F_L ...
    assert ne.state and "theta" in ne.state and np.isfinite(ne.value) and ne.value != 0
    assert "F_L = " in ne.reason and "`multiplier` gives" in ne.reason
    assert "sum F . O.y (m)" in ne.reason
    # ... whose value is the J part of the spurious term there, m l theta'^2 sin(theta)
    st = ne.state
    assert ne.value == pytest.approx(st["m"] * st["l"] * st["theta'"]**2 * np.sin(st["theta"]),
                                     rel=1e-12)
    # and symbolically exactly that term (with the multiplier's reactions substituted)
    # (the product's factors, in whatever order the printer puts them)
    assert sorted(ne.residual.replace("**", "^").split("*")) == \
        sorted(["l", "m", "theta'^2", "sin(theta)"])
    assert broken.to_dict()["mismatches"][0]["state"]
