"""One reading of sympy and symengine trees (dualmech.model.trees), and the walkers written
once over it giving the same answers on both kinds of tree."""
import pytest
import symengine as se
import sympy as sp

from dualmech.exact.rational_functions import _atoms, _reduce, _Ring
from dualmech.exact.sample_space import analyse, analyse_se
from dualmech.model import trees
from dualmech.model.dimensions import DIMENSIONLESS, LENGTH, audit

x, y = sp.symbols("x y", real=True)
f = sp.Function("f")

# each sympy node and its kind; symengine's conversion must read the same
_NODES = [
    (x + y, trees.ADD), (2 * x * y, trees.MUL), (x ** 3, trees.POW), (sp.sqrt(x), trees.POW),
    (x, trees.SYMBOL), (sp.Integer(-4), trees.INTEGER), (sp.Rational(-3, 7), trees.RATIONAL),
    (sp.Float(0.25), trees.FLOAT), (sp.I, trees.SPECIAL), (sp.oo, trees.SPECIAL),
    (sp.zoo, trees.SPECIAL), (sp.pi, trees.CONSTANT), (sp.E, trees.CONSTANT),
    (f(x), trees.UNDEFINED), (f(x).diff(x, 2), trees.DERIVATIVE), (sp.sin(x), trees.FUNCTION),
    (sp.Abs(x), trees.FUNCTION), (sp.Max(x, y), trees.FUNCTION), (sp.atan2(y, x), trees.FUNCTION),
    (sp.Piecewise((x, x > 0), (0, True)), trees.FUNCTION), (x > y, trees.OTHER),
]


@pytest.mark.parametrize("expr, kind", _NODES, ids=[str(e) for e, _ in _NODES])
def test_a_node_has_one_kind_in_both_libraries(expr, kind):
    held = se.sympify(expr)
    assert trees.kind(expr) == kind
    assert trees.kind(held) == kind
    if kind in (trees.FUNCTION, trees.CONSTANT, trees.UNDEFINED, trees.SYMBOL):
        assert trees.name(held) == trees.name(expr)
    if kind in (trees.INTEGER, trees.RATIONAL, trees.FLOAT):
        assert trees.fraction(held) == trees.fraction(expr)


def test_exp_is_a_function_in_sympy_and_a_power_of_e_in_symengine():
    assert trees.kind(sp.exp(x)) == trees.FUNCTION and trees.name(sp.exp(x)) == "exp"
    assert trees.kind(se.exp(se.Symbol("x"))) == trees.POW


def test_a_derivative_counts_each_variable_in_both_libraries():
    t = sp.Symbol("t")
    expr = f(x, t).diff(x, 2).diff(t)
    held = se.sympify(expr)
    assert dict(trees.derivative_parts(expr)[1]) == {x: 2, t: 1}
    assert {str(v): n for v, n in trees.derivative_parts(held)[1]} == {"x": 2, "t": 1}


def test_a_float_reads_as_its_binary_value():
    from fractions import Fraction
    assert trees.fraction(sp.Float(0.1)) == Fraction(0.1) == trees.fraction(se.RealDouble(0.1))
    assert trees.fraction(sp.Float(0.1)) != Fraction(1, 10)


@pytest.mark.parametrize("expr, found", [
    (x * y + x, []),
    (x * y + x + y ** 2, ["term `y**2` has dimension 1 where the rest has L"]),
    (sp.sin(x) * x + x, ["argument `x` of sin has dimension L; it must be dimensionless"]),
    (x ** y + 1, ["`x**y`: a symbolic power needs a dimensionless base and exponent"]),
], ids=["consistent", "odd-term", "argument", "power"])
def test_the_dimension_audit_reads_both_trees_alike(expr, found):
    dims = {x: LENGTH, y: DIMENSIONLESS}
    names = {"x": x, "y": y}
    assert sorted(str(i) for i in audit(expr, dims)) == found
    assert sorted(str(i) for i in audit(se.sympify(expr), dims, names=names)) == found


def test_ring_atoms_and_fractions_are_the_same_from_both_trees():
    expr = (sp.sin(x) ** 2 + x / 3) / (y * sp.cos(x) - 2) + f(x)
    mine, theirs = {}, {}
    _atoms(expr, mine)
    _atoms(se.sympify(expr), theirs)
    assert sorted(map(str, mine)) == sorted(map(str, theirs))
    atoms = sorted(mine, key=sp.default_sort_key)
    ring = _Ring(atoms)
    held = {se.sympify(a): i for i, a in enumerate(atoms)}
    assert _reduce(*ring.fraction(expr)) == _reduce(*ring.fraction(se.sympify(expr), held))


def test_the_symengine_world_is_the_sympy_world():
    """A product of symbols inside a sine (``omega t``) is a circle atom in both routes."""
    w, t = sp.symbols("omega t", real=True)
    expr = sp.sin(w * t + 2 * x) * sp.cos(x / 3) + sp.tan(w * t)
    via_sp, via_se = analyse([expr], [w, t, x]), analyse_se([se.sympify(expr)], [w, t, x])
    assert via_se is not None
    assert via_se.atoms == via_sp.atoms
    assert sorted(terms for _, terms, _ in via_se.args) == \
        sorted(terms for _, terms, _ in via_sp.args)
