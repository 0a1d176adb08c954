"""``largest_coupled_block``: the largest set of unknowns a solve must treat together, on
patterns whose block structure is read off by hand."""
from __future__ import annotations

import pytest
import sympy as sp

from dualmech.verify.display import largest_coupled_block


def _matrix(rows) -> sp.Matrix:
    x = iter(sp.symbols("x0:81"))
    return sp.Matrix([[next(x) if v else 0 for v in row] for row in rows])


@pytest.mark.parametrize("rows, expected", [
    ([[1, 0, 0], [1, 1, 1], [1, 1, 1]], 2),        # one decoupled unknown, a 2x2 block
    ([[1, 1, 0], [0, 1, 1], [1, 0, 1]], 3),        # a cycle couples all three
    ([[1, 0], [0, 1]], 1),                         # diagonal: nothing coupled
    ([[0, 1], [1, 0]], 1),                         # a permuted diagonal
    ([[1, 1], [0, 0]], 2),                         # singular pattern: all of them
    ([[1, 1, 0, 0, 0], [1, 1, 0, 0, 0], [0, 1, 1, 1, 0], [0, 0, 1, 1, 0],
      [1, 0, 0, 1, 1]], 2),                        # lower block-triangular: 2, 2 and 1
], ids=["block", "cycle", "diagonal", "permuted", "singular", "triangular"])
def test_known_patterns(rows, expected):
    assert largest_coupled_block(_matrix(rows)) == expected


def test_empty_matrix():
    assert largest_coupled_block(sp.zeros(0, 0)) == 0
