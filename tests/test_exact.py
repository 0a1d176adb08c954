"""The exact rational-point evaluator (dualmech.exact.form)."""
import random
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
import sympy as sp

from dualmech.exact.form import ExactForm, SAMPLE_BITS

th, ph, w, tt, a = sp.symbols("theta phi omega t a")


def _values(exprs, symbols, seed=0):
    form = ExactForm.build(exprs, symbols)
    return form, form.evaluate(form.sample(random.Random(seed)))


@pytest.mark.parametrize("identity", [
    sp.sin(2 * th) - 2 * sp.sin(th) * sp.cos(th),
    sp.cos(th + ph) - (sp.cos(th) * sp.cos(ph) - sp.sin(th) * sp.sin(ph)),
    sp.sin(th) ** 2 + sp.cos(th) ** 2 - 1,
    sp.tan(th) * sp.cos(th) - sp.sin(th),
    sp.sin(w * tt + th) - sp.sin(w * tt) * sp.cos(th) - sp.cos(w * tt) * sp.sin(th),
    sp.cos(3 * th) - 4 * sp.cos(th) ** 3 + 3 * sp.cos(th),
], ids=["double", "sum", "pythagoras", "tan", "forcing", "triple"])
def test_trig_identities_vanish_exactly(identity):
    form, vals = _values([identity], [th, ph, w, tt])
    assert form.method == "exact"
    assert vals == [0]


@pytest.mark.parametrize("almost", [
    sp.sin(2 * th) - sp.sin(th) * sp.cos(th),          # a factor 2 lost
    sp.sin(th) ** 2 - sp.cos(th) ** 2 - 1,             # a sign flipped
    th - sp.sin(th),                                    # small-angle approximation
    sp.cos(w * tt) - sp.cos(tt),                        # a parameter dropped
], ids=["factor", "sign", "small-angle", "dropped"])
def test_non_identities_give_nonzero_exact_values(almost):
    form, vals = _values([almost], [th, w, tt])
    assert form.method == "exact"
    assert isinstance(vals[0], Fraction) and vals[0] != 0


def test_angle_and_its_sine_are_independent_variables():
    # k*theta + sin(theta) is not identically zero for any k: the angle itself and the point
    # on the circle are sampled independently (they are algebraically independent functions)
    form, vals = _values([3 * th + sp.sin(th)], [th])
    assert vals[0] != 0


@pytest.mark.parametrize("identity", [
    sp.sqrt(a) ** 2 - a,
    sp.exp(a) * sp.exp(-a) - 1,
    sp.exp(2 * a) - sp.exp(a) ** 2,
    sp.Float(0.5) * a - a / 2,                          # 0.5 is exactly 1/2 in binary
    sp.sin(th / 2) ** 2 - (1 - sp.cos(th)) / 2,         # half angle: the atom is theta/2
    sp.cosh(a) ** 2 - sp.sinh(a) ** 2 - 1,
], ids=["sqrt", "exp", "exp-double", "float", "half-angle", "hyperbolic"])
def test_roots_exponentials_and_floats_stay_exact(identity):
    form, vals = _values([identity], [a, th])
    assert form.method == "exact"
    assert vals == [0]
    assert form.false_equal_bound(5) < 1e-60


@pytest.mark.parametrize("expr", [sp.atan(a), sp.log(1 + a**2), a ** sp.Rational(1, 3)],
                         ids=["atan", "log", "cube-root"])
def test_what_leaves_the_exact_world_falls_back_to_intervals(expr):
    form = ExactForm.build([expr], [a, th])
    assert form.method == "interval"
    assert form.false_equal_bound(5) != form.false_equal_bound(5)  # nan: no probability claim
    assert "exact test not applicable" in form.notes[-1]


def test_undeclared_symbol_is_a_clear_error():
    with pytest.raises(ValueError, match="undeclared symbols"):
        ExactForm.build([a + th], [a])


