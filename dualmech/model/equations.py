"""The canonical equation object every derivation ends in.

An :class:`EquationSet` holds equations ``e_i(q'', lambda, q', q, t) = 0`` that are linear in
the accelerations ``q''`` and in the unknown reactions or multipliers ``lambda``::

    [M(q, t)  B(q, t)] [q''; lambda] = f(q, q', t)

Downstream code -- comparison, reaction recovery, linearisation, simulation, code generation --
works from this one object.  Nothing here needs a symbolic inverse of ``M``; the symbolic
solutions (:meth:`EquationSet.solve`) exist for display and for small models only.

Example
-------
>>> import sympy as sp
>>> from dualmech.model.kinematics import coordinate, t
>>> from dualmech.model.equations import EquationSet
>>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
>>> eqs = EquationSet("spring", (x,), (m*x.diff(t, 2) + k*x,))
>>> eqs.mass_matrix(), eqs.forcing()
(Matrix([[m]]), Matrix([[-k*x(t)]]))
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cached_property
from typing import Mapping, Sequence

import symengine as se
import sympy as sp

from dualmech.model._expr import as_expr, refuse_text_in
from dualmech.model._algebra import (clearly_nonzero, is_zero_held, is_zero_trig,
                                     linear_coefficients, names_of, time_se, to_se, to_sp)
from dualmech.model.kinematics import t

__all__ = ["Constraint", "EquationSet", "ModelError", "Rows", "StateSymbols",
           "is_zero_expression", "state_symbols", "vanishes_identically"]


class ModelError(ValueError):
    """A model that cannot be used as written; the message says what to fix.

    Examples
    --------
    >>> from dualmech import NewtonEuler, Frame, coordinate
    >>> NewtonEuler(coordinates=[coordinate("x")], ground=Frame.ground()).equations()
    Traceback (most recent call last):
    ...
    dualmech.model.equations.ModelError: `newton_euler` has no equations: call linear_momentum or angular_momentum for each body.
    """


@dataclass(frozen=True)
class StateSymbols:
    """Plain symbols standing for ``q(t)``, ``q'(t)`` and ``q''(t)`` of one coordinate."""

    function: sp.Expr
    q: sp.Symbol
    qd: sp.Symbol
    qdd: sp.Symbol

    @property
    def name(self) -> str:
        return self.function.func.__name__


@dataclass(frozen=True)
class Constraint:
    """A constraint the motion keeps, at the level it was declared (not differentiated).

    A model's equations hold each constraint at the acceleration level (a row labelled
    ``label``); the declaration keeps it where it was written -- ``g(q, t) = 0`` at
    ``level="position"``, ``a(q, t) . q' + a0(q, t) = 0`` at ``level="velocity"`` -- so the
    verdict can draw its points on the motion's constraint manifold and simulation and
    linearisation know it.  Made by the builders (``NewtonEuler.constraint``,
    ``NewtonEuler.velocity_constraint``, ``NewtonEuler.rolling``, ``Lagrangian.constraint``,
    ``Lagrangian.velocity_constraint``); ``expression`` is written in the coordinates as
    functions of ``t``.

    Examples
    --------
    >>> from dualmech import coordinate, rate
    >>> x = coordinate("x")
    >>> Constraint("roll", "velocity", rate(x) - 2, "constraint roll (acceleration level)")
    Constraint(name='roll', level='velocity', expression=Derivative(x(t), t) - 2, label='constraint roll (acceleration level)')
    """

    name: str
    level: str
    expression: sp.Expr
    label: str = ""

    def __post_init__(self):
        if self.level not in ("position", "velocity"):
            raise ModelError(f"constraint `{self.name}`: `level` must be 'position' or "
                             f"'velocity', got {self.level!r}.")
        object.__setattr__(self, "expression", as_expr(self.expression))

    def plain(self, coordinates) -> sp.Expr:
        """The expression in plain state symbols (see :func:`state_symbols`)."""
        return to_plain(self.expression, coordinates)



_STATE_CACHE: dict = {}


def state_symbols(q: sp.Expr) -> StateSymbols:
    """The :class:`StateSymbols` of coordinate ``q`` (cached, so shared by every model)."""
    if q not in _STATE_CACHE:
        if not (isinstance(q, sp.core.function.AppliedUndef) and q.args == (t,)):
            raise ModelError(f"coordinate {q!r} must be a function of t, e.g. "
                             "`dualmech.coordinate('x')`.")
        name = q.func.__name__
        _STATE_CACHE[q] = StateSymbols(q, sp.Symbol(name, real=True),
                                       sp.Symbol(f"{name}_dot", real=True),
                                       sp.Symbol(f"{name}_ddot", real=True))
    return _STATE_CACHE[q]


