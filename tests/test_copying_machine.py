"""Copying machine, Example 14 (problems/copying_machine.py): a static row in the equations.

Two groups of tests.  The first pins the models themselves and checks them on the constraint
manifold with the comparator as it is (theta replaced by its static solution, so every model
becomes an ordinary one-coordinate model).  The second states what the comparator must do with
the differential-algebraic models as they stand -- the static row kept in the set.
"""
import pytest
import sympy as sp

from dualmech import EquationSet, t
from dualmech.verify.check import compare, compare_models, compare_reactions
from dualmech.problems.copying_machine import (CopyingMachine, F, L, a, b, effective_stiffness, k1, k2,
                                      m2, theta, w, y)

problem = CopyingMachine()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
ON_MANIFOLD = k2 * L * y / (k2 * L**2 + k1 * a**2)   # theta from the static row, by hand
R_O_HAND = k1 * k2 * a * (L - a) * y / (k2 * L**2 + k1 * a**2)


def _on_manifold(model: str, eqs: EquationSet | None = None) -> EquationSet:
    """Model ``model`` with theta (and the pivot travel w) put on the constraint manifold.

    The static rows vanish there identically (checked with ``cancel``: they are rational in
    the parameters) and are dropped; the rest is a one-coordinate model in ``y``.
    """
    eqs = eqs or problem.model(model)
    values = {theta: ON_MANIFOLD, w: sp.Integer(0)}
    rules = {}
    for q in eqs.coordinates:
        if q in values:
            rules[DD(q)] = values[q].diff(t, 2)
            rules[D(q)] = values[q].diff(t)
    rows, labels = [], []
    for e, label in zip(eqs.equations, eqs.labels):
        e = e.xreplace(rules).xreplace({q: values[q] for q in eqs.coordinates if q in values})
        if sp.cancel(e) != 0:
            rows.append(e)
            labels.append(label)
    return EquationSet(model, (y,), rows, eqs.unknowns, labels)


@pytest.mark.parametrize("model", ["newton_euler", "lagrange", "multiplier"])
def test_theta_has_no_inertia_so_its_rows_are_static(model):
    eqs = problem.in_reference_coordinates(problem.model(model))
    M = eqs.mass_matrix()
    assert list(M[:, 1]) == [0] * M.rows           # theta'' appears nowhere
    static = [i for i in range(M.rows) if list(M[i, :]) == [0, 0]]
    assert len(static) == M.rows - 1                 # only the m2 row is dynamic


def test_static_row_is_the_printed_one():
    # Lagrange, theta: k2 L (L theta - y) + k1 a^2 theta = 0, i.e. (k2 L^2 + k1 a^2) theta = k2 L y
    _, static = problem.model("lagrange").equations
    assert sp.expand(static - ((k2 * L**2 + k1 * a**2) * theta - k2 * L * y)) == 0
    assert sp.solve(static, theta) == [ON_MANIFOLD]


def test_reduced_model_is_the_printed_one_coordinate_equation():
    (eq,) = problem.model("reduced").equations
    printed = (m2 * DD(y) + b * D(y) + k2 * y
               - k2 * L * k2 * L / (k2 * L**2 + k1 * a**2) * y - F)
    assert sp.simplify(eq - printed) == 0
    assert sp.simplify(k2 - k2**2 * L**2 / (k2 * L**2 + k1 * a**2) - effective_stiffness()) == 0


@pytest.mark.parametrize("model", ["newton_euler", "lagrange", "multiplier"])
def test_on_the_manifold_every_model_is_the_reduced_motion(model):
    # theta -> k2 L y / (k2 L^2 + k1 a^2): the static rows vanish identically and are dropped,
    # what is left must be the one-coordinate motion (exact test)
    reduced = _on_manifold(model)
    assert all(not e.has(theta) for e in reduced.equations)
    result = compare_models(problem.model("reduced"), reduced)
    assert result.equivalent and result.method == "exact", str(result)


def test_on_the_manifold_both_pivot_reactions_agree_with_the_hand_value():
    direct, multiplier = _on_manifold("newton_euler"), _on_manifold("multiplier")
    pair = compare_reactions(problem.model("reduced"), direct, multiplier,
                             [sp.Symbol("R_O", real=True)])
    assert pair.equivalent and pair.method == "exact"
    # R_O = k1 a theta - k2 (y - L theta) = k1 k2 a (L - a) y / (k2 L^2 + k1 a^2)
    (R,) = direct.reactions_solved().values()
    assert sp.simplify(R - R_O_HAND) == 0


