"""Adversarial expression pairs for the comparator's evaluator (issue 6), with their true verdicts.

Each pair ``(a, b)`` is decided the way the comparator uses an :class:`ExactForm`: one form for
both sides, points drawn in turn over every branch case (``points_needed``), values compared
with :func:`is_zero`.  A nonzero difference at a point where ``form.certain(point)`` holds is a
certain difference; anywhere else it is a refusal, as is :class:`Undecidable` from ``build``.
No other exception may escape.  The true verdicts are hand derivations, noted beside each
pair; the target is zero false "equal" and, for identities, no false "different".
"""
from __future__ import annotations

import random

import pytest
import sympy as sp

from dualmech.exact.form import ExactForm, Undecidable, is_zero
from dualmech.exact import linalg as la

th, ph, t, x, y, f, m, w = sp.symbols("theta phi t x y f m omega")
F0, k, xp = sp.symbols("F0 k xp", positive=True)
S, C = sp.sin, sp.cos
TINY = sp.Rational(1, 10**30)


def verdict(a, b, symbols, domains=None, points=4, seed=0):
    """"equal", "different" or "refused" for the lists ``a`` and ``b``, and the form."""
    a, b = list(a), list(b)
    try:
        form = ExactForm.build(a + b, symbols, domains=domains)
    except Undecidable:
        return "refused", None
    rng = random.Random(seed)
    wanted, good = form.points_needed(points), 0
    for _ in range(30 * wanted):
        p = form.sample(rng)
        try:
            vals = form.evaluate(p)
        except (ZeroDivisionError, ValueError):
            continue
        good += 1
        for u, v in zip(vals[:len(a)], vals[len(a):]):
            if not is_zero(u - v, abs(u) + abs(v)):
                return ("different" if form.certain(p) else "refused"), form
        if good == wanted:
            return "equal", form
    raise AssertionError(f"only {good} of {wanted} points were regular")


def pair(id_, a, b, symbols, expected, method=None, domains=None):
    return pytest.param(a, b, symbols, expected, method, domains, id=id_)