class Rows(Sequence):
    """Equations (or per-equation ``{ingredient: term}`` dicts) held in symengine by a
    derivation and converted to sympy when first read.

    A derivation builds its equations on symengine (:mod:`dualmech.model._algebra`); the verdict
    needs only their linear structure (:meth:`EquationSet.plain_matrix`), so the sympy form,
    which costs more to build than the derivation itself, is made only for a reader.
    ``plain`` says whether the rows are written in plain state symbols (see
    :func:`state_symbols`) or in the coordinates as functions of time.
    """

    __slots__ = ("se", "names", "coordinates", "plain", "_sp")

    def __init__(self, exprs, names: dict, coordinates, plain: bool):
        self.se = tuple(exprs)
        self.names = names
        self.coordinates = tuple(coordinates)
        self.plain = plain
        self._sp = None

    def materialise(self) -> tuple:
        """The sympy form (built once)."""
        if self._sp is None:
            names, memo = self.names, {}
            if self.plain:   # plain state symbols straight to q(t), q', q''
                names = dict(names)
                for q in self.coordinates:
                    s = state_symbols(q)
                    # (the rates as Derivative objects: what q.diff(t) gives, without
                    # differentiation machinery)
                    names.update({s.q.name: q, s.qd.name: sp.Derivative(q, t),
                                  s.qdd.name: sp.Derivative(q, (t, 2))})
            conv = lambda e: to_sp(e, names, memo)  # noqa: E731
            self._sp = tuple({k: conv(v) for k, v in x.items()} if isinstance(x, dict)
                             else conv(x) for x in self.se)
        return self._sp

    def __len__(self) -> int:
        return len(self.se)

    def __getitem__(self, i):
        return self.materialise()[i]

    def __iter__(self):
        return iter(self.materialise())

    def __eq__(self, other) -> bool:
        return tuple(self) == (tuple(other) if isinstance(other, Sequence) else other)

    __hash__ = None

    def __add__(self, other):
        return tuple(self) + tuple(other)

    def __radd__(self, other):
        return tuple(other) + tuple(self)

    def __repr__(self) -> str:
        return repr(self.materialise())

    def substituted(self, mapping: Mapping, labels: Sequence) -> tuple:
        """``((rows, names), labels)``: the rows with each old coordinate replaced by its
        expression in ``mapping`` (functions of ``t``), in symengine, without the rows that
        vanish identically (a constraint the new coordinates satisfy by construction)."""
        names = dict(self.names)
        rules = {}
        for q, expr in mapping.items():
            expr = as_expr(expr)
            for k, v in names_of(expr).items():
                names.setdefault(k, v)
            e0 = to_se(expr)
            e1 = e0.diff(time_se())
            e2 = e1.diff(time_se())
            if self.plain:
                st = state_symbols(q)
                rules.update({se.Symbol(st.q.name): e0, se.Symbol(st.qd.name): e1,
                              se.Symbol(st.qdd.name): e2})
            else:
                f = to_se(q)
                rules.update({f.diff(time_se(), 2): e2, f.diff(time_se()): e1, f: e0})
        out, kept = [], []
        for e, label in zip(self.se, labels):
            e = e.xreplace(rules)
            if e.expand() == 0:
                continue
            out.append(e)
            kept.append(label)
        return (out, names), kept

    def __reduce__(self):   # symengine objects do not pickle: the sympy form does
        return (tuple, (self.materialise(),))


def _zero_or(x):
    """``x``, or ``0`` when it vanishes once multiplied out; expanded only when it is not
    clearly nonzero at a random point (see :func:`~dualmech.model._algebra.is_zero_held`)."""
    if x == 0 or x.is_Number or x.is_Symbol or _expanded(x):
        return x
    return se.Integer(0) if is_zero_held(x, "coefficients") else x


def _expanded(x) -> bool:
    """Whether ``x`` is already multiplied out at its top levels (a sum of products none of
    whose factors is a sum or a power of one), so that expansion leaves it as it is: symengine
    collects equal terms as it builds a sum, so such a nonzero ``x`` is nonzero expanded."""
    terms = x.args if x.is_Add else (x,)
    for term in terms:
        factors = term.args if term.is_Mul else (term,)
        for f in factors:
            if f.is_Add or (f.is_Pow and f.args[0].is_Add):
                return False
    return True


class _Nonlinear(Exception):
    """A product of two factors holding unknowns, or an unknown inside a function or power."""


