"""The dimension audit against sympy's own dimension algebra, and on shared rows.

The reference exponents come from ``sympy.physics.units`` (its Dimension algebra and SI
dimension system), independent of dualmech's own :class:`~dualmech.model.dimensions.Dimension`."""
from __future__ import annotations

from fractions import Fraction

import sympy as sp
import symengine as se
from hypothesis import given, settings, strategies as st
from sympy.physics.units.definitions import dimension_definitions as dd
from sympy.physics.units.systems.si import dimsys_SI

from dualmech.model.dimensions import (ACCELERATION, FORCE, LENGTH, MASS, TIME, audit, audit_rows,
                                      dimension_of, reduce)

m, l, g, k = sp.symbols("m l g k")
DIMS = {m: MASS, l: LENGTH, g: ACCELERATION, k: FORCE / LENGTH}
SYMPY_DIMS = {m: dd.mass, l: dd.length, g: dd.acceleration, k: dd.force / dd.length}
SYMBOLS = list(DIMS)


def _reference(powers) -> dict:
    """Base exponents of a monomial by sympy's Dimension algebra (independent of the audit)."""
    dim = sp.Integer(1)
    for s, p in powers:
        dim = dim * SYMPY_DIMS[s] ** p
    deps = dimsys_SI.get_dimensional_dependencies(dim)
    return {str(b.name) if hasattr(b, "name") else str(b): Fraction(str(e))
            for b, e in deps.items() if e != 0}


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(SYMBOLS),
                          st.sampled_from([-3, -2, -1, 1, 2, 3, sp.Rational(1, 2),
                                           sp.Rational(-3, 2)])), min_size=1, max_size=6))
def test_monomials_match_sympys_dimension_algebra(powers):
    expr = sp.Integer(3)
    for s, p in powers:
        expr = expr * s ** p
    want = _reference(powers)
    got = {name: e for name, e in dimension_of(expr, DIMS)}
    assert got == want
    got_se = {name: e for name, e in dimension_of(se.sympify(expr), DIMS,
                                                  names={str(s): s for s in SYMBOLS})}
    assert got_se == want
    # and the same with the symbols declared in sympy's dimensions
    assert {name: e for name, e in dimension_of(expr, SYMPY_DIMS)} == want


def test_a_wrong_term_is_named_and_a_shared_subexpression_once():
    shared = m * g * sp.sin(l / l)
    rows = [shared + k * l + m * l, shared + k * l]
    issues = audit_rows(rows, DIMS)
    assert [str(i) for i in issues[0]] == ["term `l*m` has dimension M L where the rest has "
                                          "M L T^-2"]
    assert issues[1] == []
    # the expected dimension, when given, overrides the majority
    assert [str(i) for i in audit(m * l + k * l, DIMS, expected=MASS * LENGTH)] == \
        ["term `k*l` has dimension M L T^-2 where the rest has M L"]
    assert reduce(FORCE / LENGTH * TIME**2) == (("mass", Fraction(1)),)


def test_function_arguments_must_be_dimensionless():
    assert [str(i) for i in audit(sp.sin(l) * m * g, DIMS)] == \
        ["argument `l` of sin has dimension L; it must be dimensionless"]


def test_an_issue_names_its_terms_as_expressions_in_every_notation():
    """The sentence holds the terms themselves, so a page typesets them and text writes them
    in the textbook's notation (a derivation held in symengine: tests/test_blame.py)."""
    from dualmech import coordinate, t
    from dualmech.model.dimensions import ANGLE
    from dualmech.model.notation import sentence
    x, th = coordinate("x"), coordinate("theta")
    c_t = sp.Symbol("c_t")      # a torsional dashpot: N m s = M L^2 T^-1
    dims = {m: MASS, l: LENGTH, g: ACCELERATION, k: FORCE / LENGTH, x: LENGTH, th: ANGLE,
            c_t: FORCE * LENGTH * TIME / ANGLE}
    row = m * x.diff(t, 2) + k * x + c_t * x.diff(t)      # c_t x' is M L^3 T^-2, not a force
    [issue] = audit(row, dims)
    assert issue.sentence() == ("term ", c_t * x.diff(t), " has dimension M L^3 T^-2 where "
                                "the rest has M L T^-2")
    assert str(issue) == "term `c_t*x'` has dimension M L^3 T^-2 where the rest has M L T^-2"
    assert sentence(issue.sentence()) == ("term c\u209c x\u0307 has dimension M L^3 T^-2 where "
                                          "the rest has M L T^-2")
    assert sentence(issue.sentence(), "primes") == ("term c\u209c x\u2032 has dimension "
                                                    "M L^3 T^-2 where the rest has M L T^-2")
    [tie] = audit(m * g + m * l * th.diff(t), dims)        # M L T^-2 against M L T^-1
    assert {p for p in tie.sentence() if not isinstance(p, str)} == {m * g, m * l * th.diff(t)}
    assert tie.sentence()[0] == "terms disagree: "
