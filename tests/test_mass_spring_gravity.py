"""Mass on a spring under gravity (problems/mass_spring_gravity.py): three derivations, statics."""
import pytest
import sympy as sp

from dualmech.model.equations import ModelError
from dualmech.problems.mass_spring_gravity import F, M, MassSpringGravity, g, k, static_equilibrium, x

problem = MassSpringGravity()


def test_gravity_as_a_generalised_force_is_minus_M_g():
    # hand: Q = -M g j . d(x j)/dx = -M g; it enters Lagrange's equation as -Q = +M g
    (parts,) = problem.model("gravity_as_force").contributions
    assert sp.expand(parts["gravity"] - M * g) == 0
    assert sp.expand(parts["applied force"] + F) == 0


def test_library_finds_the_hand_derived_static_equilibrium():
    # hand: k x* = F - M g
    (eq,) = problem.model("lagrange").equilibria()
    assert sp.simplify(eq[x] - static_equilibrium()) == 0


def test_oscillation_about_equilibrium_has_omega_squared_k_over_M():
    # gravity and the steady force only shift the equilibrium: omega^2 = k/M, free of g and F
    lg = problem.model("lagrange")
    Mlin, C, K = lg.linearize({x: static_equilibrium()})
    assert (Mlin, C, K) == (sp.Matrix([[M]]), sp.zeros(1, 1), sp.Matrix([[k]]))
    (omega,) = lg.natural_frequencies({x: static_equilibrium()})
    assert sp.simplify(omega - sp.sqrt(k / M)) == 0


def test_unstretched_position_is_not_an_equilibrium():
    with pytest.raises(ModelError, match="not an equilibrium"):
        problem.model("lagrange").linearize({x: 0})
