"""The exact rational-point evaluator (dualmech.exact)."""
import random
from fractions import Fraction

import pytest
import sympy as sp

from dualmech.exact import ExactForm, SAMPLE_BITS

th, ph, w, tt, a = sp.symbols("theta phi omega t a")


def _values(exprs, symbols, seed=0):
    form = ExactForm.build(exprs, symbols)
    return form, form.evaluate(form.sample(random.Random(seed)))


@pytest.mark.parametrize("identity", [
    sp.sin(2 * th) - 2 * sp.sin(th) * sp.cos(th),
    sp.cos(th + ph) - (sp.cos(th) * sp.cos(ph) - sp.sin(th) * sp.sin(ph)),
    sp.sin(th) ** 2 + sp.cos(th) ** 2 - 1,
    sp.tan(th) * sp.cos(th) - sp.sin(th),
    sp.sin(w * tt + th) - sp.sin(w * tt) * sp.cos(th) - sp.cos(w * tt) * sp.sin(th),
    sp.cos(3 * th) - 4 * sp.cos(th) ** 3 + 3 * sp.cos(th),
], ids=["double", "sum", "pythagoras", "tan", "forcing", "triple"])
def test_trig_identities_vanish_exactly(identity):
    form, vals = _values([identity], [th, ph, w, tt])
    assert form.method == "exact"
    assert vals == [0]


@pytest.mark.parametrize("almost", [
    sp.sin(2 * th) - sp.sin(th) * sp.cos(th),          # a factor 2 lost
    sp.sin(th) ** 2 - sp.cos(th) ** 2 - 1,             # a sign flipped
    th - sp.sin(th),                                    # small-angle approximation
    sp.cos(w * tt) - sp.cos(tt),                        # a parameter dropped
], ids=["factor", "sign", "small-angle", "dropped"])
def test_non_identities_give_nonzero_exact_values(almost):
    form, vals = _values([almost], [th, w, tt])
    assert form.method == "exact"
    assert isinstance(vals[0], Fraction) and vals[0] != 0


def test_angle_and_its_sine_are_independent_variables():
    # k*theta + sin(theta) is not identically zero for any k: the angle itself and the point
    # on the circle are sampled independently (they are algebraically independent functions)
    form, vals = _values([3 * th + sp.sin(th)], [th])
    assert vals[0] != 0


@pytest.mark.parametrize("identity", [
    sp.sqrt(a) ** 2 - a,
    sp.exp(a) * sp.exp(-a) - 1,
    sp.exp(2 * a) - sp.exp(a) ** 2,
    sp.Float(0.5) * a - a / 2,                          # 0.5 is exactly 1/2 in binary
    sp.sin(th / 2) ** 2 - (1 - sp.cos(th)) / 2,         # half angle: the atom is theta/2
    sp.cosh(a) ** 2 - sp.sinh(a) ** 2 - 1,
], ids=["sqrt", "exp", "exp-double", "float", "half-angle", "hyperbolic"])
def test_roots_exponentials_and_floats_stay_exact(identity):
    form, vals = _values([identity], [a, th])
    assert form.method == "exact"
    assert vals == [0]
    assert form.false_equal_bound(5) < 1e-60


@pytest.mark.parametrize("expr", [sp.atan(a), sp.log(1 + a**2), a ** sp.Rational(1, 3)],
                         ids=["atan", "log", "cube-root"])
def test_what_leaves_the_exact_world_falls_back_to_intervals(expr):
    form = ExactForm.build([expr], [a, th])
    assert form.method == "interval"
    assert form.false_equal_bound(5) != form.false_equal_bound(5)  # nan: no probability claim
    assert "exact test not applicable" in form.notes[-1]


def test_undeclared_symbol_is_a_clear_error():
    with pytest.raises(ValueError, match="undeclared symbols"):
        ExactForm.build([a + th], [a])


def test_false_equal_bound_shrinks_with_points():
    form = ExactForm.build([sp.sin(th) * a**3], [th, a])
    one, eight = form.false_equal_bound(1), form.false_equal_bound(8)
    assert 0 < eight < one < 1e-15
    assert one == pytest.approx(form.degree / 2.0**SAMPLE_BITS)


def test_degree_bound_counts_circle_parametrisation():
    # sin(theta) = 2u/(1+u^2): numerator degree 1, denominator 2 -> total 3
    assert ExactForm.build([sp.sin(th)], [th]).degree == 3
    assert ExactForm.build([a**4], [a]).degree == 4
