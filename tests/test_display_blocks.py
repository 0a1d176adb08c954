"""``largest_coupled_block`` (plain Python) against scipy's graph routines.

The reference is the construction the function used before: scipy's maximum bipartite
matching, then the strongly connected components of the column-permuted pattern.  The block
sizes of a matrix with a zero-free diagonal do not depend on which matching is taken, so the
two must agree on every pattern.
"""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import connected_components, maximum_bipartite_matching

from dualmech.verify.display import largest_coupled_block


def _by_scipy(pattern: np.ndarray) -> int:
    rows = pattern.shape[0]
    if rows == 0:
        return 0
    sparse = csr_matrix(pattern.astype(np.int8))
    match = maximum_bipartite_matching(sparse, perm_type="column")
    if (match < 0).any():
        return rows
    _, labels = connected_components(sparse[:, match], directed=True, connection="strong")
    return int(np.bincount(labels).max())


def _matrix(pattern: np.ndarray) -> sp.Matrix:
    x = sp.symbols(f"x0:{pattern.size or 1}")
    return sp.Matrix(pattern.shape[0], pattern.shape[1],
                     [x[k] if v else 0 for k, v in enumerate(pattern.flat)])


@settings(max_examples=300, deadline=None)
@given(st.integers(1, 9).flatmap(lambda n: st.tuples(
    st.just(n), st.lists(st.booleans(), min_size=n * n, max_size=n * n))))
def test_square_patterns_agree_with_scipy(case):
    n, flat = case
    pattern = np.array(flat, dtype=bool).reshape(n, n)
    assert largest_coupled_block(_matrix(pattern)) == _by_scipy(pattern)


@settings(max_examples=300, deadline=None)
@given(st.integers(1, 9).flatmap(lambda n: st.tuples(
    st.permutations(range(n)),
    st.lists(st.sampled_from([False] * 5 + [True]), min_size=n * n, max_size=n * n))))
def test_sparse_regular_patterns_agree_with_scipy(case):
    # a permuted diagonal (so a matching exists) and a few more entries: several blocks
    perm, flat = case
    n = len(perm)
    pattern = np.array(flat, dtype=bool).reshape(n, n)
    pattern[np.arange(n), perm] = True
    assert largest_coupled_block(_matrix(pattern)) == _by_scipy(pattern)


@pytest.mark.parametrize("rows, expected", [
    ([[1, 0, 0], [1, 1, 1], [1, 1, 1]], 2),        # one decoupled unknown, a 2x2 block
    ([[1, 1, 0], [0, 1, 1], [1, 0, 1]], 3),        # a cycle couples all three
    ([[1, 0], [0, 1]], 1),                         # diagonal: nothing coupled
    ([[0, 1], [1, 0]], 1),                         # a permuted diagonal
    ([[1, 1], [0, 0]], 2),                         # singular pattern: all of them
], ids=["block", "cycle", "diagonal", "permuted", "singular"])
def test_known_patterns(rows, expected):
    pattern = np.array(rows, dtype=bool)
    assert largest_coupled_block(_matrix(pattern)) == expected == _by_scipy(pattern)


def test_empty_matrix():
    assert largest_coupled_block(sp.zeros(0, 0)) == 0
