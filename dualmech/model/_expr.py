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


#: functions whose value jumps: equations of motion written with them are not smooth
JUMPS = frozenset({"sign", "Heaviside", "Piecewise", "Max", "Min", "floor", "ceiling"})


def refuse_jumps(exprs, what: str) -> None:
    """``ModelError`` when one of ``exprs`` (sympy or symengine) applies a function that jumps
    (:data:`JUMPS`: ``sign``, ``Heaviside``, ``Piecewise``, ...): the equations of motion are
    derived, compared, solved and integrated as smooth functions of the state, so Coulomb
    friction ``-mu N sign(v)`` is written for one sliding phase of known direction instead.

    >>> from dualmech import coordinate, rate
    >>> refuse_jumps([-sp.sign(rate(coordinate("x")))], "force `friction`")
    ... # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dualmech.model.equations.ModelError: force `friction`: sign(x') is not supported...
    """
    import symengine as se
    for e in exprs:
        if isinstance(e, (int, float)):
            continue
        base = se.Function if isinstance(e, se.Basic) else sp.core.function.Application
        for f in e.atoms(base):
            if type(f).__name__ in JUMPS:
                from dualmech.model.equations import ModelError
                raise ModelError(_jump_message(f, what))


def _jump_message(f, what: str) -> str:
    name = type(f).__name__
    arg = sp.sympify(f.args[0]) if name == "sign" and f.args else sp.S.Zero
    if name == "sign" and arg.has(sp.Derivative):   # Coulomb friction: the sign of a velocity
        arg = str(arg.replace(lambda e: isinstance(e, sp.Derivative), lambda d: sp.Symbol(
            getattr(d.expr.func, "__name__", str(d.expr)) + "'" * d.derivative_count)))
        return (f"{what}: sign({arg}) is not supported: dualmech derives, compares, solves and "
                "integrates the equations of motion as smooth functions of the state, and "
                "sign() jumps where the sliding stops or reverses (sticking is another "
                "model).  Write Coulomb friction for one sliding phase of known direction: "
                "while sliding towards +e the friction is -mu*N along e (e.g. "
                "ne.force(\"friction\", block, -mu*N*O.x), N the normal reaction; in the "
                "Lagrangian its generalised force), declare that phase with the coordinate's "
                "rate_range (e.g. (0.1, 2) for sliding towards +x), and write the opposite "
                "phase as a second problem with the friction reversed.")
    return (f"{what}: {name}(...) is not supported: dualmech derives, compares, solves and "
            f"integrates the equations of motion as smooth functions of the state, and {name} "
            "jumps.  Write each regime as its own problem (one phase of known sign), with the "
            "coordinate ranges that keep the motion in it.")


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