PAIRS = [
    # -- trigonometric identities, and near misses -----------------------------------------------
    pair("double-angle", S(2 * th), 2 * S(th) * C(th), [th], "equal", "exact"),
    pair("double-angle-factor-lost", S(2 * th), S(th) * C(th), [th], "different", "exact"),
    pair("sum-angle", C(th + ph), C(th) * C(ph) - S(th) * S(ph), [th, ph], "equal", "exact"),
    pair("sum-angle-sign", C(th + ph), C(th) * C(ph) + S(th) * S(ph), [th, ph], "different",
         "exact"),
    pair("product-to-squares", S(th - ph) * S(th + ph), S(th)**2 - S(ph)**2, [th, ph], "equal",
         "exact"),
    pair("half-angle", S(th / 2)**2, (1 - C(th)) / 2, [th], "equal", "exact"),
    pair("third-angle", S(t), 3 * S(t / 3) - 4 * S(t / 3)**3, [t], "equal", "exact"),
    pair("sec-tan", sp.sec(th)**2, 1 + sp.tan(th)**2, [th], "equal", "exact"),
    pair("forcing-phase", C(w * t + ph), C(w * t) * C(ph) - S(w * t) * S(ph), [w, t, ph],
         "equal", "exact"),
    pair("pi-frequency", S(4 * sp.pi * f * t), 2 * S(2 * sp.pi * f * t) * C(2 * sp.pi * f * t),
         [f, t], "equal", "exact"),
    # theta and its point on the circle are independent: sin(theta)(1 + theta^2) is not 2 theta
    pair("angle-beside-its-sine", S(th) * (1 + th**2), 2 * th, [th], "different", "exact"),
    pair("small-angle", S(th), th, [th], "different", "exact"),
    pair("tiny-term", C(th)**2, 1 - S(th)**2 + TINY, [th], "different", "exact"),
    # sin(pi/7) is an algebraic number: outside the exact world, decided by intervals
    pair("constant-phase", S(th + sp.pi / 7), S(th) * C(sp.pi / 7) + C(th) * S(sp.pi / 7), [th],
         "equal", "interval"),
    # -- large multiples: Gaussian powers, no expansion ------------------------------------------
    pair("multiple-1000", S(1000 * t), 2 * S(500 * t) * C(500 * t), [t], "equal", "exact"),
    pair("multiple-1000-off-by-one", S(1000 * t), 2 * S(500 * t) * C(501 * t), [t],
         "different", "exact"),
    pair("multiple-1000-tiny", S(1000 * t), 2 * S(500 * t) * C(500 * t) + sp.Rational(1, 10**40),
         [t], "different", "exact"),
    pair("multiple-beyond-exact", S(10**5 * t), 2 * S(5 * 10**4 * t) * C(5 * 10**4 * t), [t],
         "equal", "interval"),
    pair("multiple-beyond-exact-off", S(10**5 * t), 2 * S(5 * 10**4 * t) * C(5 * 10**4 * t + 1),
         [t], "different", "interval"),
    # -- square roots ------------------------------------------------------------------------------
    # sqrt(1 - sin^2) = |cos|: differs from cos wherever cos < 0
    pair("sqrt-of-square-vs-cos", sp.sqrt(1 - S(th)**2), C(th), [th], "different", "exact"),
    pair("sqrt-of-square-vs-abs", sp.sqrt(1 - S(th)**2), sp.Abs(C(th)), [th], "equal", "exact"),
    pair("sqrt-branch-declared", sp.sqrt(1 - C(th)**2), S(th), [th], "equal", "exact",
         {th: (0, sp.pi)}),
    pair("sqrt-branch-too-wide", sp.sqrt(1 - C(th)**2), S(th), [th], "different", "exact",
         {th: (0, 4)}),
    pair("sqrt-x-squared", sp.sqrt(x**2), x, [x], "different", "exact"),
    pair("sqrt-perfect-square", sp.sqrt(x**2 + 2 * x + 1), x + 1, [x], "different", "exact"),
    pair("sqrt-perfect-square-declared", sp.sqrt(x**2 + 2 * x + 1), x + 1, [x], "equal",
         "exact", {x: (-1, 10)}),
    pair("rationalised", 1 / (sp.sqrt(x**2 + 1) + x), sp.sqrt(x**2 + 1) - x, [x], "equal",
         "exact"),
    pair("rationalised-sign", 1 / (sp.sqrt(x**2 + 1) + x), sp.sqrt(x**2 + 1) + x, [x],
         "different", "exact"),
    pair("spring-length", k * (sp.sqrt(x**2 + y**2) - 1) * x / sp.sqrt(x**2 + y**2),
         k * x - k * x / sp.sqrt(x**2 + y**2), [k, x, y], "equal", "exact"),
    pair("two-radicals", sp.sqrt(2) * sp.sqrt(x**2 + 1), sp.sqrt(2 * x**2 + 2), [x], "equal",
         "exact"),
    pair("two-radicals-off", sp.sqrt(2) * sp.sqrt(x**2 + 1), sp.sqrt(3 * x**2 + 3), [x],
         "different", "exact"),
    # -- branch functions ---------------------------------------------------------------------
    pair("abs-cos", sp.Abs(C(th)), C(th), [th], "different", "exact"),
    pair("abs-product", sp.Abs(x * y), sp.Abs(x) * sp.Abs(y), [x, y], "equal", "exact"),
    pair("abs-difference-of-abs", sp.Abs(S(th)) - sp.Abs(C(th)),
         (S(th)**2 - C(th)**2) / (sp.Abs(S(th)) + sp.Abs(C(th))), [th], "equal", "exact"),
    pair("abs-double-angle", sp.Abs(S(th) * C(th)), sp.Abs(S(2 * th)) / 2, [th], "equal",
         "exact"),
    pair("abs-exp-shifted", sp.Abs(sp.exp(t) - 2), sp.exp(t) - 2, [t], "different", "exact"),
    pair("abs-exp-positive", sp.Abs(sp.exp(t) + 2), sp.exp(t) + 2, [t], "equal", "exact"),
    pair("sign-abs", sp.sign(x) * sp.Abs(x), x, [x], "equal", "exact"),
    pair("sign-ratio", sp.sign(x), x / sp.Abs(x), [x], "equal", "exact"),
    pair("sign-wrong", sp.sign(x), 1, [x], "different", "exact"),
    pair("max-min", sp.Max(x, y) + sp.Min(x, y), x + y, [x, y], "equal", "exact"),
    pair("max-abs", sp.Max(x, y), (x + y + sp.Abs(x - y)) / 2, [x, y], "equal", "exact"),
    pair("max-wrong", sp.Max(x, y), x, [x, y], "different", "exact"),
    pair("piecewise-ramp", sp.Piecewise((x, x > 0), (0, True)), (x + sp.Abs(x)) / 2, [x],
         "equal", "exact"),
    pair("piecewise-ramp-wrong", sp.Piecewise((x, x > 0), (0, True)), x, [x], "different",
         "exact"),
    pair("piecewise-staircase", sp.Piecewise((1, x < 0), (2, x < 1), (3, True)),
         1 + sp.Heaviside(x) + sp.Heaviside(x - 1), [x], "equal", "exact"),
    pair("heaviside-sign", sp.Heaviside(S(th)), (1 + sp.sign(S(th))) / 2, [th], "equal", "exact"),
    # |theta - sin theta| = sign(theta) (theta - sin theta), but the two conditions change sign
    # together at 0, which interval bisection cannot separate: a refusal, never a verdict
    pair("abs-transcendental-condition", sp.Abs(th - S(th)), sp.sign(th) * (th - S(th)), [th],
         "refused", "exact"),
    pair("abs-transcendental-wrong", sp.Abs(th - S(th)), th - S(th), [th], "different",
         "exact"),
    # -- inverse trigonometric functions: interval arithmetic over the whole domain ----------------
    pair("acos-cos", sp.acos(C(th)), th, [th], "different", "interval"),
    pair("asin-plus-acos", sp.asin(x) + sp.acos(x), sp.pi / 2, [x], "equal", "interval"),
    pair("atan-tan", sp.atan(sp.tan(th)), th, [th], "different", "interval"),
    pair("atan2-circle", sp.atan2(S(th), C(th)), th, [th], "different", "interval"),
    pair("atan2-circle-declared", sp.atan2(S(th), C(th)), th, [th], "equal", "interval",
         {th: (-3, 3)}),
    pair("atan-tiny", sp.atan(x) + sp.Rational(1, 10**40), sp.atan(x), [x], "different",
         "interval"),
    # -- discontinuities ------------------------------------------------------------------------
    pair("heaviside-late", F0 * sp.Heaviside(t - 20), 0, [F0, t], "different", "exact"),
    pair("heaviside-very-late", F0 * sp.Heaviside(t - 10**9), 0, [F0, t], "different", "exact"),
    pair("heaviside-complement", sp.Heaviside(t - 20) + sp.Heaviside(20 - t), 1, [t], "equal",
         "exact"),
    pair("step", sp.Piecewise((1, t < 5), (2, True)), 1, [t], "different", "exact"),
    pair("floor", sp.floor(t), t, [t], "different", "interval"),
    # in the interval method too, far branch regions and narrow domains are visited
    pair("interval-heaviside-very-late", F0 * sp.Heaviside(t - 10**9) * sp.atan(t), 0, [F0, t],
         "different", "interval"),
    pair("interval-piecewise-far", sp.Piecewise((sp.atan(t), t > 10**7), (0, True)), 0, [t],
         "different", "interval"),
    pair("interval-narrow-domain", sp.sqrt(x - 10**9) * sp.atan(x),
         sp.sqrt(x - 10**9) * sp.atan(x) + sp.Rational(1, 10**20), [x], "different", "interval"),
    # -- tiny and huge coefficients ---------------------------------------------------------------
    pair("tiny-next-to-exp", sp.exp(t) + TINY, sp.exp(t), [t], "different", "exact"),
    pair("coefficients-1e-35-factor-2", sp.Float("1e-35") * x + sp.Float("2e-35") * y,
         sp.Float("2e-35") * x + sp.Float("2e-35") * y, [x, y], "different", "exact"),
    # a float is its exact binary value: 1e-35 is not 10**-35
    pair("binary-float", sp.Float("1e-35") * x, sp.Rational(1, 10**35) * x, [x], "different",
         "exact"),
    pair("huge-identity", (10**300 * S(th))**2, 10**600 * (1 - C(th)**2), [th], "equal",
         "exact"),
    pair("huge-plus-tiny", 10**300 * x + y, 10**300 * x + y + sp.Rational(1, 10**300), [x, y],
         "different", "exact"),
    pair("exp-powers", sp.exp(1000 * t), sp.exp(500 * t)**2, [t], "equal", "exact"),
    pair("exp-powers-off", sp.exp(1000 * t), sp.exp(500 * t) * sp.exp(501 * t), [t],
         "different", "exact"),
    pair("hyperbolic", sp.cosh(x)**2, 1 + sp.sinh(x)**2, [x], "equal", "exact"),
    pair("tiny-times-atan", sp.Float("1e-30") * sp.atan(x), 0, [x], "different", "interval"),
    # -- assumptions, symbolic exponents -----------------------------------------------------------
    pair("same-name-unified", sp.sqrt(sp.Symbol("omega")**2), sp.Symbol("omega", positive=True),
         [sp.Symbol("omega"), sp.Symbol("omega", positive=True)], "equal", "exact"),
    pair("positive-symbol", sp.sqrt(k**2), k, [k], "equal", "exact"),
    pair("contradictory-assumptions", sp.Symbol("z", positive=True), sp.Symbol("z", negative=True),
         [sp.Symbol("z", positive=True), sp.Symbol("z", negative=True)], "refused"),
    pair("symbolic-exponent", th**m, th**m, [th, m], "equal", "interval"),
    pair("symbolic-exponent-shift", th**(m + 1), th * th**m, [th, m], "equal", "interval"),
    pair("symbolic-exponent-off", th**m, th**(m + 1), [th, m], "different", "interval"),
    pair("integer-symbol-in-sine", S(sp.Symbol("n", integer=True) * th), 0,
         [sp.Symbol("n", integer=True), th], "refused"),
    pair("undefined-function", sp.Function("g")(x), x, [x], "refused"),
    pair("complex", sp.I * x, x, [x], "refused"),
]


