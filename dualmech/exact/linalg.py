"""Small dense linear algebra on sampled values, with one code path for three kinds of number.

* **exact** -- ``Fraction`` (and ``int``) or exact square-root numbers
  (:class:`~dualmech.exact.surds.Surd`): every zero test is ``== 0``; a pivot is any nonzero
  entry.  Ranks, solutions and residuals are exact.
* **interval** -- ``mpmath.iv`` intervals (the interval method of :mod:`dualmech.exact.form`): a pivot
  must *certainly* be nonzero (its interval excludes 0).  A column whose candidates all contain 0
  without being exactly 0 is *ambiguous*: it is treated as dependent, :func:`solve_square`
  returns ``None`` (the point is skipped) and :func:`residual_after_least_squares` widens the
  residual to contain 0, so no difference is ever claimed on an undecided rank.  :func:`rank`
  is then a lower bound.
* **float** -- ``mpmath.mpf`` (display only): zero means ``|v| <= 10**(-digits/2)`` times the
  largest entry of the matrix -- relative, never an absolute floor.

Systems here are tiny (a few coordinates plus reactions), so clarity beats speed.

Example
-------
>>> from fractions import Fraction as F
>>> rank([[1, 2], [2, 4]]), solve_square([[2, 1], [1, 1]], [3, 2])
(1, [Fraction(1, 1), Fraction(1, 1)])
"""
from __future__ import annotations

import math
from fractions import Fraction

import mpmath
from mpmath import iv

try:   # FLINT's exact linear algebra, when installed (a dependency; the fallback is ours)
    import flint
except ImportError:  # pragma: no cover - platforms without python-flint wheels
    flint = None

from dualmech.exact.interval import to_interval
from dualmech.exact.surds import Quadratic, Surd, one_radicand

__all__ = ["rref", "rref_info", "rank", "solve_square", "matvec", "residual_after_least_squares",
           "kind_of"]

_DIGITS = 60  # as dualmech.exact.form.MP_DIGITS (not imported: exact imports this package)


def kind_of(rows) -> str:
    """``"exact"``, ``"interval"`` or ``"float"``: the kind of the values in ``rows``."""
    kind = "exact"
    for row in rows:
        for v in row:
            if isinstance(v, iv.mpf):
                return "interval"
            if not isinstance(v, (Fraction, int, Surd)):
                kind = "float"
    return kind


def _prepare(rows, kind):
    if kind == "exact":
        return [[v if isinstance(v, (Fraction, Surd)) else Fraction(v) for v in r] for r in rows]
    if kind == "interval":
        return [[to_interval(v) for v in r] for r in rows]
    return [[_mpf(v) for v in r] for r in rows]


def _mpf(v):
    if isinstance(v, Fraction):
        return mpmath.mpf(v.numerator) / v.denominator
    return v if isinstance(v, mpmath.mpf) else mpmath.mpf(v)


def root_field(v) -> bool:
    """Is ``v`` a value of the one-root fast path (a FLINT rational or a Quadratic)?"""
    return type(v) is Quadratic or (flint is not None and type(v) is flint.fmpq)


def _size(v) -> int:
    if isinstance(v, Fraction):
        return v.numerator.bit_length() + v.denominator.bit_length()
    if root_field(v):
        size = Quadratic.size(v)
        return (1 << 30) if size is None else size
    return 1 << 30  # a square-root number: prefer a rational pivot


def _exact_zero(v) -> bool:
    if isinstance(v, iv.mpf):
        return v.a == 0 and v.b == 0
    return v == 0


def _pivot(A, r, c, kind, tol):
    """Row index of the pivot in column ``c`` (rows ``r:``), or ``None``; and ambiguity."""
    rows = range(r, len(A))
    if kind == "exact":
        # the reduced echelon form is unique: any nonzero pivot gives the same result, and the
        # shortest one keeps the numbers short
        nonzero = [i for i in rows if A[i][c] != 0]
        return (min(nonzero, key=lambda i: _size(A[i][c])) if nonzero else None), False
    if kind == "interval":
        sure = [i for i in rows if A[i][c].a > 0 or A[i][c].b < 0]
        if sure:
            return max(sure, key=lambda i: abs(A[i][c].mid)), False
        return None, any(not _exact_zero(A[i][c]) for i in rows)
    best = max(rows, key=lambda i: abs(A[i][c]), default=None)
    if best is None or abs(A[best][c]) <= tol:
        return None, False
    return best, False


