"""dualmech's own Dimension: its algebra, its agreement with sympy's, and its refusals.

The reference for every named constant is ``sympy.physics.units`` (dimension definitions and
the SI dimension system), converted by :func:`dualmech.model.dimensions.as_dimension`.
"""
from __future__ import annotations

import pickle
import subprocess
import sys
from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st
from sympy.physics.units.definitions import dimension_definitions as dd

from dualmech.model import dimensions as D
from dualmech.model.dimensions import (ANGLE, DIMENSIONLESS, FORCE, LENGTH, MASS, TIME, Dimension,
                                      as_dimension, format_dimension, reduce)

NAMED = {  # dualmech's name -> the same dimension written with sympy's
    "MASS": dd.mass, "LENGTH": dd.length, "TIME": dd.time, "ANGLE": dd.angle,
    "FORCE": dd.force, "TORQUE": dd.force * dd.length, "ENERGY": dd.energy,
    "DIMENSIONLESS": sp.physics.units.Dimension(1), "VELOCITY": dd.velocity,
    "ACCELERATION": dd.acceleration, "STIFFNESS": dd.force / dd.length,
    "DAMPING": dd.force / dd.velocity, "TORSIONAL_STIFFNESS": dd.energy / dd.angle,
    "TORSIONAL_DAMPING": dd.energy * dd.time / dd.angle, "INERTIA": dd.mass * dd.length**2,
    "FREQUENCY": dd.frequency,
}


@pytest.mark.parametrize("name", sorted(NAMED))
def test_named_constants_equal_sympys(name):
    ours = getattr(D, name)
    assert isinstance(ours, Dimension)
    assert as_dimension(NAMED[name]) == ours
    assert hash(as_dimension(NAMED[name])) == hash(ours)
    assert reduce(NAMED[name]) == reduce(ours)


def test_every_public_dimension_is_covered():
    public = {n for n in D.__all__ if isinstance(getattr(D, n), Dimension)}
    assert public == set(NAMED)


EXPONENTS = st.fractions(min_value=-4, max_value=4, max_denominator=6)
DIMENSION = st.builds(lambda *e: Dimension(*e), *[EXPONENTS] * len(D.BASES))


@settings(max_examples=80, deadline=None)
@given(DIMENSION, DIMENSION, DIMENSION, EXPONENTS)
def test_algebra_is_that_of_exponent_vectors(a, b, c, k):
    assert (a * b) * c == a * (b * c)
    assert a * b == b * a
    assert a / a == DIMENSIONLESS and a * DIMENSIONLESS == a
    assert (a * b) / b == a
    assert (a * b) ** k == a ** k * b ** k
    assert a ** 0 == DIMENSIONLESS and a ** 1 == a and a ** -1 == 1 / a
    for base in D.BASES:
        assert (a * b).power(base) == a.power(base) + b.power(base)
        assert (a ** k).power(base) == a.power(base) * k
    assert pickle.loads(pickle.dumps(a)) == a
    assert eval(repr(a), {"Dimension": Dimension, "Fraction": Fraction}) == a


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(sorted(NAMED)),
                          st.sampled_from([-2, -1, 1, 2, 3, sp.Rational(1, 2),
                                           sp.Rational(-3, 2)])), min_size=1, max_size=5))
def test_products_of_powers_match_sympys_algebra(factors):
    ours, theirs = DIMENSIONLESS, sp.physics.units.Dimension(1)
    for name, p in factors:
        ours = ours * getattr(D, name) ** p
        theirs = theirs * NAMED[name] ** p
    assert as_dimension(theirs) == ours
    # a sympy dimension on the right of ours is converted
    assert MASS * theirs == MASS * ours and ours / theirs == DIMENSIONLESS


def test_text_forms():
    assert repr(FORCE) == "Dimension(mass=1, length=1, time=-2)"
    assert repr(DIMENSIONLESS) == "Dimension()"
    assert repr(MASS ** Fraction(1, 2)) == "Dimension(mass=Fraction(1, 2))"
    assert str(FORCE) == "M L T^-2" and str(DIMENSIONLESS) == "1"
    assert str(D.TORSIONAL_STIFFNESS) == "M L^2 T^-2 angle^-1"
    assert format_dimension(D.TORSIONAL_STIFFNESS) == "M L^2 T^-2"   # angles are radians
    assert format_dimension(dd.force) == "M L T^-2"
    assert reduce(ANGLE) == () and ANGLE != DIMENSIONLESS


def test_numbers_are_dimensionless_and_exponents_rational():
    assert 1 / TIME == D.FREQUENCY and 2 * MASS == MASS and MASS / 2.5 == MASS
    assert MASS ** sp.Rational(1, 2) == MASS ** Fraction(1, 2) == MASS ** 0.5
    assert MASS ** sp.Integer(2) == MASS * MASS


@pytest.mark.parametrize("expr, message", [
    (lambda: MASS + LENGTH, "dimensions do not add"),
    (lambda: MASS - MASS, "dimensions do not add"),
    (lambda: -MASS, "no sign"),
    (lambda: MASS * "kg", "not .kg."),
    (lambda: sp.Symbol("x") * MASS, "not x"),
    (lambda: MASS ** sp.Symbol("x"), "must be a rational number"),
    (lambda: MASS ** "2", "must be a rational number"),
    (lambda: MASS ** 0.1, "write it as a Fraction"),
    (lambda: Dimension(mass="one"), "exponent of mass"),
    (lambda: as_dimension("M L T^-2"), "a dimension must be"),
    (lambda: reduce(None), "a dimension must be"),
    (lambda: reduce(sp.Symbol("m")), "a dimension must be"),
], ids=["sum", "difference", "negation", "times-text", "times-symbol", "symbolic-power",
        "text-power", "inexact-power", "text-exponent", "text", "none", "symbol"])
def test_nonsense_is_refused(expr, message):
    with pytest.raises(TypeError, match=message):
        expr()


def test_immutable_and_unknown_bases_refused():
    with pytest.raises(AttributeError):
        FORCE._exps = ()
    with pytest.raises(ValueError, match="got .charge"):
        FORCE.power("charge")
    with pytest.raises(ValueError, match="information"):
        as_dimension(dd.information)


def test_a_problem_may_declare_sympys_dimensions():
    from dualmech import coordinate
    from dualmech.model.problem import Coordinate, Parameter, Reaction
    p = Parameter(sp.Symbol("k", positive=True), dd.force / dd.length, 1.0, (0.5, 2.0))
    c = Coordinate(coordinate("theta"), dd.angle, (-1, 1))
    r = Reaction("N", dd.force, "normal")
    assert (p.dimension, c.dimension, r.dimension) == (D.STIFFNESS, ANGLE, FORCE)
    from dualmech.numeric.units import unit
    assert unit(dd.angle) == "rad" and unit(dd.force / dd.angle) == "N/rad"


def test_importing_dimensions_leaves_sympys_units_alone():
    code = ("import sys, dualmech.model.dimensions as d; d.reduce(d.FORCE / d.ANGLE); "
            "print('sympy.physics.units' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "False"
