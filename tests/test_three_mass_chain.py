"""Three masses on springs (problems/three_mass_chain.py): matrices, frequencies, modes."""
import numpy as np
import pytest
import sympy as sp

from dualmech.problems.three_mass_chain import (ThreeMassChain, g, k1, k2, k3, m1, m2, m3,
                                       printed_matrices)

problem = ThreeMassChain()
_EPS = np.finfo(float).eps


@pytest.mark.parametrize("model", ["newton_euler", "lagrange"])
def test_library_linearisation_gives_the_printed_matrices(model):
    # the direct form carries gravity and the static extensions; x = 0 is still its
    # equilibrium (linearize refuses non-equilibria) and g drops out of M and K
    M, C, K = problem.model(model).linearize()
    M_src, K_src = printed_matrices()
    assert (M, C, K) == (M_src, sp.zeros(3, 3), K_src)
    assert g not in (M.free_symbols | K.free_symbols)


def _solve(values):
    """Library frequencies and modes, and the printed matrices as numbers."""
    omegas, modes = problem.model("lagrange").natural_frequencies(values=values)
    M, K = (np.array(A.subs(values), dtype=float) for A in printed_matrices())
    return np.real(omegas), modes, M, K


def test_frequencies_are_the_roots_of_the_printed_determinant():
    # |-w^2 M + K| = 0 (section 4) with the printed matrices, solved independently of the
    # library: the roots of the characteristic polynomial of M^-1 K
    omegas, modes, M, K = _solve(problem.defaults())
    roots = np.sort(np.roots(np.poly(np.linalg.solve(M, K))).real)
    # eigenvalue rounding: eps * cond(M^-1 K) relative to the largest w^2
    tol = 64 * _EPS * np.linalg.cond(np.linalg.solve(M, K)) * roots[-1]
    assert np.allclose(omegas**2, roots, rtol=0, atol=tol)
    for w, phi in zip(omegas, modes.T):
        residual = (K - w**2 * M) @ phi
        assert np.linalg.norm(residual) <= tol * np.linalg.norm(M) * np.linalg.norm(phi)


def test_equal_masses_and_springs_match_the_hand_solution():
    # fixed-free chain of three: w_j = 2 sqrt(k/m) sin((2j - 1) pi/14),
    # mode j ~ sin((2j - 1) n pi/7) at mass n = 1, 2, 3
    values = {s: 1.0 for s in (m1, m2, m3, k1, k2, k3)} | {g: 9.81}
    omegas, modes, M, K = _solve(values)
    j = np.arange(1, 4)
    hand = 2 * np.sin((2 * j - 1) * np.pi / 14)
    tol = 64 * _EPS * np.linalg.cond(K) * hand[-1]
    assert np.allclose(omegas, hand, rtol=0, atol=tol)
    n = np.arange(1, 4)
    for col, jj in zip(modes.T, j):
        shape = np.sin((2 * jj - 1) * n * np.pi / 7)
        cosine = abs(col @ shape) / (np.linalg.norm(col) * np.linalg.norm(shape))
        assert abs(cosine - 1) <= 64 * _EPS * np.linalg.cond(K)


def test_modes_are_orthogonal_through_the_mass_matrix():
    omegas, modes, M, K = _solve(problem.defaults())
    G = modes.T @ M @ modes
    off = G - np.diag(np.diag(G))
    assert np.max(np.abs(off)) <= 64 * _EPS * np.linalg.cond(K) * np.max(np.abs(G))
