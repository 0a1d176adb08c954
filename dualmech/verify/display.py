"""Symbolic display under a budget: readable forms for people, never used for a verdict.

Verdicts come from evaluation; what a person reads (solved accelerations, reaction formulas,
residuals) is computed here, lazily, within a size and a time budget.  Past the budget the
caller shows the structured form (``M``, ``B``, ``f``) or values at a state instead, and says so.
"""
from __future__ import annotations

import contextlib
import shutil
import signal
import textwrap
import threading

import sympy as sp

from dualmech.model.kinematics import t
from dualmech.model._expr import as_expr
from dualmech.model.equations import is_zero_expression
from dualmech.exact.rational_functions import (NotRational, solve_rational, solve_rational_held,
                                              tidy_rational)

__all__ = ["Budget", "OverBudget", "budget", "tidy", "solve_display", "largest_coupled_block",
           "dotted", "ops_within", "wrap", "width", "grouped", "CONVENTION"]

#: Default budget for one displayed expression: operations in, seconds spent.
MAX_OPS = 600
SECONDS = 3.0
#: Largest set of unknowns that one symbolic solve may couple (the irreducible blocks of the
#: matrix's block-triangular form): a dense 5 x 5 solve is seconds of work and a page of
#: formula nobody reads; every problem of the catalogue couples at most 4.
MAX_COUPLED = 4


class OverBudget(Exception):
    """A display computation went past its size or time budget."""


class Budget:
    """Size and time limits for display work.

    The size limit ``max_ops`` decides what is attempted (deterministically: the same input
    gets the same display); ``seconds`` guards each single computation against running away
    (enforced on the main thread) -- past it the expression is shown as it stands.
    """

    def __init__(self, max_ops: int = MAX_OPS, seconds: float = SECONDS):
        self.max_ops = max_ops
        self.seconds = seconds
        self.cache: dict = {}

    def remaining(self) -> float:
        return self.seconds