@pytest.mark.parametrize("a, b, symbols, expected, method, domains", PAIRS)
def test_pair_has_its_true_verdict(a, b, symbols, expected, method, domains):
    got, form = verdict([a], [b], symbols, domains)
    assert got == expected, (got, form and form.method, form and form.notes)
    if method is not None:
        assert form.method == method, form.notes


def test_refusal_names_the_sub_expression_and_why():
    g = sp.Function("g")(x)
    with pytest.raises(Undecidable) as info:
        ExactForm.build([g + 1], [x])
    assert info.value.expr == g and "undefined function" in str(info.value)
    n = sp.Symbol("n", integer=True)
    with pytest.raises(Undecidable, match="integer"):
        ExactForm.build([S(n * th)], [n, th])


def test_symbolic_exponent_is_evaluated_not_a_type_error():
    form = ExactForm.build([th**m], [th, m])
    assert form.method == "interval" and "symbolic exponent" in form.notes[-1]


def test_unified_symbols_are_reported():
    plain, pos = sp.Symbol("omega"), sp.Symbol("omega", positive=True)
    form = ExactForm.build([plain * pos], [plain, pos])
    assert any("unified" in n for n in form.notes)
    point = form.sample(random.Random(0))
    assert point[plain] == point[pos]


def test_interval_points_cover_the_whole_domain_not_the_working_range():
    # working ranges (t in (0, 10), theta in (-1.2, 1.2)) are for display: the verdict samples
    # both signs and magnitudes far outside them
    form = ExactForm.build([sp.atan(th) + t], [th, t])
    rng = random.Random(0)
    pts = [form.sample(rng, {th: (-1.2, 1.2), t: (0.0, 10.0)}) for _ in range(200)]
    ths = [float(p[th]) for p in pts]
    ts = [float(p[t]) for p in pts]
    assert min(ths) < -10 and max(ths) > 10 and min(ts) < 0 and max(ts) > 100