def test_false_equal_bound_shrinks_with_points():
    form = ExactForm.build([sp.sin(th) * a**3], [th, a])
    one, eight = form.false_equal_bound(1), form.false_equal_bound(8)
    assert 0 < eight < one < 1e-15
    assert one == pytest.approx(form.degree / 2.0**SAMPLE_BITS)


def test_degree_bound_counts_circle_parametrisation():
    # sin(theta) = 2u/(1+u^2): numerator degree 1, denominator 2 -> total 3
    assert ExactForm.build([sp.sin(th)], [th]).degree == 3
    assert ExactForm.build([a**4], [a]).degree == 4


def test_degree_bound_counts_multiples_and_square_roots():
    # sin(5 theta) = Im((1 + iu)^10) / (1 + u^2)^5: degree <= 10 over 10
    assert ExactForm.build([sp.sin(5 * th)], [th]).degree == 20
    # sqrt(a^2 + 1): the norm (a^2 + 1 - r^2 style) doubles the weighted degree
    assert ExactForm.build([sp.sqrt(a**2 + 1)], [a]).degree == 2 * 1


# -- the pieces --------------------------------------------------------------------------------
def test_square_root_numbers_are_exact():
    from dualmech.exact.surds import Surd, independent
    r2, r3 = Surd.root(2), Surd.root(3)
    assert (r2 + r3) * (r2 - r3) == -1 and (r2 * r3) ** 2 == 6
    assert 1 / (1 + r2) == r2 - 1
    assert Surd.root(Fraction(9, 4)) == Fraction(3, 2)
    assert not independent([2, 8]) and independent([2, 3, 5])
    with pytest.raises(ValueError, match="not independent"):
        Surd.root(2) * Surd.root(8)


def test_multiples_are_powers_on_the_circle():
    from dualmech.exact.trig_values import world_values
    u = Fraction(2**61 - 1)
    (s1000, c1000), (s1, c1) = world_values([("circle", ((0, 1000),), None),
                                             ("circle", ((0, 1),), None)], {0: u})
    assert s1**2 + c1**2 == 1 and s1000**2 + c1000**2 == 1
    # de Moivre, checked with a different route: (c + i s)^1000 by repeated multiplication
    z = (c1, s1)
    acc = (Fraction(1), Fraction(0))
    for _ in range(10):
        acc = (acc[0] * z[0] - acc[1] * z[1], acc[0] * z[1] + acc[1] * z[0])
    (s10, c10), = world_values([("circle", ((0, 10),), None)], {0: u})
    assert (c10, s10) == acc


def test_points_cycle_through_branch_cases_and_say_where():
    from dualmech.exact.form import CASE
    form = ExactForm.build([sp.Abs(sp.cos(th))], [th])
    rng = random.Random(0)
    points = [form.sample(rng) for _ in range(form.points_needed(3))]
    assert len(form.cases) == 2 and sorted(p[CASE] for p in points) == [0, 0, 0, 1, 1, 1]
    assert {form.where(p) for p in points} == {"cos(theta) > 0", "cos(theta) < 0"}
    assert all(form.certain(p) for p in points)
    assert form.false_equal_bound(points) == form.false_equal_bound(6)
    only_first = [p for p in points if p[CASE] == 0]
    assert form.false_equal_bound(only_first) == 1.0       # the other case got no point
    assert "branch cases" in form.describe(6)


def test_interval_values_are_rigorous_and_zero_test_is_containment():
    from dualmech.exact.form import METHOD_NAMES, is_zero
    form = ExactForm.build([sp.atan(a) - sp.atan(a), sp.atan(a)], [a])
    assert form.method == "interval" and "evidence" in METHOD_NAMES["interval"]
    zero, value = form.evaluate({a: Fraction(1)})
    assert is_zero(zero) and not is_zero(value)
    import mpmath
    with mpmath.workdps(100):
        assert mpmath.mpf(value.a) <= mpmath.pi / 4 <= mpmath.mpf(value.b)
    assert value.delta < 1e-55