def _linear_walk(x, us: set, memo: dict) -> dict:
    """``{unknown: coefficient, None: the rest}`` of ``x``, read off its tree in one pass
    (shared subtrees once, through ``memo``): a sum adds its terms' parts, a product with one
    factor holding unknowns multiplies that factor's parts by the other factors.  Raises
    :class:`_Nonlinear` where the tree is not visibly linear (``(u + x) (u + y) - u**2`` is
    linear only once multiplied out)."""
    hit = memo.get(x)
    if hit is not None:
        return hit
    if x.is_Symbol:
        out = {x: se.Integer(1)} if x in us else {None: x}
    elif x.is_Number:
        out = {None: x}
    elif x.is_Add:
        terms: dict = {}
        for a in x.args:
            for k, v in _linear_walk(a, us, memo).items():
                terms.setdefault(k, []).append(v)
        out = {k: (v[0] if len(v) == 1 else se.Add(*v)) for k, v in terms.items()}
    elif x.is_Mul:
        holding, others = None, []
        for f in x.args:
            part = _linear_walk(f, us, memo)
            if len(part) > 1 or None not in part:
                if holding is not None:
                    raise _Nonlinear
                holding = part
            else:
                others.append(f)
        if holding is None:
            out = {None: x}
        else:
            rest = se.Mul(*others)
            out = {k: rest * v for k, v in holding.items()}
    else:   # a power, a function, a derivative: linear only when free of the unknowns
        for a in x.args:
            part = _linear_walk(a, us, memo)
            if len(part) > 1 or None not in part:
                raise _Nonlinear
        out = {None: x}
    memo[x] = out
    return out


def _linear_parts(e, unknown: list, us: set, memo: dict | None = None
                  ) -> tuple[list, object, list]:
    """``(coefficients, rhs, nonlinear unknowns)`` of a row linear in ``unknown``, read off
    the row's tree (:func:`_linear_walk`); ``rhs`` is minus the row with every unknown set to
    zero.  A row that is not visibly linear is looked at again expanded (``(u + x) (u + y) s -
    u**2 s`` is linear only once multiplied out); expansion is not the first step, because it
    multiplies out products of sums (a bicycle's direct rows grow tenfold and take
    seconds)."""
    try:
        parts = _linear_walk(e, us, {} if memo is None else memo)
    except _Nonlinear:
        parts = None
    if parts is not None:
        # an entry that cancels once multiplied out is made 0, as expansion would leave it
        # (static rows, sparsity and coupling are read from the zeros)
        zero = se.Integer(0)
        return ([_zero_or(parts.get(u, zero)) for u in unknown],
                _zero_or(-parts.get(None, zero)), [])
    e = e.expand()
    buckets: dict = {}
    rest = []
    for term in (e.args if e.is_Add else (e,)):
        hit = term.free_symbols & us
        if not hit:
            rest.append(term)
        for u in hit:
            buckets.setdefault(u, []).append(term)
    row, bad = [], []
    for u in unknown:
        terms = buckets.get(u)
        a = se.Add(*terms).diff(u) if terms else se.Integer(0)
        if terms and a.free_symbols & us:
            bad.append(u)
        row.append(a)
    return row, -se.Add(*rest), bad


