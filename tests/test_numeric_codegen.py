"""Generated numeric code (dualmech.numeric): vectorised = looped, fresh arrays, solve_ivp
unchanged, printed functions right, singular states named -- for every backend available here.

References: sympy's own evaluation of the same expressions at 30 digits (printer tests);
``numpy.linalg.solve`` of the same matrices (solves); a copying wrapper of our right-hand side
(``solve_ivp`` tests).  Tolerances are the linear solves' error bound
``64 eps cond(A) max(1, |x|)`` where two different solvers meet; the compiled code's one-state
and many-state entry points run the same C function, so they must agree exactly.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from dualmech import EquationSet, Lagrangian, coordinate, t
from dualmech.numeric import NumericModel, SingularityError, StateFunction
from dualmech.numeric.cbackend import compiler

from _pendulum import Pendulum

_EPS = np.finfo(float).eps
BACKENDS = ["python", pytest.param("c", marks=pytest.mark.skipif(
    compiler() is None, reason="no C compiler here"))]


@pytest.fixture(scope="module", autouse=True)
def private_cache(tmp_path_factory):
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("DUALMECH_CACHE_DIR", str(tmp_path_factory.mktemp("dmcache")))
        yield


def three_link():
    """Planar chain of three point masses (hand-derivable, dense 3x3 mass matrix)."""
    th = [coordinate(f"a{i}") for i in range(3)]
    m = sp.symbols("m0:3", positive=True)
    lengths = sp.symbols("l0:3", positive=True)
    g = sp.Symbol("g", positive=True)
    lg = Lagrangian(coordinates=th)
    x = y = 0
    for i in range(3):
        x += lengths[i] * sp.sin(th[i])
        y -= lengths[i] * sp.cos(th[i])
        lg.kinetic(f"T{i}", m[i] * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2)
        lg.potential(f"V{i}", m[i] * g * y)
    values = dict(zip(m, (1.3, 0.7, 2.1)))
    values.update(zip(lengths, (0.9, 1.4, 0.6)))
    values[g] = 9.81
    return lg.equations(), values


@pytest.fixture(scope="module")
def models():
    from dualmech.problems.toy_car import ToyCar
    car = ToyCar()
    pend = Pendulum()
    eqs3, values3 = three_link()
    return {"toy car (lagrange)": (car.model("lagrange"), car.defaults()),
            "toy car (multiplier, N=3)": (car.model("multiplier"), car.defaults()),
            "pendulum (direct, with tension)": (pend.model("newton_euler"), pend.defaults()),
            "three-link": (eqs3, values3)}


MODEL_NAMES = ["toy car (lagrange)", "toy car (multiplier, N=3)",
               "pendulum (direct, with tension)", "three-link"]


def _states(n, k, seed=3):
    rng = np.random.default_rng(seed)
    return np.concatenate([rng.uniform(-0.9, 0.9, (n, k)), rng.uniform(-2, 2, (n, k))])


def _bound(A, x):
    return 64 * _EPS * np.linalg.cond(A) * max(1.0, np.max(np.abs(x)))


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", MODEL_NAMES)
def test_vectorised_equals_looped_and_numpy(models, name, backend):
    eqs, values = models[name]
    nm = NumericModel(eqs, values, backend=backend)
    n = eqs.n
    Y = _states(n, 7)
    times = np.linspace(0.1, 2.0, 7)
    many = nm.solve(times, Y[:n], Y[n:])
    for i in range(Y.shape[1]):
        one = nm.solve(times[i], Y[:n, i], Y[n:, i])
        A, b = nm.system(times[i], Y[:n, i], Y[n:, i])
        ref = np.linalg.solve(A, b)
        assert np.max(np.abs(one - ref)) <= _bound(A, ref)
        if backend == "c":  # one C function behind both entry points
            assert np.array_equal(many[:, i], one)
        else:
            assert np.max(np.abs(many[:, i] - one)) <= _bound(A, ref)
    As, bs = nm.system(times, Y[:n], Y[n:])
    A0, b0 = nm.system(times[0], Y[:n, 0], Y[n:, 0])
    assert np.allclose(As[0], A0, rtol=4 * _EPS, atol=0) and np.allclose(bs[0], b0, rtol=1e-14)
    rhs = nm.rhs(1.0, Y)
    assert np.array_equal(rhs[:n], Y[n:])
    for i in (0, 6):
        assert np.max(np.abs(rhs[n:, i] - nm.rhs(1.0, Y[:, i])[n:])) <= \
            _bound(*nm.system(1.0, Y[:n, i], Y[n:, i])[:1], many[:n, i])


@pytest.mark.parametrize("backend", BACKENDS)
def test_every_call_returns_a_fresh_array(models, backend):
    eqs, values = models["three-link"]
    nm = NumericModel(eqs, values, backend=backend)
    y = _states(3, 1)[:, 0]
    first = nm.rhs(0.0, y)
    kept = first.copy()
    second = nm.rhs(0.0, 0.5 * y)
    assert not np.shares_memory(first, second)
    assert np.array_equal(first, kept)          # the second call did not write into the first
    first[:] = np.nan
    assert np.array_equal(nm.rhs(0.0, y), kept)  # nor does a caller's edit reach the next call
    assert not np.shares_memory(nm.solve(0.0, y[:3], y[3:]), nm.solve(0.0, y[:3], y[3:]))


@pytest.mark.parametrize("backend", BACKENDS)
def test_solve_ivp_sees_the_same_run_as_with_a_copying_reference(models, backend):
    """A right-hand side that reused its output buffer would change solve_ivp's initial step
    (it keeps f(t0) while evaluating f at a trial step) -- the corruption PyDy's generated
    functions cause; ours must give the run of a wrapper that copies every result."""
    eqs, values = models["toy car (lagrange)"]
    nm = NumericModel(eqs, values, backend=backend)
    y0 = [0.4, 0.1, 0.3, -0.8]
    ours = solve_ivp(nm.rhs, (0, 2), y0, rtol=1e-8, atol=1e-10)
    copying = solve_ivp(lambda s, y: np.array(nm.rhs(s, y), copy=True), (0, 2), y0,
                        rtol=1e-8, atol=1e-10)
    assert ours.nfev == copying.nfev
    assert np.array_equal(ours.y, copying.y)
    buffer = np.empty(4)

    def reusing(s, y):
        buffer[:] = nm.rhs(s, y)
        return buffer

    bad = solve_ivp(reusing, (0, 2), y0, rtol=1e-8, atol=1e-10)
    assert bad.nfev != copying.nfev or not np.array_equal(bad.y, copying.y), \
        "the negative control no longer shows the buffer-reuse corruption"


def _cos_model():
    th = coordinate("theta")
    return EquationSet("car", (th,), (sp.cos(th) * th.diff(t, 2) + sp.sin(th),))


@pytest.mark.parametrize("backend", BACKENDS)
def test_singular_state_among_many_is_named(backend):
    nm = NumericModel(_cos_model(), {}, backend=backend)
    q = np.array([[0.3, 1.0, np.pi / 2, -0.2]])
    with pytest.raises(SingularityError, match=r"singular at t=0\.5, theta=1\.5708"):
        nm.solve(0.5, q, np.zeros_like(q))
    with pytest.raises(SingularityError, match=r"singular at t=0, theta=1\.5708"):
        nm.rhs(0.0, np.array([np.pi / 2, 0.0]))
    with pytest.raises(SingularityError, match=r"theta=1\.5708"):
        solve_ivp(nm.rhs, (0, 1), [np.pi / 2, 0.0])


@pytest.mark.parametrize("backend", BACKENDS)
def test_near_singular_but_regular_state_is_solved(models, backend):
    """cos(theta)^2 = 1e-10 near the toy car's singular set: the cheap estimate trips, the
    exact test (condition 1e10 < 1e12) lets it through, and the answer is the hand one:
    phi'' = (2 theta' phi' sin(theta) cos(theta) - g/R sin(phi)/cos(theta)) / cos^2(theta)
    ... written from M = diag(m R^2, m R^2 cos^2 theta) and f of the toy car."""
    eqs, values = models["toy car (lagrange)"]
    nm = NumericModel(eqs, values, backend=backend)
    R, g = (float(values[sp.Symbol(s, positive=True)]) for s in ("R", "g"))
    th = np.arccos(1e-5)
    ph, thd, phd = 0.2, 0.01, 0.3
    c, s = np.cos(th), np.sin(th)
    hand = (2 * s * c * thd * phd - g / R * c * np.sin(ph)) / (c * c)
    got = nm.accelerations(0.0, [th, ph], [thd, phd])[1]
    # error bound of the solve: eps cond(M) |phi''| with cond = 1/cos^2 = 1e10
    assert got == pytest.approx(hand, rel=64 * _EPS / (c * c))


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("kind", ["sqrt", "exp-log", "abs-sign", "atan2", "piecewise", "powers"])
def test_printed_functions_evaluate_like_sympy(kind, backend):
    """x'' = f(x, x', t): the solve returns f, printed by each backend, against sympy."""
    x = coordinate("x")
    xd = x.diff(t)
    k = sp.Symbol("k", positive=True)
    f = {"sqrt": k * sp.sqrt(1 + x**2) - 1 / sp.sqrt(2 + xd**2),
         "exp-log": sp.exp(-k * t) * sp.log(2 + sp.sin(x)) + sp.exp(xd) / 7,
         "abs-sign": sp.Abs(x - xd) * sp.sign(x) + k * sp.Abs(t - 1),
         "atan2": sp.atan2(x, xd + 3) + sp.atan(x) * sp.tanh(xd),
         "piecewise": sp.Piecewise((k * x, x > 0), (x**2, True)) + sp.Heaviside(xd),
         "powers": k * x**5 / (1 + xd**4) + x**sp.Rational(3, 2) * 0 + (2 + x)**(-3)
         + (3 + xd)**sp.Rational(1, 3) + (1 + x**2)**(-sp.Rational(1, 2))}[kind]
    eqs = EquationSet(kind, (x,), (x.diff(t, 2) - f,))
    nm = NumericModel(eqs, {k: 1.7}, backend=backend)
    Y = np.array([[0.3, -0.8, 1.2, -0.1], [0.5, 1.5, -0.7, -0.3]])
    times = np.array([0.2, 1.7, 0.9, 3.0])
    many = nm.solve(times, Y[:1], Y[1:])[0]
    for i in range(4):
        ref = float(f.subs({xd: Y[1, i]}).subs({x: Y[0, i], k: 1.7, t: times[i]}).evalf(30))
        one = nm.solve(times[i], Y[:1, i], Y[1:, i])[0]
        assert one == pytest.approx(ref, rel=1e-13, abs=1e-14)
        assert many[i] == pytest.approx(ref, rel=1e-13, abs=1e-14)


def test_state_function_gives_the_pendulum_energy():
    from _pendulum import g, l, m, th
    T = m * l**2 * th.diff(t)**2 / 2
    V = -m * g * l * sp.cos(th)
    energy = StateFunction([T + V, T], [th], {m: 2.0, l: 1.5, g: 9.81})
    q, qd = np.array([[0.3, -1.1, 2.0]]), np.array([[0.7, 0.0, -1.2]])
    hand = 0.5 * 2.0 * 1.5**2 * qd[0]**2 - 2.0 * 9.81 * 1.5 * np.cos(q[0])
    many = energy(0.0, q, qd)
    assert np.allclose(many[0], hand, rtol=4 * _EPS)
    assert np.array_equal(energy(0.0, q[:, 1], qd[:, 1]), many[:, 1])


def test_unknown_backend_is_refused(models):
    eqs, values = models["three-link"]
    with pytest.raises(ValueError, match="`backend` must be 'auto', 'python' or 'c'"):
        NumericModel(eqs, values, backend="fortran")


@pytest.mark.parametrize("backend", BACKENDS)
def test_pickled_model_rebuilds_its_code(models, backend):
    import pickle
    eqs, values = models["three-link"]
    nm = NumericModel(eqs, values, backend=backend)
    y = _states(3, 1)[:, 0]
    again = pickle.loads(pickle.dumps(nm))
    assert np.array_equal(again.rhs(0.3, y), nm.rhs(0.3, y))


@pytest.mark.parametrize("backend", BACKENDS)
def test_non_finite_state_is_named_not_called_singular(models, backend):
    eqs, values = models["toy car (lagrange)"]
    nm = NumericModel(eqs, values, backend=backend)
    with pytest.raises(ValueError, match=r"not finite at t=0, theta=nan, phi=0\.2"):
        nm.rhs(0.0, np.array([np.nan, 0.2, 0.0, 0.0]))


def test_math_error_names_the_state():
    x = coordinate("x")
    eqs = EquationSet("root", (x,), (x.diff(t, 2) - sp.sqrt(x) - 1 / (x.diff(t) - 1),))
    nm = NumericModel(eqs, {}, backend="python")
    assert nm.accelerations(0.0, [4.0], [3.0])[0] == 2.5      # sqrt(4) + 1/(3 - 1)
    with pytest.raises(ValueError, match=r"evaluating `root` at t=0, x=-1, x'=0 failed"):
        nm.accelerations(0.0, [-1.0], [0.0])
    with pytest.raises(ValueError, match=r"x=4, x'=1 failed \(ZeroDivisionError"):
        nm.rhs(0.0, np.array([4.0, 1.0]))


def _large_model():
    """Three angles, ``M = B^T B + I`` with every entry of ``B`` a long sum of products of
    sines, cosines and a square root, and a forcing of the same kind: entries whose
    expansion runs to thousands of terms, so the generator keeps their trees."""
    q = [coordinate(f"b{i}") for i in range(3)]
    c = sp.symbols("c0:6", positive=True)
    root = sp.sqrt(2 + sp.sin(q[0]) * sp.cos(q[1] - q[2]))
    fs = [sp.sin, sp.cos]
    B = sp.Matrix(3, 3, lambda i, j: sum(
        c[(i + j + k) % 6] * fs[k % 2](q[k % 3] + (k // 3 + 1) * q[(i + k) % 3])
        * fs[(k + j) % 2](q[j]) for k in range(12)) * root + c[i])
    M = B.T * B + sp.eye(3)
    f = B * sp.Matrix([qi.diff(t) ** 2 for qi in q]) + sp.Matrix(c[:3]) * root
    acc = sp.Matrix([qi.diff(t, 2) for qi in q])
    values = dict(zip(c, (1.1, 0.4, 2.3, 0.9, 1.7, 0.6)))
    return EquationSet("large", tuple(q), tuple(M * acc - f)), M, f, q, values


@pytest.mark.parametrize("backend", BACKENDS)
def test_entries_too_large_to_expand_keep_their_trees(backend):
    """Reference: numpy.linalg.solve of the matrix and forcing evaluated by sympy (30
    digits) at the same states."""
    from dualmech.numeric.codegen import EXPAND_LIMIT, expanded_terms
    import symengine as se
    eqs, M, f, q, values = _large_model()
    assert expanded_terms(se.sympify(M[0, 1]), {}) > EXPAND_LIMIT   # the tree path is taken
    nm = NumericModel(eqs, values, backend=backend)
    rng = np.random.default_rng(4)
    Y = rng.uniform(-2, 2, size=(6, 5))
    many = nm.solve(0.0, Y[:3], Y[3:])
    import mpmath
    plain = sp.symbols("x0:6")
    rename = {qi.diff(t): plain[3 + i] for i, qi in enumerate(q)}
    rename.update({qi: plain[i] for i, qi in enumerate(q)})
    ref_fn = sp.lambdify(plain, [M.xreplace(rename).subs(values), f.xreplace(rename).subs(values)],
                         modules="mpmath")
    for k in range(5):
        with mpmath.workdps(30):
            A, b = ref_fn(*[mpmath.mpf(float(v)) for v in Y[:, k]])
        A = np.array(A.tolist(), dtype=float)
        ref = np.linalg.solve(A, np.array(b.tolist(), dtype=float).ravel())
        assert np.allclose(many[:, k], ref, rtol=0, atol=_bound(A, ref))


def test_a_sum_of_thousands_of_terms_compiles():
    """A sum of 3000 distinct terms (printed as one chain of ``+`` it would exceed CPython's
    compiler depth) compiles and runs.  Reference: the same sum in plain Python floats."""
    from dualmech.numeric import codegen
    x, v, c = sp.symbols("x v c")
    n = 3000
    f = sp.Add(*[c * sp.sin(k * x) * v ** (k % 3) / (k + 1) for k in range(1, n + 1)])
    prog = codegen.program([f], t=t, q=[x], qd=[v], params=[c])
    space: dict = {}
    exec(compile(codegen.python_source(prog, "long", [c]), "long", "exec"), space)
    p = (1.5,)
    one = space["scalar"](p, space["static"](p))
    for q, u in ((0.3, -0.8), (1.2, 0.5)):
        ref = sum(1.5 * np.sin(k * q) * u ** (k % 3) / (k + 1) for k in range(1, n + 1))
        assert one(0.0, [q, u])[0] == pytest.approx(ref, rel=1e-12, abs=1e-12)
