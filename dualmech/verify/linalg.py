"""Small dense linear algebra over exact Fractions or mpmath floats, with one code path.

Verdicts need exact arithmetic (``Fraction``) and, where expressions leave the rational world,
high-precision floats (``mpmath.mpf``).  Both go through the same Gauss--Jordan elimination;
only the zero test differs (``== 0`` for Fractions, a relative ``10**(-digits/2)`` for mpf).
Systems here are tiny (a few coordinates plus reactions), so clarity beats speed.
"""
from __future__ import annotations

from fractions import Fraction

import mpmath

from ..exact import MP_DIGITS


def _exact(rows) -> bool:
    return all(isinstance(v, (Fraction, int)) for row in rows for v in row)


def _zero_test(rows):
    if _exact(rows):
        return lambda v, scale=1: v == 0
    tol = mpmath.mpf(10) ** (-(MP_DIGITS // 2))
    return lambda v, scale=1: abs(v) <= tol * (1 + abs(scale))


def rref(rows: list[list]) -> tuple[list[list], list[int]]:
    """Reduced row echelon form and pivot columns (partial pivoting for the float case)."""
    # ints must become Fractions: int / int would silently turn into a float
    A = [[Fraction(v) for v in r] for r in rows] if _exact(rows) else [list(r) for r in rows]
    zero = _zero_test(A)
    scale = max((abs(v) for r in A for v in r), default=1) or 1
    pivots, r = [], 0
    ncols = len(A[0]) if A else 0
    for c in range(ncols):
        best = max(range(r, len(A)), key=lambda i: abs(A[i][c]), default=None)
        if best is None or zero(A[best][c], scale):
            continue
        A[r], A[best] = A[best], A[r]
        p = A[r][c]
        A[r] = [v / p for v in A[r]]
        for i in range(len(A)):
            if i != r and A[i][c] != 0:
                f = A[i][c]
                A[i] = [a - f * b for a, b in zip(A[i], A[r])]
        pivots.append(c)
        r += 1
        if r == len(A):
            break
    return A, pivots


def rank(rows: list[list]) -> int:
    return len(rref(rows)[1]) if rows and rows[0] else 0


def solve_square(A: list[list], b: list) -> list | None:
    """Solution of the square system ``A x = b``, or ``None`` when ``A`` is singular."""
    n = len(A)
    aug = [list(row) + [bi] for row, bi in zip(A, b)]
    R, piv = rref(aug)
    if piv[:n] != list(range(n)) or len(piv) > n:
        return None
    return [R[i][n] for i in range(n)]


def matvec(A: list[list], x: list) -> list:
    return [sum((a * xi for a, xi in zip(row, x)), 0) for row in A]


def residual_after_least_squares(B: list[list], r: list) -> tuple[list, list, list[int]]:
    """Residual of ``r`` after removing its component in the column space of ``B``.

    Returns ``(residual, lam, undetermined)``: ``lam`` solves ``B lam ~= r`` in the least-squares
    sense on the independent columns (zero on the others), ``undetermined`` lists the columns
    of ``B`` that depend on earlier ones (unknowns the equations cannot determine).
    """
    m = len(B[0]) if B and B[0] else 0
    if m == 0:
        return list(r), [], []
    piv = _independent_columns(B)
    Bp = [[row[j] for j in piv] for row in B]
    BtB = [[sum(Bp[k][i] * Bp[k][j] for k in range(len(Bp))) for j in range(len(piv))]
           for i in range(len(piv))]
    Btr = [sum(Bp[k][i] * r[k] for k in range(len(Bp))) for i in range(len(piv))]
    lam_p = solve_square(BtB, Btr) if piv else []
    lam = [0] * m
    for j, v in zip(piv, lam_p or []):
        lam[j] = v
    res = [ri - fi for ri, fi in zip(r, matvec(B, lam))]
    undetermined = [j for j in range(m) if j not in piv]
    return res, lam, undetermined


def _independent_columns(B: list[list]) -> list[int]:
    """Pivot columns of ``B``: a maximal set of independent columns, leftmost first."""
    return rref(B)[1]