def test_linear_algebra_on_intervals_refuses_undecided_ranks():
    from mpmath import iv
    from dualmech.exact import linalg as la
    eps = iv.mpf([-1e-70, 1e-70])          # consistent with zero, not certainly zero
    assert la.solve_square([[iv.mpf(1), iv.mpf(1)], [iv.mpf(1), 1 + eps]], [1, 2]) is None
    _, piv, ambiguous = la.rref_info([[iv.mpf(1), iv.mpf(1)], [iv.mpf(1), 1 + eps]])
    assert piv == [0] and ambiguous == [1]
    from dualmech.exact.form import is_zero
    res, _, undetermined = la.residual_after_least_squares([[iv.mpf(1)], [eps]], [0, 1])
    assert undetermined == [] and not is_zero(res[1])       # a certain residual
    res, _, undetermined = la.residual_after_least_squares([[eps], [eps]], [1, 1])
    assert undetermined == [0] and all(v.a <= 0 <= v.b for v in res)   # claims nothing


def test_display_method_keeps_the_working_ranges():
    form = ExactForm.build([sp.sin(th)], [th], force_mp=True)
    rng = random.Random(0)
    assert form.method == "mpmath" and not form.certain({})
    assert all(-1.2 <= form.sample(rng, {th: (-1.2, 1.2)})[th] <= 1.2 for _ in range(50))


@pytest.mark.parametrize("engine", ["flint", "integers"])
@settings(max_examples=40, deadline=None)
@given(st.integers(1, 6), st.integers(1, 7), st.integers(0, 3), st.integers(0, 2**32 - 1))
def test_fraction_free_rref_is_the_reduced_echelon_form(engine, m, n, deficiency, seed):
    """Exact rows go through FLINT's rational reduction, or without it through integer
    (fraction-free) Gauss--Jordan; the reduced echelon form is unique, so either must equal
    sympy's ``Matrix.rref`` (an independent implementation), also for rank-deficient
    matrices (rows built as combinations of others)."""
    from unittest import mock
    from dualmech.exact import linalg
    if engine == "integers":
        with mock.patch.object(linalg, "flint", None):
            _check_rref(linalg.rref_info, m, n, deficiency, seed)
    else:
        assert linalg.flint is not None
        _check_rref(linalg.rref_info, m, n, deficiency, seed)


def _check_rref(rref_info, m, n, deficiency, seed):
    rng = random.Random(seed)
    rows = [[Fraction(rng.randint(-9, 9), rng.randint(1, 5)) for _ in range(n)] for _ in range(m)]
    for i in range(min(deficiency, m - 1)):   # dependent rows
        a, b = Fraction(rng.randint(-3, 3)), Fraction(rng.randint(-3, 3), 2)
        rows[m - 1 - i] = [a * x + b * y for x, y in zip(rows[0], rows[min(1, m - 1)])]
    R, pivots, ambiguous = rref_info([list(r) for r in rows])
    want, want_pivots = sp.Matrix(rows).applyfunc(sp.Rational).rref()
    assert list(pivots) == list(want_pivots) and ambiguous == []
    assert [[sp.Rational(v.numerator, v.denominator) for v in r] for r in R] == \
        want.tolist()


# -- the same world built from symengine (the form derivations hand to the verdict) ----------
_SE_CASES = [
    sp.sin(2 * th) - 2 * sp.sin(th) * sp.cos(th),                       # identity
    sp.cos(th + ph) - (sp.cos(th) * sp.cos(ph) - sp.sin(th) * sp.sin(ph)),
    sp.tan(th) * sp.cos(th) - sp.sin(th),
    sp.sin(th / 2) ** 2 - (1 - sp.cos(th)) / 2,                        # half angle
    sp.cos(3 * th) - 4 * sp.cos(th) ** 3 + 3 * sp.cos(th),
    sp.sin(2 * th) - sp.sin(th) * sp.cos(th),                          # not identities
    sp.sin(th) ** 2 - sp.cos(th) ** 2 - 1,
    3 * th + sp.sin(th),
    (sp.cos(th) * a + 1) / (a ** 2 + sp.sin(ph) ** 2 + 1) - a,
    sp.sqrt(a ** 2 + 1) - a,                                            # square roots
    a / sp.sqrt(a**2 + sp.sin(th)**2 + 1)
    - a * sp.sqrt(a**2 + sp.sin(th)**2 + 1) / (a**2 + sp.sin(th)**2 + 1),
    1 / sp.sqrt(2 - sp.cos(th)**2 + a**2) - 1 / sp.sqrt(1 + sp.sin(th)**2 + a**2),   # twins
    1 / sp.sqrt(2 - sp.cos(th)**2 + a**2) - 1 / sp.sqrt(1 + sp.sin(ph)**2 + a**2),
]


