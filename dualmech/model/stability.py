"""Linearisation about a steady motion, for any model: with or without multipliers, with
position- and velocity-level (nonholonomic) constraints.

A steady motion is given as values of the coordinates and their rates (``about = {q: value,
q.diff(t): rate}``, missing ones zero), possibly holding one free ``parameter`` (a forward
speed ``v``).  The model's equations ``[M B; G 0] [q''; lambda] = [f; g]`` are solved for
``q''`` where the steady motion holds (``q'' = 0`` there, else it is refused), and
``q''(q, q')`` is linearised without a symbolic inverse of the whole system: with
``r(x) = A(x) z0 - b(x)`` at the steady solution ``z0 = (0, lambda0)``,
``dz/dx = -A0^{-1} dr/dx``.

Constraints are read from the equations themselves: a row with no reaction in it that is the
time derivative of ``a(q) . q' = 0`` is a constraint (its rest must be ``-(da/dt) . q'``
exactly).  When the form ``a . dq`` is closed it is holonomic, and ``a(q0) . dq = 0`` holds
at position level too; otherwise only its velocity level linearises.  The state is reduced to
the constraints' tangent space by choosing dependent coordinates and speeds -- by default the
last ones whose block of the constraint Jacobian is regular (``independent`` names the others
instead) -- and coordinates absent from every equation (cyclic ones) are dropped; their rates
stay.

The result's state matrix is exact: symbolic in the parameter where it fits a size budget,
else made exactly at each (rational) value by :meth:`SteadyLinearisation.at`.

Example
-------
>>> import sympy as sp
>>> from dualmech import Lagrangian, coordinate, rate
>>> x, y = coordinate("x"), coordinate("y"); m, l, g = sp.symbols("m l g", positive=True)
>>> lg = Lagrangian(coordinates=[x, y])
>>> lg.kinetic("T", m * (rate(x)**2 + rate(y)**2) / 2); lg.potential("V", -m * g * y)
>>> S = lg.constraint("S", (l**2 - x**2 - y**2) / (2 * l))
>>> lin = linearize_about(lg.equations(), {y: l})
>>> lin.states, lin.dependent
(('x', "x'"), ('y', "y'"))
>>> lin.symbolic
Matrix([
[   0, 1],
[-g/l, 0]])
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from collections.abc import Mapping, Sequence

import flint
import symengine as se
import sympy as sp

from dualmech.model._algebra import to_se
from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, ModelError, is_zero_expression
from dualmech.model.kinematics import t
from dualmech.model._linearise_se import at_steady as _at_steady_se

__all__ = ["SteadyLinearisation", "linearize_about", "exact_number"]

#: largest system (equations) whose state matrix is formed symbolically in the parameter
SYMBOLIC_SIZE = 12
#: largest total operation count of a symbolic state matrix kept for display
SYMBOLIC_OPS = 4000


def exact_number(value):
    """``value`` as an exact sympy number (a float by its shortest decimal form).

    >>> exact_number(0.1), exact_number(2)
    (1/10, 2)
    """
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool):
        raise TypeError(f"expected a number, got {value!r}.")
    try:   # Fraction reads numbers (and a number's text) exactly and never evaluates anything
        exact = Fraction(str(value)) if isinstance(value, float) else Fraction(value)
    except (TypeError, ValueError):
        raise TypeError(f"expected a number, got {value!r:.60}.") from None
    return sp.Rational(exact.numerator, exact.denominator)


@dataclass(frozen=True)
class SteadyLinearisation:
    """The linearisation of one model about one steady motion.

    Attributes
    ----------
    model : str
        The model's name.
    states : tuple of str
        The reduced state, independent coordinates then independent speeds (``"theta"``,
        ``"theta'"``).
    parameter : sympy.Symbol or None
        The free parameter the matrix depends on.
    symbolic : sympy.Matrix or None
        ``A(parameter)``, when it fits the size budget (else use :meth:`at`).
    dropped : tuple of str
        Cyclic coordinates left out (absent from the equations).
    dependent : tuple of str
        Coordinates and speeds eliminated by the constraints.
    constraints : tuple of (str, str)
        ``(row label, "holonomic" or "velocity")`` of every constraint found.
    """

    model: str
    states: tuple
    parameter: sp.Symbol | None
    symbolic: sp.Matrix | None
    dropped: tuple
    dependent: tuple
    constraints: tuple
    _parts: tuple = field(repr=False, compare=False, default=())

    def at(self, value=None) -> sp.Matrix:
        """The exact state matrix at ``value`` of the parameter (a number)."""
        if self.parameter is None:
            return self.symbolic if self.symbolic is not None else _reduce(self._parts, {})
        value = exact_number(value)
        if self.symbolic is not None:
            return self.symbolic.subs(self.parameter, value)
        return _reduce(self._parts, {self.parameter: value})


def linearize_about(eqs: EquationSet, about: Mapping, values: Mapping | None = None,
                    parameter: sp.Symbol | None = None,
                    independent: Sequence[str] | None = None,
                    generic=None) -> SteadyLinearisation:
    """Linearise ``eqs`` about the steady motion ``about``; see the module docstring.

    Parameters
    ----------
    eqs : EquationSet
        Any model; with reactions or multipliers it must be square.
    about : mapping
        ``{q: value, q.diff(t): rate}`` (missing ones zero).
    values : mapping, optional
        Parameter -> number, substituted exactly (floats by their decimal form).
    parameter : sympy.Symbol, optional
        The free parameter left in the matrix (a parameter of the model, or a symbol of
        ``about``); it is not substituted from ``values``.
    independent : sequence of str, optional
        Names of the independent coordinates and speeds (``"theta"``, ``"theta'"``) when
        there are constraints; the others are dependent.
    generic : number, optional
        A value of ``parameter`` inside its range of interest (default ``7/3``): the
        dependent states are chosen there, and the steady motion and the constraints are
        checked there and at ``generic + 2/7``.
    """
    if not eqs.is_square:
        raise ModelError(f"model `{eqs.name}` has {len(eqs.equations)} equations for {eqs.n} "
                         f"accelerations and {len(eqs.unknowns)} reactions; it must be square "
                         "to be linearised.")
    subs = {k: exact_number(v) for k, v in (values or {}).items() if k != parameter}
    x0 = _point(eqs, about, subs)
    states = eqs.states
    qs, qds = [s.q for s in states], [s.qd for s in states]
    n = eqs.n
    w = sp.symbols(f"_w0:{len(eqs.equations)}")
    if eqs.plain_matrix_se() is not None:    # held in symengine: differentiate there
        A0, b0, R, cons = _at_steady_se(eqs, subs, x0, w)
    else:
        A, b = eqs.plain_matrix()
        A, b = A.subs(subs), b.subs(subs)
        cons = [(lab, [as_expr(x).subs(x0) for x in a], _rates_of(a, qs, qds, x0), closed)
                for lab, a, closed in _constraints(eqs, A, b, qs, qds)]
        A0, b0 = A.subs(x0), b.subs(x0)
        R = (A * sp.Matrix(w) - b).jacobian(qs + qds).subs(x0)
    phi, kinds = _constraint_rows(cons, n)
    # cyclic: the coordinate enters neither the linearised equations nor the constraints
    dropped = [k for k in range(n) if all(is_zero_expression(sp.expand(e)) for e in R[:, k])
               and all(is_zero_expression(row[k]) for row in phi)]
    moving = [states[k].name for k in range(n) if k not in dropped
              and not is_zero_expression(as_expr(x0[qds[k]]))]
    if moving:
        raise ModelError(f"the state {_show(x0)} is not a steady motion of `{eqs.name}`: "
                         f"{', '.join(moving)} move(s), and the equations depend on them, so "
                         "the accelerations do not stay zero; only coordinates nothing depends "
                         "on (cyclic ones) may move on a steady motion.")
    keep = [k for k in range(n) if k not in dropped] + [n + k for k in range(n)]
    names = [s.name for s in states] + [f"{s.name}'" for s in states]
    at = exact_number(generic) if generic is not None else sp.Rational(7, 3)
    checks = [{parameter: at}, {parameter: at + sp.Rational(2, 7)}] if parameter is not None \
        else [{}]
    generic = checks[0]
    dep = _dependent(phi, kinds, keep, n, names, independent, generic, eqs.name)
    parts = (A0, b0, R, w, phi, keep, dep, n, eqs.name, [c[0] for c in cons])
    for value in checks:
        _check_steady(parts, x0, eqs, value)
        for label, a0, _, _ in cons:
            c0 = sp.cancel(sum(aj * x0[qd] for aj, qd in zip(a0, qds)).subs(value))
            if not is_zero_expression(c0):
                raise ModelError(f"the state {_show(x0)} breaks the constraint [{label}] of "
                                 f"`{eqs.name}` (its velocity level is {c0}, not 0); give "
                                 "rates that satisfy it.")
    symbolic = None
    if parameter is None or A0.rows <= SYMBOLIC_SIZE:
        symbolic = _reduce(parts, {})
        if parameter is not None and sp.count_ops(symbolic) > SYMBOLIC_OPS:
            symbolic = None
    indep = [i for i in keep if i not in dep]
    return SteadyLinearisation(eqs.name, tuple(names[i] for i in indep), parameter, symbolic,
                               tuple(names[k] for k in dropped),
                               tuple(names[i] for i in dep),
                               tuple((lab, kind) for lab, kind in
                                     zip([c[0] for c in cons],
                                         ["holonomic" if c[3] else "velocity" for c in cons])),
                               parts)


def _point(eqs: EquationSet, about: Mapping, subs: dict) -> dict:
    """``{q: value, q_dot: rate}`` in plain symbols; missing ones zero."""
    point = {}
    for s in eqs.states:
        point[s.q] = 0
        point[s.qd] = 0
    known = {s.function: s.q for s in eqs.states}
    known.update({s.function.diff(s.function.args[0]): s.qd for s in eqs.states})
    for key, value in about.items():
        if key not in known:
            raise ModelError(f"`about`: {key} is not a coordinate of `{eqs.name}` or its rate; "
                             f"the coordinates are {list(eqs.coordinates)}.")
        point[known[key]] = as_expr(value).subs(subs)
    return point


def _constraints(eqs: EquationSet, A, b, qs, qds) -> list:
    """``[(label, a(q), holonomic)]``: rows free of reactions that are ``d/dt (a . q') = 0``."""
    n, out = eqs.n, []
    for i in constraint_candidates(eqs):
        a = list(A[i, :n])
        if any(not is_zero_expression(x) for x in A[i, n:]) or all(x == 0 for x in a) or \
                any(x.has(*qds) for x in a):
            continue
        rate = sum(sp.diff(a[j], qs[k]) * qds[k] * qds[j] for j in range(n) for k in range(n))
        if not is_zero_expression(sp.expand(b[i] + rate)):
            continue
        closed = all(is_zero_expression(sp.diff(a[j], qs[k]) - sp.diff(a[k], qs[j]))
                     for j in range(n) for k in range(j + 1, n))
        out.append((eqs.labels[i], a, closed))
    return out


def constraint_candidates(eqs: EquationSet) -> list[int]:
    """The rows that may be a constraint's acceleration level: the declared constraints' rows
    when the model records them (``EquationSet.constraints``), else every row of a model with
    multipliers (none without: a cyclic coordinate's equation ``d/dt (a . q') = 0`` has the
    same shape as a differentiated velocity constraint, and is not one)."""
    declared = {c.label for c in getattr(eqs, "constraints", ())}
    if declared:
        return [i for i, label in enumerate(eqs.labels) if label in declared]
    return list(range(len(eqs.labels))) if eqs.unknowns else []


def _rates_of(a, qs, qds, x0) -> list:
    """``d(a . q')/dq`` at the steady state ``x0``."""
    c = sum(aj * qd for aj, qd in zip(a, qds))
    return [sp.diff(c, q).subs(x0) for q in qs]


def _constraint_rows(cons, n) -> tuple[list, list]:
    """Linearised constraints on ``(dq, dq')``: position rows, then velocity rows."""
    pos, vel = [], []
    for _, a0, rates, holonomic in cons:
        if holonomic:
            pos.append(list(a0) + [0] * n)
        vel.append(list(rates) + list(a0))
    return pos + vel, ["position"] * len(pos) + ["velocity"] * len(vel)


def _dependent(phi, kinds, keep, n, names, independent, generic, model) -> list:
    """State indices eliminated by the constraints (a regular block of their Jacobian)."""
    if not phi:
        if independent:
            raise ModelError(f"`independent`: model `{model}` has no constraints; every "
                             "coordinate and speed is independent.")
        return []
    M = sp.Matrix(phi)[:, :].subs(generic)
    if independent is not None:
        unknown = [x for x in independent if x not in [names[i] for i in keep]]
        if unknown:
            raise ModelError(f"`independent`: {unknown} are not states of `{model}` (states: "
                             f"{', '.join(names[i] for i in keep)}).")
        dep = [i for i in keep if names[i] not in independent]
        if len(dep) != len(phi) or M[:, dep].rank(iszerofunc=is_zero_expression) < len(phi):
            raise ModelError(f"`independent` {list(independent)}: the constraints of `{model}` "
                             f"cannot be solved for the others ({', '.join(names[i] for i in dep)})"
                             f"; name {len(keep) - len(phi)} states whose complement has a "
                             "regular constraint Jacobian.")
        return dep
    npos = kinds.count("position")
    dep: list = []
    for rows, cols in ((range(npos), [k for k in reversed(keep) if k < n]),
                       (range(npos, len(phi)), None)):
        if not rows:
            continue
        if cols is None:   # velocity rows: the dependent coordinates' speeds first
            cols = [n + k for k in dep] + [k for k in reversed(keep) if k >= n and k - n not in dep]
        sub = M.extract(list(rows), cols)
        _, pivots = sub.rref(iszerofunc=is_zero_expression)
        if len(pivots) < len(rows):
            raise ModelError(f"model `{model}`: its constraints are dependent at this steady "
                             "motion (their Jacobian is singular); give `independent`.")
        dep += [cols[p] for p in pivots]
    return dep


def _solve(parts, value: dict):
    A0, b0, name = parts[0], parts[1], parts[8]
    A0v = A0.subs(value)
    if is_zero_expression(sp.cancel(A0v.det())):
        raise ModelError(f"model `{name}`: the matrix of [q''; reactions] is singular at the "
                         "steady motion; it cannot be solved for the accelerations there.")
    z0 = A0v.LUsolve(b0.subs(value), iszerofunc=is_zero_expression)
    return A0v, z0


def _check_steady(parts, x0, eqs, generic) -> None:
    _, z0 = _solve(parts, generic)
    moving = [(s.function.diff(s.function.args[0], 2), sp.cancel(z)) for s, z in
              zip(eqs.states, z0[: eqs.n]) if not is_zero_expression(sp.cancel(z))]
    if any(v.has(t) for _, v in moving):
        raise ModelError(f"model `{eqs.name}` is driven: its accelerations depend on time "
                         "explicitly there (" + _accelerations(moving)
                         + "), so it has no steady motion to linearise about (a periodic "
                         "drive's stability is Floquet's question: `dualmech atlas NAME "
                         "--section floquet`).")
    if moving:
        raise ModelError(f"the state {_show(x0)} is not a steady motion of `{eqs.name}`: there "
                         + _accelerations(moving)
                         + " (a steady motion keeps every rate constant).")


def _reduce(parts, value: dict) -> sp.Matrix:
    """The reduced state matrix at ``value`` (``{}``: symbolic in the parameter)."""
    if value and all(as_expr(v).is_Rational for v in value.values()):
        fast = _reduce_rational(parts, value)
        if fast is not None:
            return fast
    _, _, R, w, phi, keep, dep, n, name, _ = parts
    A0v, z0 = _solve(parts, value)
    Rv = R.subs(value).subs(dict(zip(w, z0)))
    dqdd = (-A0v.LUsolve(Rv, iszerofunc=is_zero_expression))[:n, :]
    J = sp.zeros(2 * n, 2 * n)
    J[:n, n:] = sp.eye(n)
    J[n:, :] = dqdd
    indep = [i for i in keep if i not in dep]
    T = sp.zeros(len(keep), len(indep))
    pos = {s: i for i, s in enumerate(keep)}
    for j, i in enumerate(indep):
        T[pos[i], j] = 1
    if dep:
        P = sp.Matrix(phi).subs(value)
        sol = -P[:, dep].LUsolve(P[:, indep], iszerofunc=is_zero_expression)
        for r, i in enumerate(dep):
            T[pos[i], :] = sol[r, :]
    out = J.extract(indep, keep) * T
    return out.applyfunc(lambda e: _timeless(sp.cancel(e), name) if e.free_symbols else e)


_HELD: dict = {}


def _held(parts) -> tuple:
    """``(A0, b0, R, phi, w)`` of ``parts`` in symengine (converted once per linearisation)."""
    hit = _HELD.get(id(parts))
    if hit is None or hit[0] is not parts:
        A0, b0, R, w, phi = parts[:5]
        conv = lambda m: se.DenseMatrix(m.rows, m.cols, [to_se(x) for x in m])  # noqa
        hit = (parts, (conv(A0), conv(b0), conv(R), conv(sp.Matrix(phi)) if phi else None,
                       [se.Symbol(x.name) for x in w]))
        if len(_HELD) > 64:
            _HELD.clear()
        _HELD[id(parts)] = hit   # parts kept alive with it: its id is not reused
    return hit[1]


def _fmpq_mat(m, subs: dict):
    """``m`` (symengine) at ``subs`` as a FLINT rational matrix; ``None`` unless every entry
    is then a rational number."""
    out = []
    for x in m.xreplace(subs) if subs else m:
        if not x.is_Rational:
            return None
        num, den = x.get_num_den()
        out.append(flint.fmpq(int(num), int(den)))
    return flint.fmpq_mat(m.rows, m.cols, out)


def _reduce_rational(parts, value: dict):
    """:func:`_reduce` at a rational value of the parameter where every entry is then a
    rational number: exact linear algebra on FLINT (the same steps, no sympy arithmetic).
    ``None`` when an entry stays irrational (a square root): the sympy route decides."""
    _, _, _, _, phi, keep, dep, n, name, _ = parts
    A0, b0, R, P, w = _held(parts)
    exact = {k: as_expr(v) for k, v in value.items()}
    if not all(v.is_Rational for v in exact.values()):
        return None
    # built from their integers: nothing here is ever parsed
    subs = {se.Symbol(k.name): se.Rational(int(v.p), int(v.q)) for k, v in exact.items()}
    A0v, b0v = _fmpq_mat(A0, subs), _fmpq_mat(b0, subs)
    if A0v is None or b0v is None:
        return None
    if A0v.det() == 0:
        raise ModelError(f"model `{name}`: the matrix of [q''; reactions] is singular at the "
                         "steady motion; it cannot be solved for the accelerations there.")
    z0 = A0v.solve(b0v)
    subs.update({wk: se.Rational(int(z0[i, 0].p), int(z0[i, 0].q)) for i, wk in enumerate(w)})
    Rv = _fmpq_mat(R, subs)
    if Rv is None:
        return None
    dqdd = -A0v.solve(Rv)
    size = 2 * n
    J = [[flint.fmpq(0)] * size for _ in range(size)]
    for i in range(n):
        J[i][n + i] = flint.fmpq(1)
        for j in range(size):
            J[n + i][j] = dqdd[i, j]
    indep = [i for i in keep if i not in dep]
    pos = {s_: i for i, s_ in enumerate(keep)}
    T = [[flint.fmpq(0)] * len(indep) for _ in keep]
    for j, i in enumerate(indep):
        T[pos[i]][j] = flint.fmpq(1)
    if dep:
        Pv = _fmpq_mat(P, subs)
        if Pv is None:
            return None
        cols = lambda idx: flint.fmpq_mat(Pv.nrows(), len(idx),  # noqa: E731
                                          [Pv[r, c] for r in range(Pv.nrows()) for c in idx])
        sol = -cols(dep).solve(cols(indep))
        for r, i in enumerate(dep):
            T[pos[i]] = [sol[r, c] for c in range(len(indep))]
    Jm = flint.fmpq_mat(len(indep), len(keep), [J[i][k] for i in indep for k in keep])
    Tm = flint.fmpq_mat(len(keep), len(indep), [x for row in T for x in row])
    out = Jm * Tm
    return sp.Matrix(out.nrows(), out.ncols(),
                     [sp.Rational(int(x.p), int(x.q)) for x in out.entries()])


def _timeless(entry, name: str):
    """``entry`` without the time ``t`` it holds only in form (``sin(w t)^2 + cos(w t)^2``
    of a rotating frame), else a refusal: the linearisation is not time-invariant."""
    if not entry.has(t):
        return entry
    if is_zero_expression(sp.diff(entry, t)):
        return sp.cancel(entry.subs(t, 0))
    raise ModelError(f"model `{name}`: its linearisation depends on time explicitly ({entry}): "
                     "a driven system has no steady motion of this kind (a periodic drive's "
                     "stability is Floquet's question: `dualmech atlas NAME --section "
                     "floquet`).")


def _show(x0: dict) -> str:
    """The state as text, its zero entries left out (all zero: said so, not ``{}``)."""
    shown = ", ".join(f"{k} = {v}" for k, v in x0.items() if v != 0)
    return "{" + shown + "}" if shown else "(every coordinate and rate zero)"


def _accelerations(moving) -> str:
    """``x'' = 5886/4075 (1.44)``, ... for the accelerations that do not vanish."""
    from dualmech.model.notation import text
    out = []
    for a, v in moving:
        value = text(v)
        try:
            value += f" (= {float(v):.6g})" if not as_expr(v).is_Rational else ""
        except (TypeError, ValueError):
            pass
        out.append(f"{text(a)} = {value}")
    return ", ".join(out)
