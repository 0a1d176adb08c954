"""Array layouts never change a number: C, Fortran, strided, transposed and 1-D states give the
same right-hand side, system ``(A, b)`` (the mass matrix and forces) and reactions -- for every
model of every problem, with the NumPy code and the compiled C code.

A state array of ``K`` states in its columns reaches the model in whatever layout the caller
built: scipy's finite-difference Jacobian (``vectorized=True``) passes a Fortran-ordered
``(2n, K)`` array.  The reference is each column evaluated alone (the 1-D entry point);
two different code paths meet within the linear solve's error bound
``64 eps cond(A) max(1, |x|)``; two layouts of one array through one path agree exactly.
"""
from functools import lru_cache

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from dualmech import problems
from dualmech.numeric import SingularityError
from dualmech.numeric.cbackend import compiler
from dualmech.numeric.formulations import formulations

from _catalogue_expected import catalogue_params

_EPS = np.finfo(float).eps
NAMES = [d.name for d in problems.declarations()]
BACKENDS = ("python", "c") if compiler() is not None else ("python",)
LAYOUTS = ("C", "F", "strided", "transposed")


@lru_cache(maxsize=None)
def _models(name):
    """``[(label, NumericModel, y0, scales)]``: every square form of the problem, each backend
    (compiled once per problem, then cached)."""
    p = problems.get(name)
    forms, _ = formulations(p, stabilisations=("none",))
    out = []
    for f in forms:
        nm = f.constrained.numeric if f.constrained else f.rhs.__self__
        for b in BACKENDS:
            out.append((f"{f.name} [{b}]", nm.with_backend(b), f.y0, f.scales))
    return out


def _layout(Y, kind):
    if kind == "C":
        return np.ascontiguousarray(Y)
    if kind == "F":
        return np.asfortranarray(Y)
    if kind == "strided":
        big = np.full((Y.shape[0] * 2, Y.shape[1] * 3), np.nan)
        big[::2, ::3] = Y
        return big[::2, ::3]
    return np.ascontiguousarray(Y.T).T  # a transposed view: Fortran order through a view


def _bound(A, x):
    return 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.max(np.abs(x))))


@pytest.mark.parametrize("name", catalogue_params(NAMES))
@settings(max_examples=4)
@given(K=st.integers(1, 5), seed=st.integers(0, 2**16), layout=st.sampled_from(LAYOUTS))
def test_every_layout_gives_the_numbers_of_one_state_at_a_time(name, K, seed, layout):
    models = _models(name)
    assume(models)
    rng = np.random.default_rng(seed)
    for label, nm, y0, scales in models:
        n = nm.n
        Y = y0[:, None] + 0.02 * scales[:, None] * rng.uniform(-1, 1, (2 * n, K))
        try:
            ref = np.column_stack([nm.solve(0.3, Y[:n, i], Y[n:, i]) for i in range(K)])
            systems = [nm.system(0.3, Y[:n, i], Y[n:, i]) for i in range(K)]
        except (SingularityError, ValueError):
            continue  # outside the model's domain here: nothing to compare
        L = _layout(Y, layout)
        assert np.array_equal(L, Y)
        x = nm.solve(0.3, L[:n], L[n:])
        rhs = nm.rhs(0.3, L)
        As, bs = nm.system(0.3, L[:n], L[n:])
        # the same array in C order through the same path: bit for bit
        assert np.array_equal(x, nm.solve(0.3, Y[:n].copy(), Y[n:].copy())), label
        assert np.array_equal(rhs, nm.rhs(0.3, Y.copy())), label
        assert np.array_equal(rhs[:n], Y[n:]), label
        for i, (A, b) in enumerate(systems):
            tol = _bound(A, ref[:, i])
            # accelerations and reactions of every state against that state alone
            assert np.max(np.abs(x[:, i] - ref[:, i])) <= tol, (label, layout, i)
            assert np.max(np.abs(rhs[n:, i] - ref[:n, i])) <= tol, (label, layout, i)
            # the system itself: the same expressions elementwise (NumPy against math)
            scale = max(1.0, float(np.abs(A).max()), float(np.abs(b).max()))
            assert np.max(np.abs(As[i] - A)) <= 16 * _EPS * scale, (label, layout, i)
            assert np.max(np.abs(bs[i] - b)) <= 16 * _EPS * scale, (label, layout, i)