@pytest.mark.parametrize("expr", _SE_CASES, ids=[f"case{i}" for i in range(len(_SE_CASES))])
def test_symengine_world_decides_as_the_sympy_world(expr):
    """Built from symengine the world has the same atoms and arguments, the same degree bound
    and the same verdict at every point as the one built from sympy."""
    import symengine as se
    from dualmech.exact.sample_space import analyse_se
    syms = [th, ph, a]
    assert analyse_se([se.sympify(expr)], syms) is not None      # it takes the fast route
    via_se = ExactForm.build([se.sympify(expr)], syms)
    via_sp = ExactForm.build([expr], syms)
    assert via_se.method == via_sp.method == "exact"
    assert via_se.degree == via_sp.degree
    rng_a, rng_b = random.Random(5), random.Random(5)
    zero = []
    for _ in range(4):
        va = via_se.evaluate(via_se.sample(rng_a))
        vb = via_sp.evaluate(via_sp.sample(rng_b))
        zero.append(va[0] == 0)
        assert (va[0] == 0) == (vb[0] == 0)
    assert all(zero) == (sp.simplify(expr) == 0)


@pytest.mark.parametrize("expr", [
    sp.sqrt(1 + sp.sqrt(a ** 2 + 1)) - a,      # a nested square root
    sp.sqrt(a**2 * sp.cos(th)**2 + 1 + 2 * a * sp.cos(th)) - a,   # a square radicand: |Y|
    sp.pi * sp.sin(th) - 3 * sp.sin(th),       # pi
    sp.exp(a) - a - 1,                         # an exponential
    sp.Abs(sp.cos(th)) - sp.cos(th),           # a branch function (not an identity)
    sp.sin(th ** 2),                           # not a linear argument
], ids=["nested-sqrt", "square-radicand", "pi", "exp", "abs", "square-argument"])
def test_symengine_input_outside_the_common_case_takes_the_general_route(expr):
    import symengine as se
    from dualmech.exact.sample_space import analyse_se
    assert analyse_se([se.sympify(expr)], [th, a]) is None
    via_se = ExactForm.build([se.sympify(expr)], [th, a])
    via_sp = ExactForm.build([expr], [th, a])
    assert via_se.method == via_sp.method
    assert via_se.degree == via_sp.degree


def test_symengine_world_refuses_an_integer_symbol_inside_a_sine():
    import symengine as se
    from dualmech.exact.form import Undecidable
    n = sp.Symbol("n", integer=True)
    with pytest.raises(Undecidable):
        ExactForm.build([se.sympify(sp.sin(n * th))], [n, th])


@pytest.mark.parametrize("engine", ["flint", "fractions"])
def test_exact_values_and_solutions_do_not_depend_on_the_engine(engine):
    """The register program and the square solve give the same exact values with FLINT's
    rationals as with Python's Fractions (checked against sympy's own evaluation)."""
    from unittest import mock
    from dualmech.exact import linalg, register_program as program
    x, y = sp.symbols("x y")
    exprs = [x**2 + x * y / 3 - 1 / (x + y) ** 2, (x - y) ** 3 / 7]
    point = {x: Fraction(3, 5), y: Fraction(-7, 2)}
    A = [[Fraction(2), Fraction(1, 3)], [Fraction(-1, 4), Fraction(5)]]
    b = [Fraction(1), Fraction(-2, 9)]
    patch = mock.patch.object if engine == "fractions" else (lambda *a: mock.MagicMock())
    with patch(program, "flint", None), patch(linalg, "flint", None):
        run = program.compile_rational([x, y], exprs)
        values = run(point[x], point[y])
        solved = linalg.solve_regular(A, b)
    want = [e.subs(point) for e in exprs]
    assert [sp.Rational(v.numerator, v.denominator) for v in values] == want
    assert all(type(v) is Fraction for v in values)
    if engine == "flint":
        X = sp.Matrix(A).LUsolve(sp.Matrix(b))
        assert solved == [Fraction(int(v.p), int(v.q)) for v in X]
        assert linalg.solve_regular([[Fraction(1), Fraction(2)], [Fraction(2), Fraction(4)]],
                                    b) is None    # singular: the caller reduces instead
    else:
        assert solved is None                     # without FLINT the caller reduces