@refuse_text_in
@dataclass(frozen=True, eq=False)
class EquationSet:
    """Equations of motion ``equations[i] = 0``, linear in ``(q'', unknowns)``.

    Parameters
    ----------
    name : str
        Which derivation produced it (``"lagrange"``, ``"newton_euler"``, ...).
    coordinates : tuple of ``q(t)``
        The generalised coordinates, as functions of :data:`dualmech.model.kinematics.t`.
    equations : tuple of sympy expressions
        Left sides; ``= 0`` implied.
    unknowns : tuple of symbols
        Reaction forces or multipliers that appear linearly.
    labels : tuple of str
        One short label per equation ("sum F . i_B", "d/dt dL/dtheta' ...").
    contributions : tuple of dict
        Optional: per equation, the additive piece each modelling ingredient contributes
        (used to generate mutants for testing the comparator).
    description : str
        One line shown beside the name.
    constraints : tuple of Constraint
        The constraints the model declares at position or velocity level (their
        acceleration-level rows are among ``equations``); the verdict samples on the manifold
        they define.

    Examples
    --------
    A set written directly (the builders :class:`~dualmech.model.direct.NewtonEuler` and
    :class:`~dualmech.model.lagrange.Lagrangian` make these for you):

    >>> import sympy as sp
    >>> from dualmech import EquationSet, coordinate, rate
    >>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
    >>> eqs = EquationSet("by hand", (x,), (m * rate(x, 2) + k * x,))
    >>> eqs.accelerations_solved()
    {Derivative(x(t), (t, 2)): -k*x(t)/m}
    """

    name: str
    coordinates: tuple
    equations: tuple
    unknowns: tuple = ()
    labels: tuple = ()
    contributions: tuple = field(default=(), repr=False)
    description: str = ""
    constraints: tuple = field(default=(), repr=False)

    def __post_init__(self):
        object.__setattr__(self, "coordinates", tuple(self.coordinates))
        object.__setattr__(self, "constraints", tuple(self.constraints))
        for c in self.constraints:
            if not isinstance(c, Constraint):
                raise ModelError(f"model `{self.name}`: `constraints` holds {c!r}; each must "
                                 "be a dualmech Constraint (declare them with the builders).")
        if not isinstance(self.equations, Rows):
            object.__setattr__(self, "equations", tuple(as_expr(e) for e in self.equations))
        if not isinstance(self.contributions, Rows):
            object.__setattr__(self, "contributions", tuple(self.contributions))
        object.__setattr__(self, "unknowns", tuple(self.unknowns))
        if not self.equations:
            raise ModelError(f"model `{self.name}` has no equations.")
        if not self.coordinates:
            raise ModelError(f"model `{self.name}` has no coordinates.")
        for q in self.coordinates:
            state_symbols(q)
        labels = tuple(self.labels) or tuple(f"eq{i + 1}" for i in range(len(self.equations)))
        if len(labels) != len(self.equations):
            raise ModelError(f"model `{self.name}`: {len(labels)} labels for "
                             f"{len(self.equations)} equations.")
        object.__setattr__(self, "labels", labels)
        self._check_linear()

    def __getstate__(self) -> dict:
        state = dict(self.__dict__)
        state.pop("_plain_se", None)   # symengine matrices do not pickle (rebuilt on demand)
        return state

    # -- symbols -----------------------------------------------------------------------
    @property
    def states(self) -> tuple[StateSymbols, ...]:
        return tuple(state_symbols(q) for q in self.coordinates)

    @property
    def accelerations(self) -> tuple:
        return _rates(tuple(self.coordinates))[1]

    @property
    def velocities(self) -> tuple:
        return _rates(tuple(self.coordinates))[0]

    @property
    def n(self) -> int:
        return len(self.coordinates)

    def to_plain(self, expr):
        """Replace ``q''``, ``q'``, ``q`` by plain symbols (see :func:`state_symbols`)."""
        return to_plain(expr, self.coordinates)

    # -- the linear structure ----------------------------------------------------------
    @cached_property
    def _unknown_vector(self) -> list:
        return list(self.accelerations) + list(self.unknowns)

    @cached_property
    def _plain(self) -> tuple[sp.Matrix, sp.Matrix]:
        """``(A, b)`` in plain symbols (``q``, ``q_dot``; see :func:`state_symbols`)."""
        if isinstance(self.equations, Rows):
            A, b, names = self._plain_se
            memo: dict = {}   # shared subexpressions converted once
            return (sp.Matrix(A.rows, A.cols, [to_sp(x, names, memo) for x in A]),
                    sp.Matrix(b.rows, 1, [to_sp(x, names, memo) for x in b]))
        plain = [self.to_plain(e) for e in self.equations]
        unknown = [s.qdd for s in self.states] + list(self.unknowns)
        try:
            A, b, bad = linear_coefficients(plain, unknown)
        except ValueError as exc:
            raise ModelError(f"model `{self.name}`: {exc}") from None
        self._refuse_nonlinear(bad)
        return A, b

    def _refuse_nonlinear(self, bad) -> None:
        if bad:
            names = [from_plain(u, self.coordinates) for u in bad]
            raise ModelError(f"model `{self.name}` is not linear in {names}; the equations must "
                             "be linear in the accelerations and the reactions.")

    @cached_property
    def _plain_se(self) -> tuple:
        """``(A, b, names)`` of equations held in symengine (:class:`Rows`), in plain
        symbols, without building a sympy expression."""
        rows = self.equations
        names = dict(rows.names)
        for s in self.states:
            for sym in (s.q, s.qd, s.qdd):
                names[sym.name] = sym
        exprs = list(rows.se) if rows.plain else \
            [to_plain_se(e, self.coordinates) for e in rows.se]
        for e in (exprs if not rows.plain else ()):   # plain rows have no functions of t
            left = e.atoms(se.Derivative, se.FunctionSymbol)
            if left:
                what = to_sp(next(iter(left)), names)
                raise ModelError(f"model `{self.name}` contains {what}: only the coordinates "
                                 f"{list(self.coordinates)}, their rates and accelerations "
                                 "may appear.")
        unknown = [se.Symbol(s.qdd.name) for s in self.states] + \
            [se.Symbol(u.name) for u in self.unknowns]
        for u in self.unknowns:
            names[u.name] = u
        us = set(unknown)
        A, b, bad = [], [], []
        memo: dict = {}     # shared subtrees of the rows walked once
        for e in exprs:
            row, rhs, nonlinear = _linear_parts(e, unknown, us, memo)
            A += row
            b.append(rhs)
            bad += nonlinear
        self._refuse_nonlinear([to_sp(u, names) for u in dict.fromkeys(bad)])
        return (se.DenseMatrix(len(exprs), len(unknown), A), se.DenseMatrix(len(exprs), 1, b),
                names)

    @cached_property
    def _matrix(self) -> tuple[sp.Matrix, sp.Matrix]:
        A, b = self._plain
        back = lambda e: from_plain(e, self.coordinates)  # noqa: E731
        return A.applyfunc(back), b.applyfunc(back)

    def _check_linear(self) -> None:
        if isinstance(self.equations, Rows):
            self._plain_se  # noqa: B018  (raises ModelError when not linear)
            return
        allowed = set(self.coordinates)
        for e in self.equations:
            for d in e.atoms(sp.Derivative):
                if d.derivative_count > 2:
                    raise ModelError(f"model `{self.name}` contains {d}: at most second "
                                     "derivatives of the coordinates may appear.")
            for f in e.atoms(sp.core.function.AppliedUndef):
                if f not in allowed:
                    raise ModelError(f"model `{self.name}` uses {f}, which is not one of its "
                                     f"coordinates {list(self.coordinates)}.")
        self._plain  # noqa: B018  (raises ModelError when not linear)

    def free_symbols(self) -> set:
        """Symbols of the equations other than time-dependent coordinates (parameters,
        reactions, ``t``), read without converting equations held in symengine."""
        if isinstance(self.equations, Rows):
            names = self.equations.names
            out = set()
            for e in self.equations.se:
                for s in e.free_symbols:
                    mine = names.get(s.name)
                    out.add(mine if isinstance(mine, sp.Symbol) else sp.Symbol(s.name))
            if self.equations.plain:
                out -= {x for st in self.states for x in (st.q, st.qd, st.qdd)}
            return out
        return set().union(*(e.free_symbols for e in self.equations))

    def plain_matrix_se(self) -> tuple | None:
        """``(A, b, names)`` in symengine and plain symbols for equations a derivation holds
        in symengine (``names`` maps symbol names back to sympy); ``None`` for equations
        given in sympy."""
        return self._plain_se if isinstance(self.equations, Rows) else None

    def plain_matrix(self) -> tuple[sp.Matrix, sp.Matrix]:
        """``(A, b)`` with ``A [q''; unknowns] = b``, in plain state symbols."""
        return self._plain

    def matrix(self) -> tuple[sp.Matrix, sp.Matrix]:
        """``(A, b)`` with ``A [q''; unknowns] = b``."""
        return self._matrix

    def mass_matrix(self) -> sp.Matrix:
        return self._matrix[0][:, : self.n]

    def reaction_matrix(self) -> sp.Matrix:
        return self._matrix[0][:, self.n:]

    def forcing(self) -> sp.Matrix:
        return self._matrix[1]

    @property
    def is_square(self) -> bool:
        return len(self.equations) == self.n + len(self.unknowns)

    # -- symbolic solutions (display, small models) ------------------------------------
    @cached_property
    def _solution(self) -> dict:
        if not self.is_square:
            raise ModelError(f"model `{self.name}` has {len(self.equations)} equations for "
                             f"{self.n} accelerations and {len(self.unknowns)} reactions.")
        A, b = self._matrix
        # unsimplified entries (sin^2 + cos^2 - 1) must not be taken as pivots: a structural
        # zero used as a pivot gives nan
        try:
            sol = A.LUsolve(b, iszerofunc=is_zero_expression)
        except ValueError:          # sympy's NonInvertibleMatrixError: no pivot left
            empty = [self.labels[i] for i in range(A.rows)
                     if all(is_zero_expression(x) for x in A.row(i))]
            why = (f"equation(s) {', '.join(f'`{e}`' for e in empty)} hold no acceleration "
                   "or reaction (a massless part, or a constraint written at position level)"
                   if empty else "its matrix [M B] is singular for every state")
            raise ModelError(f"model `{self.name}` cannot be solved for its accelerations and "
                             f"reactions: {why}. Such a model is judged together with the "
                             "others (dualmech check) but has no solved form of its own.") \
                from None
        return {u: _tidy(s) for u, s in zip(self._unknown_vector, sol)}

    def solve(self) -> dict:
        """Symbolic ``{q'': ..., reaction: ...}`` (LU solve, then simplified)."""
        return dict(self._solution)

    def accelerations_solved(self) -> dict:
        return {a: self._solution[a] for a in self.accelerations}

    def reactions_solved(self) -> dict:
        return {u: self._solution[u] for u in self.unknowns}

    # -- transformations ---------------------------------------------------------------
    def substitute(self, mapping: Mapping, name: str | None = None) -> "EquationSet":
        """The same equations with ``mapping`` substituted (parameters, not coordinates)."""
        eqs = tuple(as_expr(e).subs(mapping, simultaneous=True) for e in self.equations)
        contrib = tuple({k: as_expr(v).subs(mapping, simultaneous=True) for k, v in c.items()}
                        for c in self.contributions)
        cons = tuple(Constraint(c.name, c.level, c.expression.subs(mapping, simultaneous=True),
                                c.label) for c in self.constraints)
        return EquationSet(name or self.name, self.coordinates, eqs, self.unknowns,
                           self.labels, contrib, self.description, cons)

    def change_coordinates(self, coordinates: Sequence, mapping: Mapping,
                           name: str | None = None) -> "EquationSet":
        """Rewrite in new coordinates, ``mapping = {old_q(t): expression in new q(t)}``.

        Equations that vanish identically after the substitution (the acceleration form of a
        constraint that the new coordinates satisfy by construction) are dropped.
        """
        missing = [q for q in self.coordinates if q not in mapping]
        if missing:
            raise ModelError(f"`mapping` must give every old coordinate; missing {missing}.")
        title = name or f"{self.name} in {', '.join(_name(q) for q in coordinates)}"
        if isinstance(self.equations, Rows):
            eqs, labels = self.equations.substituted(mapping, self.labels)
            return EquationSet(title, tuple(coordinates), Rows(*eqs, coordinates, plain=False),
                               self.unknowns, tuple(labels), (), self.description,
                               self._constraints_in(mapping, labels, coordinates))
        rules = {}
        for q, expr in mapping.items():
            expr = as_expr(expr)
            rules[q.diff(t, 2)] = expr.diff(t, 2)
            rules[q.diff(t)] = expr.diff(t)
        eqs, labels = [], []
        for e, label in zip(self.equations, self.labels):
            e = e.xreplace(rules).xreplace(dict(mapping))
            if sp.expand(e) == 0:
                continue  # a constraint the new coordinates satisfy by construction
            eqs.append(e)
            labels.append(label)
        return EquationSet(title, tuple(coordinates), tuple(eqs), self.unknowns,
                           tuple(labels), (), self.description,
                           self._constraints_in(mapping, labels, coordinates))

    def _constraints_in(self, mapping: Mapping, labels: Sequence, coordinates) -> tuple:
        """The declared constraints rewritten by ``mapping`` (old coordinate -> expression in
        the new ones), without those the new coordinates satisfy by construction.  Only the
        rates the constraints hold are differentiated (a position-level constraint holds
        none, and most models declare no constraint)."""
        if not self.constraints:
            return ()
        rules = {}
        for c in self.constraints:
            for d in c.expression.atoms(sp.Derivative):
                q = d.expr
                if d not in rules and q in mapping and d.variables == (t,) * len(d.variables):
                    rules[d] = as_expr(mapping[q]).diff(t, len(d.variables))
        out = []
        for c in self.constraints:
            e = c.expression.xreplace(rules).xreplace(dict(mapping))
            if vanishes_identically(e, coordinates):
                continue
            out.append(Constraint(c.name, c.level, e, c.label if c.label in labels else ""))
        return tuple(out)

    def without(self, key: str) -> "EquationSet":
        """The model with ingredient ``key`` removed from every equation (for mutation tests)."""
        return self._edit(key, 0, f"{self.name} without {key}")

    def flipped(self, key: str) -> "EquationSet":
        """The model with the sign of ingredient ``key`` flipped (for mutation tests)."""
        return self._edit(key, -1, f"{self.name} with {key} sign-flipped")

    def _edit(self, key: str, factor, name: str) -> "EquationSet":
        """Multiply ingredient ``key`` by ``factor`` in every equation."""
        if not any(key in c for c in self.contributions):
            raise KeyError(f"model `{self.name}` has no ingredient {key!r}.")
        eqs = tuple(e + (factor - 1) * c.get(key, 0)
                    for e, c in zip(self.equations, self.contributions))
        contrib = tuple({k: (v * factor if k == key else v) for k, v in c.items()}
                        for c in self.contributions)
        return EquationSet(name, self.coordinates, eqs, self.unknowns, self.labels,
                           contrib, self.description, self.constraints)

    def simplified(self) -> "EquationSet":
        """The same equations with each ingredient expanded and trig-simplified.

        Components differentiated through a chain of frames keep identities such as
        ``sin^2 + cos^2`` in place; simplifying ingredient by ingredient (identity-preserving)
        makes the printed equations read like hand ones and structural zeros exact zeros.
        """
        if not self.contributions:
            eqs = tuple(sp.trigsimp(sp.expand(e)) for e in self.equations)
            return EquationSet(self.name, self.coordinates, eqs, self.unknowns, self.labels,
                               (), self.description, self.constraints)
        parts = tuple({k: sp.trigsimp(sp.expand(v)) for k, v in c.items()}
                      for c in self.contributions)
        return EquationSet(self.name, self.coordinates, tuple(sp.Add(*p.values()) for p in parts),
                           self.unknowns, self.labels, parts, self.description,
                           self.constraints)

    def ingredients(self) -> list[str]:
        seen = []
        for c in self.contributions:
            for k, v in c.items():
                if k not in seen and as_expr(v) != 0:
                    seen.append(k)
        return seen

    # -- equilibria and linearisation --------------------------------------------------
    def equilibria(self, values: Mapping | None = None) -> list[dict]:
        """Static equilibria: solutions of the equations with ``q' = q'' = 0``.

        ``values`` (parameter -> value) may fix parameters first.  Returns a list of
        ``{coordinate: value}`` as :func:`sympy.solve` finds them: for trigonometric equations
        that is not always every solution (it may miss ``pi``, and never adds multiples of
        ``2 pi``), so check a candidate with :meth:`linearize`, which refuses non-equilibria.
        Reaction-free models only.
        """
        if self.unknowns:
            raise ModelError(f"model `{self.name}` has reactions; find equilibria of a "
                             "reaction-free model.")
        still = {}
        for s in self.states:
            still[s.qd] = 0
            still[s.qdd] = 0
        eqs = [self.to_plain(e).subs(still) for e in self.equations]
        if values:
            eqs = [e.subs(values) for e in eqs]
        eqs = [e for e in eqs if e != 0]
        qs = [s.q for s in self.states]
        sols = sp.solve(eqs, qs, dict=True) if eqs else [{}]
        out = []
        for sol in sols:
            out.append({s.function: sol.get(s.q, s.q) for s in self.states})
        return out


    def linearize(self, equilibrium: Mapping | None = None) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
        """Mass, damping and stiffness matrices ``M q'' + C q' + K q = 0`` about ``equilibrium``.

        ``equilibrium`` maps coordinates to their values (default all zero); velocities are
        zero there.  Only reaction-free models can be linearised.
        """
        if self.unknowns:
            raise ModelError(f"model `{self.name}` has reactions {list(self.unknowns)}; "
                             "linearise a reaction-free model (e.g. the Lagrangian one), or use "
                             "`dualmech.linearize_about`, which solves for the accelerations "
                             "and reduces the constraints.")
        equilibrium = dict(equilibrium or {})
        point = {}
        for s in self.states:
            point[s.q] = equilibrium.get(s.function, 0)
            point[s.qd] = 0
            point[s.qdd] = 0
        eqs = sp.Matrix([self.to_plain(e) for e in self.equations])
        at = lambda m: m.subs(point).applyfunc(sp.simplify)  # noqa: E731
        M = at(eqs.jacobian([s.qdd for s in self.states]))
        C = at(eqs.jacobian([s.qd for s in self.states]))
        K = at(eqs.jacobian([s.q for s in self.states]))
        residual = at(eqs)
        if any(r != 0 for r in residual):
            raise ModelError(f"{equilibrium} is not an equilibrium of `{self.name}`: the "
                             f"static residual is {list(residual)}.")
        return M, C, K

    def natural_frequencies(self, equilibrium: Mapping | None = None, values: Mapping | None = None):
        """Undamped natural frequencies (rad/s) and mode shapes at ``equilibrium``.

        With ``values`` (parameter -> number) the result is numeric: ``(omegas, modes)`` as
        NumPy arrays, modes in columns.  Without, the symbolic roots of ``det(K - w^2 M) = 0``.
        """
        M, _, K = self.linearize(equilibrium)
        if values is None:
            w2 = sp.Symbol("omega2")
            roots = sp.solve(sp.Eq((K - w2 * M).det(), 0), w2)
            return [sp.sqrt(r) for r in roots]
        import numpy as np
        import scipy.linalg
        Mn = np.array(M.subs(values).evalf(), dtype=float)
        Kn = np.array(K.subs(values).evalf(), dtype=float)
        w2, modes = scipy.linalg.eig(Kn, Mn)
        order = np.argsort(w2.real)
        return np.sqrt(w2.real[order].astype(complex)), modes[:, order].real

    def pretty(self, latex: bool = False, notation: str = "dots") -> str:
        """The equations as a worked solution writes them, one ``[label]`` block each:
        two-dimensional unicode text, or LaTeX with ``latex=True``; rates as dots
        (``notation="dots"``: ``θ̈``, ``\\ddot{\\theta}``) or primes (``"primes"``)."""
        from dualmech.model import notation as _notation
        lines = []
        for label, e in zip(self.labels, self.equations):
            body = (_notation.latex(e, notation, self.coordinates) + " = 0" if latex else
                    _notation.pretty(sp.Eq(e, 0, evaluate=False), notation, self.coordinates))
            lines.append(f"[{label}]\n{body}")
        return "\n\n".join(lines)

    def __str__(self) -> str:
        from dualmech.model import notation as _notation
        rows = "; ".join(f"{_notation.text(e, self.coordinates)} = 0" for e in self.equations)
        return f"{self.name}: {rows}"

    def __repr__(self) -> str:
        coords = ", ".join(q.func.__name__ for q in self.coordinates)
        return f"<EquationSet {self.name} in ({coords}): " + str(self).partition(": ")[2] + ">"

    def _repr_latex_(self) -> str:
        """Jupyter: the equations as an aligned LaTeX block, rates as dots."""
        from dualmech.model import notation as _notation
        rows = r" \\ ".join(
            f"{_notation.latex(e, 'dots', self.coordinates)} &= 0 "
            rf"&& \text{{{_latex_text(label)}}}" for label, e in zip(self.labels, self.equations))
        return rf"$$\begin{{aligned}} {rows} \end{{aligned}}$$"