# -- linear algebra on sampled values: hidden singular determinants -------------------------------
def _matrices(form, rows, cols, seed=0, points=6):
    rng = random.Random(seed)
    out = []
    while len(out) < points:
        p = form.sample(rng)
        try:
            v = form.evaluate(p)
        except (ZeroDivisionError, ValueError):
            continue
        out.append([v[i * cols:(i + 1) * cols] for i in range(rows)])
    return out


@pytest.mark.parametrize("entries", [
    [[S(th)**2 + C(th)**2, 1], [1, 1]],                                  # det 1 - 1
    [[sp.sqrt(x**2 + 1), 1], [1, 1 / sp.sqrt(x**2 + 1)]],                # det 1 - 1
    [[sp.Abs(C(th)), sp.sqrt(1 - S(th)**2)], [1, 1]],                    # equal columns
    [[sp.atan(x), 1], [2 * sp.atan(x), 2]],                              # intervals
], ids=["trig", "sqrt", "abs", "interval"])
def test_hidden_singular_matrix_is_never_solved(entries):
    syms = sorted(set().union(*(sp.sympify(e).free_symbols for r in entries for e in r)), key=str)
    form = ExactForm.build([e for r in entries for e in r], syms)
    for A in _matrices(form, 2, 2):
        assert la.solve_square(A, [1, 2]) is None
        assert la.rank(A) <= 1


def test_nearly_singular_matrix_is_regular():
    form = ExactForm.build([S(th)**2 + C(th)**2, 1, 1, 1 + sp.Rational(1, 10**40)], [th])
    for A in _matrices(form, 2, 2):
        assert la.rank(A) == 2
        x1, x2 = la.solve_square(A, [1, 1])
        assert x1 == 1 and x2 == 0