@contextlib.contextmanager
def budget(seconds: float):
    """Raise :class:`OverBudget` inside the block after ``seconds`` (main thread, POSIX only)."""
    usable = (seconds and seconds > 0 and hasattr(signal, "setitimer")
              and threading.current_thread() is threading.main_thread())
    if not usable:
        yield
        return

    def _stop(signum, frame):
        raise OverBudget(f"display took longer than {seconds:g} s")

    old = signal.signal(signal.SIGALRM, _stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def tidy(expr, limits: Budget | None = None):
    """A readable form of ``expr``: cancel, then ``sin^2 + cos^2 = 1`` applied whichever way
    makes it shortest (a polynomial reduction, far cheaper than ``trigsimp``), while the
    budget lasts.  Returns the best form reached; raises :class:`OverBudget` only when the
    input itself is past the size budget."""
    limits = limits or Budget()
    expr = as_expr(expr)
    if not ops_within(expr, 4 * limits.max_ops):
        raise OverBudget(f"expression of {sp.count_ops(expr)} operations")
    best = expr
    try:
        with budget(limits.remaining()):
            try:   # polynomial arithmetic in C (FLINT); sympy's route for anything else
                return tidy_rational(expr)
            except (NotRational, ZeroDivisionError):
                pass
            best = sp.cancel(sp.together(expr))
            if sp.count_ops(best) < limits.max_ops and best.has(sp.sin, sp.cos):
                num, den = sp.fraction(best)
                forms = [best] + [sp.factor_terms(sp.cancel(_pythagoras(num, f, g)
                                                            / _pythagoras(den, f, g)))
                                  for f, g in ((sp.sin, sp.cos), (sp.cos, sp.sin))]
                best = min(forms, key=sp.count_ops)
    except OverBudget:
        pass
    except (TypeError, ValueError, RecursionError, sp.PolynomialError):
        pass
    return best


def _pythagoras(poly, f, g):
    """``poly`` expanded with every ``f(a)**k`` (k >= 2) written through ``1 - g(a)**2``."""
    out = sp.expand(poly).replace(
        lambda x: x.is_Pow and isinstance(x.base, f) and x.exp.is_Integer and x.exp >= 2,
        lambda x: (1 - g(x.base.args[0])**2)**(int(x.exp) // 2) * x.base**(int(x.exp) % 2))
    return sp.expand(out)


def solve_display(eqs, limits: Budget | None = None) -> dict:
    """``{symbol: expression}`` of the accelerations and reactions of a square ``eqs``.

    Raises :class:`OverBudget` when the system is too large to solve symbolically within
    the budget (more than eight unknowns, a matrix past the size budget, or no time left).
    Results are kept in ``limits.cache``.
    """
    limits = limits or Budget()
    key = id(eqs)
    hit = limits.cache.get(key)
    if hit is not None and hit[0] is eqs:
        return hit[1]
    n = len(eqs.accelerations) + len(eqs.unknowns)
    if n > 8:   # decided before the matrix is built: its sympy form costs more than a verdict
        raise OverBudget(f"{n} unknowns")
    held = eqs.plain_matrix_se() if hasattr(eqs, "plain_matrix_se") else None
    if held is not None:
        out = _solve_held(eqs, held, limits)
        limits.cache[key] = (eqs, out)
        return out
    A, b = eqs.matrix()
    if A.rows != A.cols:
        raise OverBudget(f"{A.rows} equations for {A.cols} unknowns: not a square system")
    # (a system of at most MAX_COUPLED unknowns cannot couple more: no structural analysis,
    # nor its scipy import, for the common small system)
    coupled = largest_coupled_block(A) if A.cols > MAX_COUPLED else A.cols
    if coupled > MAX_COUPLED:
        raise OverBudget(f"{coupled} unknowns are coupled (a symbolic solution would be "
                         "pages long)")
    ops = sp.count_ops(A) + sp.count_ops(b)
    if ops > 4 * limits.max_ops:
        raise OverBudget(f"{A.cols} unknowns, {ops} operations")
    with budget(limits.remaining()):
        sol = A.LUsolve(b, iszerofunc=is_zero_expression)
    unknowns = list(eqs.accelerations) + list(eqs.unknowns)
    out = {u: tidy(s, limits) for u, s in zip(unknowns, sol)}
    limits.cache[key] = (eqs, out)
    return out


def _solve_held(eqs, held, limits: Budget) -> dict:
    """:func:`solve_display` for equations a derivation holds in symengine: Gaussian
    elimination on the symengine matrix (no sympy arithmetic, no symbolic zero tests), the
    pivots chosen by their values at a random real point, computed alongside in floats --
    an entry that is zero on the motion (``sin^2 + cos^2 - 1``, a cancelled term) is never a
    pivot.  The solution is a rational function of the state, unique wherever the matrix is
    regular, so the route taken does not change what :func:`tidy` shows."""
    import numpy as np
    import symengine as se

    from dualmech.model._algebra import to_sp
    from dualmech.model.equations import _rules
    A, b, names = held
    if A.rows != A.cols:
        raise OverBudget(f"{A.rows} equations for {A.cols} unknowns: not a square system")
    n = A.rows
    if n > MAX_COUPLED:
        pattern = sp.Matrix([[0 if A[i, j] == 0 else 1 for j in range(n)] for i in range(n)])
        coupled = largest_coupled_block(pattern)
        if coupled > MAX_COUPLED:
            raise OverBudget(f"{coupled} unknowns are coupled (a symbolic solution would be "
                             "pages long)")
    # multiplied out, as a teacher reads them (the held matrix keeps products of sums)
    A, b = A.expand(), b.expand()
    entries = [A[i, j] for i in range(n) for j in range(n)] + [b[i] for i in range(n)]
    ops = sum(se.count_ops(e) for e in entries)
    if ops > 4 * limits.max_ops:
        raise OverBudget(f"{n} unknowns, {ops} operations")
    symbols = sorted(set().union(*(e.free_symbols for e in entries)), key=str)
    rng = np.random.default_rng(20240229)
    point = rng.uniform(0.3, 1.7, len(symbols))
    # complex values: a root of a negative number at the random point is still a number
    values = np.array(se.Lambdify(symbols, entries, real=False)(point) if symbols else
                      [complex(e) for e in entries], dtype=complex)
    if not np.isfinite(values).all():
        raise ValueError("the matrix is not finite at a sampled state")
    M = [[A[i, j] for j in range(n)] + [b[i]] for i in range(n)]
    N = np.concatenate([values[:n * n].reshape(n, n), values[n * n:].reshape(n, 1)], axis=1)
    scale = max(float(np.abs(N[:, :n]).max()), 1e-300)
    tiny = 1e-9 * scale
    memo: dict = {}
    # straight into the function form (theta(t), its derivatives): no second walk
    timed = dict(names)
    timed.update({sym.name: f for sym, f in _rules(eqs.coordinates)[2].items()})
    unknowns = list(eqs.accelerations) + list(eqs.unknowns)
    try:    # exact fractions on FLINT, cancelled at every step (see ratfun.solve_rational)
        pivots = _pivots(N.copy(), tiny)
        with budget(limits.remaining()):
            try:    # from the symengine trees, only their atoms converted to sympy
                solved = solve_rational_held([row[:n] for row in M], [row[n] for row in M],
                                             pivots, lambda a: to_sp(a, timed, memo))
            except NotRational:
                solved = solve_rational([[to_sp(x, timed, memo) for x in row[:n]]
                                         for row in M],
                                        [to_sp(row[n], timed, memo) for row in M], pivots)
        return _within(dict(zip(unknowns, solved)), limits)
    except NotRational:
        pass
    except ZeroDivisionError:
        raise ValueError("Matrix det == 0; not invertible.") from None
    with budget(limits.remaining()):
        for k in range(n):
            p = k + int(np.argmax(np.abs(N[k:, k])))
            if abs(N[p, k]) <= tiny:
                raise ValueError("Matrix det == 0; not invertible.")
            if p != k:
                M[k], M[p] = M[p], M[k]
                N[[k, p]] = N[[p, k]]
            for r in range(k + 1, n):
                if M[r][k] == 0:      # structurally: the exact solution, term for term
                    continue
                f, nf = M[r][k] / M[k][k], N[r, k] / N[k, k]
                for c in range(k + 1, n + 1):
                    if M[k][c] != 0:
                        M[r][c] = M[r][c] - f * M[k][c]
                N[r, k + 1:] -= nf * N[k, k + 1:]
        x = [None] * n
        for k in reversed(range(n)):
            acc = M[k][n]
            for c in range(k + 1, n):
                if M[k][c] != 0:
                    acc = acc - M[k][c] * x[c]
            x[k] = acc / M[k][k]
    out = {}
    for u, v in zip(unknowns, x):
        expr = to_sp(v, timed, memo)
        try:    # the reduced fraction (FLINT); tidy's general route for anything else
            out[u] = tidy_rational(expr)
        except (NotRational, ZeroDivisionError):
            out[u] = tidy(expr, limits)
    return _within(out, limits)


def _pivots(N, tiny: float) -> list:
    """The rows partial pivoting brings up at each step of eliminating the (numeric) ``N``:
    the largest value in the column at a real point, so never an entry zero there."""
    import numpy as np
    n = N.shape[0]
    out = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(N[k:, k])))
        if abs(N[p, k]) <= tiny:
            raise ZeroDivisionError("a zero pivot")
        out.append(p)
        if p != k:
            N[[k, p]] = N[[p, k]]
        N[k + 1:, k:] -= np.outer(N[k + 1:, k] / N[k, k], N[k, k:])
    return out


def _within(solution: dict, limits: Budget) -> dict:
    """``solution``, unless one of its forms is a page long (then shown as M q'' = f)."""
    for shown in solution.values():
        if not ops_within(shown, 4 * limits.max_ops):
            raise OverBudget(f"expression of {sp.count_ops(shown)} operations")
    return solution


#: ``sympy.count_ops`` counts at most this many operations per node of an expression tree:
#: a node's own sign, division and kind (three) plus one per argument it joins
OPS_PER_NODE = 4


def ops_within(expr, limit: int) -> bool:
    """Whether ``sympy.count_ops(expr) <= limit``.

    A tree of at most ``limit / OPS_PER_NODE`` nodes is within the limit without counting
    (counting the nodes is a walk; ``count_ops`` builds a fraction and a negation per
    product); a larger one is counted.

    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> e = -x / (2 * y) + sp.sin(x)        # count_ops: SUB, DIV, MUL, SIN
    >>> ops_within(e, 36), ops_within(e, 4), ops_within(e, 3)   # 9 nodes: 36 needs no count
    (True, True, False)
    """
    nodes = 0
    for _ in sp.preorder_traversal(expr):
        nodes += 1
        if OPS_PER_NODE * nodes > limit:
            return sp.count_ops(expr) <= limit
    return True


def largest_coupled_block(A) -> int:
    """Size of the largest irreducible diagonal block of the square matrix ``A`` in
    block-triangular form (structural: from which entries are zero), i.e. the largest set of
    unknowns a solve must treat together; ``A.rows`` when no permutation gives a zero-free
    diagonal.

    Example
    -------
    >>> import sympy as sp
    >>> a, b, c = sp.symbols("a b c")
    >>> largest_coupled_block(sp.Matrix([[a, 0, 0], [b, a, c], [c, b, a]]))
    2
    """
    # scipy's graph routines (imported here: only a system of more than MAX_COUPLED unknowns
    # asks, so a check of a small problem never pays for the import)
    import numpy as np
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components, maximum_bipartite_matching
    if A.rows == 0:
        return 0
    pattern = csr_matrix(np.array([[1 if A[i, j] != 0 else 0 for j in range(A.cols)]
                                   for i in range(A.rows)], dtype=np.int8))
    match = maximum_bipartite_matching(pattern, perm_type="column")
    if (match < 0).any():
        return A.rows
    _, labels = connected_components(pattern[:, match], directed=True, connection="strong")
    return int(np.bincount(labels).max())


def dotted(expr, coordinates=None) -> str:
    """``expr`` as text with ``theta'`` and ``theta''`` for the coordinates' derivatives."""
    from dualmech.model._expr import dotted as _dotted
    return _dotted(as_expr(expr))


def width() -> int:
    """The terminal's width, or 100 columns when the output is not a terminal."""
    import sys
    if not sys.stdout.isatty():
        return 100
    return max(40, shutil.get_terminal_size((100, 24)).columns)


def wrap(line: str, columns: int | None = None, indent: str = "    ") -> str:
    """``line`` wrapped to ``columns`` (default :func:`width`), continuation lines indented
    by the line's own leading spaces plus ``indent``; words (and expressions) are not broken.

    >>> print(wrap("T of bob: lagrange is missing the term m a x' theta' cos(theta)", 30))
    T of bob: lagrange is missing
        the term m a x' theta'
        cos(theta)
    """
    columns = columns or width()
    lead = line[:len(line) - len(line.lstrip(" "))]
    if len(line) <= columns:
        return line
    return textwrap.fill(line.strip(" "), columns, initial_indent=lead,
                         subsequent_indent=lead + indent, break_long_words=False,
                         break_on_hyphens=False)


def fit(text: str, columns: int | None = None) -> str:
    r"""Every line of a report wrapped to the terminal's width (:func:`width`), its
    continuation indented under it; the verdict line stays whole (scripts grep it).

    >>> print(fit("  verdict: " + "x " * 30 + "\n    N = " + "a + " * 12 + "b", 30))
      verdict: x x x x x x x x x x x x x x x x x x x x x x x x x x x x x x
        N = a + a + a + a + a + a
            + a + a + a + a + a + a
            + b
    """
    columns = columns or width()
    return "\n".join(line if line.startswith("  verdict: ") else wrap(line, columns)
                     for line in text.split("\n"))


#: how :func:`grouped` writes every row, whichever model it comes from
CONVENTION = ("rows as a teacher writes them: acceleration terms, then rate terms = the "
              "loads; the direct form's sum F - m a = 0 written m a = sum F, as Lagrange's "
              "rows read")


def grouped(expr, coordinates, sign: int = 1, limits: Budget | None = None):
    """One equation row ``expr = 0`` as ``(left, right)``, ``left = right``: ``left`` the
    terms in the accelerations ``q''`` (one coefficient each, in coordinate order), then
    the terms in the rates grouped by their product of rates; ``right`` the rest.  The
    row is taken times ``sign`` first (``-1`` turns a balance ``sum F - m a`` into
    ``m a = sum F``).  Display only; ``None`` past the budget (the caller shows the row as
    it stands).

    >>> import sympy as sp
    >>> from dualmech import coordinate, rate
    >>> x, th = coordinate("x"), coordinate("theta")
    >>> m, M, l, F = sp.symbols("m M l F", positive=True)
    >>> row = (M + m) * rate(x, 2) + m * l * sp.cos(th) * rate(th, 2) \\
    ...     - m * l * sp.sin(th) * rate(th) * rate(x) - F
    >>> left, right = grouped(sp.expand(row), [x, th])
    >>> from dualmech.model.notation import pretty
    >>> print(pretty(sp.Eq(left, right, evaluate=False), "primes", [x, th], order="none"))
    (M + m)⋅x′′ + l⋅m⋅cos(θ)⋅θ′′ - l⋅m⋅sin(θ)⋅θ′⋅x′ = F
    """
    limits = limits or Budget()
    expr = sp.S(sp.expand(sp.S(as_expr(expr)) * sign))
    if not ops_within(expr, 4 * limits.max_ops):
        return None
    acc = [q.diff(t, 2) for q in coordinates]
    vel = [q.diff(t) for q in coordinates]
    a_sym = [sp.Dummy(f"a{i}") for i in range(len(acc))]
    v_sym = [sp.Dummy(f"v{i}") for i in range(len(vel))]
    back = dict(zip(a_sym + v_sym, acc + vel))
    plain = sp.S(expr.xreplace(dict(zip(acc, a_sym))).xreplace(dict(zip(vel, v_sym))))
    try:
        with budget(limits.remaining()):
            left = [(_coefficient(plain.diff(a), limits).xreplace(back), q)
                    for a, q in zip(a_sym, acc)]
            rest = sp.S(plain.xreplace({a: 0 for a in a_sym}))
            loads = sp.S(rest.xreplace({v: 0 for v in v_sym}))
            rates = sp.Poly(sp.expand(rest - loads), *v_sym, domain="EX") \
                if v_sym and rest != loads else None
            for monomial, c in (rates.terms() if rates is not None else ()):
                product = sp.Mul(*[v**k for v, k in zip(vel, monomial) if k])
                left.append((_coefficient(c, limits).xreplace(back), product))
            right = _coefficient(-loads, limits).xreplace(back)
    except (OverBudget, sp.PolynomialError, TypeError, ValueError):
        return None
    terms = [_term(c, what) for c, what in left if c != 0]
    lhs = sp.Add(*terms, evaluate=False) if len(terms) > 1 else \
        (terms[0] if terms else sp.Integer(0))
    return lhs, right


def _coefficient(c, limits: Budget):
    """A coefficient as a teacher writes it: tidied (:func:`tidy`), common factors out."""
    try:
        return sp.factor_terms(sp.S(tidy(c, limits)))
    except OverBudget:
        return sp.S(c)


def _term(c, what):
    """``c * what`` kept as written: the coefficient first, its sign outside."""
    if c.could_extract_minus_sign():
        inner = sp.Mul(-c, what, evaluate=False) if (-c) != 1 else what
        return sp.Mul(-1, inner, evaluate=False)
    return sp.Mul(c, what, evaluate=False) if c != 1 else what


def row_sign(eqs) -> int:
    """``-1`` for a model the direct-form builder made (its rows are ``sum F - m a``), so
    that :func:`grouped` writes them ``m a = sum F`` as Lagrange's rows read; else ``1``."""
    from dualmech.model.declared import builder_of
    from dualmech.model.direct import NewtonEuler
    return -1 if isinstance(builder_of(eqs), NewtonEuler) else 1


def rows_text(eqs, latex: bool = False, notation: str = "dots") -> str:
    """Every row of ``eqs`` under its ``[label]``, grouped by :func:`grouped` in the one
    sign convention :data:`CONVENTION` (a row past the display budget as ``row = 0``):
    two-dimensional unicode text, or LaTeX with ``latex=True``."""
    from dualmech.model import notation as _notation
    sign, coords, out = row_sign(eqs), eqs.coordinates, []
    for label, e in zip(eqs.labels, eqs.equations):
        sides = grouped(e, coords, sign)
        left, right = sides if sides is not None else (as_expr(e), sp.Integer(0))
        if latex:
            body = (f"{_notation.latex(left, notation, coords, order='none')} = "
                    f"{_notation.latex(right, notation, coords)}")
        else:
            body = _notation.pretty(sp.Eq(left, right, evaluate=False), notation, coords,
                                    order="none")
        out.append(f"[{label}]\n{body}")
    return "\n\n".join(out)