def _latex_text(label: str) -> str:
    """``label`` safe inside ``\\text{}``."""
    return re.sub(r"([#$%&_{}\\^~])", lambda m: "\\" + m.group(1)
                  if m.group(1) not in "\\^~" else " ", label)


_RULES: dict = {}


_RATES: dict = {}


def _rates(coordinates: tuple) -> tuple[tuple, tuple]:
    """``(velocities, accelerations)`` of ``coordinates`` (built once: sympy's ``diff`` is
    not free, and these are asked for on every solve and display)."""
    hit = _RATES.get(coordinates)
    if hit is None:
        hit = _RATES[coordinates] = (tuple(q.diff(t) for q in coordinates),
                                     tuple(q.diff(t, 2) for q in coordinates))
    return hit


def _rules(coordinates) -> tuple[dict, dict, dict]:
    """``(derivatives -> plain, q -> plain, plain -> function form)`` for ``coordinates``."""
    key = tuple(coordinates)
    hit = _RULES.get(key)
    if hit is None:
        d, q0, back = {}, {}, {}
        for q in key:
            s = state_symbols(q)
            d2, d1 = q.diff(t, 2), q.diff(t)
            d[d2], d[d1], q0[q] = s.qdd, s.qd, s.q
            back[s.qdd], back[s.qd], back[s.q] = d2, d1, q
        hit = _RULES[key] = (d, q0, back)
    return hit


