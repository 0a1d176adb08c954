"""Strict conversion to sympy expressions: numbers and sympy objects only, never text.

``sympy.sympify`` evaluates strings as Python; the library never needs that, and a string that
reaches it by mistake (or from an untrusted answer) must be refused, not run.
"""
from __future__ import annotations

import sympy as sp
from sympy.core.sympify import SympifyError


def as_expr(value):
    """``value`` as a sympy object; ``TypeError`` for strings and anything sympy cannot convert
    without parsing text."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"expected a sympy expression or a number, got the text {value!r}; "
                        "build expressions with sympy symbols (text is never evaluated).")
    try:
        return sp.sympify(value, strict=True)
    except SympifyError as exc:
        raise TypeError(f"cannot use {value!r} ({type(value).__name__}) as an expression") \
            from exc


def as_matrix(value) -> sp.Matrix:
    """``value`` (a sympy Matrix or nested sequences of expressions) as a Matrix, every entry
    converted by :func:`as_expr` (text refused, never evaluated)."""
    if isinstance(value, sp.MatrixBase):
        return value.applyfunc(as_expr) if any(isinstance(x, str) for x in value) else value
    if isinstance(value, (str, bytes)):
        as_expr(value)  # raises the TypeError that explains
    rows = list(value)
    if rows and isinstance(rows[0], (list, tuple)):
        return sp.Matrix([[as_expr(x) for x in row] for row in rows])
    return sp.Matrix([as_expr(x) for x in rows])