def rref_info(rows: list[list]) -> tuple[list[list], list[int], list[int]]:
    """Reduced row echelon form, pivot columns, and ambiguous columns (interval kind only)."""
    kind = kind_of(rows)
    if kind == "exact" and rows and rows[0] and \
            all(type(v) is Fraction or type(v) is int for r in rows for v in r):
        return _rref_integer(rows)
    root = one_radicand(v for r in rows for v in r) if kind == "exact" else None
    if root is not None:   # one square root: the same elimination in FLINT rationals
        d = Quadratic.lift(root, root)
        A = [[Quadratic.lift(v, root, d) for v in r] for r in rows]
    else:
        A = _prepare(rows, kind)
    tol = 0
    if kind == "float":
        scale = max((abs(v) for r in A for v in r), default=0)
        tol = mpmath.mpf(10) ** (-(_DIGITS // 2)) * scale
    pivots, ambiguous, r = [], [], 0
    ncols = len(A[0]) if A else 0
    for c in range(ncols):
        if r == len(A):
            break
        best, unsure = _pivot(A, r, c, kind, tol)
        if best is None:
            if unsure:
                ambiguous.append(c)
            continue
        A[r], A[best] = A[best], A[r]
        p = A[r][c]
        A[r] = [v / p for v in A[r]]
        for i in range(len(A)):
            if i != r and not _exact_zero(A[i][c]):
                f = A[i][c]
                A[i] = [a - f * b for a, b in zip(A[i], A[r])]
                A[i][c] = A[r][c] * 0  # exactly eliminated (an exact zero of the right kind)
        pivots.append(c)
        r += 1
    if root is not None:
        A = [[Quadratic.back(v, root) for v in row] for row in A]
    return A, pivots, ambiguous


def _rref_integer(rows: list[list]) -> tuple[list[list], list[int], list[int]]:
    """:func:`rref_info` of a rational matrix, fraction-free: each row is scaled to integers,
    eliminated with integer arithmetic (each updated row divided by the gcd of its entries,
    which keeps the numbers short: Bareiss' exact division by the previous pivot lets them
    grow to full minors, far slower here), and divided by its pivot at the end.  The reduced
    echelon form is unique, so this is Gauss--Jordan on fractions without a gcd per
    operation."""
    if flint is not None:
        return _rref_flint(rows)
    A = []
    for row in rows:
        den = math.lcm(*[v.denominator for v in row])
        A.append([v.numerator * (den // v.denominator) for v in row])
    m, ncols = len(A), len(A[0])
    pivots, r = [], 0
    for c in range(ncols):
        if r == m:
            break
        nonzero = [i for i in range(r, m) if A[i][c]]
        if not nonzero:
            continue
        best = min(nonzero, key=lambda i: abs(A[i][c]))
        A[r], A[best] = A[best], A[r]
        pr = A[r]
        p = pr[c]
        for i in range(m):
            f = A[i][c]
            if i != r and f:
                new = [p * a - f * b for a, b in zip(A[i], pr)]
                g = math.gcd(*new)
                A[i] = [x // g for x in new] if g > 1 else new
        pivots.append(c)
        r += 1
    out = [[Fraction(x, row[c]) for x in row] for row, c in zip(A, pivots)]
    out += [[Fraction(0)] * ncols for _ in range(m - r)]
    return out, pivots, []


def _rref_flint(rows: list[list]) -> tuple[list[list], list[int], list[int]]:
    """:func:`_rref_integer` by FLINT's exact rational reduction (``fmpq_mat.rref``)."""
    m, ncols = len(rows), len(rows[0])
    M = flint.fmpq_mat(m, ncols, [flint.fmpq(v.numerator, v.denominator)
                                  for row in rows for v in row])
    R, rank = M.rref()
    out, pivots = [], []
    for i in range(m):
        row = [R[i, j] for j in range(ncols)]
        if i < rank:
            pivots.append(next(j for j, x in enumerate(row) if x != 0))
        out.append([Fraction(int(x.p), int(x.q)) for x in row])
    return out, pivots, []


def solve_regular(A: list[list], b: list) -> list | None:
    """The solution of the square rational system ``A x = b`` by FLINT (``fmpq_mat.solve``),
    or ``None`` when ``A`` is singular, FLINT is missing or the entries are not rational
    (callers then reduce with :func:`rref_info`, which also says how it is singular)."""
    n = len(A)
    if flint is None or not n or len(A[0]) != n or kind_of(A) != "exact" or \
            not all(type(v) is Fraction or type(v) is int for row in A for v in row) or \
            not all(type(v) is Fraction or type(v) is int for v in b):
        return None
    q = lambda v: flint.fmpq(v.numerator, v.denominator)  # noqa: E731
    M = flint.fmpq_mat(n, n, [q(v) for row in A for v in row])
    try:
        X = M.solve(flint.fmpq_mat(n, 1, [q(v) for v in b]))
    except ZeroDivisionError:
        return None
    return [Fraction(int(X[i, 0].p), int(X[i, 0].q)) for i in range(n)]


def rref(rows: list[list]) -> tuple[list[list], list[int]]:
    """Reduced row echelon form and pivot columns."""
    A, pivots, _ = rref_info(rows)
    return A, pivots


def rank(rows: list[list]) -> int:
    """Rank (exact kinds); for intervals, the number of certain pivots (a lower bound)."""
    return len(rref(rows)[1]) if rows and rows[0] else 0


def solve_square(A: list[list], b: list) -> list | None:
    """Solution of the square system ``A x = b``, or ``None`` when ``A`` is singular (or, for
    intervals, not certainly regular)."""
    n = len(A)
    aug = [list(row) + [bi] for row, bi in zip(A, b)]
    R, piv, ambiguous = rref_info(aug)
    if piv[:n] != list(range(n)) or len(piv) > n or any(c < n for c in ambiguous):
        return None
    return [R[i][n] for i in range(n)]


def matvec(A: list[list], x: list) -> list:
    return [sum((a * xi for a, xi in zip(row, x)), 0) for row in A]


def residual_after_least_squares(B: list[list], r: list) -> tuple[list, list, list[int]]:
    """Residual of ``r`` after removing its component in the column space of ``B``.

    Returns ``(residual, lam, undetermined)``: ``lam`` solves ``B lam ~= r`` on the independent
    columns (zero on the others) -- least squares for real values; for exact square-root
    numbers (not ordered) it is solved on a set of independent rows, which gives a residual
    that is zero exactly when ``r`` is in the column space.  ``undetermined`` lists the
    columns of ``B`` that depend on earlier ones (unknowns the equations cannot determine).
    """
    m = len(B[0]) if B and B[0] else 0
    if m == 0:
        return list(r), [], []
    _, piv, ambiguous = rref_info(B)
    Bp = [[row[j] for j in piv] for row in B]
    surds = any(isinstance(v, Surd) for row in Bp for v in row) or \
        any(isinstance(v, Surd) for v in r)
    lam_p = _fit(Bp, r, len(piv), surds) if piv else []
    if lam_p is None:  # not certainly regular (intervals): claim nothing at this point
        ambiguous = ambiguous + piv
        lam_p = [0] * len(piv)
    lam = [0] * m
    for j, v in zip(piv, lam_p):
        lam[j] = v
    res = [ri - fi for ri, fi in zip(r, matvec(B, lam))]
    if ambiguous:
        res = [_with_zero(v) for v in res]
    undetermined = sorted(set(j for j in range(m) if j not in piv) | set(ambiguous))
    return res, lam, undetermined


def _fit(Bp, r, k, surds):
    if surds:
        rows = rref_info([list(col) for col in zip(*Bp)])[1]   # independent rows of Bp
        return solve_square([Bp[i] for i in rows], [r[i] for i in rows])
    BtB = [[sum(Bp[q][i] * Bp[q][j] for q in range(len(Bp))) for j in range(k)]
           for i in range(k)]
    Btr = [sum(Bp[q][i] * r[q] for q in range(len(Bp))) for i in range(k)]
    return solve_square(BtB, Btr)


def _with_zero(v):
    """An interval holding ``v`` and 0 (exact kinds are returned unchanged)."""
    if isinstance(v, iv.mpf):
        return iv.mpf([min(v.a, 0), max(v.b, 0)])
    return v


def _independent_columns(B: list[list]) -> list[int]:
    """Pivot columns of ``B``: a maximal set of independent columns, leftmost first."""
    return rref(B)[1]