def to_plain(expr, coordinates):
    """Replace ``q''``, ``q'``, ``q`` of ``coordinates`` in ``expr`` by plain symbols."""
    d, q0, _ = _rules(coordinates)
    return as_expr(expr).xreplace(d).xreplace(q0)


_SE_RULES: dict = {}


def to_plain_se(expr, coordinates):
    """:func:`to_plain` in symengine: ``expr`` (sympy or symengine) with ``q''``, ``q'``,
    ``q`` of ``coordinates`` replaced by the plain state symbols' symengine twins."""
    key = tuple(coordinates)
    rules = _SE_RULES.get(key)
    if rules is None:
        rules = {}
        for q in key:
            s = state_symbols(q)
            f = to_se(q)
            rules[f.diff(time_se(), 2)] = se.Symbol(s.qdd.name)
            rules[f.diff(time_se())] = se.Symbol(s.qd.name)
            rules[f] = se.Symbol(s.q.name)
        _SE_RULES[key] = rules
    e = expr if isinstance(expr, se.Basic) else to_se(as_expr(expr))
    return e.xreplace(rules)


def from_plain(expr, coordinates):
    """Inverse of :func:`to_plain`."""
    return as_expr(expr).xreplace(_rules(coordinates)[2])


def _name(q) -> str:
    return q.func.__name__


