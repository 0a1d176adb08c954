"""The display budget's size test (:func:`dualmech.verify.display.ops_within`) decides exactly
what ``sympy.count_ops`` would: a tree small enough is let through by its node count alone,
which is sound only because ``count_ops`` counts at most ``OPS_PER_NODE`` per node."""
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from dualmech import coordinate, t
from dualmech.verify.display import OPS_PER_NODE, ops_within

x, y = sp.symbols("x y")
q = coordinate("q")
ATOMS = [x, y, q, q.diff(t), q.diff(t, 2), sp.Integer(-2), sp.Rational(-1, 3),
         sp.Rational(5, 2), sp.pi, sp.E, sp.Integer(7)]


def _tree(max_leaves):
    leaves = st.sampled_from(ATOMS)
    return st.recursive(leaves, lambda kids: st.one_of(
        st.lists(kids, min_size=2, max_size=4).map(lambda a: sp.Add(*a)),
        st.lists(kids, min_size=2, max_size=4).map(lambda a: sp.Mul(*a)),
        st.tuples(kids, st.sampled_from([-1, -2, 2, 3, sp.Rational(1, 2),
                                         sp.Rational(-3, 2)])).map(lambda p: sp.Pow(*p)),
        kids.map(lambda a: -a),
        kids.map(sp.sin), kids.map(sp.exp),
        kids.map(lambda a: 1 / (1 + a**2)),
    ), max_leaves=max_leaves)


def _nodes(e) -> int:
    return sum(1 for _ in sp.preorder_traversal(e))


@settings(max_examples=300)
@given(_tree(24))
def test_count_ops_is_at_most_ops_per_node_times_the_nodes(e):
    assert sp.count_ops(e) <= OPS_PER_NODE * _nodes(e)


@settings(max_examples=150)
@given(_tree(24), st.integers(0, 120))
def test_ops_within_agrees_with_count_ops(e, limit):
    assert ops_within(e, limit) == (sp.count_ops(e) <= limit)


def test_the_worst_kinds_of_node_stay_within_the_bound():
    # a negative fraction, a negated quotient, negated sums: count_ops's NEG, DIV and SUB
    for e in (sp.Rational(-1, 3), -x / (2 * y), -x - y, -2 * x**-2 * y**-3 / 3,
              1 / (-x - y), sp.exp(-x) / (-3 * y)):
        assert sp.count_ops(e) <= OPS_PER_NODE * _nodes(e), e
