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


#: parameters that legitimately take text: names, labels, keys, axis letters
TEXT_PARAMETERS = frozenset({
    "name", "key", "label", "labels", "description", "axes", "axis", "normal", "model",
    "title", "source", "summary", "where", "kind", "direction_name", "backend", "method",
    "which", "section", "coordinates_of", "self", "cls", "notation"})


#: dict-valued parameters whose keys are names (ingredient labels), not expressions
NAMED_KEYS = frozenset({"parts", "contributions", "names"})


def _find_text(value, depth: int = 0, named_keys: bool = False):
    """The first str/bytes inside ``value`` (sequences, dict keys and values, matrices)."""
    if isinstance(value, (str, bytes, bytearray)):
        return value
    if depth > 4:
        return None
    if isinstance(value, dict):
        for k, v in value.items():
            if not (named_keys and isinstance(k, str)):
                found = _find_text(k, depth + 1)
                if found is not None:
                    return found
            found = _find_text(v, depth + 1, named_keys)
            if found is not None:
                return found
    elif isinstance(value, (list, tuple, set, frozenset)):
        for v in value:
            found = _find_text(v, depth + 1, named_keys)
            if found is not None:
                return found
    elif isinstance(value, sp.MatrixBase):
        for v in value:
            if isinstance(v, (str, bytes)):
                return v
    return None


def refuse_text(fn):
    """Decorator: every argument of ``fn`` except those in :data:`TEXT_PARAMETERS` must be free
    of text (``str``/``bytes``, also inside sequences and dict values) -- text is refused with
    a TypeError naming the argument, never passed on to sympy, which would evaluate it."""
    import functools
    import inspect
    sig = inspect.signature(fn)

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            bound = sig.bind_partial(*args, **kwargs)
        except TypeError:
            return fn(*args, **kwargs)
        for pname, value in bound.arguments.items():
            if pname in TEXT_PARAMETERS:
                continue
            found = _find_text(value, named_keys=pname in NAMED_KEYS)
            if found is not None:
                raise TypeError(
                    f"`{pname}` of {fn.__qualname__}() got the text {found!r:.60}; give sympy "
                    "expressions and numbers (build them with sympy symbols): text is never "
                    "evaluated.")
        return fn(*args, **kwargs)

    wrapper.__signature__ = sig
    return wrapper


def refuse_text_in(cls):
    """Class decorator: :func:`refuse_text` on every public method and ``__init__``."""
    for attr, value in list(vars(cls).items()):
        wrapped_kind = isinstance(value, (staticmethod, classmethod))   # not callable() in 3.10
        if attr == "__init__" or (not attr.startswith("_") and (callable(value) or wrapped_kind)):
            if isinstance(value, (staticmethod, classmethod)):
                wrapped = type(value)(refuse_text(value.__func__))
            elif isinstance(value, property):
                continue
            else:
                wrapped = refuse_text(value)
            setattr(cls, attr, wrapped)
    return cls


def dotted(expr) -> str:
    """``expr`` as text with ``theta'`` and ``theta''`` for the derivatives of functions of
    time (the notation people read), ``theta`` for ``theta(t)``: :func:`dualmech.model.notation.text`.
    """
    from dualmech.model.notation import text
    return text(as_expr(expr))