def test_programs_over_one_square_root_match_sympys_algebraic_numbers():
    """The register program's fast path for values in one field Q(sqrt d) (pairs of FLINT
    rationals) against sympy's own algebraic-number arithmetic on the same expressions:
    sums, products, negative powers and quotients, where ``a + b sqrt(d)`` is exact."""
    from fractions import Fraction

    from dualmech.exact.register_program import compile_rational
    from dualmech.exact.surds import Surd
    x, y, z = sp.symbols("x y z")
    exprs = [x**2 - 2 * x * y + 3, 1 / (x + y) ** 2 - z / x, (x * y - 1) ** 3 / (z + x),
             y / 7 + z, x**-3 * y]
    run = compile_rational([x, y, z], exprs)
    r = Surd.root(Fraction(5, 3))
    values = (Fraction(1, 3) + 2 * r, Fraction(-2, 5) * r, Fraction(7, 11))
    exact = {x: sp.Rational(1, 3) + 2 * sp.sqrt(sp.Rational(5, 3)),
             y: sp.Rational(-2, 5) * sp.sqrt(sp.Rational(5, 3)), z: sp.Rational(7, 11)}
    from dualmech.exact import register_program
    assert register_program.one_radicand(values) == Fraction(5, 3)    # the fast path runs
    got = run(*values)
    assert isinstance(got[0], Surd) and isinstance(got[3], Surd)
    for value, e in zip(got, exprs):
        want = sp.radsimp(e.xreplace(exact))
        a = sp.Rational(str(value.terms.get(frozenset(), 0))) if isinstance(value, Surd) \
            else sp.Rational(str(value))
        b = sp.Rational(str(value.terms.get(frozenset([Fraction(5, 3)]), 0))) \
            if isinstance(value, Surd) else 0
        assert sp.expand(want - (a + b * sp.sqrt(sp.Rational(5, 3)))) == 0
    with pytest.raises(ZeroDivisionError):
        compile_rational([x], [1 / (x**2 - 3)])(Surd.root(3))


def test_row_reduction_over_one_square_root_matches_the_surd_field(monkeypatch):
    """The exact row reduction of a matrix over Q(sqrt 5) (FLINT pairs) gives the same pivots
    and reduced form as the general square-root field (Surd, Fractions), including a
    dependent row."""
    from dualmech.exact import linalg, surds
    r = surds.Surd.root(Fraction(5))
    rng = random.Random(3)
    rows = [[Fraction(rng.randint(-5, 5), rng.randint(1, 4)) + rng.randint(-3, 3) * r
             for _ in range(5)] for _ in range(4)]
    rows[3] = [a + (2 - r) * b for a, b in zip(rows[0], rows[1])]
    assert surds.one_radicand(v for row in rows for v in row) == 5
    fast, pivots, _ = linalg.rref_info(rows)
    monkeypatch.setattr(surds, "flint", None)
    assert surds.one_radicand(v for row in rows for v in row) is None
    slow, pivots_slow, _ = linalg.rref_info(rows)
    assert pivots == pivots_slow == [0, 1, 2]
    assert all(x == y for a, b in zip(fast, slow) for x, y in zip(a, b))
    assert all(v == 0 for v in fast[3])