def is_zero_expression(expr) -> bool:
    """Exactly zero?  Cancel, then reduce ``sin(a)^2`` to ``1 - cos(a)^2`` in the numerator:
    a canonical form for polynomials in sines and cosines (display solves only)."""
    if expr == 0:
        return True
    if not expr.has(sp.sin, sp.cos):
        return sp.cancel(expr) == 0
    num = sp.fraction(sp.cancel(sp.together(expr)))[0]
    num = sp.expand(num).replace(
        lambda x: x.is_Pow and isinstance(x.base, sp.sin) and x.exp.is_Integer and x.exp >= 2,
        lambda x: (1 - sp.cos(x.base.args[0])**2)**(int(x.exp) // 2) * x.base**(int(x.exp) % 2))
    return sp.expand(num) == 0


def vanishes_identically(expr, coordinates=()) -> bool:
    """Is ``expr`` (in ``coordinates`` as functions of ``t``, their rates and parameters)
    zero for every state?  A value away from zero at one random real point says no at once
    (big expressions are not cancelled for nothing); otherwise :func:`is_zero_expression`
    decides exactly.

    >>> from dualmech import coordinate
    >>> q = coordinate("q")
    >>> vanishes_identically(sp.sin(q)**2 + sp.cos(q)**2 - 1, [q]), vanishes_identically(q, [q])
    (True, False)
    """
    expr = as_expr(expr)
    held = to_plain_se(expr, coordinates)
    if clearly_nonzero(held):
        return False
    if is_zero_trig(held):      # exact, at rational points of the circle (symengine)
        return True
    # near zero but not shown zero in the rational world (a root, an exponential): sympy
    plain = to_plain(expr, coordinates) if coordinates else expr
    import random
    rng = random.Random(20261127)
    point = {x: sp.Float(rng.uniform(0.3, 1.7), 30) for x in plain.free_symbols}
    try:
        value = complex(plain.xreplace(point).evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        value = None
    if value is not None and abs(value) > 1e-12:
        return False
    return is_zero_expression(sp.expand(expr))


def _tidy(expr):
    """A readable form of ``expr`` without letting ``simplify`` run away on big input."""
    expr = sp.cancel(sp.together(expr))
    if sp.count_ops(expr) < 400:
        try:
            expr = sp.trigsimp(sp.factor_terms(expr))
        except Exception:  # pragma: no cover - simplification is cosmetic
            pass
    return expr
