"""The exact world (:mod:`.world`) built straight from symengine, for the common case.

Derivations hand the verdict their matrices ``[A | b]`` in symengine
(:meth:`dualmech.model.equations.EquationSet.plain_matrix_se`).  When every expression is a rational
function of the symbols and of ``sin``/``cos``/``tan`` of rational combinations of real
symbols -- which is what rigid-body models produce -- the world is built here without a
sympy expression: the same atoms (``exp(i a)`` sampled on the unit circle), the same argument
variables ``S``, ``C`` per argument, the same degree bound, so the verdict and its
false-equal bound are those of :func:`.world.analyse`.  Anything else (square roots, ``pi``,
exponentials, branch functions, floats, an integer symbol inside a sine) returns ``None`` and
the caller takes the general sympy route, which decides or refuses it.

Example
-------
>>> import symengine as se, sympy as sp
>>> th, t = sp.symbols("theta t", real=True)
>>> w = analyse_se([se.sin(2 * se.Symbol("theta")) + se.cos(se.Symbol("theta") / 3)], [th, t])
>>> [str(a) for a in w.atoms], [terms for _, terms, _ in w.args]
(['exp(i*theta/3)'], [((0, 6),), ((0, 1),)])
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import Sequence

import symengine as se
import sympy as sp

from dualmech.exact.sample_space import MAX_MULTIPLE, AtomKey, World

__all__ = ["analyse_se"]

_TRIG = ("sin", "cos", "tan")


def analyse_se(exprs: Sequence, symbols: Sequence) -> World | None:
    """The exact world of symengine ``exprs`` in the (sympy) ``symbols``, or ``None`` when
    they leave the common case (see the module docstring)."""
    by_name = {s.name: s for s in symbols}
    if len(by_name) != len(symbols) or not all(type(s) is sp.Symbol for s in symbols):
        return None
    trig = _scan(exprs, by_name)
    if trig is None:
        return None
    # atoms: one per symbol inside a trigonometric argument, scaled by the lcm of the
    # denominators of its coefficients (as world.analyse does)
    lcd: dict = {}
    for _, lin in trig.values():
        for name, c in lin.items():
            lcd[name] = math.lcm(lcd.get(name, 1), c.denominator)
    order = sorted(lcd, key=lambda n: sp.default_sort_key(by_name[n]))
    atoms, index, u, scales = [], {}, {}, []
    for name in order:
        L = lcd[name]
        m = by_name[name]
        index[name] = (len(atoms), L)
        atoms.append(AtomKey("circle", m / L))
        scales.append(("circle", m, L))
        u[len(atoms) - 1] = se.Dummy(f"u_{name}")
    args, arg_index, rules = [], {}, {}
    for node, (kind, lin) in trig.items():
        terms = tuple(sorted((index[n][0], int(c * index[n][1])) for n, c in lin.items()))
        if sum(abs(k) for _, k in terms) > MAX_MULTIPLE:
            return None
        at = arg_index.get(terms)
        if at is None:
            at = arg_index[terms] = len(args)
            args.append(("circle", terms, (se.Dummy(f"S{at}"), se.Dummy(f"C{at}"))))
        s, c = args[at][2]
        rules[node] = s if kind == "sin" else c if kind == "cos" else s / c
    out = [e.xreplace(rules) for e in exprs] if rules else list(exprs)
    return World(out, list(symbols), atoms, args, None, u, [], [], [], scales)


def _scan(exprs, by_name: dict) -> dict | None:
    """``{trig node: (kind, {symbol name: Fraction})}``, or ``None`` outside the common case."""
    seen: set = set()
    trig: dict = {}
    stack = list(exprs)
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if isinstance(e, (se.Integer, se.Rational)):
            continue
        if e.is_Symbol:
            if e.name not in by_name or type(e) is not se.Symbol:
                return None          # undeclared (the general route says so) or a dummy
            continue
        if e.is_Add or e.is_Mul:
            stack.extend(e.args)
            continue
        if e.is_Pow:
            base, x = e.args
            if not isinstance(x, se.Integer):
                return None
            stack.append(base)
            continue
        kind = type(e).__name__
        if kind in _TRIG:
            lin = _linear(e.args[0], by_name)
            if lin is None:
                return None
            trig[e] = (kind, lin)
            continue
        return None
    return trig


def _linear(arg, by_name: dict) -> dict | None:
    """``arg`` as ``{symbol name: nonzero Fraction}``: a rational combination of real,
    non-integer symbols with no constant term; ``None`` otherwise."""
    out: dict = {}
    for term in (arg.args if arg.is_Add else (arg,)):
        if term.is_Symbol:
            name, c = term.name, Fraction(1)
        elif term.is_Mul and len(term.args) == 2:
            a, b = term.args
            if isinstance(b, (se.Integer, se.Rational)):
                a, b = b, a
            if not (isinstance(a, (se.Integer, se.Rational)) and b.is_Symbol):
                return None
            p, q = a.get_num_den()
            name, c = b.name, Fraction(int(p), int(q))
        else:
            return None
        s = by_name.get(name)
        if s is None or s.is_integer:   # an integer symbol: the general route refuses it
            return None
        out[name] = out.get(name, 0) + c
    out = {k: v for k, v in out.items() if v != 0}
    return out or None