def test_tiny_entries_have_no_absolute_floor():
    # a matrix of 1e-40 (exact binary floats) is as regular as one of ones
    eps = sp.Float("1e-40")
    form = ExactForm.build([eps * C(th)**2 + eps * S(th)**2, eps, 0, eps], [th])
    for A in _matrices(form, 2, 2):
        assert la.rank(A) == 2 and la.solve_square(A, [A[0][1], A[0][1]]) == [0, 1]


def test_nearly_singular_interval_matrix_is_certainly_regular():
    form = ExactForm.build([sp.atan(x), 1, sp.atan(x), 1 + sp.Rational(1, 10**30)], [x])
    for A in _matrices(form, 2, 2):
        assert la.rank(A) == 2 and la.solve_square(A, [0, 1]) is not None


def _pair_verdict(ref, cand, symbols, domains=None, points=4):
    """The comparator's test on two systems ``(A, b)`` (1 coordinate + reactions)."""
    (Ar, br), (Ac, bc) = ref, cand
    flat = [e for r in Ar for e in r] + br + [e for r in Ac for e in r] + bc
    form = ExactForm.build(flat, symbols, domains=domains)
    rng = random.Random(0)
    good = 0
    n, m = len(Ar), len(Ac[0])
    for _ in range(30 * form.points_needed(points)):
        p = form.sample(rng)
        try:
            v = form.evaluate(p)
        except (ZeroDivisionError, ValueError):
            continue
        A1 = [v[i * n:(i + 1) * n] for i in range(n)]
        b1 = v[n * n:n * n + n]
        off = n * n + n
        A2 = [v[off + i * m:off + (i + 1) * m] for i in range(len(Ac))]
        b2 = v[off + len(Ac) * m:off + len(Ac) * m + len(Ac)]
        qdd = la.solve_square(A1, b1)
        if qdd is None:
            continue
        good += 1
        M = [r[:n] for r in A2]
        B = [r[n:] for r in A2]
        r = [bi - mi for bi, mi in zip(b2, la.matvec(M, qdd))]
        res, _, undetermined = la.residual_after_least_squares(B, r)
        nonzero = any(not is_zero(z) for z in res) or undetermined or la.rank(A2) < m
        if nonzero:
            return "different" if form.certain(p) else "refused"
        if good == form.points_needed(points):
            return "equal"
    raise AssertionError("no regular point")


def test_rows_combined_by_a_regular_matrix_with_branches_are_equivalent():
    # reference: two equations in (x'', lambda); candidate: rows mixed by
    # T = [[|cos| + 1, 0], [sqrt(1 - sin^2), 1]], det T = |cos| + 1 > 0
    a, lam_row = [[m, 1], [k, -1]], [F0 * C(th), k * th]
    T = [[sp.Abs(C(th)) + 1, 0], [sp.sqrt(1 - S(th)**2), 1]]
    Ac = [[sum(T[i][j] * a[j][c] for j in range(2)) for c in range(2)] for i in range(2)]
    bc = [sum(T[i][j] * lam_row[j] for j in range(2)) for i in range(2)]
    # the reference is square in the unknowns (x'', lambda): compare as one block
    got = _pair_verdict((a, lam_row), (Ac, bc), [m, k, F0, th])
    assert got == "equal"


def test_rows_combined_by_a_hidden_singular_matrix_are_not_equivalent():
    # T = [[1, sin], [cos... ]] with det T = sin^2 + cos^2 - 1 = 0: the candidate's second row
    # is a multiple of its first, it no longer determines (x'', lambda)
    a, rhs = [[m, 1], [k, -1]], [F0 * C(th), k * th]
    T = [[C(th), S(th)], [C(th) * (S(th)**2 + C(th)**2), S(th)]]
    Ac = [[sum(T[i][j] * a[j][c] for j in range(2)) for c in range(2)] for i in range(2)]
    bc = [sum(T[i][j] * rhs[j] for j in range(2)) for i in range(2)]
    assert _pair_verdict((a, rhs), (Ac, bc), [m, k, F0, th]) == "different"


def test_square_root_rows_solve_exactly():
    # x'' = g/sqrt(1 + x^2) written twice, one row scaled by the root
    g = sp.Symbol("g", positive=True)
    r = sp.sqrt(1 + x**2)
    ref = ([[1]], [g / r])
    cand = ([[r]], [g])
    assert _pair_verdict(ref, cand, [g, x]) == "equal"
    wrong = ([[r]], [g * r])
    assert _pair_verdict(ref, wrong, [g, x]) == "different"