def test_on_the_manifold_a_wrong_spring_is_caught():
    broken = problem.model("newton_euler").flipped("spring k1")
    moved = _on_manifold("newton_euler", broken)
    assert not compare_models(problem.model("reduced"), moved, explain=False).equivalent


def test_static_deflection_under_a_constant_force():
    # at rest the one-coordinate model gives y = F / k_e; the bar then turns by
    # theta = k2 L y / (k2 L^2 + k1 a^2) = F L / (k1 a^2): the moment F L balanced by k1 a^2
    (eq,) = problem.model("reduced").equations
    (y_static,) = sp.solve(eq.subs({DD(y): 0, D(y): 0}).subs(y, sp.Symbol("Y")), sp.Symbol("Y"))
    assert sp.simplify(y_static - F / effective_stiffness()) == 0
    assert sp.simplify(ON_MANIFOLD.subs(y, y_static) - F * L / (k1 * a**2)) == 0


def test_printed_answers_judged_by_hand_on_the_manifold():
    # expressions: printed - derived must vanish; equations: on the manifold (theta from the
    # static row, y'' from the one-coordinate model) the printed left sides must vanish
    (eq,) = problem.model("reduced").equations
    (ydd,) = sp.solve(eq, DD(y))
    theta_dd = ON_MANIFOLD.diff(t, 2).subs(DD(y), ydd)
    on_shell = lambda e: sp.simplify(  # noqa: E731
        e.subs(DD(theta), theta_dd).subs(D(theta), ON_MANIFOLD.diff(t))
        .subs(theta, ON_MANIFOLD).subs(DD(y), ydd))
    wrong = set()
    for pub in problem.published():
        if pub.kind == "expression":
            left = [sp.simplify(p - r) for p, r in zip(pub.printed, pub.reference)]
        else:
            left = [on_shell(p) for p in pub.printed]
        if any(v != 0 for v in left):
            wrong.add(pub.label)
    assert wrong == {"Lagrange's equation for theta"}
    # ... and what it gets wrong is the sign of dU/dtheta: printed - derived = -2 dU/dtheta
    (pub,) = [p for p in problem.published() if p.label == "Lagrange's equation for theta"]
    dU = (k2 * (L * theta - y)**2 / 2 + k1 * (a * theta)**2 / 2).diff(theta)
    assert sp.simplify(pub.printed[0] - pub.reference[0] + 2 * dU) == 0


# -- what the comparator does with the static row kept in the set (that it decides the
# differential-algebraic models, and judges the printed answers, is checked with every
# problem's in tests/test_catalogue_checks.py) ------------------------------------------------
def test_check_solves_the_static_row_and_shows_y_theta_and_R_O():
    # hand (module docstring): theta = k2 L y / (k2 L^2 + k1 a^2) from the static row,
    # m2 y'' = F - b y' - k2 (y - L theta), R_O = k1 k2 a (L - a) y / (k2 L^2 + k1 a^2)
    c = compare(problem)
    assert c.display_notes == []
    assert set(c.accelerations) == {"y"} and set(c.static) == {"theta"}
    assert sp.simplify(c.static["theta"] - ON_MANIFOLD) == 0
    y_dd = (F - b * D(y) - k2 * (y - L * ON_MANIFOLD)) / m2
    assert sp.simplify(c.accelerations["y"] - y_dd) == 0
    assert sp.simplify(c.reactions["R_O"] - R_O_HAND) == 0
    d = c.to_dict()
    assert set(d["accelerations"]) == {"y"} and set(d["static"]) == {"theta"}
    assert set(d["reactions"]) == {"R_O"} and d["reactions_not_cross_checked"] == []
    assert "θ = L k₂ y/(L^2 k₂ + a^2 k₁)   (static row: no inertia in θ)" in str(c)


def test_simulating_the_dae_as_an_ode_is_refused_saying_what_it_is(capsys):
    """The reference model holds the massless bar's balance (no acceleration in the theta
    row): ``simulate`` says it is a DAE and where it is integrated as one, instead of
    reporting a singular state and telling the user to stay away from it."""
    from dualmech import get, simulate
    from dualmech.cli.main import main
    from dualmech.numeric import SingularityError
    with pytest.raises(SingularityError, match=r"static rows \(Lagrange, theta.*is a DAE"):
        simulate(get("copying_machine"), t_span=(0, 1))
    assert main(["simulate", "copying_machine"]) == 1
    err = capsys.readouterr().err
    assert "dualmech chart copying_machine" in err and "stay away" not in err
